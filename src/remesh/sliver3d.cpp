// Sliver removal: swaps, optimising moves and collapses around the worst tets.
#include "remesh/sliver3d.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/adjacency.hpp"

namespace riemesh {
namespace {

/// The point that makes (p, a, b, c) a regular tet in the metric mm, on v's side of face
/// (a, b, c) (`side`: v's current position).
Vec3 ideal_apex(const SymMat3& mm, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& side) {
  Vec3 n = cross(b - a, c - a);
  if (dot(n, side - a) < 0.0) n = -1.0 * n;
  const Vec3 d = inverse(mm) * n;  // the metric normal, in space
  const double dn = std::sqrt(std::max(dot(n, d), 0.0));
  const double mean = (length(mm, b - a) + length(mm, c - b) + length(mm, a - c)) / 3.0;
  const Vec3 g = (1.0 / 3.0) * (a + b + c);
  if (!(dn > 0.0)) return g;
  return g + (std::sqrt(2.0 / 3.0) * mean / dn) * d;
}

/// The worst quality of the ball with v at p (v's metric unchanged), or some value <= floor
/// once it is known not to exceed floor; ball[first] is tried first (the likely worst).
double worst_at(TetMesh& m, Id v, const std::vector<Id>& ball, const Vec3& p, double floor,
                std::size_t first) {
  const Vec3 old = m.xyz[v];
  m.xyz[v] = p;
  double worst = std::min(1.0, tet_quality(m, ball[first]));
  for (std::size_t k = 0; k < ball.size() && worst > 0.0 && worst > floor; ++k)
    if (k != first) worst = std::min(worst, tet_quality(m, ball[k]));
  m.xyz[v] = old;
  return worst;
}

}  // namespace

Outcome optimise_vertex(Remesh3dContext& ctx, Id v) {
  TetMesh& m = ctx.mesh();
  if (m.vkind[v] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  thread_local MoveCache cache;  // the ball, handed to move_vertex with its worst quality
  std::vector<Id>& ball = cache.ball;
  cache.v = kNoId;
  collect_ball(m, v, ball);
  if (ball.empty()) return Outcome::kRejectedTopology;
  const Vec3 p0 = m.xyz[v];
  Vec3 sum{}, worst_apex = p0;
  double wsum = 0.0, worst = 2.0;
  std::size_t worst_index = 0;
  for (std::size_t k = 0; k < ball.size(); ++k) {
    const Id t = ball[k];
    const Id* tv = &m.tv[4 * t];
    const int i = tet_index(m, t, v);
    const Id a = tv[kTetFace[i][0]], b = tv[kTetFace[i][1]], c = tv[kTetFace[i][2]];
    const SymMat3 mm = 0.25 * (m.metric[a] + m.metric[b] + m.metric[c] + m.metric[v]);
    const Vec3 apex = ideal_apex(mm, m.xyz[a], m.xyz[b], m.xyz[c], p0);
    const double q = cached_quality(m, t);
    const double w = 1.0 / std::pow(std::max(q, 0.02), 4);
    sum = sum + w * apex, wsum += w;
    if (q < worst) worst = q, worst_apex = apex, worst_index = k;
  }
  const Vec3 targets[2] = {(1.0 / wsum) * sum, worst_apex};
  Vec3 best_p = p0;
  double best = worst;
  for (const Vec3& target : targets)
    for (const double f : {1.0, 0.5, 0.25, 0.1}) {
      Vec3 p = p0 + f * (target - p0);
      if (!ctx.constrain(v, p)) return Outcome::kRejectedTopology;
      const double q = worst_at(m, v, ball, p, best, worst_index);
      if (q > best) best = q, best_p = p;
    }
  if (!(best > worst + 1e-4)) return Outcome::kRejectedQuality;
  cache.v = v, cache.worst = std::min(worst, 1.0), cache.first = worst_index;  // as move_vertex
  const Outcome o = move_vertex(m, v, best_p, ctx.metric_for(best_p, v), &cache);
  if (o == Outcome::kApplied) ctx.inherit_hint(v);
  return o;
}

long sliver_sweeps(Remesh3dContext& ctx, const SliverLimits& limits, PassStats& st) {
  TetMesh& m = ctx.mesh();
  std::vector<std::pair<double, Id>> bad;
  long total = 0;
  for (int sweep = 0; sweep < limits.sweeps; ++sweep) {
    bad.clear();
    for (std::size_t ti = 0; ti < m.tet_capacity(); ++ti) {
      const Id t = static_cast<Id>(ti);
      if (!m.tet_alive(t)) continue;
      const double q = cached_quality(m, t);
      if (q < limits.target) bad.emplace_back(q, t);
    }
    std::sort(bad.begin(), bad.end());
    const double cap = std::max(100.0, limits.budget * static_cast<double>(m.num_live_tets()));
    if (static_cast<double>(bad.size()) > cap) bad.resize(static_cast<std::size_t>(cap));
    long done = 0;
    for (const auto& [q0, t] : bad) {
      if (!m.tet_alive(t) || cached_quality(m, t) >= limits.target) continue;
      Id v[4];
      std::copy(&m.tv[4 * t], &m.tv[4 * t] + 4, v);
      bool applied = false;
      for (int k = 0; k < 6 && !applied && limits.swap; ++k)
        if (swap_edge(m, v[kTetEdge[k][0]], v[kTetEdge[k][1]], 1e-4, limits.max_length, t) ==
            Outcome::kApplied)
          applied = true, ++st.swaps;
      for (int i = 0; i < 4 && !applied && limits.swap; ++i)
        if (swap_face(m, 4 * t + i, 1e-4, limits.max_length) == Outcome::kApplied)
          applied = true, ++st.swaps;
      for (int i = 0; i < 4 && !applied && limits.move; ++i)
        if (optimise_vertex(ctx, v[i]) == Outcome::kApplied) {
          ++st.moves;
          applied = !m.tet_alive(t) || cached_quality(m, t) >= limits.target;
          if (!applied) ++done;  // counted, but the tet is worked on further
        }
      if (!applied && limits.collapse && m.tet_alive(t)) {
        std::pair<double, int> edges[6];
        for (int k = 0; k < 6; ++k)
          edges[k] = {edge_length(m, v[kTetEdge[k][0]], v[kTetEdge[k][1]]), k};
        std::sort(edges, edges + 6);
        for (int e = 0; e < 6 && !applied; ++e) {
          const Id a = v[kTetEdge[edges[e].second][0]], b = v[kTetEdge[edges[e].second][1]];
          for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}})
            if (collapse_edge(m, from, to, {1.0, limits.max_length}) == Outcome::kApplied) {
              applied = true, ++st.collapses;
              break;
            }
        }
      }
      if (applied) ++done;
      else ++st.rejected;
    }
    total += done;
    if (done == 0) break;
  }
  return total;
}

}  // namespace riemesh
