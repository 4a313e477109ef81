#include "metric/approach.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/spd.hpp"

namespace riemesh {

int approach_stages(double longest, double growth) {
  if (!(growth > 1.0) || !std::isfinite(growth))
    throw InputError("metric approach: the growth per stage must be a number > 1");
  if (!(longest > growth)) return 1;
  const double n = std::ceil(std::log(longest) / std::log(growth) - 1e-9);
  return std::isfinite(n) ? static_cast<int>(std::clamp(n, 1.0, 64.0)) : 64;
}

template <int D>
MetricApproach<D>::MetricApproach(std::vector<SymMat<D>>&& implied_logs,
                                  const std::vector<bool>& in_simplex,
                                  std::span<const SymMat<D>> target)
    : from_(std::move(implied_logs)), target_(target.begin(), target.end()) {
  if (from_.size() != target_.size() || in_simplex.size() != target_.size())
    throw InputError("metric approach: " + std::to_string(from_.size()) + " implied metrics for " +
                     std::to_string(target_.size()) + " target metrics");
  to_.resize(target_.size());
  for (std::size_t v = 0; v < target_.size(); ++v) {
    to_[v] = log_spd(target_[v]);
    if (!in_simplex[v]) from_[v] = to_[v];
  }
}

template <int D>
std::vector<SymMat<D>> MetricApproach<D>::field(double t) const {
  if (t >= 1.0) return target_;
  std::vector<SymMat<D>> out(to_.size());
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = exp_sym((1.0 - t) * from_[v] + t * to_[v]);
  return out;
}

template class MetricApproach<2>;
template class MetricApproach<3>;

}  // namespace riemesh
