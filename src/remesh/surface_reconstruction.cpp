#include "remesh/surface_reconstruction.hpp"

#include <cmath>

#include "core/error.hpp"

namespace riemesh {
namespace {

/// Control-point slots of triangle edge (i → j): the one next to P_i, then the one next to P_j.
/// Edges 0→1: b210, b120; 1→2: b021, b012; 2→0: b102, b201.
constexpr int kEdgeSlot[3][2] = {{3, 4}, {5, 6}, {7, 8}};  // edge k goes from P_k to P_(k+1)%3

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

}  // namespace

CubicTriangle pn_triangle(const Vec3 (&p)[3], const Vec3 (&n)[3]) {
  CubicTriangle c{};
  for (int i = 0; i < 3; ++i) c.b[i] = p[i];
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    // (2 P_i + P_j − w_ij N_i)/3 with w_ij = (P_j − P_i)·N_i.
    c.b[kEdgeSlot[k][0]] = (2.0 * p[i] + p[j] - dot(p[j] - p[i], n[i]) * n[i]) / 3.0;
    c.b[kEdgeSlot[k][1]] = (2.0 * p[j] + p[i] - dot(p[i] - p[j], n[j]) * n[j]) / 3.0;
  }
  update_centre(c);
  return c;
}

void update_centre(CubicTriangle& c) {
  Vec3 e = Vec3::zero();
  for (int k = 3; k < 9; ++k) e += c.b[k];
  e = e / 6.0;
  const Vec3 v = (c.b[0] + c.b[1] + c.b[2]) / 3.0;
  c.b[9] = e + 0.5 * (e - v);
}

Vec3 evaluate(const CubicTriangle& c, double u, double v) {
  const double w = 1.0 - u - v;
  return (w * w * w) * c.b[0] + (u * u * u) * c.b[1] + (v * v * v) * c.b[2] +
         (3.0 * w * w * u) * c.b[3] + (3.0 * w * u * u) * c.b[4] + (3.0 * u * u * v) * c.b[5] +
         (3.0 * u * v * v) * c.b[6] + (3.0 * w * v * v) * c.b[7] + (3.0 * w * w * v) * c.b[8] +
         (6.0 * w * u * v) * c.b[9];
}

Vec3 cubic_curve(const Vec3& p0, const Vec3& c0, const Vec3& c1, const Vec3& p1, double s) {
  const double r = 1.0 - s;
  return (r * r * r) * p0 + (3.0 * r * r * s) * c0 + (3.0 * r * s * s) * c1 + (s * s * s) * p1;
}

Vec3 circle_tangent(const Vec3& a, const Vec3& v, const Vec3& b) {
  const Vec3 va = a - v, vb = b - v;
  const Vec3 t = dot(va, va) * vb - dot(vb, vb) * va;
  const double l = norm(t);
  if (l > 0.0) return t / l;
  const double lab = norm(b - a);
  return lab > 0.0 ? (b - a) / lab : Vec3::zero();
}

SurfaceReconstruction::SurfaceReconstruction(const Mesh& mesh, const Adjacency& adj,
                                             const SurfaceFeatures& features,
                                             const SurfaceSectors& sectors)
    : mesh_(mesh), adj_(adj) {
  const std::size_t nv = mesh.num_vertices(), nt = mesh.num_triangles();
  if (features.edge_feature.size() != adj.num_edges() || sectors.corner2sector.size() != 3 * nt ||
      adj.num_elements() != nt)
    throw InputError("SurfaceReconstruction: features or sectors not built from this mesh");
  const std::vector<Id> line = feature_neighbours(adj, features);
  tangent_.assign(nv, Vec3::zero());
  for (std::size_t v = 0; v < nv; ++v)
    if (features.feature_degree[v] == 2 && !(features.vert_tag[v] & kTagCorner))
      tangent_[v] = circle_tangent(vertex_at(mesh, line[2 * v]), vertex_at(mesh, static_cast<Id>(v)),
                                   vertex_at(mesh, line[2 * v + 1]));
  patch_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    Vec3 p[3], n[3];
    for (int i = 0; i < 3; ++i) {
      p[i] = vertex_at(mesh, mesh.triangles[3 * t + i]);
      n[i] = sectors.normal[static_cast<std::size_t>(sectors.corner2sector[3 * t + i])];
    }
    CubicTriangle c = pn_triangle(p, n);
    bool changed = false;
    for (int k = 0; k < 3; ++k) {
      const int i = k, j = (k + 1) % 3;
      // Local edge k -> k+1 is the adjacency's local edge opposite vertex (k + 2) % 3.
      const auto e = static_cast<std::size_t>(adj.elem2edge[3 * t + (k + 2) % 3]);
      if (!features.edge_feature[e]) continue;
      const Vec3 d = p[j] - p[i];
      const double len = norm(d);
      auto end_tangent = [&](int at, const Vec3& toward) {
        const Vec3& tau = tangent_[static_cast<std::size_t>(mesh.triangles[3 * t + at])];
        if (dot(tau, tau) == 0.0) return len > 0.0 ? toward / len : Vec3::zero();
        return dot(tau, toward) >= 0.0 ? tau : -tau;
      };
      c.b[kEdgeSlot[k][0]] = p[i] + (len / 3.0) * end_tangent(i, d);
      c.b[kEdgeSlot[k][1]] = p[j] + (len / 3.0) * end_tangent(j, -d);
      changed = true;
    }
    if (changed) update_centre(c);
    patch_[t] = c;
  }
}

Vec3 SurfaceReconstruction::edge_point(Id a, Id b, double s) const {
  if (a == b || a < 0 || b < 0 || static_cast<std::size_t>(a) >= adj_.num_vertices ||
      static_cast<std::size_t>(b) >= adj_.num_vertices)
    throw InputError("edge_point: not an edge of the mesh");
  for (Id t : ball(adj_, a)) {
    const Id* tri = &mesh_.triangles[3 * static_cast<std::size_t>(t)];
    const int ib = local_index(tri, 3, b);
    if (ib < 0) continue;
    const int ia = local_index(tri, 3, a);
    double w[3] = {0.0, 0.0, 0.0};
    w[ia] = 1.0 - s;
    w[ib] = s;
    return point(t, w[1], w[2]);
  }
  throw InputError("edge_point: not an edge of the mesh");
}

}  // namespace riemesh
