// Feature edges, corners and chaining of the curves of a planar mesh (boundary_curves.hpp).
#include "remesh/boundary_curves.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>
#include <string>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "mesh/adjacency.hpp"

namespace riemesh {

void CurveOptions::validate() const {
  if (!(angle_deg >= 0.0 && angle_deg <= 180.0)) {
    std::string msg = "curve options: angle must be in [0, 180] degrees, got ";
    msg += std::to_string(angle_deg);
    throw InputError(msg);
  }
}

Id BoundaryCurves::find_feature_edge(Id a, Id b) const {
  if (a > b) std::swap(a, b);
  const auto it = std::lower_bound(edges.begin(), edges.end(), std::pair{a, b},
                                   [](const FeatureEdge& e, const std::pair<Id, Id>& k) {
                                     return std::pair{e.v0, e.v1} < k;
                                   });
  if (it == edges.end() || it->v0 != a || it->v1 != b) return kNoId;
  return static_cast<Id>(it - edges.begin());
}

namespace {

Vec2 xy(const Mesh& m, Id v) { return {{m.coords[2 * v], m.coords[2 * v + 1]}}; }

std::int32_t tri_ref(const Mesh& m, Id t) {
  return static_cast<std::size_t>(t) < m.tri_ref.size() ? m.tri_ref[t] : 0;
}

void check_input(const Mesh& mesh) {
  if (mesh.dim != 2) throw InputError("boundary curves: the mesh must be planar (dimension 2)");
  if (!mesh.tets.empty()) throw InputError("boundary curves: the mesh has tetrahedra");
  const auto nv = static_cast<Id>(mesh.num_vertices());
  if (mesh.edges.size() % 2 != 0) throw InputError("boundary curves: odd edge array size");
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const Id a = mesh.edges[2 * e], b = mesh.edges[2 * e + 1];
    if (a < 0 || a >= nv || b < 0 || b >= nv || a == b) {
      std::string msg = "boundary curves: bad edge ";
      msg += std::to_string(e + 1);
      throw InputError(msg);
    }
  }
}

/// Per feature edge (directed v0 -> v1): the triangle on its left and on its right, or kNoId.
struct Sides {
  std::vector<Id> left, right;
};

/// Unique feature edges sorted by (v0, v1), refs from mesh.edges, and the map listed -> feature:
/// the boundary and interface sides of the triangles (by their neighbours, no edge numbering)
/// and every listed edge, as (smaller, larger) vertex pairs.
std::vector<FeatureEdge> collect_feature_edges(const Mesh& mesh, const Adjacency& adj,
                                               std::vector<Id>& input2feature) {
  std::vector<FeatureEdge> out;
  for (std::size_t t = 0; t < adj.num_elements(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id n = adj.elem2elem[3 * t + i];
      if (n != kNoId && tri_ref(mesh, n) == tri_ref(mesh, static_cast<Id>(t))) continue;
      if (n != kNoId && n < static_cast<Id>(t)) continue;  // listed from the other side
      const Id a = mesh.triangles[3 * t + kTriEdge[i][0]], b = mesh.triangles[3 * t + kTriEdge[i][1]];
      out.push_back({std::min(a, b), std::max(a, b)});
    }
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const Id a = mesh.edges[2 * e], b = mesh.edges[2 * e + 1];
    out.push_back({std::min(a, b), std::max(a, b)});
  }
  const auto key = [](const FeatureEdge& f) { return std::pair{f.v0, f.v1}; };
  std::sort(out.begin(), out.end(), [&](const auto& x, const auto& y) { return key(x) < key(y); });
  out.erase(std::unique(out.begin(), out.end(),
                        [&](const auto& x, const auto& y) { return key(x) == key(y); }),
            out.end());

  BoundaryCurves lookup;  // find_feature_edge on the sorted list
  lookup.edges = std::move(out);
  input2feature.assign(mesh.num_edges(), kNoId);
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const Id f = lookup.find_feature_edge(mesh.edges[2 * e], mesh.edges[2 * e + 1]);
    input2feature[e] = f;
    FeatureEdge& fe = lookup.edges[f];
    if (fe.input_edge == kNoId) {  // the first listing gives the ref
      fe.input_edge = static_cast<Id>(e);
      fe.ref = e < mesh.edge_ref.size() ? mesh.edge_ref[e] : 0;
    }
  }
  return std::move(lookup.edges);
}

