// `riemesh unsteady`: the unsteady fixed-point loop of BOOK.md §8 on an analytic moving front
// (remesh/unsteady2d.hpp): per mean complexity N̄, the space–time error and vertex counts with
// n sub-intervals and with one mesh for all time, and the fitted slopes.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/parse.hpp"
#include "core/error.hpp"
#include "remesh/unsteady2d.hpp"

namespace riemesh::cli {
namespace {

struct UnsteadyArgs {
  std::string function = "tanh-front", complexities = "1000,2000,4000,8000";
  std::string combine = "lp", time = "max", recovery = "lsq";
  bool json = false, no_single = false;
  UnsteadyOptions opt;
  const CLI::Option* time_given = nullptr;
};

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void print_step(const UnsteadyStep& s) {
  std::string note;
  if (!s.converged) {
    note = " (adapt2d did not converge: ";
    note += s.stall_reason;
    note += ")";
  }
  std::printf("  %8.0f %9d %10.0f %10zu %10zu %9.0f %11.4e %7.2fs%s\n", s.complexity, s.intervals,
              s.mean_vertices, s.total_vertices, s.max_vertices, s.metric_complexity, s.error,
              s.seconds, note.c_str());
  std::fflush(stdout);
}

std::string json_steps(const std::vector<UnsteadyStep>& steps) {
  std::string o = "[";
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const UnsteadyStep& s = steps[i];
    if (i) o += ", ";
    o += "{\"complexity\": " + json_number(s.complexity);
    o += ", \"intervals\": " + std::to_string(s.intervals);
    o += ", \"mean_vertices\": " + json_number(s.mean_vertices);
    o += ", \"total_vertices\": " + std::to_string(s.total_vertices);
    o += ", \"max_vertices\": " + std::to_string(s.max_vertices);
    o += ", \"metric_complexity\": " + json_number(s.metric_complexity);
    o += ", \"error\": " + json_number(s.error);
    o += s.converged ? ", \"converged\": true" : ", \"converged\": false";
    o += ", \"seconds\": " + json_number(s.seconds);
    o += "}";
  }
  return o + "]";
}

void run(UnsteadyArgs& a) {
  const MovingFunction& f = moving_function(a.function);
  a.opt.complexities = parse_numbers(a.complexities, "--complexities");
  a.opt.recovery = parse_recovery_method(a.recovery);
  if (a.combine == "lp") a.opt.combine = UnsteadyCombine::kLp;
  else if (a.combine == "intersect") a.opt.combine = UnsteadyCombine::kIntersect;
  else throw InputError("--combine must be lp or intersect, got '" + a.combine + "'");
  if (a.time == "max") a.opt.time = TimeCombination::kMax;
  else if (a.time == "integral") a.opt.time = TimeCombination::kIntegral;
  else throw InputError("--time must be max or integral, got '" + a.time + "'");
  if (a.opt.combine == UnsteadyCombine::kIntersect && a.time_given->count() > 0)
    throw InputError("--time applies to --combine lp (intersect takes every sample's metric)");
  a.opt.single = !a.no_single;
  a.opt.validate();
  UnsteadyCallback on_step;
  if (!a.json) {
    std::printf("riemesh unsteady: %s, u = %s\n", std::string(f.name).c_str(),
                std::string(f.formula).c_str());
    std::printf("%d sub-intervals of [0, 1], %d Hessian samples each, %d fixed-point "
                "iterations, %s metric (L%g%s), sizes in [%g, %g]\n",
                a.opt.intervals, a.opt.samples, a.opt.iterations,
                a.opt.combine == UnsteadyCombine::kLp ? "space-time Lp" : "intersected Lp",
                a.opt.norm,
                a.opt.combine == UnsteadyCombine::kLp
                    ? (a.opt.time == TimeCombination::kMax ? ", max in time" : ", integral in time")
                    : "",
                a.opt.hmin, a.opt.hmax);
    std::printf("  error: max over t of the L2 interpolation error, at the samples and between "
                "them\n");
    std::printf("  %8s %9s %10s %10s %10s %9s %11s %7s\n", "N", "intervals", "mean verts",
                "total", "max verts", "C(M)", "L2 error", "time");
    on_step = print_step;
  }
  const UnsteadyResult r = unsteady_loop(f, a.opt, on_step);
  if (a.json) {
    std::string o = "{\"function\": \"";
    o += f.name;
    o += "\", \"intervals\": " + std::to_string(a.opt.intervals);
    o += ", \"combine\": \"" + a.combine + "\", \"multi\": " + json_steps(r.multi);
    o += ", \"single\": " + json_steps(r.single);
    o += ", \"slopes\": {\"multi\": " + json_number(r.multi_slope);
    o += ", \"single\": " + json_number(r.single_slope) + "}}\n";
    std::fputs(o.c_str(), stdout);
    return;
  }
  std::printf("  fitted slope (error ∝ mean vertices^s): %d intervals %.3f", a.opt.intervals,
              r.multi_slope);
  if (!r.single.empty()) std::printf(", one mesh %.3f", r.single_slope);
  std::printf("\n");
}

}  // namespace

