#pragma once
// The built-in unsteady adaptation loop (`riemesh unsteady`, issue #5; BOOK.md §8 "Unsteady"),
// with an analytic moving field in place of a solver: [0, 1] is split into n sub-intervals, each
// with its own mesh, and a fixed-point loop over the whole time span repeats
//   for every sub-interval: Hessians of u(·, t_k) at K samples t_k of the interval, on its mesh
//   → one metric per sub-interval (intersection of the samples' Lp metrics, or the space–time
//     Lp metric of metric/spacetime_metric.hpp, normalised over all sub-intervals at once)
//   → adapt2d of every sub-interval's mesh.
// The error is the space–time interpolation error max_t ‖u(·,t) − Π_{h_i} u(·,t)‖_L2 over times
// at the samples and between them (each sub-interval's mesh at its own times), set against the
// mean vertex count per time step (equal steps: the mean over the sub-intervals).
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/mesh.hpp"
#include "metric/recovery.hpp"
#include "metric/spacetime_metric.hpp"
#include "remesh/interpolation_error.hpp"

namespace riemesh {

/// A field of [−1,1]² × [0, 1].
struct MovingFunction {
  std::string_view name;
  std::string_view formula;
  double (*value)(double x, double y, double t);
};

/// The built-in moving fields: "tanh-front" (a straight tanh front crossing the square) and
/// "rotating-front" (a curved front turning about the centre).
std::span<const MovingFunction> moving_functions();
/// The field of that name; InputError listing the names otherwise.
const MovingFunction& moving_function(std::string_view name);

enum class UnsteadyCombine {
  kIntersect,  ///< each sample's Lp metric for N̄, intersected over the sub-interval's samples
  kLp,         ///< the space–time Lp metric (global normalisation to the mean complexity N̄)
};

struct UnsteadyOptions {
  std::vector<double> complexities = {1000, 2000, 4000, 8000};  ///< mean complexities N̄
  int intervals = 4;   ///< sub-intervals of [0, 1]
  int samples = 5;     ///< Hessian samples per sub-interval (equally spaced, ends included)
  int iterations = 3;  ///< fixed-point iterations over the whole time span per N̄
  UnsteadyCombine combine = UnsteadyCombine::kLp;
  TimeCombination time = TimeCombination::kMax;  ///< for kLp: how samples make H_i
  double norm = 2.0;
  RecoveryMethod recovery = RecoveryMethod::kLeastSquares;
  double hmin = 1e-4;
  double hmax = 0.5;
  int start_cells = 20;  ///< every sub-interval starts from square_mesh(start_cells)
  bool single = true;    ///< also one mesh for the whole time span (n = 1) at each N̄
  ErrorQuadrature quadrature{1, 4};
  /// Throws InputError naming the option for out-of-range values.
  void validate() const;
};

/// One run: a mean complexity and a number of sub-intervals.
struct UnsteadyStep {
  double complexity = 0;  ///< N̄
  int intervals = 0;
  double mean_vertices = 0;  ///< Σ n_i V_i / Σ n_i (equal steps: the mean over the meshes)
  std::size_t total_vertices = 0, max_vertices = 0;
  double metric_complexity = 0;  ///< Σ n_i C(M_i) / Σ n_i of the last metrics
  double error = 0;              ///< max over the error times of the L2 interpolation error
  bool converged = true;         ///< every adapt2d of the last iteration converged
  std::string stall_reason;      ///< the first one that did not, with its sub-interval
  double seconds = 0;
};

struct UnsteadyResult {
  std::vector<UnsteadyStep> multi, single;  ///< n = options.intervals, and n = 1
  /// Fitted error ∝ mean_vertices^slope (NaN with fewer than two steps).
  double multi_slope = std::numeric_limits<double>::quiet_NaN();
  double single_slope = std::numeric_limits<double>::quiet_NaN();
};

using UnsteadyCallback = std::function<void(const UnsteadyStep&)>;

/// The fixed-point loop for one N̄ and n sub-intervals, from `meshes` (n meshes; empty: the
/// start meshes), which receive the adapted meshes. Deterministic.
UnsteadyStep unsteady_run(const MovingFunction& f, double complexity, int intervals,
                          const UnsteadyOptions& options, std::vector<Mesh>& meshes);

/// unsteady_run at every N̄ (each from the previous meshes), for options.intervals and, with
/// options.single, for one interval sampled at the same times (n (K − 1) + 1 samples). Throws
/// InputError for bad options.
UnsteadyResult unsteady_loop(const MovingFunction& f, const UnsteadyOptions& options,
                             const UnsteadyCallback& on_step = {});

}  // namespace riemesh
