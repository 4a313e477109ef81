#pragma once
// Functions of symmetric positive definite tensors through their eigendecomposition:
// f(M) = R diag(f(λ)) Rᵀ. log, exp, sqrt, powers, the SPD check and the projection onto
// tensors with eigenvalues in [lo, hi] (eigenvalue clipping).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/eigen.hpp"
#include "core/fast_exp.hpp"
#include "core/symmat.hpp"

namespace riemesh {

/// f(M) = R diag(f(λᵢ)) Rᵀ for any scalar function f.
template <int D, class F>
inline SymMat<D> map_eigenvalues(const SymMat<D>& m, F f) {
  SymEigen<D> e = eigen(m);
  for (int i = 0; i < D; ++i) e.values[i] = f(e.values[i]);
  return compose(e.vectors, e.values);
}

/// True when M is finite, symmetric positive definite, with eigenvalues in the normal range of
/// doubles (so that sizes 1/sqrt(λ) and their logs are finite).
template <int D>
inline bool is_spd(const SymMat<D>& m) {
  if (!is_finite(m)) return false;
  const SymEigen<D> e = eigen(m);
  return e.values[0] >= std::numeric_limits<double>::min() &&
         e.values[D - 1] < std::numeric_limits<double>::infinity();
}

/// Matrix logarithm of an SPD tensor (result symmetric, possibly indefinite).
template <int D>
inline SymMat<D> log_spd(const SymMat<D>& m) {
  return map_eigenvalues(m, [](double l) { return std::log(l); });
}
/// Matrix exponential of a symmetric tensor (result SPD).
template <int D>
inline SymMat<D> exp_sym(const SymMat<D>& m) {
  return map_eigenvalues(m, [](double l) { return std::exp(l); });
}
/// Product of two symmetric tensors that commute (polynomials in one tensor): symmetric.
template <int D>
inline SymMat<D> commuting_product(const SymMat<D>& x, const SymMat<D>& y) {
  if constexpr (D == 3) {  // packed (00, 01, 11, 02, 12, 22), written out: the hot case
    const double* a = x.c;
    const double* b = y.c;
    return SymMat<D>{{a[0] * b[0] + a[1] * b[1] + a[3] * b[3], a[0] * b[1] + a[1] * b[2] + a[3] * b[4],
                      a[1] * b[1] + a[2] * b[2] + a[4] * b[4], a[0] * b[3] + a[1] * b[4] + a[3] * b[5],
                      a[1] * b[3] + a[2] * b[4] + a[4] * b[5], a[3] * b[3] + a[4] * b[4] + a[5] * b[5]}};
  } else {
    SymMat<D> p{};
    for (int j = 0; j < D; ++j)
      for (int i = 0; i <= j; ++i) {
        double s = 0.0;
        for (int k = 0; k < D; ++k) s += x(i, k) * y(k, j);
        p.at(i, j) = s;
      }
    return p;
  }
}

/// exp of a symmetric 2x2 tensor in closed form: with μ = tr m / 2 and B = m − μ I trace-free,
/// B² = δ² I (δ² = −det B), so exp(m) = e^μ (cosh δ I + (sinh δ / δ) B) = ½ (e⁺ + e⁻) I +
/// (e⁺ − e⁻) / (2δ) B with e± = e^(μ±δ), the exponentials of the eigenvalues. The difference
/// loses digits as δ → 0, but only in a term of size δ: the result keeps ~1e-16 relative in norm;
/// below δ = 1e-3 the series of cosh and sinh / δ (next terms < 1e-20). Exact on isotropic input
/// up to fast_exp (within 2 ulp of e^x).
inline SymMat<2> exp_sym_2d(const SymMat<2>& m) {
  const double mu = 0.5 * (m.c[0] + m.c[2]), h = 0.5 * (m.c[0] - m.c[2]), b = m.c[1];
  const double d2 = h * h + b * b;
  double even, odd;  // e^μ cosh δ, e^μ sinh δ / δ
  if (d2 < 1e-6) {
    const double e = fast_exp(mu);
    even = e * (1.0 + d2 * (0.5 + d2 / 24.0));
    odd = e * (1.0 + d2 * (1.0 / 6.0 + d2 / 120.0));
  } else {
    const double delta = std::sqrt(d2), plus = fast_exp(mu + delta), minus = fast_exp(mu - delta);
    even = 0.5 * (plus + minus);
    odd = 0.5 * (plus - minus) / delta;
  }
  return SymMat<2>{{even + odd * h, odd * b, even - odd * h}};
}

/// exp_sym without an eigendecomposition, for hot loops. In 2D the closed form exp_sym_2d; in 3D
/// exp(m) = e^{tr m / D} exp(B) with B the trace-free part, B scaled by 2^-s until ‖B‖_F <= 1/4,
/// its Taylor series to degree 9 (Paterson–Stockmeyer: 4 products; truncation below 3e-13
/// relative), then s squarings. Relative error ~1e-13·2^s against exp_sym
/// (tests/core/test_spd.cpp); about 3x cheaper.
template <int D>
inline SymMat<D> exp_sym_series(const SymMat<D>& m) {
  if constexpr (D == 2) return exp_sym_2d(m);
  const double shift = trace(m) / D;
  SymMat<D> x = m - SymMat<D>::diagonal(shift);
  double n2 = 0.0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) n2 += x(i, j) * x(i, j);
  int s = 0;
  double scale = 1.0;
  while (n2 * scale * scale > 0.0625 && s < 64) scale *= 0.5, ++s;
  x = scale * x;
  const SymMat<D> x2 = commuting_product(x, x), x3 = commuting_product(x2, x);
  const SymMat<D> id = SymMat<D>::identity();
  // Σ x^k / k!, k <= 9, grouped as q0 + x³ (q1 + x³ (q2 + x³ / 9!)).
  constexpr double f[10] = {1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720,
                            1.0 / 5040, 1.0 / 40320, 1.0 / 362880};
  const SymMat<D> q2 = f[6] * id + f[7] * x + f[8] * x2 + f[9] * x3;
  const SymMat<D> q1 = f[3] * id + f[4] * x + f[5] * x2 + commuting_product(x3, q2);
  SymMat<D> e = f[0] * id + f[1] * x + f[2] * x2 + commuting_product(x3, q1);
  for (int k = 0; k < s; ++k) e = commuting_product(e, e);
  return std::exp(shift) * e;
}

/// Principal square root of an SPD tensor.
template <int D>
inline SymMat<D> sqrt_spd(const SymMat<D>& m) {
  return map_eigenvalues(m, [](double l) { return std::sqrt(l); });
}
/// M^p for an SPD tensor and any real p (p = -1/2 gives the "size tensor" M^{-1/2}).
template <int D>
inline SymMat<D> pow_spd(const SymMat<D>& m, double p) {
  return map_eigenvalues(m, [p](double l) { return std::pow(l, p); });
}
/// The tensor with the same eigenvectors and eigenvalues clipped to [lo, hi]: the nearest SPD
/// tensor in the Frobenius norm with bounded spectrum (for metrics: sizes clipped to
/// [1/sqrt(hi), 1/sqrt(lo)]). Negative or zero eigenvalues become lo.
template <int D>
inline SymMat<D> project_spd(const SymMat<D>& m, double lo, double hi) {
  return map_eigenvalues(m, [lo, hi](double l) { return std::clamp(l, lo, hi); });
}

}  // namespace riemesh
