// Sliver removal: swaps, optimising moves and collapses around the worst tets.
#include "remesh/sliver3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "core/eigen.hpp"
#include "mesh/adjacency.hpp"

namespace riemesh {
namespace {

// Tets on fixed vertices only get a new interior vertex (star_sliver, split_sliver) below this
// quality: the kept surface's slivers (rotor), not the ordinary bad tets of the surface layer.
constexpr double kSplitBelow = 0.1;

// optimise_vertex refines its best candidate by a compass search when the ball is worse than this.
constexpr double kCompassBelow = 0.5;

// The band of unit lengths [1/sqrt 2, sqrt 2].
constexpr double kBandLow = 0.70710678118654752, kBandHigh = 1.4142135623730951;

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

/// v's ball frozen for a search over v's position (v's metric unchanged, as worst_at): each
/// tet's metric and other vertices, each edge at v with its end metrics (and Simpson's midpoint
/// metric where they do not commute) and its allowed length range.
struct BallModel {
  struct Tet {
    SymMat3 metric;
    double scale;  // 3 sqrt(det metric)
    Vec3 p[4];
    int at;  // v's index
  };
  struct Edge {
    Vec3 w;
    SymMat3 mw, mid;
    bool turning;
    double lo, hi;
  };
  SymMat3 mv;
  std::vector<Tet> tets;
  std::vector<Edge> edges;

