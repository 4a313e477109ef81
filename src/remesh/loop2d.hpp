#pragma once
// The built-in adaptation loop on an analytic function (`riemesh loop`, issue #5; BOOK.md §8
// "Stationary loop" with the exact function in place of a solver): for rising target complexities
// N, a few fixed-point iterations of
//   u at the vertices → Hessian recovery → Lp-optimal metric (complexity N) → adapt2d,
// then the interpolation error of the final mesh against the exact function (L1, L2, L∞), beside
// uniform meshes of about the same vertex counts, and the fitted slopes of error against vertex
// count (optimal: N^{−2/d} = N^{−1} in 2D).
#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "metric/recovery.hpp"
#include "remesh/analytic_functions.hpp"
#include "remesh/interpolation_error.hpp"

namespace riemesh {

struct LoopOptions {
  std::vector<double> complexities = {500, 1000, 2000, 4000, 8000, 16000};  ///< rising N
  int iterations = 3;  ///< fixed-point iterations (metric, adapt) per complexity
  double norm = 2.0;   ///< p of the Lp metric
  RecoveryMethod recovery = RecoveryMethod::kLeastSquares;
  double hmin = 1e-5;  ///< sizes clipped to [hmin, hmax] (the domain is 2 wide)
  double hmax = 0.5;
  double aniso_max = std::numeric_limits<double>::infinity();  ///< largest h_max/h_min
  /// adapt2d's gradation; off by default: the Lp metric is already optimal for the function,
  /// and gradation at 1.3 roughly triples the vertex count of the steep fronts here.
  double hgrad = 0.0;
  int start_cells = 20;  ///< the first mesh: square_mesh(start_cells)
  bool uniform = true;   ///< also the uniform meshes of matching vertex counts
  /// Slopes are fitted over the steps with at least this target complexity (0: all steps);
  /// uniform meshes: over the ones matching those steps.
  double fit_from = 0.0;
  ErrorQuadrature quadrature;
  /// Throws InputError naming the option for out-of-range values.
  void validate() const;
};

/// One mesh of the table: its counts and error norms.
struct LoopStep {
  double complexity = 0;  ///< target N (adapted), or 0 for a uniform mesh
  int cells = 0;          ///< uniform meshes: cells per side (0 for adapted)
  std::size_t vertices = 0, triangles = 0;
  ErrorNorms errors;
  double metric_complexity = 0;  ///< C(M) of the last metric (adapted steps)
  bool converged = true;         ///< adapt2d converged on the last iteration
  std::string stall_reason;      ///< why it did not (adapt2d's report), empty if it did
  double seconds = 0;            ///< time for the step (adapted: all iterations)
};

/// Fitted error ∝ vertices^slope for each norm (NaN with fewer than two steps).
struct LoopSlopes {
  double l1 = std::numeric_limits<double>::quiet_NaN();
  double l2 = std::numeric_limits<double>::quiet_NaN();
  double linf = std::numeric_limits<double>::quiet_NaN();
};

struct LoopResult {
  std::vector<LoopStep> adapted, uniform;
  LoopSlopes adapted_slopes, uniform_slopes;
  Mesh final_mesh;  ///< the adapted mesh of the last complexity
};

/// Called after each step (adapted or uniform), for progress lines.
using LoopCallback = std::function<void(const LoopStep&, bool adapted)>;

/// [−1,1]² meshed as unit_square(n, n) mapped by (x, y) ↦ (2x − 1, 2y − 1): same ids, refs,
/// tags and orientation.
Mesh square_mesh(int n);

/// The slopes of each norm against the vertex counts of the steps with at least `min_vertices`
/// vertices (the asymptotic range: coarse meshes that do not resolve the fronts yet converge
/// faster than N^−1).
LoopSlopes fit_slopes(const std::vector<LoopStep>& steps, std::size_t min_vertices = 0);

/// Runs the loop on the function (deterministic). Throws InputError for bad options.
LoopResult adaptation_loop(const AnalyticFunction& f, const LoopOptions& options,
                           const LoopCallback& on_step = {});

}  // namespace riemesh
