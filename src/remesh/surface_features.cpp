#include "remesh/surface_features.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>

#include "core/error.hpp"

namespace riemesh {
namespace {

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

/// The angle of triangle t at its local corner i (0 for a degenerate corner).
double corner_angle(const Mesh& mesh, std::size_t t, int i) {
  const Id* tri = &mesh.triangles[3 * t];
  const Vec3 p = vertex_at(mesh, tri[i]);
  const Vec3 a = vertex_at(mesh, tri[(i + 1) % 3]) - p, b = vertex_at(mesh, tri[(i + 2) % 3]) - p;
  const double na = norm(a), nb = norm(b);
  if (na == 0.0 || nb == 0.0) return 0.0;
  return std::acos(std::clamp(dot(a, b) / (na * nb), -1.0, 1.0));
}

void require_surface(const Mesh& mesh, const Adjacency& adj) {
  if (mesh.dim != 3 || mesh.triangles.empty() || !mesh.tets.empty())
    throw InputError("surface analysis needs a surface mesh (3D triangles, no tetrahedra)");
  if (adj.verts_per_simplex != 3 || adj.num_elements() != mesh.num_triangles() ||
      adj.num_vertices != mesh.num_vertices())
    throw InputError("surface analysis: adjacency not built from the mesh's triangles");
  // A triangle that repeats a vertex has an edge the adjacency does not list: the analysis wrote
  // before its arrays (heap corruption, abort).
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
    const Id* v = &mesh.triangles[3 * t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
      throw InputError("triangle " + std::to_string(t + 1) + " repeats vertex " +
                       std::to_string((v[0] == v[1] || v[0] == v[2] ? v[0] : v[1]) + 1) +
                       " (a degenerate triangle)");
    // Two vertices at one point (a UV sphere's unmerged pole): the error came from the
    // gradation, naming an internal 0-based edge.
    for (int i = 0; i < 3; ++i) {
      const Vec3 a = vertex_at(mesh, v[i]), b = vertex_at(mesh, v[(i + 1) % 3]);
      if (a == b) {
        char at[96];
        std::snprintf(at, sizeof at, " at (%g, %g, %g)", a[0], a[1], a[2]);
        throw InputError("triangle " + std::to_string(t + 1) + ": vertices " +
                         std::to_string(v[i] + 1) + " and " + std::to_string(v[(i + 1) % 3] + 1) +
                         " are at the same point" + at + " (merge them)");
      }
    }
  }
}

/// Triangles on each adjacency edge: count, and the first two (with their local edge index).
struct EdgeTriangles {
  std::vector<int> count;
  std::vector<Id> first;  // 2 per edge: 3 * triangle + local edge
};

EdgeTriangles edge_triangles(const Adjacency& adj) {
  EdgeTriangles et;
  et.count.assign(adj.num_edges(), 0);
  et.first.assign(2 * adj.num_edges(), kNoId);
  for (std::size_t k = 0; k < adj.elem2edge.size(); ++k) {
    const auto e = static_cast<std::size_t>(adj.elem2edge[k]);
    if (et.count[e] < 2) et.first[2 * e + et.count[e]] = static_cast<Id>(k);
    ++et.count[e];
  }
  return et;
}

/// Angle (radians) between the normals of the two triangles at corners k0 = 3 t0 + j0 and
/// k1 = 3 t1 + j1 (local edges j0, j1 on the same edge); -1 when either triangle is degenerate.
double dihedral(const Mesh& mesh, const std::vector<Vec3>& tn, Id k0, Id k1) {
  const auto t0 = static_cast<std::size_t>(k0 / 3), t1 = static_cast<std::size_t>(k1 / 3);
  const Vec3 n0 = tn[t0];
  Vec3 n1 = tn[t1];
  if (dot(n0, n0) == 0.0 || dot(n1, n1) == 0.0) return -1.0;
  // Consistently oriented neighbours traverse their common edge in opposite directions.
  const Id a0 = mesh.triangles[3 * t0 + kTriEdge[k0 % 3][0]];
  const Id a1 = mesh.triangles[3 * t1 + kTriEdge[k1 % 3][0]];
  if (a0 == a1) n1 = -n1;
  return std::acos(std::clamp(dot(n0, n1), -1.0, 1.0));
}

/// Turn of a feature line at v between its neighbours a and b: the angle between a→v and v→b.
double turn_angle(const Mesh& mesh, Id a, Id v, Id b) {
  const Vec3 u = vertex_at(mesh, v) - vertex_at(mesh, a), w = vertex_at(mesh, b) - vertex_at(mesh, v);
  const double nu = norm(u), nw = norm(w);
  if (nu == 0.0 || nw == 0.0) return std::numbers::pi;
  return std::acos(std::clamp(dot(u, w) / (nu * nw), -1.0, 1.0));
}

void mark_given_edges(const Mesh& mesh, const Adjacency& adj, SurfaceFeatures& f) {
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const Id id = find_edge(adj, mesh.edges[2 * e], mesh.edges[2 * e + 1]);
    // A listed edge that is no triangle edge bounds nothing on the surface: ignored here.
    if (id != kNoId) f.edge_feature[static_cast<std::size_t>(id)] |= kFeatureGiven;
  }
}

void find_corners(const Mesh& mesh, const Adjacency& adj, double angle, SurfaceFeatures& f) {
  const std::size_t nv = mesh.num_vertices();
  for (std::size_t e = 0; e < adj.num_edges(); ++e) {
    if (!f.edge_feature[e]) continue;
    ++f.feature_degree[static_cast<std::size_t>(adj.edges[2 * e])];
    ++f.feature_degree[static_cast<std::size_t>(adj.edges[2 * e + 1])];
  }
  const std::vector<Id> other = feature_neighbours(adj, f);
  for (std::size_t v = 0; v < nv; ++v) {
    std::uint8_t& tag = f.vert_tag[v];
    if (mesh.vert_tag.size() == nv) tag |= mesh.vert_tag[v] & (kTagCorner | kTagRequired);
    if (tag & kTagRequired) tag |= kTagCorner;
    const int d = f.feature_degree[v];
    if (d > 0) tag |= kTagRidge;
    if (d == 1 || d > 2) tag |= kTagCorner;
    if (d == 2 && turn_angle(mesh, other[2 * v], static_cast<Id>(v), other[2 * v + 1]) > angle)
      tag |= kTagCorner;
    if (tag & kTagCorner) ++f.num_corners;
  }
}

}  // namespace

