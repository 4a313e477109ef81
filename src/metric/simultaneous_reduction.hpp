#pragma once
// Simultaneous reduction of two metrics (BOOK.md §1, "Interpolation of metrics"): a basis
// P = [e_1 .. e_D] in which both quadratic forms are diagonal, e_iᵀ M_k e_j = 0 for i != j.
//
// The textbook route diagonalises the non-symmetric N = A⁻¹B, whose eigenvectors are
// ill-conditioned when eigenvalues are close and arbitrary when they repeat. We solve the
// equivalent symmetric problem instead: C = A^{-1/2} B A^{-1/2} = Q diag(ν) Qᵀ with the
// symmetric eigensolver, and take P = A^{-1/2} Q. Then PᵀAP = I and PᵀBP = diag(ν) by
// construction; a repeated ν gets an orthonormal Q-block, i.e. an A-orthogonal basis of the
// eigenspace, as the book prescribes.
#include <cmath>

#include "core/eigen.hpp"
#include "core/mat.hpp"
#include "core/symmat.hpp"
#include "core/vec.hpp"

namespace riemesh {

/// Common diagonalising basis of two metrics: M_k = dual diag(mu_k) dualᵀ, dual = basis^{-T}.
///
/// The columns of `basis` are eigenvectors of A⁻¹B scaled to unit Euclidean length, so that
/// mu_k,i = e_iᵀ M_k e_i = 1/h_k,i² is the squared inverse size of metric k along e_i, in
/// length units. `dual` (= basis^{-T}) is returned too because it is what rebuilds a metric
/// from new coefficients, and computing it from A (below) is more accurate than inverting P.
template <int D>
struct SimultaneousReduction {
  Mat<D> basis;
  Mat<D> dual;
  Vec<D> mu_a, mu_b;
};

/// The simultaneous reduction of two SPD tensors a and b (precondition: both SPD).
template <int D>
inline SimultaneousReduction<D> simultaneous_reduction(const SymMat<D>& a, const SymMat<D>& b) {
  // A = R diag(λ) Rᵀ gives A^{±1/2} = R diag(λ^{±1/2}) Rᵀ from one decomposition.
  const SymEigen<D> ea = eigen(a);
  Vec<D> root{}, inv_root{};
  for (int i = 0; i < D; ++i) {
    root[i] = std::sqrt(ea.values[i]);
    inv_root[i] = 1.0 / root[i];
  }
  const Mat<D> a_half = compose(ea.vectors, root).to_mat();
  const Mat<D> a_inv_half = compose(ea.vectors, inv_root).to_mat();
  const SymEigen<D> ec = eigen(congruence(a_inv_half, b));

  // P0 = A^{-1/2} Q is A-orthonormal; its dual basis is P0^{-T} = A P0 = A^{1/2} Q.
  // Scaling column i of P0 by 1/s_i (s_i = |P0 e_i|) scales the dual column by s_i and the
  // diagonal coefficients by 1/s_i².
  SimultaneousReduction<D> r{};
  r.basis = a_inv_half * ec.vectors;
  r.dual = a_half * ec.vectors;
  for (int i = 0; i < D; ++i) {
    const double s = norm(r.basis.column(i));
    for (int k = 0; k < D; ++k) {
      r.basis(k, i) /= s;
      r.dual(k, i) *= s;
    }
    r.mu_a[i] = 1.0 / (s * s);
    r.mu_b[i] = ec.values[i] / (s * s);
  }
  return r;
}

/// Eigenvalues ν (ascending) of A⁻¹B, i.e. of the symmetric A^{-1/2} B A^{-1/2}: how much
/// larger B is than A along each common direction (B ⪰ A iff ν_min >= 1).
template <int D>
inline Vec<D> relative_eigenvalues(const SymMat<D>& a, const SymMat<D>& b) {
  const SymEigen<D> ea = eigen(a);
  Vec<D> inv_root{};
  for (int i = 0; i < D; ++i) inv_root[i] = 1.0 / std::sqrt(ea.values[i]);
  return eigen(congruence(compose(ea.vectors, inv_root).to_mat(), b)).values;
}

/// One reduced coefficient at parameter t: the size h = mu^{-1/2} interpolated linearly, or
/// geometrically (mu_a^{1-t} mu_b^t, which gives det M_t = det A^{1-t} det B^t).
inline double interpolate_reduced(double mu_a, double mu_b, double t, bool geometric) {
  if (geometric) return mu_a * std::pow(mu_b / mu_a, t);
  const double h = (1.0 - t) / std::sqrt(mu_a) + t / std::sqrt(mu_b);
  return 1.0 / (h * h);
}

/// The metric with coefficients mu in the reduced basis: dual diag(mu) dualᵀ = P^{-T} diag(mu) P^{-1}.
template <int D>
inline SymMat<D> rebuild_metric(const SimultaneousReduction<D>& r, const Vec<D>& mu) {
  return congruence_diag(r.dual, mu);
}

}  // namespace riemesh
