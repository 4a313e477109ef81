#pragma once
// A twisted triangular prism for the 3D meshing tests (test_surface_delaunay3d,
// test_boundary_recovery3d).
#include <cmath>

#include "mesh/mesh.hpp"

namespace riemesh::test {

/// A twisted triangular prism (bottom radius 1 at z = 0, top radius 0.8 at z = 1 turned by 30°,
/// so no 5 points are cospherical), each side quad split along one diagonal or the other. One
/// choice is the convex hull; the other is Schönhardt's polyhedron, which has no
/// tetrahedralisation without Steiner points, so some of its triangles are no Delaunay faces.
inline Mesh twisted_prism(bool other_diagonal) {
  Mesh s;
  s.dim = 3;
  for (int level = 0; level < 2; ++level)
    for (int i = 0; i < 3; ++i) {
      const double angle = (120.0 * i + 30.0 * level) * M_PI / 180, r = level ? 0.8 : 1.0;
      s.coords.insert(s.coords.end(), {r * std::cos(angle), r * std::sin(angle), double(level)});
    }
  s.triangles = {0, 2, 1, 3, 4, 5};
  for (Id i = 0; i < 3; ++i) {
    const Id a = i, a1 = (i + 1) % 3, b = 3 + i, b1 = 3 + (i + 1) % 3;
    if (other_diagonal)
      s.triangles.insert(s.triangles.end(), {a, a1, b, a1, b1, b});
    else
      s.triangles.insert(s.triangles.end(), {a, a1, b1, a, b1, b});
  }
  s.vert_ref.assign(6, 0);
  s.vert_tag.assign(6, 0);
  s.tri_ref.assign(8, 1);
  s.tri_tag.assign(8, 0);
  return s;
}

}  // namespace riemesh::test
