#include "generate/surface_delaunay3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/volume_regions3d.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/check.hpp"

namespace riemesh {

namespace {

using detail::Face;
using detail::sorted_face;

/// "vertices 3 and 7" (1-based).
std::string edge_name(Id a, Id b) {
  std::string s = "vertices ";
  s += std::to_string(a + 1);
  s += " and ";
  s += std::to_string(b + 1);
  return s;
}

/// Directed edges (a, b, triangle) of the surface, sorted by undirected edge.
struct DirectedEdge {
  Id lo, hi;
  bool forward;  // a < b as traversed by the triangle
  Id tri;
};

std::vector<DirectedEdge> directed_edges(const Mesh& s) {
  std::vector<DirectedEdge> e;
  e.reserve(3 * s.num_triangles());
  for (std::size_t t = 0; t < s.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id a = s.triangles[3 * t + i], b = s.triangles[3 * t + (i + 1) % 3];
      e.push_back({std::min(a, b), std::max(a, b), a < b, static_cast<Id>(t)});
    }
  std::sort(e.begin(), e.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.tri < y.tri;
  });
  return e;
}

/// The triangles as (sorted vertices, triangle id), sorted: a triangle listed twice is next to
/// its copy.
std::vector<std::pair<Face, Id>> faces_by_vertices(const Mesh& s) {
  std::vector<std::pair<Face, Id>> faces(s.num_triangles());
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    const Id* v = &s.triangles[3 * t];
    faces[t] = {sorted_face(v[0], v[1], v[2]), static_cast<Id>(t)};
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

void throw_defect(const char* what, std::size_t count, const std::string& first) {
  std::string msg = "the surface cannot bound a volume: ";
  msg += std::to_string(count);
  msg += " ";
  msg += what;
  msg += " (first: ";
  msg += first;
  msg += ")";
  throw InputError(msg);
}

}  // namespace

std::size_t require_closed_surface(const Mesh& s) {
  if (s.dim != 3 || s.num_triangles() == 0)
    throw InputError("the surface cannot bound a volume: no triangles in 3D");
  // Normals and squared lengths of differences must stay finite (a coordinate of 1e308 in a
  // damaged file made the recovery's predicates see infinities: an internal check failed).
  constexpr double kLargest = 1e150;
  for (const Id v : s.triangles)
    for (int k = 0; k < 3; ++k)
      if (const double x = s.coords[3 * static_cast<std::size_t>(v) + k];
          !(std::fabs(x) <= kLargest)) {
        char msg[120];
        std::snprintf(msg, sizeof msg,
                      "vertex %d: coordinate %g is out of range (at most 1e150 in magnitude)",
                      v + 1, x);
        throw InputError(msg);
      }
  const std::size_t nv = s.num_vertices();
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    const Id* v = &s.triangles[3 * t];
    for (int i = 0; i < 3; ++i)
      if (v[i] < 0 || static_cast<std::size_t>(v[i]) >= nv)
        throw InputError("triangle " + std::to_string(t + 1) + ": vertex id out of range");
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      throw_defect("triangles with a repeated vertex", 1, "triangle " + std::to_string(t + 1));
  }
  // Zero-area triangles (three collinear vertices, decided exactly: no plane through them holds
  // the three points a + e_i): named here, not as a self-intersection with their neighbours.
  std::size_t flat = 0, first_flat = 0;
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    const double* p[3];
    for (int i = 0; i < 3; ++i)
      p[i] = &s.coords[3 * static_cast<std::size_t>(s.triangles[3 * t + i])];
    bool collinear = true;
    for (int i = 0; i < 3 && collinear; ++i) {
      double q[3] = {p[0][0], p[0][1], p[0][2]};
      q[i] = p[0][i] + 1.0 != p[0][i] ? p[0][i] + 1.0 : 2.0 * p[0][i];
      collinear = orient3d(p[0], p[1], p[2], q) == 0.0;
    }
    if (collinear && flat++ == 0) first_flat = t;
  }
  if (flat)
    throw_defect("triangles of zero area (collinear vertices)", flat,
                 "triangle " + std::to_string(first_flat + 1));
  // The same three vertices twice: a zero-volume region between the copies.
  const std::vector<std::pair<Face, Id>> faces = faces_by_vertices(s);
  std::size_t twice = 0;
  std::string first_twice;
  for (std::size_t k = 0; k + 1 < faces.size(); ++k)
    if (faces[k].first == faces[k + 1].first && twice++ == 0)
      first_twice = "triangles " + std::to_string(faces[k].second + 1) + " and " +
                    std::to_string(faces[k + 1].second + 1);
  if (twice) throw_defect("triangles listed twice (same three vertices)", twice, first_twice);
  // A seam not merged (a vertex and its copy) also leaves edges on one triangle: named as what
  // it is, not as holes.
  if (const CoincidentVertices same = find_coincident_vertices(s); same.pairs > 0)
    throw_defect("pairs of vertices at the same place", same.pairs,
                 edge_name(same.first_a, same.first_b));
  // Edges on more than two triangles are where regions meet (a wall inside a box, the interface
  // of two solids listed once): allowed; their orientation says nothing (an interface faces away
  // from one of its regions, into the other). Edges on two triangles must be traversed both ways
  // on a surface of one region; with several, a triangle of an interface may face either way
  // (half an interface turned was refused), so those are counted, not refused.
  const std::vector<DirectedEdge> e = directed_edges(s);
  std::size_t open = 0, flipped = 0;
  bool regions_meet = false;
  std::string first_open, first_flipped;
  for (std::size_t i = 0; i < e.size();) {
    std::size_t j = i;
    while (j < e.size() && e[j].lo == e[i].lo && e[j].hi == e[i].hi) ++j;
    const std::string name = edge_name(e[i].lo, e[i].hi);
    if (j - i == 1 && open++ == 0) first_open = name;
    if (j - i == 2 && e[i].forward == e[i + 1].forward && flipped++ == 0) first_flipped = name;
    regions_meet = regions_meet || j - i > 2;
    i = j;
  }
  if (open) throw_defect("edges on one triangle only (holes)", open, "edge of " + first_open);
  if (flipped && !regions_meet)
    throw_defect("edges traversed the same way by both their triangles (inconsistent orientation)",
                 flipped, "edge of " + first_flipped);
  // The triangles at a vertex, joined across their edges through it, form cycles (around
  // edges where regions meet, every triangle on the edge is joined); more than one set is a
  // vertex where separate sheets touch (two cubes sharing a corner), whose volume is no
  // manifold: its tets around that vertex are not connected through faces, which the
  // optimiser's walks need. Union-find on the corners (3 t + i: triangle t at its vertex i), the
  // corners of each edge's triangles at each end joined.
  std::vector<Id> parent(3 * s.num_triangles());
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = static_cast<Id>(k);
  const auto root = [&](Id k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  const auto corner = [&](Id t, Id v) {
    const Id* tv = &s.triangles[3 * static_cast<std::size_t>(t)];
    return 3 * t + (tv[0] == v ? 0 : tv[1] == v ? 1 : 2);
  };
  for (std::size_t i = 0; i < e.size();) {
    std::size_t j = i + 1;
    for (; j < e.size() && e[j].lo == e[i].lo && e[j].hi == e[i].hi; ++j)
      for (const Id v : {e[i].lo, e[i].hi}) {
        const Id x = root(corner(e[i].tri, v)), y = root(corner(e[j].tri, v));
        parent[std::max(x, y)] = std::min(x, y);
      }
    i = j;
  }
  // Per vertex, the first root seen; another root at the same vertex is a second sheet.
  std::vector<Id> sheet(nv, kNoId);
  std::size_t pinched = 0;
  Id first_pinched = kNoId;
  std::vector<std::uint8_t> counted(nv, 0);
  for (std::size_t k = 0; k < parent.size(); ++k) {
    const Id v = s.triangles[k], r = root(static_cast<Id>(k));
    if (sheet[v] == kNoId)
      sheet[v] = r;
    else if (sheet[v] != r && !counted[v]) {
      counted[v] = 1;
      if (pinched++ == 0 || v < first_pinched) first_pinched = v;
    }
  }
  if (pinched)
    throw_defect("non-manifold vertices (where separate sheets of the surface touch)", pinched,
                 "vertex " + std::to_string(first_pinched + 1));
  return flipped;
}

