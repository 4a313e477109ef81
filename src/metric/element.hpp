#pragma once
// The metric of an element, element quality in a metric, and the metric implied by a mesh.
// BOOK.md §1 "Element metric and quality"; log-Euclidean means after Arsigny et al. (2006).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "core/error.hpp"
#include "core/spd.hpp"
#include "metric/metric.hpp"

namespace riemesh {

/// A simplex whose measure is below this fraction of (longest edge)^D is degenerate. The
/// regular simplex has 0.43 (2D) and 0.12 (3D); 1e-12 only rejects what rounding cannot tell
/// from flat, where N = Σ v vᵀ is singular and M_K meaningless.
inline constexpr double kDegenerateSimplexRatio = 1e-12;

/// The unique metric in which simplex p is unit and regular: M_K = ((D+1)/2) N⁻¹ with
/// N = Σ_{i<j} v_ij v_ijᵀ (BOOK.md §1). Throws InputError("degenerate simplex").
template <int D>
SymMat<D> element_metric(const Vec<D> (&p)[D + 1]) {
  SymMat<D> n = SymMat<D>::zero();
  double longest2 = 0.0;
  for (int i = 0; i < D + 1; ++i)
    for (int j = i + 1; j < D + 1; ++j) {
      const Vec<D> v = p[j] - p[i];
      n += outer(v);
      longest2 = std::max(longest2, dot(v, v));
    }
  // Relative test: scale-free, and !(x > y) also rejects NaN coordinates.
  const double measure = std::abs(simplex_measure(p));
  if (!(measure > kDegenerateSimplexRatio * std::pow(longest2, 0.5 * D)))
    throw InputError("degenerate simplex");
  return (0.5 * (D + 1)) * inverse(n);
}

/// Mean-ratio quality of simplex p in the constant metric m: 2D 4√3|K|_M / Σl², 3D
/// 12 (3|K|_M)^{2/3} / Σl² (BOOK.md §1). 1 for the regular simplex of m, → 0 when flat,
/// negative for an inverted simplex (the sign of its measure); 0 when all vertices coincide.
template <int D>
double quality(const SymMat<D>& m, const Vec<D> (&p)[D + 1]) {
  static_assert(D == 2 || D == 3);
  double sum_l2 = 0.0;
  for (int i = 0; i < D + 1; ++i)
    for (int j = i + 1; j < D + 1; ++j) sum_l2 += quadratic(m, p[j] - p[i]);
  if (sum_l2 == 0.0) return 0.0;
  const double measure = simplex_measure(m, p);
  if constexpr (D == 2) {
    return 4.0 * std::sqrt(3.0) * measure / sum_l2;
  } else {
    const double c = std::cbrt(3.0 * std::abs(measure));
    return std::copysign(12.0 * c * c / sum_l2, measure);
  }
}

/// Weighted log-Euclidean mean exp(Σ wᵢ log Mᵢ / Σ wᵢ) (Arsigny et al. 2006): order independent,
/// keeps det M between the extremes, dilutes anisotropy least (BOOK.md §1 "Interpolation").
/// Weights must be non-negative with a positive sum.
template <int D>
SymMat<D> log_euclidean_mean(std::span<const SymMat<D>> m, std::span<const double> w) {
  if (m.empty() || m.size() != w.size())
    throw InputError("log_euclidean_mean: need as many weights as metrics, at least one");
  SymMat<D> sum = SymMat<D>::zero();
  double wsum = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!(w[i] >= 0.0) || !std::isfinite(w[i]))
      throw InputError("log_euclidean_mean: weights must be finite and non-negative");
    sum += w[i] * log_spd(m[i]);
    wsum += w[i];
  }
  if (!(wsum > 0.0)) throw InputError("log_euclidean_mean: weights sum to zero");
  return exp_sym((1.0 / wsum) * sum);
}

/// Unweighted log-Euclidean mean of n >= 1 metrics.
template <int D>
SymMat<D> log_euclidean_mean(const SymMat<D>* m, int n) {
  if (n < 1) throw InputError("log_euclidean_mean: need at least one metric");
  SymMat<D> sum = SymMat<D>::zero();
  for (int i = 0; i < n; ++i) sum += log_spd(m[i]);
  return exp_sym((1.0 / n) * sum);
}

/// Quality of simplex p in the log-Euclidean mean of its vertex metrics (the metric "at the
/// element" of BOOK.md §1).
template <int D>
double quality(const Vec<D> (&p)[D + 1], const SymMat<D> (&m)[D + 1]) {
  return quality(log_euclidean_mean(m, D + 1), p);
}

/// Per-vertex kernel of the implied metric: the log-Euclidean mean of the element metrics of
/// the vertex's ball weighted by the elements' (Euclidean, unsigned) measures.
template <int D>
SymMat<D> implied_vertex_metric(std::span<const SymMat<D>> ball_metrics,
                                std::span<const double> ball_measures) {
  return log_euclidean_mean(ball_metrics, ball_measures);
}

/// The metric implied by a mesh: at each vertex, implied_vertex_metric over its ball. coords
/// holds D numbers per vertex, simplices D+1 vertex ids (0-based) per simplex. Throws
/// InputError for malformed arrays, degenerate simplices and vertices in no simplex.
template <int D>
std::vector<SymMat<D>> implied_metric(std::span<const double> coords,
                                      std::span<const int32_t> simplices);

/// log M at each vertex of the metric implied by a mesh (implied_metric's mean before its
/// exponential). `in_simplex`, when given, receives whether each vertex is in a simplex, and a
/// vertex in none gets the zero matrix instead of an InputError.
template <int D>
std::vector<SymMat<D>> implied_log_metric(std::span<const double> coords,
                                          std::span<const int32_t> simplices,
                                          std::vector<bool>* in_simplex = nullptr);

extern template std::vector<SymMat<2>> implied_log_metric<2>(std::span<const double>,
                                                             std::span<const int32_t>,
                                                             std::vector<bool>*);
extern template std::vector<SymMat<3>> implied_log_metric<3>(std::span<const double>,
                                                             std::span<const int32_t>,
                                                             std::vector<bool>*);
extern template std::vector<SymMat<2>> implied_metric<2>(std::span<const double>,
                                                         std::span<const int32_t>);
extern template std::vector<SymMat<3>> implied_metric<3>(std::span<const double>,
                                                         std::span<const int32_t>);

}  // namespace riemesh
