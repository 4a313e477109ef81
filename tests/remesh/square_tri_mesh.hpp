#pragma once
// A TriMesh of the unit square for operator tests: unit_square(n, n) with the four sides as
// feature curves 0..3 (refs 1..4, parameter = the coordinate along the side) and a constant
// metric.
#include "mesh/fixtures.hpp"
#include "remesh/tri_mesh_io.hpp"

namespace riemesh::test_support {

inline TriMesh square_tri_mesh(int n, const SymMat2& metric) {
  const Mesh mesh = unit_square(n, n);
  std::vector<SymMat2> metrics(mesh.num_vertices(), metric);
  std::vector<TriFeature> features;
  for (std::size_t e = 0; e < mesh.num_edges(); ++e)
    features.push_back({mesh.edges[2 * e], mesh.edges[2 * e + 1], mesh.edge_ref[e] - 1,
                        mesh.edge_ref[e], kTagNone});
  std::vector<VertexCurve> curves(mesh.num_vertices());
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    if (mesh.vert_tag[v] & kTagCorner) continue;
    const double x = mesh.coords[2 * v], y = mesh.coords[2 * v + 1];
    if (y == 0.0) curves[v] = {0, x};
    if (x == 1.0) curves[v] = {1, y};
    if (y == 1.0) curves[v] = {2, x};
    if (x == 0.0) curves[v] = {3, y};
  }
  return build_tri_mesh(mesh, metrics, features, curves);
}

/// Total area of the live triangles.
inline double total_area(const TriMesh& m) {
  double a = 0.0;
  for (std::size_t t = 0; t < m.triangle_capacity(); ++t)
    if (m.tri_alive(static_cast<Id>(t)))
      a += signed_area(m.xy[m.tv[3 * t]], m.xy[m.tv[3 * t + 1]], m.xy[m.tv[3 * t + 2]]);
  return a;
}

}  // namespace riemesh::test_support