/// The feature edge joining a and b, from the features at the smaller of the two (the CSR of
/// vertex_features), or kNoId.
Id feature_between(Id a, Id b, const std::vector<FeatureEdge>& fes, const std::vector<Id>& off,
                   const std::vector<Id>& list) {
  const Id lo = std::min(a, b), hi = std::max(a, b);
  for (Id k = off[lo]; k < off[lo + 1]; ++k) {
    const FeatureEdge& f = fes[list[k]];
    if (f.v0 == lo && f.v1 == hi) return list[k];
  }
  return kNoId;
}

/// Which side of each feature edge each incident triangle lies on, by the sign of its area
/// (robust to clockwise input triangles); the smallest triangle id when a side has several.
Sides feature_sides(const Mesh& mesh, const std::vector<FeatureEdge>& fes,
                    const std::vector<Id>& off, const std::vector<Id>& list) {
  Sides s{std::vector<Id>(fes.size(), kNoId), std::vector<Id>(fes.size(), kNoId)};
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id* tv = &mesh.triangles[3 * t];
      const Id a = tv[kTriEdge[i][0]], b = tv[kTriEdge[i][1]];
      // Most vertices are on no feature edge: the test is then two loads.
      if (off[a] == off[a + 1] || off[b] == off[b + 1]) continue;
      const Id f = feature_between(a, b, fes, off, list);
      if (f == kNoId) continue;
      const Vec2 p0 = xy(mesh, fes[f].v0), p1 = xy(mesh, fes[f].v1);
      double o = cross(p1 - p0, xy(mesh, tv[i]) - p0);
      if (o == 0.0)  // degenerate triangle: its combinatorial orientation decides
        o = tv[kTriEdge[i][0]] == fes[f].v0 ? 1.0 : -1.0;
      Id& slot = o > 0.0 ? s.left[f] : s.right[f];
      if (slot == kNoId) slot = static_cast<Id>(t);
    }
  return s;
}

std::int32_t side_ref(const Mesh& mesh, Id t) { return t == kNoId ? kNoId : tri_ref(mesh, t); }

/// The feature edges at each vertex (CSR, increasing feature id).
void vertex_features(std::size_t nv, const std::vector<FeatureEdge>& fes, std::vector<Id>& off,
                     std::vector<Id>& list) {
  off.assign(nv + 1, 0);
  for (const FeatureEdge& f : fes) ++off[f.v0 + 1], ++off[f.v1 + 1];
  for (std::size_t v = 0; v < nv; ++v) off[v + 1] += off[v];
  list.assign(static_cast<std::size_t>(off[nv]), kNoId);
  std::vector<Id> fill(off.begin(), off.end() - 1);
  for (std::size_t f = 0; f < fes.size(); ++f) {
    list[fill[fes[f].v0]++] = static_cast<Id>(f);
    list[fill[fes[f].v1]++] = static_cast<Id>(f);
  }
}

/// Refuses two feature edges at v along the same ray whose far ends differ: the nearer end lies
/// inside the other edge, a vertex in the middle of a triangle's side (a hanging vertex), and
/// the remesher made a slit of it, with two vertices at one place (exit 0; `check` then called
/// the output valid). A crack's tip (both far ends at one place) is kept.
void require_no_overlap(const Mesh& mesh, const std::vector<FeatureEdge>& fes, Id v,
                        std::span<const Id> edges) {
  const Vec2 p = xy(mesh, v);
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const FeatureEdge &e = fes[static_cast<std::size_t>(edges[i])],
                        &f = fes[static_cast<std::size_t>(edges[j])];
      const Vec2 a = xy(mesh, e.v0 == v ? e.v1 : e.v0), b = xy(mesh, f.v0 == v ? f.v1 : f.v0);
      // Along the same ray to rounding (a midpoint written with 17 digits is off the side by
      // ~1e-17 of its length): the turn between them below 1e-10 rad.
      const Vec2 da = a - p, db = b - p;
      if (!(dot(da, db) > 0.0) || std::abs(orient2d(p.x, a.x, b.x)) > 1e-10 * norm(da) * norm(db))
        continue;
      if (a[0] == b[0] && a[1] == b[1]) continue;  // a crack's tip
      // Named by place: the 2D remesher works on a renumbered copy.
      const bool a_nearer = norm(a - p) < norm(b - p);
      const Vec2 inner = a_nearer ? a : b, outer = a_nearer ? b : a;
      char msg[280];
      std::snprintf(msg, sizeof msg,
                    "the mesh is not conforming at (%g, %g): a vertex there lies in the middle of "
                    "a triangle's side, from (%g, %g) to (%g, %g)",
                    inner[0], inner[1], p[0], p[1], outer[0], outer[1]);
      throw InputError(msg);
    }
}

