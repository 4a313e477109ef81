#pragma once
// The P1 interpolation error u − Π_h u of a known function on a planar triangle mesh (Π_h u: the
// linear interpolant of the vertex values on each triangle), in the L1, L2 and L∞ norms, and the
// log-log slope of errors against a mesh size (BOOK.md §2: Lp-adapted meshes give N^{−2/d}).
#include <functional>
#include <span>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

struct ErrorNorms {
  double l1 = 0.0;    ///< ∫ |u − Π_h u|
  double l2 = 0.0;    ///< (∫ (u − Π_h u)²)^{1/2}
  double linf = 0.0;  ///< max |u − Π_h u| over the sample points
};

struct ErrorQuadrature {
  /// Each triangle is split into 4^levels similar sub-triangles, each integrated with the 7-point
  /// degree-5 rule (Strang & Fix; Dunavant 1985): exact for polynomials of degree 5 when 0.
  int levels = 2;
  /// L∞ samples: the barycentric lattice with this many intervals per side ((n+1)(n+2)/2 points)
  /// plus the quadrature points.
  int samples = 8;
};

/// The three norms of u − Π_h u on one triangle p[0..2] with the vertex values u(p[i]) (L1 and
/// L2 as the integral and the integral of the square, i.e. before any square root).
ErrorNorms triangle_interpolation_error(const Vec2 (&p)[3], const std::function<double(Vec2)>& u,
                                        const ErrorQuadrature& q = {});

/// The norms of u − Π_h u over a planar triangle mesh (mesh.dim == 2), Π_h u interpolating u at
/// the vertices. Throws InputError for another kind of mesh or a bad quadrature.
ErrorNorms interpolation_error(const Mesh& mesh, const std::function<double(Vec2)>& u,
                               const ErrorQuadrature& q = {});

/// y ≈ coefficient · x^slope fitted by least squares on (log x, log y).
struct PowerFit {
  double slope = 0.0;
  double coefficient = 0.0;
};

/// The least-squares power law through the points; throws InputError for fewer than two points,
/// a size mismatch, a non-positive value or all x equal.
PowerFit fit_power_law(std::span<const double> x, std::span<const double> y);

}  // namespace riemesh
