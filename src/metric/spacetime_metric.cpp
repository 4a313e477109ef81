// Unsteady metrics (BOOK.md §8): Hessian samples combined in time, and the space–time Lp metric
// of all sub-intervals at once. The formula and its derivation are in spacetime_metric.hpp.
#include "metric/spacetime_metric.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "metric/metric.hpp"

namespace riemesh {

template <int D>
SymMat<D> abs_hessian(const SymMat<D>& h, double floor) {
  SymEigen<D> e = eigen(h);
  for (int i = 0; i < D; ++i) e.values[i] = std::max(std::abs(e.values[i]), floor);
  return compose(e.vectors, e.values);
}

template <int D>
std::vector<SymMat<D>> combine_in_time(std::span<const std::vector<SymMat<D>>> samples,
                                       double length, TimeCombination how) {
  if (samples.empty()) throw InputError("no Hessian sample in the sub-interval");
  if (!(length > 0.0) || !std::isfinite(length))
    throw InputError("a sub-interval needs a length > 0");
  const std::size_t n = samples[0].size();
  double largest = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    if (samples[k].size() != n)
      throw InputError("Hessian sample " + std::to_string(k + 1) + " has " +
                       std::to_string(samples[k].size()) + " vertices, sample 1 has " +
                       std::to_string(n));
    for (const SymMat<D>& h : samples[k]) {
      if (!is_finite(h)) throw InputError("a Hessian sample is not finite");
      const SymEigen<D> e = eigen(h);
      for (int i = 0; i < D; ++i) largest = std::max(largest, std::abs(e.values[i]));
    }
  }
  // A sub-interval without interpolation error (a linear field throughout) has H_i = 0, so that
  // it takes (almost) none of the space-time complexity: floored to the identity, it weighed as
  // |H| = I against the others, whatever their scale (1999.8 of 2000 against a Hessian of 1e-6).
  if (largest == 0.0) return std::vector<SymMat<D>>(n, SymMat<D>::zero());
  const double floor = 1e-12 * largest;
  std::vector<std::vector<SymMat<D>>> abs(samples.size(), std::vector<SymMat<D>>(n));
  for (std::size_t k = 0; k < samples.size(); ++k)
    for (std::size_t v = 0; v < n; ++v) abs[k][v] = abs_hessian<D>(samples[k][v], floor);
  if (how == TimeCombination::kMax) {
    std::vector<SymMat<D>> out = combine_metrics<D>(abs);
    for (SymMat<D>& m : out) m = length * m;
    return out;
  }
  // Trapezoid rule over equally spaced samples, ends included; one sample: the midpoint rule.
  const std::size_t k_count = samples.size();
  std::vector<SymMat<D>> out(n, SymMat<D>{});
  for (std::size_t k = 0; k < k_count; ++k) {
    double w = length;
    if (k_count > 1) w = (k == 0 || k + 1 == k_count ? 0.5 : 1.0) * length / (k_count - 1.0);
    for (std::size_t v = 0; v < n; ++v) out[v] += w * abs[k][v];
  }
  return out;
}

template <int D>
double lp_shape_integral(const Mesh& mesh, std::span<const SymMat<D>> h, double norm) {
  const std::vector<Id>& elems = D == 2 ? mesh.triangles : mesh.tets;
  if (h.size() != mesh.num_vertices() || elems.empty() || mesh.dim != D)
    throw InputError("space-time metric: a Hessian field that does not match its mesh");
  const double e = std::isfinite(norm) ? norm / (2.0 * norm + D) : 0.5;
  std::vector<double> f(h.size());
  for (std::size_t v = 0; v < f.size(); ++v) f[v] = std::pow(std::max(det(h[v]), 0.0), e);
  double sum = 0.0;
  for (std::size_t k = 0; k + D < elems.size(); k += D + 1) {
    Vec<D> p[D + 1];
    double mean = 0.0;
    for (int i = 0; i <= D; ++i) {
      const auto v = static_cast<std::size_t>(elems[k + i]);
      for (int a = 0; a < D; ++a) p[i][a] = mesh.coords[D * v + a];
      mean += f[v] / (D + 1);
    }
    sum += std::abs(simplex_measure<D>(p)) * mean;
  }
  return sum;
}

template <int D>
std::vector<double> spacetime_complexities(std::span<const SpaceTimeInterval<D>> intervals,
                                           double mean_complexity, double norm) {
  if (intervals.empty()) throw InputError("space-time metric: no sub-interval");
  if (!(mean_complexity > 0.0) || !std::isfinite(mean_complexity))
    throw InputError("space-time metric: the complexity must be > 0");
  if (!(norm >= 1.0) || !std::isfinite(norm))
    throw InputError("space-time metric: the norm p must be finite and >= 1");
  const double q = 2.0 * norm + D;
  double steps = 0.0, denominator = 0.0;
  std::vector<double> integral(intervals.size());
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    const SpaceTimeInterval<D>& in = intervals[i];
    if (!in.mesh || !(in.time_steps > 0.0) || !std::isfinite(in.time_steps))
      throw InputError("space-time metric: sub-interval " + std::to_string(i + 1) +
                       " needs a mesh and a number of time steps > 0");
    integral[i] = lp_shape_integral<D>(*in.mesh, in.hessian, norm);
    steps += in.time_steps;
    denominator += std::pow(in.time_steps, 2.0 * norm / q) * integral[i];
  }
  if (!(denominator > 0.0)) throw InputError("space-time metric: the Hessians are all zero");
  const double n_st = mean_complexity * steps;
  std::vector<double> out(intervals.size());
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = n_st * std::pow(intervals[i].time_steps, -D / q) * integral[i] / denominator;
  return out;
}

template <int D>
std::vector<std::vector<SymMat<D>>> spacetime_lp_metrics(
    std::span<const SpaceTimeInterval<D>> intervals, const HessianMetricOptions& options,
    std::vector<MetricReport>* reports) {
  options.validate();
  const std::vector<double> n =
      spacetime_complexities<D>(intervals, options.complexity, options.norm);
  std::vector<std::vector<SymMat<D>>> out;
  if (reports) reports->clear();
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    HessianMetricOptions o = options;
    o.complexity = std::max(n[i], 1e-6);  // (a sub-interval with H_i = 0 gets 0: the coarsest)
    MetricReport r;
    out.push_back(hessian_metric<D>(*intervals[i].mesh, intervals[i].hessian, o, &r));
    if (reports) reports->push_back(r);
  }
  return out;
}

#define RIEMESH_INSTANTIATE(D)                                                                    \
  template SymMat<D> abs_hessian<D>(const SymMat<D>&, double);                                    \
  template std::vector<SymMat<D>> combine_in_time<D>(std::span<const std::vector<SymMat<D>>>,     \
                                                     double, TimeCombination);                    \
  template double lp_shape_integral<D>(const Mesh&, std::span<const SymMat<D>>, double);          \
  template std::vector<double> spacetime_complexities<D>(                                         \
      std::span<const SpaceTimeInterval<D>>, double, double);                                     \
  template std::vector<std::vector<SymMat<D>>> spacetime_lp_metrics<D>(                           \
      std::span<const SpaceTimeInterval<D>>, const HessianMetricOptions&,                         \
      std::vector<MetricReport>*);
RIEMESH_INSTANTIATE(2)
RIEMESH_INSTANTIATE(3)
#undef RIEMESH_INSTANTIATE

}  // namespace riemesh