/// Corner flags: tags, ends of required edges, junctions, ref or side changes, sharp turns.
std::vector<std::uint8_t> find_corners(const Mesh& mesh, const CurveOptions& opt,
                                       const std::vector<FeatureEdge>& fes, const Sides& sides,
                                       const std::vector<Id>& off, const std::vector<Id>& list) {
  const std::size_t nv = mesh.num_vertices();
  const double cos_max = std::cos(opt.angle_deg * std::numbers::pi / 180.0);
  std::vector<std::uint8_t> corner(nv, 0);
  // A required edge is kept as given, its ends too: they never move, and no collapse removes
  // them (splits already refused the edge; collapses merged 12 required edges into 4 and slid
  // their ends along curved boundaries: QA hunt 5 F4).
  for (const FeatureEdge& f : fes)
    if (f.input_edge != kNoId && static_cast<std::size_t>(f.input_edge) < mesh.edge_tag.size() &&
        (mesh.edge_tag[f.input_edge] & kTagRequired))
      corner[f.v0] = corner[f.v1] = 1;
  for (std::size_t vi = 0; vi < nv; ++vi) {
    const auto v = static_cast<Id>(vi);
    const Id deg = off[vi + 1] - off[vi];
    if (deg == 0) continue;
    require_no_overlap(mesh, fes, v,
                       std::span<const Id>(list).subspan(static_cast<std::size_t>(off[vi]),
                                                         static_cast<std::size_t>(deg)));
    const std::uint8_t tag = vi < mesh.vert_tag.size() ? mesh.vert_tag[vi] : 0;
    if (corner[vi] || deg != 2 || (tag & (kTagCorner | kTagRequired))) {
      corner[vi] = 1;
      continue;
    }
    const FeatureEdge& in = fes[list[off[vi]]];       // walked toward v
    const FeatureEdge& out = fes[list[off[vi] + 1]];  // walked away from v
    const Id in_l = in.v1 == v ? sides.left[list[off[vi]]] : sides.right[list[off[vi]]];
    const Id in_r = in.v1 == v ? sides.right[list[off[vi]]] : sides.left[list[off[vi]]];
    const Id out_l = out.v0 == v ? sides.left[list[off[vi] + 1]] : sides.right[list[off[vi] + 1]];
    const Id out_r = out.v0 == v ? sides.right[list[off[vi] + 1]] : sides.left[list[off[vi] + 1]];
    if (in.ref != out.ref || side_ref(mesh, in_l) != side_ref(mesh, out_l) ||
        side_ref(mesh, in_r) != side_ref(mesh, out_r)) {
      corner[vi] = 1;
      continue;
    }
    // Without angle detection (-nr) a turn of 90 degrees or more is still a corner: a smooth
    // curve through it leaves both edges at 45 degrees or more, bulging by a fifth of their
    // length and more ((L/2) tan(turn/4)), spikes rounded into blobs that the passes could only
    // fill with flat triangles (the star20 domain: quality 8e-10 at the tips, exit 0; QA hunt 5
    // F12).
    const double cos_turn = opt.detect_angles ? cos_max : 1e-9;  // (a square's rounded cos 90°)
    const Vec2 p = xy(mesh, v);
    const Vec2 a = p - xy(mesh, in.v0 == v ? in.v1 : in.v0);
    const Vec2 b = xy(mesh, out.v0 == v ? out.v1 : out.v0) - p;
    const double na = norm(a), nb = norm(b);
    if (na > 0.0 && nb > 0.0 && dot(a, b) < cos_turn * na * nb) corner[vi] = 1;
  }
  return corner;
}

}  // namespace

