#pragma once
// Complexity of a simplex in a metric field, C(K) = ∫_K sqrt(det M(x)) dx (BOOK.md §1: the
// vertex count of a unit mesh is proportional to the complexity of the field).
//
// Log-Euclidean field: det M(x) = det exp(Σ λᵢ log Mᵢ) = exp(Σ λᵢ ln det Mᵢ), so sqrt(det M) is
// the exponential of the affine function Σ λᵢ aᵢ, aᵢ = ½ ln det Mᵢ, and (Hermite–Genocchi)
//     ∫_K exp(Σ λᵢ aᵢ) dx = D! |K| exp[a₀, ..., a_D],
// the divided difference of exp. Other schemes: a degree-5 simplex quadrature rule.
#include <algorithm>
#include <cmath>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "metric/interpolation.hpp"
#include "metric/metric.hpp"

namespace riemesh {
namespace detail {

/// exp[x₀..x_n] for close points: with c the mean and yᵢ = xᵢ - c (|yᵢ| < 1),
/// exp[x] = e^c Σ_j h_j(y) / (j + n)!, h_j the complete homogeneous symmetric polynomials
/// (the divided difference of t^k is h_{k-n}). Terms fall like 1/(n! j!): 22 are plenty.
inline double exp_divided_difference_series(const double* x, int n) {
  double c = 0.0;
  for (int i = 0; i <= n; ++i) c += x[i];
  c /= (n + 1);
  constexpr int kTerms = 22;
  double h[kTerms + 1];
  h[0] = 1.0;
  for (int j = 1; j <= kTerms; ++j) h[j] = h[j - 1] * (x[0] - c);
  for (int i = 1; i <= n; ++i)  // add variable yᵢ: h_j ← h_j + yᵢ h_{j-1} (new)
    for (int j = 1; j <= kTerms; ++j) h[j] += (x[i] - c) * h[j - 1];
  double factorial = 1.0;
  for (int k = 2; k <= n; ++k) factorial *= k;
  double sum = 0.0;
  for (int j = 0; j <= kTerms; ++j) {
    sum += h[j] / factorial;
    factorial *= (j + n + 1);
  }
  return std::exp(c) * sum;
}

/// exp[x₀..x_n] for sorted x (ascending), accurate for any spacing, repeated points included:
/// the series when the spread is below 1, else the recurrence over the two extreme points,
/// whose denominator (the spread) then cannot cause cancellation.
inline double exp_divided_difference(const double* x, int n) {
  if (n == 0) return std::exp(x[0]);
  const double spread = x[n] - x[0];
  if (spread < 1.0) return exp_divided_difference_series(x, n);
  return (exp_divided_difference(x + 1, n - 1) - exp_divided_difference(x, n - 1)) / spread;
}

/// Symmetric simplex quadrature rules of degree 5 with positive weights (weights sum to 1):
/// triangle, Radon's 7 points (a = (6 ∓ √15)/21); tetrahedron, 14 points (Walkington), as
/// orbits of barycentric coordinates. Values solved to 40 digits from the moment equations.
template <int D>
struct SimplexRule;
template <>
struct SimplexRule<2> {
  static constexpr int kPoints = 7;
  static constexpr double kPoint[kPoints][3] = {
      {1.0 / 3, 1.0 / 3, 1.0 / 3},
      {0.10128650732345634, 0.10128650732345634, 0.79742698535308732},
      {0.10128650732345634, 0.79742698535308732, 0.10128650732345634},
      {0.79742698535308732, 0.10128650732345634, 0.10128650732345634},
      {0.47014206410511509, 0.47014206410511509, 0.05971587178976982},
      {0.47014206410511509, 0.05971587178976982, 0.47014206410511509},
      {0.05971587178976982, 0.47014206410511509, 0.47014206410511509}};
  static constexpr double kWeight[kPoints] = {0.225,
                                              0.12593918054482715, 0.12593918054482715,
                                              0.12593918054482715, 0.13239415278850618,
                                              0.13239415278850618, 0.13239415278850618};
};
template <>
struct SimplexRule<3> {
  static constexpr int kPoints = 14;
  static constexpr double a = 0.092735250310891226, a3 = 1.0 - 3.0 * a;
  static constexpr double b = 0.31088591926330061, b3 = 1.0 - 3.0 * b;
  static constexpr double c = 0.045503704125649649, c2 = 0.5 - c;
  static constexpr double wa = 0.07349304311636195, wb = 0.11268792571801585,
                          wc = 0.042546020777081466;
  static constexpr double kPoint[kPoints][4] = {
      {a, a, a, a3}, {a, a, a3, a}, {a, a3, a, a}, {a3, a, a, a},
      {b, b, b, b3}, {b, b, b3, b}, {b, b3, b, b}, {b3, b, b, b},
      {c, c, c2, c2}, {c, c2, c, c2}, {c, c2, c2, c}, {c2, c, c, c2}, {c2, c, c2, c}, {c2, c2, c, c}};
  static constexpr double kWeight[kPoints] = {wa, wa, wa, wa, wb, wb, wb, wb,
                                              wc, wc, wc, wc, wc, wc};
};

}  // namespace detail

/// ∫_K sqrt(det M(x)) dx over the simplex p with vertex metrics m interpolated by scheme s
/// (analytic for kLogEuclidean, a degree-5 rule otherwise). Orientation-independent (>= 0).
template <int D>
inline double complexity(const Vec<D> (&p)[D + 1], const SymMat<D> (&m)[D + 1],
                         InterpScheme s = InterpScheme::kLogEuclidean) {
  const double measure = std::abs(simplex_measure(p));
  if (s == InterpScheme::kLogEuclidean) {
    double a[D + 1];
    for (int i = 0; i <= D; ++i) a[i] = 0.5 * std::log(det(m[i]));
    std::sort(a, a + D + 1);
    return factorial<D>() * measure * detail::exp_divided_difference(a, D);
  }
  using Rule = detail::SimplexRule<D>;
  double sum = 0.0;
  for (int q = 0; q < Rule::kPoints; ++q)
    sum += Rule::kWeight[q] * std::sqrt(det(interpolate(s, m, Rule::kPoint[q])));
  return measure * sum;
}

}  // namespace riemesh
