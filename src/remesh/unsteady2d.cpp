#include "remesh/unsteady2d.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "metric/hessian_metric.hpp"
#include "remesh/adapt2d.hpp"
#include "remesh/loop2d.hpp"

namespace riemesh {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A straight front of width ~1/20 normal to (cos 30°, sin 30°), crossing the square at constant
// speed: its position s(t) = −0.6 + 1.2t sweeps most of the square, so one mesh for all time
// must refine the whole band it sweeps. (Samples must follow the front closely enough that
// consecutive sample fronts' refined bands touch: a few per front width of travel.)
double tanh_front(double x, double y, double t) {
  const double c = std::cos(kPi / 6.0), s = std::sin(kPi / 6.0);
  return std::tanh(20.0 * (c * x + s * y - (-0.6 + 1.2 * t)));
}

// A disc of radius 0.3 with a tanh rim whose centre goes once round the circle of radius 0.5.
double moving_circle(double x, double y, double t) {
  const double cx = 0.5 * std::cos(2.0 * kPi * t), cy = 0.5 * std::sin(2.0 * kPi * t);
  return std::tanh(30.0 * (std::hypot(x - cx, y - cy) - 0.3));
}

constexpr std::array<MovingFunction, 2> kMoving = {{
    {"tanh-front", "tanh(20 (x cos30 + y sin30 - (1.2 t - 0.6))), t in [0, 1]", tanh_front},
    {"moving-circle",
     "tanh(30 (|(x, y) - 0.5 (cos 2 pi t, sin 2 pi t)| - 0.3)), t in [0, 1]", moving_circle},
}};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// K sample times of [a, b]: equally spaced with the ends, or the midpoint for K = 1.
std::vector<double> sample_times(double a, double b, int k) {
  if (k == 1) return {0.5 * (a + b)};
  std::vector<double> t(static_cast<std::size_t>(k));
  for (int j = 0; j < k; ++j) t[static_cast<std::size_t>(j)] = a + (b - a) * j / (k - 1.0);
  return t;
}

std::vector<SymMat2> hessians_at(const Mesh& m, const MovingFunction& f, double t,
                                 RecoveryMethod method) {
  std::vector<double> u(m.num_vertices());
  for (std::size_t v = 0; v < u.size(); ++v) u[v] = f.value(m.coords[2 * v], m.coords[2 * v + 1], t);
  return recover_hessian<2>(m, u, method);
}

HessianMetricOptions metric_options(const UnsteadyOptions& o, double complexity) {
  HessianMetricOptions h;
  h.norm = o.norm;
  h.complexity = complexity;
  h.hmin = o.hmin;
  h.hmax = o.hmax;
  return h;
}

/// One fixed-point iteration: the metric of every sub-interval on its current mesh.
std::vector<std::vector<SymMat2>> interval_metrics(const MovingFunction& f, double complexity,
                                                   const UnsteadyOptions& o,
                                                   const std::vector<Mesh>& meshes,
                                                   double& mean_complexity) {
  const auto n = meshes.size();
  const double dt = 1.0 / static_cast<double>(n);
  std::vector<std::vector<SymMat2>> out(n), combined(n);
  std::vector<MetricReport> reports(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::vector<SymMat2>> samples;
    for (double t : sample_times(dt * i, dt * (i + 1), o.samples))
      samples.push_back(hessians_at(meshes[i], f, t, o.recovery));
    if (o.combine == UnsteadyCombine::kIntersect) {
      std::vector<std::vector<SymMat2>> metrics;
      for (const auto& h : samples)
        metrics.push_back(hessian_metric<2>(meshes[i], h, metric_options(o, complexity)));
      out[i] = combine_metrics<2>(metrics);
      reports[i] = metric_report<2>(meshes[i], out[i]);
    } else {
      combined[i] = combine_in_time<2>(samples, dt, o.time);
    }
  }
  if (o.combine == UnsteadyCombine::kLp) {
    std::vector<SpaceTimeInterval<2>> st(n);
    for (std::size_t i = 0; i < n; ++i) st[i] = {&meshes[i], combined[i], dt};
    out = spacetime_lp_metrics<2>(st, metric_options(o, complexity), &reports);
  }
  mean_complexity = 0.0;
  for (const MetricReport& r : reports) mean_complexity += r.complexity / static_cast<double>(n);
  return out;
}

}  // namespace

std::span<const MovingFunction> moving_functions() { return kMoving; }

const MovingFunction& moving_function(std::string_view name) {
  std::string names;
  for (const MovingFunction& f : kMoving) {
    if (f.name == name) return f;
    if (!names.empty()) names += ", ";
    names += f.name;
  }
  std::string msg = "unknown moving function '";
  msg += name;
  msg += "' (expected one of: ";
  msg += names;
  msg += ")";
  throw InputError(msg);
}