  void build(const TetMesh& m, Id v, const std::vector<Id>& ball) {
    mv = m.metric[v];
    tets.clear(), edges.clear();
    std::vector<Id> seen;
    for (const Id t : ball) {
      const Id* tv = &m.tv[4 * t];
      Tet x{tet_metric(m, tv[0], tv[1], tv[2], tv[3]), 0.0, {}, 0};
      x.scale = 3.0 * std::sqrt(det(x.metric));
      for (int i = 0; i < 4; ++i) {
        x.p[i] = m.xyz[tv[i]];
        if (tv[i] == v) {
          x.at = i;
        } else if (std::find(seen.begin(), seen.end(), tv[i]) == seen.end()) {
          seen.push_back(tv[i]);
          const Id w = tv[i];
          Edge e{m.xyz[w], m.metric[w], {}, !commute(mv, m.metric[w]), 0.0, 0.0};
          if (e.turning) e.mid = exp_sym_series(0.5 * (log_at(m, v) + log_at(m, w)));
          const double l = length_to(e, m.xyz[v]);
          e.lo = std::min(l, kBandLow), e.hi = std::max(l, kBandHigh);
          edges.push_back(e);
        }
      }
      tets.push_back(x);
    }
  }
  /// v's log metric, kept by the mesh once some metric turns.
  static SymMat3 log_at(const TetMesh& m, Id v) {
    const SymMat3* l = log_of(m.log_metric, v);
    return l ? *l : log_spd(m.metric[v]);
  }
  /// edge_length_simpson of the edge from p.
  double length_to(const Edge& e, const Vec3& p) const {
    const Vec3 d = e.w - p;
    if (!e.turning) return edge_length_geometric(mv, e.mw, d);
    return (length(mv, d) + 4.0 * length(e.mid, d) + length(e.mw, d)) / 6.0;
  }
  /// The worst quality with v at p (quality_in, by its cube: no cube root per tet), or some
  /// value <= floor once known not to exceed it.
  double worst(const Vec3& p, double floor) {
    const double floor3 = floor > 0.0 ? floor * floor * floor : 0.0;
    double out3 = 1.0;
    for (Tet& t : tets) {
      t.p[t.at] = p;
      const Vec3 e[6] = {t.p[1] - t.p[0], t.p[2] - t.p[0], t.p[3] - t.p[0],
                         t.p[2] - t.p[1], t.p[3] - t.p[1], t.p[3] - t.p[2]};
      double l2 = 0.0, longest = 0.0;
      for (const Vec3& x : e) l2 += quadratic(t.metric, x), longest = std::max(longest, dot(x, x));
      const double vol = tet_volume(t.p[0], t.p[1], t.p[2], t.p[3]);
      if (!(vol > kMinRelativeVolume * longest * std::sqrt(longest))) return std::min(vol, 0.0);
      const double c3 = t.scale * vol;  // 3 sqrt(det M) |K|, the cube of quality_in's c
      out3 = std::min(out3, 1728.0 * c3 * c3 / (l2 * l2 * l2));
      if (!(out3 > floor3)) break;
    }
    return std::cbrt(out3);
  }
  bool lengths_ok(const Vec3& p) const {
    for (const Edge& e : edges) {
      const double l = length_to(e, p);
      if (!(l >= e.lo && l <= e.hi)) return false;
    }
    return true;
  }
};

/// Whether the edge (a, b) of the closed shell `shell` lies in no listed face.
bool interior_edge(const TetMesh& m, std::span<const Id> shell, Id a, Id b) {
  for (const Id t : shell)
    for (int i = 0; i < 4; ++i) {
      const Id v = m.tv[4 * t + i];
      if (v != a && v != b && (m.fbdy[4 * t + i] || m.tadj[4 * t + i] == kNoId)) return false;
    }
  return true;
}

/// The tets that cutting the shell of (a, b) at a new vertex x creates (as split_edge: a, then
/// b replaced by x), and x's index in each.
void split_tets(const TetMesh& m, std::span<const Id> shell, Id a, Id b, Id x,
                std::vector<std::array<Id, 4>>& out, std::vector<int>& at) {
  out.clear(), at.clear();
  for (const Id t : shell)
    for (const Id gone : {b, a}) {
      std::array<Id, 4> v{};
      for (int i = 0; i < 4; ++i) {
        v[i] = m.tv[4 * t + i] == gone ? x : m.tv[4 * t + i];
        if (v[i] == x) at.push_back(i);
      }
      out.push_back(v);
    }
}

/// The worst quality of `tets` with x at p, and the index of the worst in *worst_index.
double worst_with(TetMesh& m, Id x, const Vec3& p, const std::vector<std::array<Id, 4>>& tets,
                  std::size_t* worst_index) {
  m.xyz[x] = p;
  double worst = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < tets.size(); ++k) {
    const double q = tet_quality(m, tets[k].data());
    if (q < worst) worst = q, *worst_index = k;
  }
  return worst;
}

/// Off-edge split of the interior edge (a, b): the position of a new interior vertex x cutting
/// every tet of the shell in two that maximises the worst new tet (from the edge's middle, moves
/// toward the ideal apexes as optimise_vertex), its metric in *metric; returns that worst.
double best_split_point(Remesh3dContext& ctx, std::span<const Id> shell, Id a, Id b, Vec3& best_p,
                        SymMat3& metric) {
  TetMesh& m = ctx.mesh();
  thread_local std::vector<std::array<Id, 4>> tets;
  thread_local std::vector<int> at;
  best_p = 0.5 * (m.xyz[a] + m.xyz[b]);
  metric = ctx.metric_for(best_p, a);
  const Id x = m.add_vertex(best_p, metric);
  split_tets(m, shell, a, b, x, tets, at);
  std::size_t wi = 0;
  double best = worst_with(m, x, best_p, tets, &wi);
  for (int iter = 0; iter < 20; ++iter) {
    Vec3 sum{}, worst_apex{};
    double wsum = 0.0;
    for (std::size_t k = 0; k < tets.size(); ++k) {
      const std::array<Id, 4>& v = tets[k];
      const int i = at[k];
      const Vec3 &pa = m.xyz[v[kTetFace[i][0]]], &pb = m.xyz[v[kTetFace[i][1]]],
                 &pc = m.xyz[v[kTetFace[i][2]]];
      const Vec3 inward = pa - cross(pb - pa, pc - pa);  // x's side of the outward face
      const SymMat3 mm = tet_metric(m, v[0], v[1], v[2], v[3]);
      const Vec3 apex = ideal_apex(mm, pa, pb, pc, inward);
      const double q = tet_quality(m, v.data());
      const double w = 1.0 / std::pow(std::max(q, 0.02), 4);
      sum = sum + w * apex, wsum += w;
      if (k == wi) worst_apex = apex;
    }
    const Vec3 p0 = best_p;
    bool improved = false;
    for (const Vec3& target : {(1.0 / wsum) * sum, worst_apex})
      for (const double f : {1.0, 0.5, 0.25, 0.1, 0.03}) {
        const Vec3 p = p0 + f * (target - p0);
        std::size_t k = 0;
        const double q = worst_with(m, x, p, tets, &k);
        if (q > best + 1e-6) best = q, best_p = p, wi = k, improved = true;
      }
    if (!improved) break;
  }
  m.kill_vertex(x);
  metric = ctx.metric_for(best_p, a);
  return best;
}

constexpr std::size_t kMaxCavity = 64;  // star_cavity's limit

/// The star of x (at p) over a cavity grown from tet t: a face of the cavity's boundary whose
/// tet with x is below `floor` takes the tet behind it into the cavity (not across a listed or
/// domain-boundary face; at most kMaxCavity tets). On success `cavity` and `tets` hold the
/// cavity and its star (x at p, every tet above floor), every cavity vertex on its boundary.
bool star_cavity(TetMesh& m, Id t, Id x, double floor, std::vector<Id>& cavity,
                 std::vector<NewTet>& tets) {
  cavity.assign(1, t);
  for (bool grown = true; grown;) {
    grown = false;
    tets.clear();
    for (std::size_t k = 0; k < cavity.size() && !grown; ++k) {
      const Id c = cavity[k];
      for (int i = 0; i < 4 && !grown; ++i) {
        const Id r = m.tadj[4 * c + i];
        if (r != kNoId && std::find(cavity.begin(), cavity.end(), r / 4) != cavity.end()) continue;
        NewTet nt{};
        std::copy(&m.tv[4 * c], &m.tv[4 * c] + 4, nt.v);
        nt.v[i] = x, nt.ref = m.tref[c];
        if (tet_quality(m, nt.v) >= floor) {
          tets.push_back(nt);
          continue;
        }
        if (r == kNoId || m.fbdy[4 * c + i] || cavity.size() >= kMaxCavity) return false;
        cavity.push_back(r / 4), grown = true;
      }
    }
  }
  // Every vertex of the cavity must stay (on a face of its boundary).
  for (const Id c : cavity)
    for (int i = 0; i < 4; ++i) {
      const Id v = m.tv[4 * c + i];
      bool kept = false;
      for (const NewTet& nt : tets) kept = kept || std::find(nt.v, nt.v + 4, v) != nt.v + 4;
      if (!kept) return false;
    }
  return true;
}

}  // namespace

