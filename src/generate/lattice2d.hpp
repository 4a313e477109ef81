#pragma once
// Field points for a constant metric: the unit equilateral lattice (BOOK.md §1, the unit mesh of
// a constant metric is the image of the regular triangular lattice). With M = LᵀL (L upper
// triangular), the points x with L·x on the lattice u = o + i·(1, 0) + j·(1/2, √3/2) are at unit
// metric distance from their six neighbours, so their Delaunay triangulation in the metric is made
// of unit equilateral triangles: inside the domain the optimiser has nothing left to do. Near the
// boundary the lattice is cut at a clearance from the boundary edges; the field point rounds and
// the optimiser join it to the boundary.
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// The map of a constant metric to its unit space: u = L·x, LᵀL = M, L upper triangular with a
/// positive diagonal (orientation kept; Euclidean lengths of u are metric lengths of x).
struct MetricMap2d {
  double l11 = 1.0, l12 = 0.0, l22 = 1.0;

  /// Throws InputError unless m is symmetric positive definite (finite).
  explicit MetricMap2d(const SymMat2& m);
  void to_unit(const double* x, double* u) const {
    u[0] = l11 * x[0] + l12 * x[1];
    u[1] = l22 * x[1];
  }
  void from_unit(const double* u, double* x) const {
    x[1] = u[1] / l22;
    x[0] = (u[0] - l12 * x[1]) / l11;
  }
};

/// The lattice points of the constant metric m inside the triangles of `domain` (dim 2, its
/// triangles cover the domain, its Edges bound it) at metric distance at least `clearance`
/// (0 < clearance ≤ 1/2) from every Edge and from every vertex on no Edge. The lattice starts at
/// the lowest corner of the domain's box in the unit space. 2 doubles per point, each point once,
/// in row order. Deterministic.
std::vector<double> lattice_points2d(const Mesh& domain, const SymMat2& m, double clearance);

}  // namespace riemesh