void UnsteadyOptions::validate() const {
  if (complexities.empty()) throw InputError("unsteady: no complexity given");
  for (double n : complexities)
    if (!(n >= 10.0 && n <= 1e7))
      throw InputError("unsteady: complexities must be in 10..1e7, got " + std::to_string(n));
  if (intervals < 1 || intervals > 1000)
    throw InputError("unsteady: --intervals must be in 1..1000");
  if (samples < 1 || samples > 100) throw InputError("unsteady: --samples must be in 1..100");
  if (iterations < 1 || iterations > 20)
    throw InputError("unsteady: --iterations must be in 1..20");
  if (!(norm >= 1.0) || !std::isfinite(norm))
    throw InputError("unsteady: the norm p must be finite and >= 1");
  if (!(hmin > 0.0) || !(hmax > hmin) || !std::isfinite(hmax))
    throw InputError("unsteady: sizes need 0 < hmin < hmax < inf");
  if (start_cells < 2 || start_cells > 1000)
    throw InputError("unsteady: start_cells must be in 2..1000");
}

UnsteadyStep unsteady_run(const MovingFunction& f, double complexity, int intervals,
                          const UnsteadyOptions& o, std::vector<Mesh>& meshes) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto n = static_cast<std::size_t>(intervals);
  if (meshes.size() != n) meshes.assign(n, square_mesh(o.start_cells));
  UnsteadyStep s;
  s.complexity = complexity;
  s.intervals = intervals;
  Adapt2dOptions ao;
  ao.hmin = o.hmin;
  ao.hmax = o.hmax;
  ao.hgrad = 0.0;  // as riemesh loop: the Lp metric is already the optimum for the field
  for (int it = 0; it < o.iterations; ++it) {
    const std::vector<std::vector<SymMat2>> metrics =
        interval_metrics(f, complexity, o, meshes, s.metric_complexity);
    s.converged = true;
    s.stall_reason.clear();
    for (std::size_t i = 0; i < n; ++i) {
      Adapt2dResult a = adapt2d(meshes[i], metrics[i], ao);
      if (!a.report.converged && s.converged) {
        s.converged = false;
        s.stall_reason = "sub-interval " + std::to_string(i + 1) + ": " + a.report.stall_reason;
      }
      meshes[i] = std::move(a.mesh);
    }
  }
  // Error times: the samples and the midpoints between them (ends of every interval included).
  const double dt = 1.0 / static_cast<double>(n);
  const int error_points = 2 * std::max(o.samples - 1, 1) + 1;
  for (std::size_t i = 0; i < n; ++i) {
    for (double t : sample_times(dt * i, dt * (i + 1), error_points)) {
      const ErrorNorms e = interpolation_error(
          meshes[i], [&f, t](Vec2 p) { return f.value(p[0], p[1], t); }, o.quadrature);
      s.error = std::max(s.error, e.l2);
    }
    const std::size_t v = meshes[i].num_vertices();
    s.total_vertices += v;
    s.max_vertices = std::max(s.max_vertices, v);
    s.mean_vertices += static_cast<double>(v) / static_cast<double>(n);
  }
  s.seconds = seconds_since(t0);
  return s;
}

UnsteadyResult unsteady_loop(const MovingFunction& f, const UnsteadyOptions& o,
                             const UnsteadyCallback& on_step) {
  o.validate();
  UnsteadyResult r;
  auto run_all = [&](int intervals, std::vector<UnsteadyStep>& steps) {
    std::vector<Mesh> meshes;
    for (double n : o.complexities) {
      steps.push_back(unsteady_run(f, n, intervals, o, meshes));
      if (on_step) on_step(steps.back());
    }
  };
  auto slope = [](const std::vector<UnsteadyStep>& steps) {
    if (steps.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    std::vector<double> x, y;
    for (const UnsteadyStep& s : steps) x.push_back(s.mean_vertices), y.push_back(s.error);
    return fit_power_law(x, y).slope;
  };
  run_all(o.intervals, r.multi);
  r.multi_slope = slope(r.multi);
  if (o.single && o.intervals > 1) {
    // The same sample times (hence the same time resolution) for the one mesh of [0, 1].
    UnsteadyOptions one = o;
    one.samples = o.intervals * std::max(o.samples - 1, 1) + (o.samples > 1 ? 1 : 0);
    auto single_all = [&](std::vector<UnsteadyStep>& steps) {
      std::vector<Mesh> meshes;
      for (double n : o.complexities) {
        steps.push_back(unsteady_run(f, n, 1, one, meshes));
        if (on_step) on_step(steps.back());
      }
    };
    single_all(r.single);
    r.single_slope = slope(r.single);
  }
  return r;
}

}  // namespace riemesh