namespace {

/// Walks from vertex `start` along feature edge f until a corner, or back to start.
BoundaryCurve walk(Id start, Id f, const std::vector<FeatureEdge>& fes,
                   const std::vector<std::uint8_t>& corner, const std::vector<Id>& off,
                   const std::vector<Id>& list, std::vector<std::uint8_t>& visited) {
  BoundaryCurve c;
  c.vertices.push_back(start);
  Id v = start;
  for (;;) {
    visited[f] = 1;
    c.edges.push_back(f);
    v = fes[f].v0 == v ? fes[f].v1 : fes[f].v0;
    c.vertices.push_back(v);
    if (corner[v] || v == start) break;
    const Id g0 = list[off[v]], g1 = list[off[v] + 1];  // degree 2 at non-corners
    f = g0 == f ? g1 : g0;
  }
  c.closed = !corner[start];
  c.ref = fes[c.edges.front()].ref;
  return c;
}

/// Orients a curve (see BoundaryCurve::left_ref) and sets its side refs.
void orient(BoundaryCurve& c, const Mesh& mesh, const std::vector<FeatureEdge>& fes,
            const Sides& sides) {
  const Id f = c.edges.front();
  const bool forward = fes[f].v0 == c.vertices[0];
  Id lt = forward ? sides.left[f] : sides.right[f];
  Id rt = forward ? sides.right[f] : sides.left[f];
  const std::int32_t lr = side_ref(mesh, lt), rr = side_ref(mesh, rt);
  bool reverse;
  if ((lt == kNoId) != (rt == kNoId)) {
    reverse = lt == kNoId;
  } else if (lt != kNoId && lr != rr) {
    reverse = lr > rr;
  } else if (c.vertices.front() != c.vertices.back()) {
    reverse = c.vertices.front() > c.vertices.back();
  } else {
    reverse = c.vertices[c.vertices.size() - 2] < c.vertices[1];
  }
  if (reverse) {
    std::reverse(c.vertices.begin(), c.vertices.end());
    std::reverse(c.edges.begin(), c.edges.end());
    std::swap(lt, rt);
  }
  c.left_ref = side_ref(mesh, lt);
  c.right_ref = side_ref(mesh, rt);
}

void fill_vertex_maps(BoundaryCurves& out, std::size_t nv) {
  std::vector<Id>& off = out.vert2curve_offsets;
  off.assign(nv + 1, 0);
  const auto for_each_entry = [&](auto&& fn) {
    for (std::size_t ci = 0; ci < out.curves.size(); ++ci) {
      const BoundaryCurve& c = out.curves[ci];
      const int n = c.num_edges(), last = c.closed ? n - 1 : n;
      for (int k = 0; k <= last; ++k) fn(c.vertices[k], CurveVertex{static_cast<Id>(ci), 1.0 * k});
    }
  };
  for_each_entry([&](Id v, const CurveVertex&) { ++off[v + 1]; });
  for (std::size_t v = 0; v < nv; ++v) off[v + 1] += off[v];
  out.vert2curve.resize(static_cast<std::size_t>(off[nv]));
  std::vector<Id> fill(off.begin(), off.end() - 1);
  for_each_entry([&](Id v, const CurveVertex& cv) { out.vert2curve[fill[v]++] = cv; });
}

}  // namespace

BoundaryCurves build_boundary_curves(const Mesh& mesh, const CurveOptions& options,
                                     const Adjacency* adjacency) {
  options.validate();
  check_input(mesh);
  const std::size_t nv = mesh.num_vertices();
  const Adjacency own = adjacency ? Adjacency{} : build_face_adjacency(mesh.triangles, 3, nv);
  const Adjacency& adj = adjacency ? *adjacency : own;  // no copy of the caller's

  BoundaryCurves out;
  out.edges = collect_feature_edges(mesh, adj, out.input_edge2feature);
  const std::vector<FeatureEdge>& fes = out.edges;
  for (const FeatureEdge& f : fes)
    if (xy(mesh, f.v0) == xy(mesh, f.v1)) {
      std::string msg = "boundary curves: zero-length edge between vertices ";
      msg += std::to_string(f.v0 + 1);
      msg += " and ";
      msg += std::to_string(f.v1 + 1);
      throw InputError(msg);
    }
  std::vector<Id> off, list;
  vertex_features(nv, fes, off, list);
  const Sides sides = feature_sides(mesh, fes, off, list);
  out.corner = find_corners(mesh, options, fes, sides, off, list);

  // Open curves from the corners in increasing id, then the corner-free loops from their
  // smallest vertex (the first unvisited edge in (v0, v1) order starts at its loop's minimum).
  std::vector<std::uint8_t> visited(fes.size(), 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!out.corner[v]) continue;
    for (Id i = off[v]; i < off[v + 1]; ++i)
      if (!visited[list[i]])
        out.curves.push_back(
            walk(static_cast<Id>(v), list[i], fes, out.corner, off, list, visited));
  }
  for (std::size_t f = 0; f < fes.size(); ++f)
    if (!visited[f])
      out.curves.push_back(
          walk(fes[f].v0, static_cast<Id>(f), fes, out.corner, off, list, visited));

  std::vector<Vec2> pts;
  for (std::size_t ci = 0; ci < out.curves.size(); ++ci) {
    BoundaryCurve& c = out.curves[ci];
    orient(c, mesh, fes, sides);
    for (std::size_t k = 0; k < c.edges.size(); ++k) {
      out.edges[c.edges[k]].curve = static_cast<Id>(ci);
      out.edges[c.edges[k]].index = static_cast<Id>(k);
    }
    pts.clear();
    for (const Id v : c.vertices) pts.push_back(xy(mesh, v));
    build_curve_geometry(c, pts);
  }
  fill_vertex_maps(out, nv);
  return out;
}

}  // namespace riemesh