void register_unsteady(CLI::App& app) {
  auto a = std::make_shared<UnsteadyArgs>();
  std::string names;
  for (const MovingFunction& f : moving_functions()) {
    if (!names.empty()) names += ", ";
    names += f.name;
  }
  auto* cmd = app.add_subcommand(
      "unsteady", "Unsteady adaptation on a moving front of [-1,1]² x [0,1]: one mesh per "
                  "time sub-interval, fixed-point loop, space-time error against vertices");
  cmd->add_option("--function", a->function, "Moving field: " + names)->capture_default_str();
  cmd->add_option("--complexities", a->complexities,
                  "Mean complexities N per time step, rising (comma list)")
      ->capture_default_str();
  cmd->add_option("--intervals", a->opt.intervals, "Sub-intervals of [0, 1]")->capture_default_str();
  cmd->add_option("--samples", a->opt.samples, "Hessian samples per sub-interval (ends included)")
      ->capture_default_str();
  cmd->add_option("--iterations", a->opt.iterations, "Fixed-point iterations per N")
      ->capture_default_str();
  cmd->add_option("--combine", a->combine,
                  "lp: space-time Lp metric normalised over all sub-intervals; intersect: the "
                  "samples' Lp metrics (each for N) intersected")
      ->capture_default_str();
  a->time_given =
      cmd->add_option("--time", a->time, "lp: samples combined by max (intersection) or integral")
          ->capture_default_str();
  cmd->add_option("--norm", a->opt.norm, "p of the Lp metric")->capture_default_str();
  cmd->add_option("--recovery", a->recovery, "Hessian recovery: lsq, l2 or green")
      ->capture_default_str();
  cmd->add_option("--hmin", a->opt.hmin, "Smallest size")->capture_default_str();
  cmd->add_option("--hmax", a->opt.hmax, "Largest size")->capture_default_str();
  cmd->add_flag("--no-single", a->no_single, "Skip the one-mesh-for-all-time comparison");
  cmd->add_flag("--json", a->json, "Print one JSON object (multi, single, slopes)");
  cmd->footer(
      "Each sub-interval i of length dt has its own mesh. Per fixed-point iteration, the Hessians "
      "of u(., t_k) are recovered on mesh i at the samples t_k and combined: --combine lp builds "
      "H_i = dt * intersection_k |H(t_k)| (--time max) or the trapezoid integral of |H| "
      "(--time integral), then the space-time Lp metric "
      "M_i = N_st^(2/d) (sum_j n_j^(2p/(2p+d)) int det(H_j)^(p/(2p+d)))^(-2/d) "
      "n_i^(-2/(2p+d)) det(H_i)^(-1/(2p+d)) H_i with N_st = N * sum_j n_j (n_j: time steps, "
      "here dt); every mesh is then adapted. The error is the largest L2 interpolation error "
      "over the samples and the midpoints between them.");
  cmd->callback([a] { run(*a); });
}

}  // namespace riemesh::cli