void FeatureOptions::validate() const {
  if (!(angle_deg > 0.0 && angle_deg < 180.0)) {
    char msg[80];
    std::snprintf(msg, sizeof msg, "--angle must be in (0, 180) degrees on a surface, got %g",
                  angle_deg);
    throw InputError(msg);
  }
}

std::vector<Id> feature_neighbours(const Adjacency& adj, const SurfaceFeatures& features) {
  std::vector<Id> other(2 * adj.num_vertices, kNoId);
  std::vector<int> count(adj.num_vertices, 0);
  for (std::size_t e = 0; e < adj.num_edges(); ++e) {
    if (!features.edge_feature[e]) continue;
    const Id a = adj.edges[2 * e], b = adj.edges[2 * e + 1];
    for (const auto& [v, w] : {std::pair{a, b}, std::pair{b, a}}) {
      const auto s = static_cast<std::size_t>(v);
      if (count[s] < 2) other[2 * s + count[s]] = w;
      ++count[s];
    }
  }
  return other;
}

std::vector<Vec3> triangle_normals(const Mesh& mesh) {
  std::vector<Vec3> n(mesh.num_triangles(), Vec3::zero());
  for (std::size_t t = 0; t < n.size(); ++t) {
    const Id* tri = &mesh.triangles[3 * t];
    const Vec3 p = vertex_at(mesh, tri[0]);
    const Vec3 c = cross(vertex_at(mesh, tri[1]) - p, vertex_at(mesh, tri[2]) - p);
    const double l = norm(c);
    if (l > 0.0) n[t] = c / l;
  }
  return n;
}

std::vector<Vec3> vertex_normals(const Mesh& mesh, const Adjacency& adj) {
  require_surface(mesh, adj);
  const std::vector<Vec3> tn = triangle_normals(mesh);
  std::vector<Vec3> n(mesh.num_vertices(), Vec3::zero());
  for (std::size_t t = 0; t < tn.size(); ++t)
    for (int i = 0; i < 3; ++i)
      n[static_cast<std::size_t>(mesh.triangles[3 * t + i])] += corner_angle(mesh, t, i) * tn[t];
  for (Vec3& v : n) {
    const double l = norm(v);
    if (l > 0.0) v = v / l;
  }
  return n;
}

SurfaceFeatures detect_features(const Mesh& mesh, const Adjacency& adj,
                                const FeatureOptions& options) {
  require_surface(mesh, adj);
  options.validate();
  const double angle = options.angle_deg * std::numbers::pi / 180.0;
  SurfaceFeatures f;
  f.edge_feature.assign(adj.num_edges(), 0);
  f.vert_tag.assign(mesh.num_vertices(), kTagNone);
  f.feature_degree.assign(mesh.num_vertices(), 0);
  const std::vector<Vec3> tn = triangle_normals(mesh);
  const EdgeTriangles et = edge_triangles(adj);
  for (std::size_t e = 0; e < adj.num_edges(); ++e) {
    std::uint8_t& bits = f.edge_feature[e];
    if (et.count[e] == 1) bits |= kFeatureOpen;
    if (et.count[e] > 2) bits |= kFeatureNonManifold;
    if (et.count[e] != 2) continue;
    const Id k0 = et.first[2 * e], k1 = et.first[2 * e + 1];
    if (mesh.tri_ref.size() == mesh.num_triangles() &&
        mesh.tri_ref[static_cast<std::size_t>(k0 / 3)] != mesh.tri_ref[static_cast<std::size_t>(k1 / 3)])
      bits |= kFeatureRefChange;
    if (options.detect_angle && dihedral(mesh, tn, k0, k1) > angle) bits |= kFeatureAngle;
  }
  mark_given_edges(mesh, adj, f);
  for (std::uint8_t bits : f.edge_feature) {
    if (bits) ++f.num_feature_edges;
    if (bits & kFeatureAngle) ++f.num_angle_edges;
  }
  find_corners(mesh, adj, angle, f);
  return f;
}