Outcome split_sliver(Remesh3dContext& ctx, Id t, double min_gain, Id* created) {
  TetMesh& m = ctx.mesh();
  const double q0 = cached_quality(m, t);
  thread_local std::vector<Id> shell;
  Id v[4];
  std::copy(&m.tv[4 * t], &m.tv[4 * t] + 4, v);
  double best = q0 + min_gain;
  Id ba = kNoId, bb = kNoId;
  NewVertex3 nv;
  for (const auto& [i, j] : kTetEdge) {
    collect_shell(m, v[i], v[j], shell, t);
    if (shell.empty() || !interior_edge(m, shell, v[i], v[j])) continue;
    Vec3 p;
    SymMat3 metric;
    const double q = best_split_point(ctx, shell, v[i], v[j], p, metric);
    if (q > best) best = q, ba = v[i], bb = v[j], nv.p = p, nv.metric = metric;
  }
  if (ba == kNoId) return Outcome::kRejectedQuality;
  nv.kind = VertexKind::kInterior;
  const Outcome o = split_edge(m, ba, bb, nv, q0 + min_gain, created, t);
  if (o == Outcome::kApplied) ctx.inherit_hint(*created);
  return o;
}

Outcome star_sliver(Remesh3dContext& ctx, Id t, double floor, Id* created) {
  TetMesh& m = ctx.mesh();
  thread_local std::vector<Id> cavity, best_cavity;
  thread_local std::vector<NewTet> tets, best_tets;
  Id v[4];
  std::copy(&m.tv[4 * t], &m.tv[4 * t] + 4, v);
  const Vec3 g = 0.25 * (m.xyz[v[0]] + m.xyz[v[1]] + m.xyz[v[2]] + m.xyz[v[3]]);
  const SymMat3 mm = tet_metric(m, v[0], v[1], v[2], v[3]);
  const Id x = m.add_vertex(g, mm);
  double best = floor;
  Vec3 best_p{};
  bool found = false;
  for (int i = 0; i < 4; ++i) {
    // Above face i, on either side: the ideal apex, and the way there.
    const Vec3 &pa = m.xyz[v[kTetFace[i][0]]], &pb = m.xyz[v[kTetFace[i][1]]],
               &pc = m.xyz[v[kTetFace[i][2]]];
    const Vec3 n = cross(pb - pa, pc - pa);
    const Vec3 fg = (1.0 / 3.0) * (pa + pb + pc);
    for (const double side : {-1.0, 1.0}) {
      const Vec3 apex = ideal_apex(mm, pa, pb, pc, pa + side * n);
      for (const double f : {1.0, 0.5, 0.25, 0.12, 0.06, 0.03}) {
        m.xyz[x] = fg + f * (apex - fg);
        if (!star_cavity(m, t, x, best, cavity, tets)) continue;
        double worst = std::numeric_limits<double>::infinity();
        for (const NewTet& nt : tets) worst = std::min(worst, tet_quality(m, nt.v));
        if (!(worst > best)) continue;
        best = worst, best_p = m.xyz[x], found = true;
        best_cavity = cavity, best_tets = tets;
      }
    }
  }
  if (!found) {
    m.kill_vertex(x);
    return Outcome::kRejectedQuality;
  }
  m.xyz[x] = best_p;
  m.set_metric(x, ctx.metric_for(best_p, v[0]));
  for (const NewTet& nt : best_tets)
    if (!(tet_quality(m, nt.v) > floor)) {
      m.kill_vertex(x);
      return Outcome::kRejectedQuality;
    }
  if (!replace_cavity(m, best_cavity, best_tets, {})) {
    m.kill_vertex(x);
    return Outcome::kRejectedTopology;
  }
  m.vkind[x] = VertexKind::kInterior;
  ctx.inherit_hint(x);
  *created = x;
  return Outcome::kApplied;
}