std::optional<Mesh> merge_interfaces_listed_twice(const Mesh& s, std::size_t* merged) {
  *merged = 0;
  const std::vector<std::pair<Face, Id>> faces = faces_by_vertices(s);
  // Same vertex set: opposite orientations when the second's vertex after the first's v[0] is
  // the first's v[2].
  const auto opposite = [&](Id a, Id b) {
    const Id* p = &s.triangles[3 * static_cast<std::size_t>(a)];
    const Id* q = &s.triangles[3 * static_cast<std::size_t>(b)];
    const int k = q[0] == p[0] ? 0 : q[1] == p[0] ? 1 : 2;
    return q[(k + 1) % 3] == p[2];
  };
  std::vector<char> drop(s.num_triangles(), 0);
  for (std::size_t k = 0; k + 1 < faces.size(); ++k)
    if (faces[k].first == faces[k + 1].first &&
        (k + 2 == faces.size() || faces[k + 2].first != faces[k].first) &&
        (k == 0 || faces[k - 1].first != faces[k].first) &&
        opposite(faces[k].second, faces[k + 1].second)) {
      drop[static_cast<std::size_t>(faces[k + 1].second)] = 1;
      ++*merged;
    }
  if (*merged == 0) return std::nullopt;
  Mesh out = s;
  out.triangles.clear(), out.tri_ref.clear(), out.tri_tag.clear();
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    if (drop[t]) continue;
    out.triangles.insert(out.triangles.end(),
                         s.triangles.begin() + static_cast<std::ptrdiff_t>(3 * t),
                         s.triangles.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
    if (t < s.tri_ref.size()) out.tri_ref.push_back(s.tri_ref[t]);
    if (t < s.tri_tag.size()) out.tri_tag.push_back(s.tri_tag[t]);
  }
  return out;
}

