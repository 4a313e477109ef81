// Topological checks on distinct elements: non-manifold faces, orientation of surfaces, closure
// and manifoldness of the boundary, and the listed boundary entities against the elements.
#include <algorithm>
#include <set>

#include "mesh/adjacency.hpp"
#include "mesh/check_detail.hpp"

namespace riemesh::check_detail {
namespace {

/// The checked elements after removing duplicates, with their ids in the mesh.
struct Distinct {
  std::vector<Id> verts;  // k per element
  std::vector<Id> orig;   // element -> id in the mesh
  Id id(std::size_t e) const { return orig[e]; }
};

Distinct distinct_elements(const Elements& el, const std::vector<Id>& kept) {
  Distinct d;
  d.verts.reserve(kept.size() * static_cast<std::size_t>(el.k));
  for (Id e : kept) {
    const auto v = el.of(e);
    d.verts.insert(d.verts.end(), v.begin(), v.end());
  }
  d.orig = kept;
  return d;
}

/// The vertices of face f of element e (k = 3: an edge; k = 4: a triangle, outward).
std::vector<Id> face_vertices(const std::vector<Id>& s, int k, std::size_t e, int f) {
  if (k == 4)
    return {s[4 * e + kTetFace[f][0]], s[4 * e + kTetFace[f][1]], s[4 * e + kTetFace[f][2]]};
  return {s[3 * e + kTriEdge[f][0]], s[3 * e + kTriEdge[f][1]]};
}

std::vector<Id> sorted(std::vector<Id> v) {
  std::sort(v.begin(), v.end());
  return v;
}

bool is_nonmanifold(const Adjacency& adj, Id face) {
  return std::binary_search(adj.nonmanifold_faces.begin(), adj.nonmanifold_faces.end(), face);
}

/// Faces on more than two elements. On a surface those are edges where regions meet (a wall
/// inside a box, the interface of two solids), reported as kRegionsMeet.
void check_nonmanifold(const Adjacency& adj, const Distinct& d, bool surface, Collector& col) {
  const int k = adj.verts_per_simplex;
  const auto category = surface ? CheckCategory::kRegionsMeet : CheckCategory::kNonManifoldFace;
  std::set<std::vector<Id>> seen;  // the few non-manifold faces, counted once each
  for (Id f : adj.nonmanifold_faces) {
    const auto fv = face_vertices(d.verts, k, f / k, f % k);
    if (seen.insert(sorted(fv)).second)
      col.add(category, k == 4 ? EntityKind::kTet : EntityKind::kTriangle, d.id(f / k), fv, f % k);
  }
}

/// Calls f(e, i, n) for each pair of neighbouring triangles e < n (3 ids each in `tris`) that
/// traverse their common edge (edge i of e) the same way; stops when f returns false.
template <class F>
void for_edges_traversed_alike(const Adjacency& adj, std::span<const Id> tris, F f) {
  for (std::size_t e = 0; e < adj.num_elements(); ++e)
    for (int i = 0; i < 3; ++i) {
      const Id n = adj.elem2elem[3 * e + i];
      if (n == kNoId || static_cast<std::size_t>(n) < e) continue;
      const Id p = tris[3 * e + kTriEdge[i][0]], q = tris[3 * e + kTriEdge[i][1]];
      const int lp = local_index(&tris[3 * n], 3, p), lq = local_index(&tris[3 * n], 3, q);
      if (lp != (lq + 1) % 3 && !f(e, i, static_cast<std::size_t>(n))) return;
    }
}

/// The two vertices of edge i of triangle e.
std::vector<Id> edge_of(std::span<const Id> tris, std::size_t e, int i) {
  return {tris[3 * e + kTriEdge[i][0]], tris[3 * e + kTriEdge[i][1]]};
}

/// Surfaces: a neighbour must traverse the common edge the other way (edge q -> p for p -> q).
void check_surface_orientation(const Adjacency& adj, const Distinct& d, Collector& col) {
  for_edges_traversed_alike(adj, d.verts, [&](std::size_t e, int i, std::size_t) {
    col.add(CheckCategory::kInconsistentOrientation, EntityKind::kTriangle, d.id(e),
            edge_of(d.verts, e, i), i);
    return true;
  });
}

/// Planar meshes: the folds (planar_folds), each reported at its first triangle.
void check_planar_folds(const Mesh& m, const Adjacency& adj, const Distinct& d, Collector& col) {
  for (const PlanarFold& f : planar_folds(m.coords, d.verts, adj))
    col.add(CheckCategory::kOverlappingElements, EntityKind::kTriangle, d.id(f.triangle),
            edge_of(d.verts, f.triangle, f.edge), f.edge);
}

/// Listed edges must be edges of the elements, listed once; returns how often each is listed.
std::vector<int> check_listed_edges(const Mesh& m, const Adjacency& adj, Collector& col) {
  std::vector<int> listed(adj.num_edges(), 0);
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const Id a = m.edges[2 * e], b = m.edges[2 * e + 1];
    if (a == b) continue;  // reported as a repeated vertex
    const Id id = find_edge(adj, a, b);
    const std::vector<Id> v{a, b};
    if (id == kNoId)
      col.add(CheckCategory::kOrphanEntity, EntityKind::kEdge, static_cast<Id>(e), v);
    else if (listed[id]++ > 0)
      col.add(CheckCategory::kDuplicateBoundaryEntity, EntityKind::kEdge, static_cast<Id>(e), v);
  }
  return listed;
}

/// 2D: boundary edges form closed loops (an even count at each boundary vertex: two, or four and
/// more where loops touch, as a hole touching the outer boundary at a vertex, which `riemesh mesh`
/// and `adapt` make and keep) and are all listed.
void check_planar_boundary(const Mesh& m, const Adjacency& adj, const Distinct& d, Collector& col) {
  const std::vector<int> listed = check_listed_edges(m, adj, col);
  std::vector<int> degree(m.num_vertices(), 0);
  for (std::size_t e = 0; e < adj.num_elements(); ++e)
    for (int i = 0; i < 3; ++i) {
      const Id f = static_cast<Id>(3 * e + i);
      if (adj.elem2elem[f] != kNoId || is_nonmanifold(adj, f)) continue;
      const auto fv = face_vertices(d.verts, 3, e, i);
      ++degree[fv[0]], ++degree[fv[1]];
      if (listed[adj.elem2edge[f]] == 0)
        col.add(CheckCategory::kMissingBoundary, EntityKind::kTriangle, d.id(e), fv, i);
    }
  for (std::size_t v = 0; v < degree.size(); ++v)
    if (degree[v] % 2 != 0) {
      const Id id = static_cast<Id>(v);
      col.add(CheckCategory::kNonManifoldBoundary, EntityKind::kVertex, id, {&id, 1});
    }
}

/// Whether some tetrahedron around a holds the triangle (a, b, c).
bool is_tet_face(const Adjacency& adj, const std::vector<Id>& tets, Id a, Id b, Id c) {
  for (Id t : ball(adj, a))
    if (local_index(&tets[4 * t], 4, b) >= 0 && local_index(&tets[4 * t], 4, c) >= 0) return true;
  return false;
}

/// Volume: listed triangles are tet faces, listed once; boundary faces are listed; the boundary
/// surface is closed and edge-manifold.
void check_volume_boundary(const Mesh& m, const Adjacency& adj, const Distinct& d, Collector& col) {
  check_listed_edges(m, adj, col);
  std::vector<std::pair<std::vector<Id>, Id>> listed;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const std::vector<Id> v(m.triangles.begin() + 3 * t, m.triangles.begin() + 3 * t + 3);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) continue;  // a repeated vertex
    if (!is_tet_face(adj, d.verts, v[0], v[1], v[2]))
      col.add(CheckCategory::kOrphanEntity, EntityKind::kTriangle, static_cast<Id>(t), v);
    listed.emplace_back(sorted(v), static_cast<Id>(t));
  }
  std::sort(listed.begin(), listed.end());
  for (std::size_t i = 1; i < listed.size(); ++i)
    if (listed[i].first == listed[i - 1].first) {
      const Id t = listed[i].second;
      col.add(CheckCategory::kDuplicateBoundaryEntity, EntityKind::kTriangle, t,
              {m.triangles.data() + 3 * t, 3});
    }
  const auto is_listed = [&listed](const std::vector<Id>& key) {
    const auto it = std::lower_bound(listed.begin(), listed.end(), std::make_pair(key, Id{0}));
    return it != listed.end() && it->first == key;
  };
  std::vector<int> faces_on_edge(adj.num_edges(), 0);
  for (std::size_t e = 0; e < adj.num_elements(); ++e)
    for (int i = 0; i < 4; ++i) {
      const Id f = static_cast<Id>(4 * e + i);
      if (adj.elem2elem[f] != kNoId || is_nonmanifold(adj, f)) continue;
      for (int j = 0; j < 6; ++j)  // the 3 edges of face i avoid local vertex i
        if (kTetEdge[j][0] != i && kTetEdge[j][1] != i) ++faces_on_edge[adj.elem2edge[6 * e + j]];
      const auto fv = face_vertices(d.verts, 4, e, i);
      if (!is_listed(sorted(fv)))
        col.add(CheckCategory::kMissingBoundary, EntityKind::kTet, d.id(e), fv, i);
    }
  for (std::size_t g = 0; g < adj.num_edges(); ++g) {
    if (faces_on_edge[g] == 0 || faces_on_edge[g] == 2) continue;
    const auto cat =
        faces_on_edge[g] == 1 ? CheckCategory::kOpenBoundary : CheckCategory::kNonManifoldBoundary;
    col.add(cat, EntityKind::kNone, kNoId, {adj.edges.data() + 2 * g, 2});
  }
}

}  // namespace

