// `riemesh demo`: the main job on an embedded input: a square meshed 20 x 20 adapted, pass after
// pass, to the analytic polar-2 metric of the UGAWG benchmark; then a short tour of the metric
// toolbox. Writes riemesh-demo/square.mesh, .sol and .png in the working folder.
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "io/medit.hpp"
#include "io/sol.hpp"
#include "mesh/fixtures.hpp"
#include "metric/analytic.hpp"
#include "metric/interpolation.hpp"
#include "metric/intersection.hpp"
#include "metric/metric.hpp"
#include "remesh/adapt2d.hpp"
#include "render/render.hpp"

namespace riemesh::cli {
namespace {

/// The demo's folder, made before the demo runs: a file, an empty name or a path that cannot
/// be made is bad input named here (it was an internal error after the whole demo had run).
void make_folder(const std::string& dir) {
  if (dir.empty()) throw InputError("--dir: empty folder name");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir, ec))
    throw InputError(dir + ": cannot make the demo's folder" + (ec ? ": " + ec.message() : ""));
}

void adaptation_demo(const std::string& dir) {
  make_folder(dir);
  const AnalyticCase c{AnalyticField::kPolar2, 0.004};
  std::printf("Adapting the unit square (20 x 20 cells) to the polar-2 metric (sizes 0.004 to 0.1,\n"
              "anisotropy up to 25), re-evaluating the metric after each run as the UGAWG\n"
              "benchmark does:\n");
  Mesh m = unit_square(20, 20);
  Adapt2dOptions o;
  o.hgrad = 0.0;  // the analytic field is prescribed exactly
  for (int run = 1; run <= 4; ++run) {
    const Adapt2dResult r = adapt2d(m, analytic_metrics(c, m), o);
    const PassStats& s = r.report.passes.back();
    std::printf("  run %d: %6zu vertices %6zu triangles, %5.1f%% of edges of metric length in "
                "[1/√2, √2], quality min %.2f mean %.3f (%zu passes)\n",
                run, s.vertices, s.triangles, 100.0 * s.len_in, s.q_min, s.q_mean,
                r.report.passes.size());
    m = r.mesh;
  }
  write_medit(m, dir + "/square.mesh");
  Field f{"metric", FieldKind::kSymTensor, {}};
  for (const SymMat2& x : analytic_metrics(c, m)) f.values.insert(f.values.end(), {x.c[0], x.c[1], x.c[2]});
  write_sol(dir + "/square.sol", {f}, 2);
  RenderOptions ro;
  ro.title = "riemesh demo: polar-2 metric";
  ro.metric = f.values;
  render_mesh(m, dir + "/square.png", ro);
  std::printf("  wrote %s/square.mesh, square.sol and square.png\n\n", dir.c_str());
}

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
  std::printf("  maximal volume, any order det %.6g  (smallest det = largest unit ball)\n",
              det(intersect_max_volume<2>(reversed)));
}

}  // namespace

void register_demo(CLI::App& app) {
  auto* demo = app.add_subcommand(
      "demo", "Adapt an embedded square mesh to an analytic anisotropic metric, then a tour of "
              "the metric toolbox");
  auto dir = std::make_shared<std::string>("riemesh-demo");
  demo->add_option("--dir", *dir, "Folder for the demo's output files")->capture_default_str();
  demo->callback([dir] {
    adaptation_demo(*dir);
    interpolation_tour();
    intersection_tour();
  });
}

}  // namespace riemesh::cli