SurfaceDelaunay delaunay_of_surface(const Mesh& s) {
  require_closed_surface(s);
  SurfaceDelaunay d;
  std::vector<Id> old2new(s.num_vertices(), kNoId);
  for (Id v : s.triangles) old2new[static_cast<std::size_t>(v)] = 0;
  for (std::size_t v = 0; v < old2new.size(); ++v)
    if (old2new[v] != kNoId) {
      old2new[v] = static_cast<Id>(d.vertices.size());
      d.vertices.push_back(static_cast<Id>(v));
      d.coords.insert(d.coords.end(), s.coords.begin() + static_cast<std::ptrdiff_t>(3 * v),
                      s.coords.begin() + static_cast<std::ptrdiff_t>(3 * v + 3));
    }
  d.tz = delaunay3d(d.coords);
  for (std::size_t v = 0; v < d.tz.duplicate_of.size(); ++v)
    if (d.tz.duplicate_of[v] != kNoId)
      throw_defect("pairs of vertices at the same place", 1,
                   edge_name(d.vertices[static_cast<std::size_t>(d.tz.duplicate_of[v])],
                             d.vertices[v]));

  // Edges and faces of the tetrahedralisation, sorted for lookups.
  std::vector<std::pair<Id, Id>> tet_edges;
  std::vector<Face> tet_faces;
  tet_edges.reserve(6 * d.tz.num_tets());
  tet_faces.reserve(4 * d.tz.num_tets());
  for (std::size_t t = 0; t < d.tz.num_tets(); ++t) {
    const Id* v = &d.tz.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) tet_edges.push_back(std::minmax(v[i], v[j]));
      tet_faces.push_back(sorted_face(v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4]));
    }
  }
  std::sort(tet_edges.begin(), tet_edges.end());
  std::sort(tet_faces.begin(), tet_faces.end());
  std::vector<std::pair<Id, Id>> surface_edges;
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    const Id* v = &s.triangles[3 * t];
    const Id a = old2new[static_cast<std::size_t>(v[0])], b = old2new[static_cast<std::size_t>(v[1])],
             c = old2new[static_cast<std::size_t>(v[2])];
    ++d.num_faces;
    if (!std::binary_search(tet_faces.begin(), tet_faces.end(), sorted_face(a, b, c)))
      ++d.missing_faces;
    surface_edges.push_back(std::minmax(a, b));
    surface_edges.push_back(std::minmax(b, c));
    surface_edges.push_back(std::minmax(c, a));
  }
  std::sort(surface_edges.begin(), surface_edges.end());
  surface_edges.erase(std::unique(surface_edges.begin(), surface_edges.end()), surface_edges.end());
  d.num_edges = surface_edges.size();
  for (const auto& e : surface_edges)
    if (!std::binary_search(tet_edges.begin(), tet_edges.end(), e)) ++d.missing_edges;
  return d;
}