void check_edge_loops(const Mesh& m, Collector& col) {
  std::vector<int> degree(m.num_vertices(), 0);
  std::vector<std::pair<std::pair<Id, Id>, Id>> keys;
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const Id a = m.edges[2 * e], b = m.edges[2 * e + 1];
    if (a == b) continue;  // reported as a repeated vertex
    ++degree[a], ++degree[b];
    keys.push_back({{std::min(a, b), std::max(a, b)}, static_cast<Id>(e)});
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) {
      const Id e = keys[i].second;
      col.add(CheckCategory::kDuplicateBoundaryEntity, EntityKind::kEdge, e,
              {m.edges.data() + 2 * e, 2});
    }
  for (std::size_t v = 0; v < degree.size(); ++v) {
    if (degree[v] == 0 || degree[v] == 2) continue;
    const Id id = static_cast<Id>(v);
    col.add(degree[v] == 1 ? CheckCategory::kOpenBoundary : CheckCategory::kNonManifoldBoundary,
            EntityKind::kVertex, id, {&id, 1});
  }
}

void check_topology(const Mesh& m, const Elements& el, const std::vector<Id>& kept,
                    Collector& col) {
  const Distinct d = distinct_elements(el, kept);
  const Adjacency adj = build_adjacency(d.verts, el.k, m.num_vertices());
  check_nonmanifold(adj, d, m.kind() == MeshKind::kSurface, col);
  switch (m.kind()) {
    case MeshKind::kVolume:
      check_volume_boundary(m, adj, d, col);
      break;
    case MeshKind::kPlanar:
      check_planar_folds(m, adj, d, col);
      check_planar_boundary(m, adj, d, col);
      break;
    case MeshKind::kSurface:
      check_surface_orientation(adj, d, col);
      check_listed_edges(m, adj, col);
      break;
    case MeshKind::kEmpty:
      break;
  }
}

}  // namespace riemesh::check_detail

namespace riemesh {

std::vector<PlanarFold> planar_folds(std::span<const double> coords, std::span<const Id> triangles,
                                     const Adjacency& adj, std::size_t most) {
  // Two counter-clockwise neighbours traverse their common edge the same way only where one
  // lies over the other (clockwise ones are inverted, reported as such by check_mesh).
  const auto ccw = [&](std::size_t e) {
    const Id* v = &triangles[3 * e];
    const auto p = [&](int k) { return &coords[2 * static_cast<std::size_t>(v[k])]; };
    return (p(1)[0] - p(0)[0]) * (p(2)[1] - p(0)[1]) - (p(1)[1] - p(0)[1]) * (p(2)[0] - p(0)[0]) >
           0.0;
  };
  std::vector<PlanarFold> out;
  if (most == 0) return out;
  check_detail::for_edges_traversed_alike(adj, triangles, [&](std::size_t e, int i, std::size_t n) {
    if (ccw(e) && ccw(n)) out.push_back({e, n, i});
    return out.size() < most;
  });
  return out;
}

}  // namespace riemesh
