// Edge collapse: vertex `from` disappears into `to`; the tets of the edge's shell go.
#include <algorithm>

#include "remesh/boundary3d.hpp"
#include "remesh/ops3d.hpp"

namespace riemesh {
namespace {

/// The boundary rules: which listed faces hold edge (from, to), against from's kind. A planar
/// interface counts once (its face is listed on both sides): its planar and ridge vertices go
/// along their plane or line as those of the outer boundary (remesh3d_context.hpp).
bool boundary_ok(const TetMesh& m, const std::vector<Id>& shell, Id from, Id to) {
  const VertexKind k = m.vkind[from];
  if (k == VertexKind::kFixed) return false;
  std::int32_t refs[4];
  int n = 0;
  bool interface = false;
  for (const Id t : shell)
    for (int i = 0; i < 4; ++i) {
      const Id v = m.tv[4 * t + i], s = 4 * t + i, r = m.tadj[s];
      if (v == from || v == to || !m.fbdy[s] || (r != kNoId && r < s)) continue;
      if (n == 4) return false;
      refs[n++] = m.face_ref(s);
      interface = interface || r != kNoId;
    }
  if (k == VertexKind::kInterior) return n == 0;
  const std::int32_t p0 = m.vplane[2 * from], p1 = m.vplane[2 * from + 1];
  if (k == VertexKind::kRidge) {  // along its line: the edge in both planes
    const auto has = [&](std::int32_t p) { return std::find(refs, refs + n, p) != refs + n; };
    // (a line of the input's Edges inside planar patch p0 = p1: along the line's edges)
    return n >= 2 && has(p0) && has(p1) && (p0 != p1 || m.on_line(from, to));
  }
  // A rim vertex (remesh3d_context.hpp: the rebuilt curved patch p0 meets the planar p1, with
  // 2 or 3 faces on the rim): along the rim, an edge on both.
  if (k == VertexKind::kCurve && m.surface && m.surface->curved(p0) && !m.surface->curved(p1)) {
    const auto has = [&](std::int32_t p) { return std::find(refs, refs + n, p) != refs + n; };
    return has(p0) && has(p1);
  }
  if (n != 2) return false;
  if (k == VertexKind::kPlanar) return refs[0] == p0 && refs[1] == p0;
  // (curved patches meeting a kept interface are fixed; a rebuilt curved interface is on the
  // reconstruction: m.surface)
  if (interface && !(m.surface && m.surface->curved(refs[0]) && m.surface->curved(refs[1])))
    return false;
  if (k == VertexKind::kSurface) return refs[0] == p0 && refs[1] == p0;
  if (k == VertexKind::kCurve)  // along its feature line only
    return m.surface && ((refs[0] == p0 && refs[1] == p1) || (refs[0] == p1 && refs[1] == p0)) &&
           m.surface->feature_edge(m, from, to, refs[0], refs[1]);
  return (refs[0] == p0 && refs[1] == p1) || (refs[0] == p1 && refs[1] == p0);
}

/// The worst quality of the tets with four boundary vertices among `tets` (1 when none).
template <class Tets, class Verts>
double worst_on_boundary(const TetMesh& m, const Tets& tets, Verts verts) {
  double worst = 1.0;
  for (const auto& t : tets) {
    const Id* v = verts(t);
    bool all = true;
    for (int i = 0; i < 4 && all; ++i) all = m.vkind[v[i]] != VertexKind::kInterior;
    if (all) worst = std::min(worst, tet_quality(m, v));
  }
  return worst;
}

}  // namespace

bool collapse_too_long(const TetMesh& m, std::span<const Id> neighbours, Id to,
                       const CollapseLimits& limits) {
  for (const Id x : neighbours)
    if (x != to && edge_longer_than(m, to, x, limits.max_length)) return true;
  return false;
}

Outcome collapse_edge(TetMesh& m, Id from, Id to, const CollapseLimits& limits) {
  thread_local std::vector<Id> ball, shell;
  thread_local std::vector<NewTet> tets;
  if (m.vkind[from] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  collect_ball(m, from, ball);
  shell.clear();
  for (const Id t : ball)
    if (tet_index(m, t, to) >= 0) shell.push_back(t);
  if (shell.empty()) return Outcome::kRejectedTopology;
  if (!boundary_ok(m, shell, from, to)) return Outcome::kRejectedTopology;
  // New edge lengths first: the cheapest check and the one that refuses most (each neighbour
  // once: it is in several tets of the ball).
  thread_local std::vector<Id> seen;
  seen.clear();
  for (const Id t : ball)
    for (int i = 0; i < 4; ++i) {
      const Id x = m.tv[4 * t + i];
      if (x == from || x == to || std::find(seen.begin(), seen.end(), x) != seen.end()) continue;
      if (edge_longer_than(m, to, x, limits.max_length)) return Outcome::kRejectedQuality;
      seen.push_back(x);
    }
  // A vertex on a line of the input's Edges goes only along it (m.line_ref).
  bool on_lines = false;
  for (const Id x : seen) on_lines = on_lines || m.on_line(from, x);
  if (on_lines && !m.on_line(from, to)) return Outcome::kRejectedTopology;
  tets.clear();
  double new_worst = 1.0;
  for (const Id t : ball) {
    if (tet_index(m, t, to) >= 0) continue;
    NewTet n{};
    for (int i = 0; i < 4; ++i) {
      const Id v = m.tv[4 * t + i];
      n.v[i] = v == from ? to : v;
    }
    n.ref = m.tref[t];
    const double q = tet_quality(m, n.v);
    if (!(q > 0.0)) return Outcome::kRejectedGeometry;
    new_worst = std::min(new_worst, q);
    tets.push_back(n);
  }
  // With curved patches, no new tet on four boundary vertices below the floor (boundary3d.hpp)
  // unless the ball had a worse one: such tets, at folds of the surface, stay for good.
  if (m.surface) {
    const double w4 = worst_on_boundary(m, tets, [](const NewTet& n) { return n.v; });
    if (w4 < kBoundaryTetFloor &&
        w4 < worst_on_boundary(m, ball, [&m](Id t) { return &m.tv[4 * t]; }))
      return Outcome::kRejectedQuality;
  }
  // Below the floor only when the ball was already worse (its worst quality, computed only then).
  if (new_worst < limits.min_quality) {
    double old_worst = 1.0;
    for (const Id t : ball) old_worst = std::min(old_worst, cached_quality(m, t));
    if (new_worst < old_worst) return Outcome::kRejectedQuality;
  }
  // A vertex of a curved patch: the new boundary triangles stay near the input surface.
  if (on_curved_boundary(m.vkind[from]) && !curved_boundary_ok(m, ball, from, to, m.xyz[to]))
    return Outcome::kRejectedGeometry;
  const Substitution subst[1] = {{to, from}};
  if (!replace_cavity(m, ball, tets, subst)) return Outcome::kRejectedTopology;
  if (!m.line_ref.empty()) {  // from's lines now end at `to` (the edge (from, to) is gone)
    m.line_ref.erase(TetMesh::line_key(from, to));
    for (const Id x : seen)
      if (const auto it = m.line_ref.find(TetMesh::line_key(from, x)); it != m.line_ref.end()) {
        const std::int32_t ref = it->second;
        m.line_ref.erase(it);
        m.line_ref.emplace(TetMesh::line_key(to, x), ref);
      }
  }
  m.kill_vertex(from);
  return Outcome::kApplied;
}

}  // namespace riemesh