namespace {

/// The orientation of each triangle of v's ball `b` relative to the first of its sector, found
/// across the smooth edges through v: -1 where a triangle runs along such an edge the same way
/// as the one it was reached from. Volume meshes list their boundary triangles in any
/// orientation; summed as given, the normals of a flipped triangle and its neighbour cancel (a
/// cylinder's side got a sector normal tangent to it).
void orient_ball(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& features, Id v,
                 std::span<const Id> b, std::vector<double>& sign) {
  sign.assign(b.size(), 0.0);
  std::vector<std::size_t> stack;
  for (std::size_t first = 0; first < b.size(); ++first) {
    if (sign[first] != 0.0) continue;
    sign[first] = 1.0;
    stack.assign(1, first);
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      const auto t = static_cast<std::size_t>(b[i]);
      const Id* tri = &mesh.triangles[3 * t];
      const int iv = local_index(tri, 3, v);
      for (int j : {(iv + 1) % 3, (iv + 2) % 3}) {
        if (features.edge_feature[static_cast<std::size_t>(adj.elem2edge[3 * t + j])]) continue;
        const Id nb = adj.elem2elem[3 * t + j];
        if (nb == kNoId) continue;
        const auto k =
            static_cast<std::size_t>(std::lower_bound(b.begin(), b.end(), nb) - b.begin());
        if (k >= b.size() || b[k] != nb || sign[k] != 0.0) continue;
        // The edge opposite corner j runs tri[j+1] -> tri[j+2] in t; nb agrees if it runs back.
        const Id* other = &mesh.triangles[3 * static_cast<std::size_t>(nb)];
        const int ia = local_index(other, 3, tri[(j + 1) % 3]);
        const bool same_way = other[(ia + 1) % 3] == tri[(j + 2) % 3];
        sign[k] = same_way ? -sign[i] : sign[i];
        stack.push_back(k);
      }
    }
  }
}

}  // namespace

SurfaceSectors surface_sectors(const Mesh& mesh, const Adjacency& adj,
                               const SurfaceFeatures& features) {
  require_surface(mesh, adj);
  const std::vector<Vec3> tn = triangle_normals(mesh);
  SurfaceSectors s;
  s.corner2sector.assign(mesh.triangles.size(), kNoId);
  std::vector<Id> label;  // sector label of each ball triangle, by union of neighbours
  std::vector<double> sign;  // +1 or -1: each ball triangle's orientation against its sector's
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const auto b = ball(adj, static_cast<Id>(v));
    label.resize(b.size());
    for (std::size_t i = 0; i < b.size(); ++i) label[i] = static_cast<Id>(i);
    // Propagate the smallest label across smooth manifold edges through v until stable (balls
    // are small: a few sweeps).
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = 0; i < b.size(); ++i) {
        const auto t = static_cast<std::size_t>(b[i]);
        const int iv = local_index(&mesh.triangles[3 * t], 3, static_cast<Id>(v));
        for (int j : {(iv + 1) % 3, (iv + 2) % 3}) {
          if (features.edge_feature[static_cast<std::size_t>(adj.elem2edge[3 * t + j])]) continue;
          const Id nb = adj.elem2elem[3 * t + j];
          if (nb == kNoId) continue;
          const auto it = std::lower_bound(b.begin(), b.end(), nb);
          const auto k = static_cast<std::size_t>(it - b.begin());
          const Id m = std::min(label[i], label[k]);
          if (label[i] != m || label[k] != m) {
            label[i] = label[k] = m;
            changed = true;
          }
        }
      }
    }
    orient_ball(mesh, adj, features, static_cast<Id>(v), b, sign);
    // Number the sectors of v in order of their smallest ball index, then sum their normals.
    const auto first_sector = static_cast<Id>(s.sector2vert.size());
    std::vector<Id> id_of(b.size(), kNoId);
    for (std::size_t i = 0; i < b.size(); ++i) {
      const auto l = static_cast<std::size_t>(label[i]);
      if (id_of[l] == kNoId) {
        id_of[l] = static_cast<Id>(s.sector2vert.size());
        s.sector2vert.push_back(static_cast<Id>(v));
        s.normal.push_back(Vec3::zero());
      }
      const auto t = static_cast<std::size_t>(b[i]);
      const int iv = local_index(&mesh.triangles[3 * t], 3, static_cast<Id>(v));
      const Id sec = id_of[l];
      s.corner2sector[3 * t + iv] = sec;
      s.normal[static_cast<std::size_t>(sec)] += (corner_angle(mesh, t, iv) * sign[i]) * tn[t];
    }
    for (auto k = static_cast<std::size_t>(first_sector); k < s.normal.size(); ++k) {
      const double l = norm(s.normal[k]);
      if (l > 0.0) s.normal[k] = s.normal[k] / l;
    }
  }
  return s;
}

}  // namespace riemesh
