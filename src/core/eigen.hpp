#pragma once
// Eigendecomposition of symmetric 2x2 and 3x3 tensors: M = R diag(λ) Rᵀ.
//
// 2D: one exact Jacobi rotation. 3D: closed form for the best-separated eigenvalue, then the
// exact 2D problem in the orthogonal plane (see eigen(SymMat3)). Both are backward stable for
// any eigenvalue spread, give orthonormal eigenvectors for repeated eigenvalues and return a
// diagonal input exactly.
#include <algorithm>
#include <cmath>

#include "core/mat.hpp"
#include "core/symmat.hpp"
#include "core/vec.hpp"

namespace riemesh {

/// Eigenvalues in ascending order and the matching orthonormal eigenvectors (columns of `vectors`).
template <int D>
struct SymEigen {
  Vec<D> values;
  Mat<D> vectors;
};

namespace detail {

/// The Jacobi rotation that zeroes a_pq: tangent t of the angle (the smaller root, |t| <= 1).
inline double jacobi_tangent(double app, double aqq, double apq) {
  const double theta = (aqq - app) / (2.0 * apq);
  const double at = std::abs(theta);
  // For huge theta, sqrt(theta² + 1) overflows; t ≈ 1/(2 theta) then.
  const double t = (at > 1e150) ? 0.5 / at : 1.0 / (at + std::sqrt(at * at + 1.0));
  return theta < 0.0 ? -t : t;
}

/// Sort eigenpairs by ascending eigenvalue (a fixed network: deterministic and branch-light).
template <int D>
inline void sort_eigen(SymEigen<D>& e) {
  auto swap_pair = [&e](int i, int j) {
    if (e.values[j] < e.values[i]) {
      std::swap(e.values[i], e.values[j]);
      for (int r = 0; r < D; ++r) std::swap(e.vectors(r, i), e.vectors(r, j));
    }
  };
  if constexpr (D == 2) {
    swap_pair(0, 1);
  } else {
    swap_pair(0, 1);
    swap_pair(1, 2);
    swap_pair(0, 1);
  }
}

}  // namespace detail

/// Eigendecomposition of a symmetric 2x2 tensor: one exact Jacobi rotation.
inline SymEigen<2> eigen(const SymMat2& m) {
  SymEigen<2> e{};
  const double a = m.c[0], b = m.c[1], d = m.c[2];
  if (b == 0.0) {
    e.values = {{a, d}};
    e.vectors = Mat2::identity();
  } else {
    // The Jacobi rotation that zeroes b, written so that the dependency chain is short
    // (sqrt, then a division and a sqrt in parallel): with h = (d - a)/2 and
    // den = h ± sqrt(h² + b²) (sign of h, no cancellation), the tangent is t = b/den and
    // cos = |den|/sqrt(den² + b²). t, cos and sin depend on h/b alone: where h² + b² would
    // under- or overflow (both below ~1e-150 or one above ~1e150), h and b are first scaled by
    // a power of two, exactly (equal diagonal entries with b = 1e-170 gave den = 0, t = inf and
    // NaN eigenvalues: the identity plus a negligible b was "not positive definite").
    double h = 0.5 * (d - a), g = b;
    const double big = std::max(std::abs(h), std::abs(g));
    if ((big < 0x1p-500 || big > 0x1p500) && std::isfinite(big)) {
      const int k = std::ilogb(big);
      h = std::ldexp(h, -k), g = std::ldexp(g, -k);
    }
    const double hyp = std::sqrt(h * h + g * g);
    const double den = h + std::copysign(hyp, h);
    const double t = g / den;
    const double inv = 1.0 / std::sqrt(den * den + g * g);
    const double c = std::abs(den) * inv, s = std::copysign(1.0, den) * g * inv;
    const double l0 = a - t * b, l1 = d + t * b;
    // Columns (c, -s) for l0 and (s, c) for l1; the smaller eigenvalue goes first (computed
    // slots rather than a data-dependent branch).
    const int i0 = l0 <= l1 ? 0 : 1;
    e.values[i0] = l0;
    e.values[1 - i0] = l1;
    e.vectors(0, i0) = c;
    e.vectors(1, i0) = -s;
    e.vectors(0, 1 - i0) = s;
    e.vectors(1, 1 - i0) = c;
    return e;
  }
  detail::sort_eigen(e);
  return e;
}

namespace detail {

/// The root of β³ - 3β = 2r (|r| <= 1) farthest from the other two: 2cos(acos(r)/3) for r >= 0,
/// its mirror image for r < 0. Computed without trigonometric calls: a degree-4 Chebyshev fit as
/// first guess (error < 2e-5 on [0, 1]) polished by two Newton steps (quadratic convergence with
/// f''/2f' < 1 on the bracket [√3, 2]: 2e-5 -> 4e-10 -> rounding level).
inline double separated_root(double r) {
  const double x = std::abs(r);
  double b = 1.73206895 + x * (0.33275175 + x * (-0.09171204 + x * (0.0350064 - 0.00812871 * x)));
  for (int k = 0; k < 2; ++k) b -= (b * (b * b - 3.0) - 2.0 * x) / (3.0 * (b * b - 1.0));
  return r >= 0.0 ? b : -b;
}

/// Eigenvector (not normalised) of A for an eigenvalue `lambda` that is well separated from the
/// other two: the largest cross product of two rows of A - lambda I (which has rank 2).
inline Vec3 separated_eigenvector(const double (&a)[3][3], double lambda) {
  const Vec3 r0{{a[0][0] - lambda, a[0][1], a[0][2]}};
  const Vec3 r1{{a[0][1], a[1][1] - lambda, a[1][2]}};
  const Vec3 r2{{a[0][2], a[1][2], a[2][2] - lambda}};
  const Vec3 c01 = cross(r0, r1), c02 = cross(r0, r2), c12 = cross(r1, r2);
  const double d01 = dot(c01, c01), d02 = dot(c02, c02), d12 = dot(c12, c12);
  // Selections written as ternaries on values (compiled to blends, not branches: the winner is
  // data dependent and would mispredict half of the time).
  Vec3 best;
  const bool take02 = d02 > d01;
  const double dmax02 = take02 ? d02 : d01;
  const bool take12 = d12 > dmax02;
  for (int k = 0; k < 3; ++k) {
    const double b02 = take02 ? c02[k] : c01[k];
    best[k] = take12 ? c12[k] : b02;
  }
  const double dmax = take12 ? d12 : dmax02;
  if (dmax == 0.0) return Vec3::unit(0);  // A = lambda I to rounding: any vector will do
  return best;
}

/// An orthonormal pair (u, w) spanning the plane orthogonal to n; `inv_norm` is 1/|n|.
inline void orthonormal_complement(const Vec3& n, double inv_norm, Vec3& u, Vec3& w) {
  // Zero the component of largest magnitude's partner for a well-conditioned u (Eberly 2014).
  if (std::abs(n[0]) > std::abs(n[1])) {
    const double inv = 1.0 / std::sqrt(n[0] * n[0] + n[2] * n[2]);
    u = {{-n[2] * inv, 0.0, n[0] * inv}};
  } else {
    const double inv = 1.0 / std::sqrt(n[1] * n[1] + n[2] * n[2]);
    u = {{0.0, n[2] * inv, -n[1] * inv}};
  }
  w = cross(n, u) * inv_norm;
}

}  // namespace detail

namespace detail {

/// Diagonal tensor (or one whose off-diagonals are negligible): sorted diagonal, axis vectors.
inline SymEigen<3> eigen_diagonal(const SymMat3& m) {
  SymEigen<3> e{};
  e.values = {{m.c[0], m.c[2], m.c[5]}};
  e.vectors = Mat3::identity();
  sort_eigen(e);
  return e;
}

/// The eigensolver proper on A = m; eigenvalues are multiplied by `unscale` (an exact power of
/// two that undoes the caller's scaling of m, 1 for most inputs). Returns false, leaving e
/// untouched, when the spread p of the spectrum or the mean q are outside the range where the
/// cubic's coefficients neither overflow nor underflow; the caller then rescales.
inline bool eigen3_in_range(const SymMat3& m, double unscale, SymEigen<3>& e) {
  const double a[3][3] = {
      {m.c[0], m.c[1], m.c[3]}, {m.c[1], m.c[2], m.c[4]}, {m.c[3], m.c[4], m.c[5]}};
  // Shifted, normalised B = (A - qI)/p has eigenvalues 2cos(φ + 2kπ/3), det(B)/2 = cos(3φ).
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  const double b00 = a[0][0] - q, b11 = a[1][1] - q, b22 = a[2][2] - q;
  const double offs = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  const double p = std::sqrt((b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * offs) / 6.0);
  if (!(p > 1e-60 && p < 1e60 && std::abs(q) < 1e250)) return false;  // NaN lands here too
  const double c00 = b11 * b22 - a[1][2] * a[1][2];
  const double c01 = a[0][1] * b22 - a[1][2] * a[0][2];
  const double c02 = a[0][1] * a[1][2] - b11 * a[0][2];
  const double half_det =
      std::clamp((b00 * c00 - a[0][1] * c01 + a[0][2] * c02) / (2.0 * p * p * p), -1.0, 1.0);
  const double beta = separated_root(half_det);
  const Vec3 n_sep = separated_eigenvector(a, q + p * beta);
  const double inv_norm = 1.0 / norm(n_sep);
  const Vec3 v_sep = n_sep * inv_norm;

  // The exact 2x2 problem in the plane orthogonal to v_sep.
  Vec3 u, w;
  orthonormal_complement(n_sep, inv_norm, u, w);
  auto apply = [&a](const Vec3& x) {
    return Vec3{{a[0][0] * x[0] + a[0][1] * x[1] + a[0][2] * x[2],
                 a[0][1] * x[0] + a[1][1] * x[1] + a[1][2] * x[2],
                 a[0][2] * x[0] + a[1][2] * x[1] + a[2][2] * x[2]}};
  };
  const Vec3 au = apply(u), aw = apply(w), av = apply(v_sep);
  const SymEigen<2> e2 = eigen(SymMat2{{dot(u, au), dot(u, aw), dot(w, aw)}});
  const Vec3 v0 = e2.vectors(0, 0) * u + e2.vectors(1, 0) * w;
  const Vec3 v1 = e2.vectors(0, 1) * u + e2.vectors(1, 1) * w;
  // The pair from the plane is sorted; the separated eigenvalue is the largest when
  // half_det >= 0 and the smallest otherwise, so no sort is needed: the slots are computed
  // (stores at computed indices instead of a data-dependent branch).
  const int first = half_det >= 0.0 ? 0 : 1;  // slot of the plane's smaller eigenvalue
  const int sep = half_det >= 0.0 ? 2 : 0;
  e.values[first] = e2.values[0] * unscale;
  e.values[first + 1] = e2.values[1] * unscale;
  e.values[sep] = dot(v_sep, av) * unscale;
  e.vectors.set_column(first, v0);
  e.vectors.set_column(first + 1, v1);
  e.vectors.set_column(sep, v_sep);
  return true;
}

}  // namespace detail

/// Eigendecomposition of a symmetric 3x3 tensor.
///
/// Robust non-iterative method (after D. Eberly, "A robust eigensolver for 3x3 symmetric
/// matrices", 2014): the eigenvalue farthest from the other two is found in closed form; its
/// eigenvector, from cross products of rows of A - λI, is accurate because its gap is at least
/// half the spectral spread. The other two eigenpairs come from the exact 2x2 problem in the
/// orthogonal plane (one Jacobi rotation), which handles repeated eigenvalues. The result is
/// backward stable (|R Λ Rᵀ - A| ≈ ε|A|) for any eigenvalue spread; a diagonal input is
/// returned exactly. Inputs whose coefficients would overflow or underflow in the cubic are
/// rescaled by a power of two (rare: metrics with sizes between 1e-25 and 1e25 never are).
inline SymEigen<3> eigen(const SymMat3& m) {
  if (m.c[1] == 0.0 && m.c[3] == 0.0 && m.c[4] == 0.0) return detail::eigen_diagonal(m);
  SymEigen<3> e;
  if (detail::eigen3_in_range(m, 1.0, e)) return e;
  double scale = 0.0;
  for (int k = 0; k < 6; ++k) scale = std::max(scale, std::abs(m.c[k]));
  if (!std::isfinite(scale) || scale == 0.0) return detail::eigen_diagonal(m);
  const int exponent = std::ilogb(scale);
  if (detail::eigen3_in_range(std::ldexp(1.0, -exponent) * m, std::ldexp(1.0, exponent), e))
    return e;
  // Spread below 1e-60 of the largest coefficient: the off-diagonals are negligible.
  return detail::eigen_diagonal(m);
}

/// R diag(λ) Rᵀ: rebuild a symmetric tensor from eigenvectors and (new) eigenvalues.
template <int D>
constexpr SymMat<D> compose(const Mat<D>& vectors, const Vec<D>& values) {
  return congruence_diag(vectors, values);
}

}  // namespace riemesh