void orient_boundary_triangles(Mesh& v) {
  // The kept tets' faces, each with its tet and the face's outward orientation.
  struct Side {
    Face key;
    std::array<Id, 3> out;
    int ref;
  };
  std::vector<Side> sides;
  sides.reserve(4 * v.num_tets());
  for (std::size_t t = 0; t < v.num_tets(); ++t)
    for (int i = 0; i < 4; ++i) {
      const Id* q = &v.tets[4 * t];
      const std::array<Id, 3> f = {q[kTetFace[i][0]], q[kTetFace[i][1]], q[kTetFace[i][2]]};
      sides.push_back({sorted_face(f[0], f[1], f[2]), f, v.tet_ref[t]});
    }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.key != b.key ? a.key < b.key : a.ref < b.ref;
  });
  for (std::size_t t = 0; t < v.num_triangles(); ++t) {
    Id* f = &v.triangles[3 * t];
    const Face key = sorted_face(f[0], f[1], f[2]);
    const auto it = std::lower_bound(sides.begin(), sides.end(), key,
                                     [](const Side& a, const Face& k) { return a.key < k; });
    if (it == sides.end() || it->key != key) continue;
    // Facing out of its tet, or of the region of lower ref between two (the first after the
    // sort); the same cyclic order as that face means the same orientation.
    const std::array<Id, 3>& o = it->out;
    const int k = o[0] == f[0] ? 0 : o[1] == f[0] ? 1 : 2;
    if (o[(k + 1) % 3] != f[1]) std::swap(f[1], f[2]);
  }
}

Mesh volume_inside(const Mesh& s, const SurfaceDelaunay& d, std::span<const double> hole_points,
                   bool no_holes) {
  if (!d.conforming()) throw Error("volume_inside: the surface is not in the tetrahedralisation");
  std::vector<Id> old2new(s.num_vertices(), kNoId);
  for (std::size_t k = 0; k < d.vertices.size(); ++k)
    old2new[static_cast<std::size_t>(d.vertices[k])] = static_cast<Id>(k);
  std::vector<Id> local(s.triangles.size());
  for (std::size_t k = 0; k < local.size(); ++k)
    local[k] = old2new[static_cast<std::size_t>(s.triangles[k])];
  const std::vector<int> ref = tet_regions(d.tz, local, d.coords, hole_points, no_holes).ref;
  Mesh out;
  out.dim = 3;
  out.coords = d.coords;
  for (Id v : d.vertices) {
    const auto vu = static_cast<std::size_t>(v);
    out.vert_ref.push_back(vu < s.vert_ref.size() ? s.vert_ref[vu] : 0);
    out.vert_tag.push_back(vu < s.vert_tag.size() ? s.vert_tag[vu] : 0);
  }
  for (std::size_t t = 0; t < d.tz.num_tets(); ++t)
    if (ref[t] > 0) {
      out.tets.insert(out.tets.end(), d.tz.tets.begin() + static_cast<std::ptrdiff_t>(4 * t),
                      d.tz.tets.begin() + static_cast<std::ptrdiff_t>(4 * t + 4));
      out.tet_ref.push_back(ref[t]);
    }
  require_no_pinch(out);
  out.triangles = std::move(local);
  for (std::size_t t = 0; t < s.num_triangles(); ++t) {
    out.tri_ref.push_back(t < s.tri_ref.size() ? s.tri_ref[t] : 0);
    out.tri_tag.push_back(t < s.tri_tag.size() ? s.tri_tag[t] : 0);
  }
  orient_boundary_triangles(out);
  return out;
}

}  // namespace riemesh
