#pragma once
// Intersection of metrics (BOOK.md §1, "Intersection"): the metric whose unit ball is the
// largest ellipsoid inside the unit balls of all the inputs, i.e. which prescribes, in every
// direction, at most the smallest size. Inputs are SPD (callers validate with require_metric).
#include <span>

#include "core/symmat.hpp"
#include "metric/simultaneous_reduction.hpp"

namespace riemesh {

/// Intersection of two metrics by simultaneous reduction: in the common basis keep
/// mu_i = max(mu_a,i, mu_b,i), the smaller size. Exact (returns the input) when one unit ball is
/// inside the other; the result is the unique maximal-volume ellipsoid inside both.
template <int D>
inline SymMat<D> intersect(const SymMat<D>& a, const SymMat<D>& b) {
  const SimultaneousReduction<D> r = simultaneous_reduction(a, b);
  bool a_wins = true, b_wins = true;
  Vec<D> mu{};
  for (int i = 0; i < D; ++i) {
    a_wins = a_wins && r.mu_a[i] >= r.mu_b[i];
    b_wins = b_wins && r.mu_b[i] >= r.mu_a[i];
    mu[i] = r.mu_a[i] >= r.mu_b[i] ? r.mu_a[i] : r.mu_b[i];
  }
  if (a_wins) return a;  // nested balls: no rounding from the change of basis
  if (b_wins) return b;
  return rebuild_metric(r, mu);
}

/// ((m₀ ∩ m₁) ∩ m₂) ∩ ...: cheap, contained in every input, but order dependent for three or
/// more metrics. Throws InputError on an empty list.
template <int D>
SymMat<D> intersect_sequential(std::span<const SymMat<D>> m);

/// The order-independent intersection of any number of metrics: the maximal-volume centred
/// ellipsoid inside every unit ball (the John ellipsoid of the intersection), i.e. the metric M
/// of smallest det with M ⪰ mᵢ for all i. Solved as a convex problem by a barrier/Newton
/// method (see intersection.cpp); `tol` is the target accuracy in log det. The result contains
/// (⪰) every input exactly up to rounding. For two metrics it equals intersect(a, b).
/// Throws InputError on an empty list.
template <int D>
SymMat<D> intersect_max_volume(std::span<const SymMat<D>> m, double tol = 1e-12);

/// True when the unit ball of a lies inside that of b (a ⪰ b): every eigenvalue of
/// b^{-1/2} a b^{-1/2} is at least 1 - rtol.
template <int D>
inline bool contained_in(const SymMat<D>& a, const SymMat<D>& b, double rtol = 1e-12) {
  return relative_eigenvalues(b, a)[0] >= 1.0 - rtol;
}

/// True when a and b are the same metric up to a relative tolerance: every eigenvalue of
/// a^{-1/2} b a^{-1/2} lies within rtol of 1 (independent of units and of the frame).
template <int D>
inline bool metrics_equal(const SymMat<D>& a, const SymMat<D>& b, double rtol = 1e-12) {
  const Vec<D> nu = relative_eigenvalues(a, b);
  return nu[0] >= 1.0 - rtol && nu[D - 1] <= 1.0 + rtol;
}

}  // namespace riemesh
