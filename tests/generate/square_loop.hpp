#pragma once
// A square boundary loop for the tests of meshing from boundaries (domain2d, lattice2d, mesh2d,
// regenerate2d).
#include "mesh/mesh.hpp"

namespace riemesh::test {

/// Appends the boundary of [x0, x0 + s]² with n edges a side: counter-clockwise (the domain on
/// its left) or clockwise (a hole), every edge with ref `ref`.
inline void add_square(Mesh& m, double x0, double s, int n, bool ccw, int ref = 1) {
  const Id first = static_cast<Id>(m.num_vertices());
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < n; ++k) {
      const double t = s * k / n;
      const double xy[4][2] = {
          {x0 + t, x0}, {x0 + s, x0 + t}, {x0 + s - t, x0 + s}, {x0, x0 + s - t}};
      m.coords.push_back(xy[side][0]);  // (push_back: GCC 12 warns falsely on insert here)
      m.coords.push_back(xy[side][1]);
    }
  for (Id i = 0; i < 4 * n; ++i) {
    const Id a = first + i, b = first + (i + 1) % (4 * n);
    if (ccw)
      m.edges.insert(m.edges.end(), {a, b});
    else
      m.edges.insert(m.edges.end(), {b, a});
    m.edge_ref.push_back(ref);
  }
}

}  // namespace riemesh::test
