#pragma once
// Basic quantities of a metric M (SPD tensor, M = R diag(1/h_i²) Rᵀ): lengths, angles, measures,
// sizes and directions. BOOK.md §1.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/mat.hpp"
#include "core/spd.hpp"
#include "core/symmat.hpp"

namespace riemesh {

template <int D>
using Metric = SymMat<D>;

/// Length of vector u in metric M: sqrt(uᵀ M u).
template <int D>
inline double length(const SymMat<D>& m, const Vec<D>& u) {
  return std::sqrt(quadratic(m, u));
}

/// Angle (radians, in [0, π]) between u and v measured in M.
template <int D>
inline double angle(const SymMat<D>& m, const Vec<D>& u, const Vec<D>& v) {
  const double c = bilinear(m, u, v) / (length(m, u) * length(m, v));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

/// d!: the measure of the unit simplex is 1/d! times |det| of its edge matrix.
template <int D>
constexpr double factorial() {
  double f = 1.0;
  for (int i = 2; i <= D; ++i) f *= i;
  return f;
}

/// Signed Euclidean measure (area in 2D, volume in 3D) of a simplex, positive when the vertices
/// are ordered counter-clockwise (2D) or with a right-handed first corner (3D).
template <int D>
inline double simplex_measure(const Vec<D> (&p)[D + 1]) {
  return det(edge_matrix(p)) / factorial<D>();
}

/// Measure of a simplex in a constant metric M: sqrt(det M) |K| (signed like simplex_measure).
template <int D>
inline double simplex_measure(const SymMat<D>& m, const Vec<D> (&p)[D + 1]) {
  return std::sqrt(det(m)) * simplex_measure(p);
}

/// Sizes h_i = 1/sqrt(λ_i) in descending order (largest size first), with their unit directions
/// as the columns of `directions`.
template <int D>
struct MetricSizes {
  Vec<D> sizes;
  Mat<D> directions;
};

template <int D>
inline MetricSizes<D> sizes(const SymMat<D>& m) {
  const SymEigen<D> e = eigen(m);  // ascending eigenvalues = descending sizes
  MetricSizes<D> s{};
  for (int i = 0; i < D; ++i) s.sizes[i] = 1.0 / std::sqrt(e.values[i]);
  s.directions = e.vectors;
  return s;
}

/// Anisotropy ratio h_max / h_min = sqrt(λ_max / λ_min).
template <int D>
inline double anisotropy(const SymMat<D>& m) {
  const SymEigen<D> e = eigen(m);
  return std::sqrt(e.values[D - 1] / e.values[0]);
}

/// The isotropic metric of size h: I / h².
template <int D>
constexpr SymMat<D> isotropic_metric(double h) {
  return SymMat<D>::diagonal(1.0 / (h * h));
}

/// The metric with sizes h_i along the orthonormal directions given as columns of r.
template <int D>
inline SymMat<D> metric_from_sizes(const Mat<D>& r, const Vec<D>& h) {
  Vec<D> l{};
  for (int i = 0; i < D; ++i) l[i] = 1.0 / (h[i] * h[i]);
  return compose(r, l);
}

/// Throws InputError("<what>: ...") unless m is a finite SPD tensor with a finite determinant
/// (beyond, sizes under ~1e-154 in 2D, ~1e-102 in 3D, lengths and complexities overflow).
template <int D>
inline void require_metric(const SymMat<D>& m, const std::string& what) {
  if (!is_finite(m)) throw InputError(what + ": metric has a NaN or infinite coefficient");
  if (!is_spd(m)) {
    // Positive but below the smallest normal double (a tensor of 1e-310, subnormal: a size of
    // 1e155) is out of range, not indefinite (it was said "not positive definite").
    const double smallest = eigen(m).values[0];
    if (smallest > 0.0) {
      char size[48];
      std::snprintf(size, sizeof size, "%g", 1.0 / std::sqrt(smallest));
      throw InputError(what + ": metric out of range: a size of " + size +
                       " (sizes above ~1e154 cannot be squared in doubles)");
    }
    throw InputError(what + ": metric is not positive definite");
  }
  if (!std::isfinite(det(m)))
    throw InputError(what + ": metric too large (its determinant overflows)");
  // Sizes beyond ~1e150 (2D; ~1e100 in 3D): the determinant underflows, and the background mesh
  // then took the tensor for not positive definite, blaming the mesh.
  if (!(det(m) >= std::numeric_limits<double>::min())) {
    // A product of diagonal entries far above the determinant is cancellation, not underflow:
    // an SPD tensor of anisotropy ~1e5 was said to be "too small".
    double diagonal = 1.0;
    for (int i = 0; i < D; ++i) diagonal *= m(i, i);
    if (diagonal >= 1e-200)
      throw InputError(what +
                       ": metric too ill-conditioned (its determinant cancels out in "
                       "double precision)");
    throw InputError(what + ": metric too small (its determinant underflows)");
  }
}

/// The metric every entry of `metrics` is, when they are all the same (exactly: a constant
/// field, e.g. from a uniform size); none when they differ or there are none.
template <int D>
std::optional<SymMat<D>> same_metric(std::span<const SymMat<D>> metrics) {
  if (metrics.empty()) return std::nullopt;
  for (const SymMat<D>& m : metrics)
    if (!(m == metrics.front())) return std::nullopt;
  return metrics.front();
}

}  // namespace riemesh