double compass_search(Remesh3dContext& ctx, Id v, const std::vector<Id>& ball, Vec3& p,
                      double best) {
  const TetMesh& m = ctx.mesh();
  thread_local BallModel model;
  model.build(m, v, ball);
  const SymEigen<3> e = eigen(m.metric[v]);
  Vec3 dir[3];
  for (int i = 0; i < 3; ++i) {
    const double h = 1.0 / std::sqrt(std::max(e.values[i], 1e-300));
    dir[i] = Vec3{{h * e.vectors(0, i), h * e.vectors(1, i), h * e.vectors(2, i)}};
  }
  int moves = 0;
  for (double step = 0.2; step > 0.02 && moves < 12;) {
    Vec3 next = p;
    double next_q = best;
    for (int i = 0; i < 6; ++i) {
      Vec3 q = p + ((i & 1) ? -step : step) * dir[i / 2];
      if (!ctx.constrain(v, q)) return best;
      const double w = model.worst(q, next_q);
      if (w > next_q && model.lengths_ok(q)) next_q = w, next = q;
    }
    if (next_q > best + 1e-6) {
      p = next, best = next_q, ++moves;
    } else {
      step *= 0.5;
    }
  }
  return best;
}

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
    const SymMat3 mm = tet_metric(m, a, b, c, v);
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
  if (worst < kCompassBelow && m.vkind[v] == VertexKind::kInterior)
    best = compass_search(ctx, v, ball, best_p, best);
  if (!(best > worst + 1e-4)) return Outcome::kRejectedQuality;
  cache.v = v, cache.worst = std::min(worst, 1.0), cache.first = worst_index;  // as move_vertex
  const Outcome o = move_vertex(m, v, best_p, ctx.metric_for(best_p, v), &cache);
  if (o == Outcome::kApplied) ctx.inherit_hint(v);
  return o;
}

long sliver_sweeps(Remesh3dContext& ctx, const SliverLimits& limits, PassStats& st,
                   const NeighbourTable* nbrs, FailureMemo* memo) {
  TetMesh& m = ctx.mesh();
  if (limits.split_fixed || !nbrs) memo = nullptr;
  std::vector<std::pair<double, Id>> bad;
  long total = 0;
  for (int sweep = 0; sweep < limits.sweeps; ++sweep) {
    bad.clear();
    for (std::size_t ti = 0; ti < m.tet_capacity(); ++ti) {
      const Id t = static_cast<Id>(ti);
      if (!m.tet_alive(t)) continue;
      const double q = cached_quality(m, t);
      if (q < limits.target && !(memo && memo->known_to_fail(m, t, *nbrs))) bad.emplace_back(q, t);
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
      // Last, a tet none of whose vertices may move (a kept surface): a new interior vertex,
      // the star of a cavity around it or else off one of its interior edges.
      if (!applied && limits.split_fixed && m.tet_alive(t) && cached_quality(m, t) < kSplitBelow &&
          std::all_of(v, v + 4, [&](Id x) { return m.vkind[x] == VertexKind::kFixed; })) {
        Id created = kNoId;
        if (star_sliver(ctx, t, cached_quality(m, t) + 1e-3, &created) == Outcome::kApplied ||
            split_sliver(ctx, t, 1e-3, &created) == Outcome::kApplied) {
          applied = true, ++st.splits;
          for (int k = 0; k < 3 && optimise_vertex(ctx, created) == Outcome::kApplied; ++k)
            ++st.moves;
        }
      }
      if (applied) {
        ++done;
      } else {
        ++st.rejected;
        if (memo) memo->failed(m, t);
      }
    }
    total += done;
    if (done == 0) break;
  }
  return total;
}

}  // namespace riemesh
