// `riemesh demo`: a short tour of the metric toolbox on embedded inputs.
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "apps/commands.hpp"
#include "metric/gradation.hpp"
#include "metric/interpolation.hpp"
#include "metric/intersection.hpp"
#include "metric/metric.hpp"

namespace riemesh::cli {
namespace {

void interpolation_tour() {
  // Two metrics with sizes 1 x 0.01, crossed at 90 degrees: the classic anisotropy-dilution case.
  const SymMat2 a = metric_from_sizes(Mat2::identity(), Vec2{{1.0, 0.01}});
  const SymMat2 b = metric_from_sizes(Mat2{{{0.0, -1.0}, {1.0, 0.0}}}, Vec2{{1.0, 0.01}});
  std::printf("Interpolating two crossed metrics (sizes 1 x 0.01) half-way, by scheme:\n");
  std::printf("  %-20s %12s %12s %12s\n", "scheme", "h_max", "h_min", "det");
  for (InterpScheme s : {InterpScheme::kLinear, InterpScheme::kSimredLinear,
                         InterpScheme::kSimredGeometric, InterpScheme::kPower,
                         InterpScheme::kLogEuclidean, InterpScheme::kCholesky}) {
    const SymMat2 m = interpolate(s, a, b, 0.5);
    const MetricSizes<2> sz = sizes(m);
    std::printf("  %-20s %12.5g %12.5g %12.5g\n", std::string(scheme_name(s)).c_str(), sz.sizes[0],
                sz.sizes[1], det(m));
  }
  std::printf("  (det at the ends: %.5g; schemes with the maximum principle stay at it)\n\n",
              det(a));
}

Mat2 rotation(double degrees) {
  const double a = degrees * std::numbers::pi / 180.0, c = std::cos(a), s = std::sin(a);
  return Mat2{{{c, -s}, {s, c}}};
}

void intersection_tour() {
  // Three anisotropic metrics at 0, 50 and 110 degrees: sequential intersection depends on
  // the order, the maximal-volume intersection does not.
  const std::array<SymMat2, 3> ms = {metric_from_sizes(rotation(0), Vec2{{1.0, 0.1}}),
                                     metric_from_sizes(rotation(50), Vec2{{0.5, 0.05}}),
                                     metric_from_sizes(rotation(110), Vec2{{1.0, 0.2}})};
  const std::array<SymMat2, 3> reversed = {ms[2], ms[1], ms[0]};
  const std::array<SymMat2, 3> swapped = {ms[0], ms[2], ms[1]};
  std::printf("Intersecting three metrics (1 x 0.1 at 0, 0.5 x 0.05 at 50, 1 x 0.2 at 110 degrees):\n");
  std::printf("  sequential, order 1 2 3   det %.6g\n", det(intersect_sequential<2>(ms)));
  std::printf("  sequential, order 1 3 2   det %.6g\n", det(intersect_sequential<2>(swapped)));
  std::printf("  maximal volume, any order det %.6g  (smallest det = largest unit ball)\n\n",
              det(intersect_max_volume<2>(reversed)));
}

void gradation_tour() {
  // A chain of 11 vertices on [0, 1]; a size of 0.02 at x = 0.5 and 0.5 elsewhere.
  const int n = 11;
  std::vector<double> coords;
  std::vector<int32_t> edges;
  std::vector<SymMat2> metrics;
  for (int i = 0; i < n; ++i) {
    coords.push_back(i / double(n - 1));
    coords.push_back(0.0);
    metrics.push_back(isotropic_metric<2>(i == n / 2 ? 0.02 : 0.5));
    if (i > 0) edges.insert(edges.end(), {i - 1, i});
  }
  GradationOptions opt;
  opt.mode = GradationMode::kHShock;
  opt.threshold = 1.3;
  const GradationReport r = gradate<2>(coords, edges, metrics, opt);
  std::printf("Gradation (H-shock, beta = 1.3) on a chain with a 25x size jump:\n");
  std::printf("  max H-shock %.4g -> %.4g in %d passes (%zu vertices changed)\n  sizes:",
              r.measure_before, r.measure_after, r.passes, r.modified_vertices);
  for (const SymMat2& m : metrics) std::printf(" %.3g", 1.0 / std::sqrt(m.c[0]));
  std::printf("\n");
}

}  // namespace

void register_demo(CLI::App& app) {
  auto* demo = app.add_subcommand("demo", "A short tour of the metric toolbox on embedded inputs");
  demo->callback([] {
    std::printf("Riemesh demo: the metric toolbox (remeshing arrives with issue #4).\n\n");
    interpolation_tour();
    intersection_tour();
    gradation_tour();
  });
}

}  // namespace riemesh::cli
