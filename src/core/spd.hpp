#pragma once
// Functions of symmetric positive definite tensors through their eigendecomposition:
// f(M) = R diag(f(λ)) Rᵀ. log, exp, sqrt, powers, the SPD check and the projection onto
// tensors with eigenvalues in [lo, hi] (eigenvalue clipping).
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/eigen.hpp"
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
