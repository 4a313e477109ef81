#pragma once
// Measures of a TetMesh shared by the 3D operator tests.
#include <algorithm>
#include <cstddef>

#include "remesh/ops3d.hpp"

namespace riemesh::test {

/// Sum of the volumes of the live tetrahedra.
inline double volume(const TetMesh& m) {
  double s = 0;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
    if (!m.tet_alive(static_cast<Id>(t))) continue;
    const Id* v = &m.tv[4 * t];
    s += tet_volume(m.xyz[v[0]], m.xyz[v[1]], m.xyz[v[2]], m.xyz[v[3]]);
  }
  return s;
}

/// The smallest metric quality of the live tetrahedra.
inline double worst_quality(const TetMesh& m) {
  double q = 1.0;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t))) q = std::min(q, tet_quality(m, static_cast<Id>(t)));
  return q;
}

}  // namespace riemesh::test
