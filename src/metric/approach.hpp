#pragma once
// The staged approach of a remesher to its target metric field (issue #7): from the metric its
// input mesh implies, I, to the target T through the fields exp((1 − t) log I + t log T),
// t = k/n, each a log-Euclidean interpolation at each vertex. A mesh far coarser than its target
// (a coarse cube refined 100x near a plane, a faceted cylinder refined 100x in its normal
// direction) is then refined step by step instead of at once, where every new vertex joins
// vertices whose offsets are long in the target metric and the splits cascade in every
// direction (Omega_h approaches its target the same way). Pure.
#include <span>
#include <vector>

#include "core/symmat.hpp"

namespace riemesh {

/// The number of stages n ≥ 1 so that the input's edges, unit in I and as long as `longest` in
/// T (the longest of their metric lengths there), grow by at most `growth` from a stage to the
/// next: n = ⌈ln longest / ln growth⌉ (1 when longest ≤ growth). Throws InputError unless
/// growth > 1 and finite; a non-finite `longest` gives the most stages, 64.
int approach_stages(double longest, double growth);

template <int D>
class MetricApproach {
 public:
  /// implied_logs: log I per vertex (implied_log_metric); in_simplex: whether it is known (a
  /// vertex in no simplex goes straight to its target); target: T per vertex (SPD, copied).
  MetricApproach(std::vector<SymMat<D>>&& implied_logs, const std::vector<bool>& in_simplex,
                 std::span<const SymMat<D>> target);

  /// The field at t in [0, 1]: exp((1 − t) log I + t log T) per vertex; exactly T at t = 1.
  std::vector<SymMat<D>> field(double t) const;

 private:
  std::vector<SymMat<D>> from_, to_;  // log I, log T
  std::vector<SymMat<D>> target_;
};

extern template class MetricApproach<2>;
extern template class MetricApproach<3>;

}  // namespace riemesh
