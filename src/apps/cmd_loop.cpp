// `riemesh loop`: the built-in adaptation loop on an analytic function (issue #5): a table of
// vertices, elements and interpolation errors per target complexity, the fitted slopes, and
// (--plot) a log-log picture of the errors, adapted beside uniform.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/parse.hpp"
#include "core/error.hpp"
#include "remesh/loop2d.hpp"
#include "render/line_plot.hpp"

namespace riemesh::cli {
namespace {

struct LoopArgs {
  std::string function = "tanh", complexities = "500,1000,2000,4000,8000,16000", plot;
  std::string recovery = "lsq";
  bool json = false, uniform = false;
  LoopOptions opt;
};

void print_header(bool adapted) {
  std::printf("  %8s %9s %9s %11s %11s %11s %9s %7s\n", adapted ? "N" : "cells", "vertices",
              "triangles", "L1", "L2", "Linf", adapted ? "C(M)" : "", "time");
}

void print_step(const LoopStep& s, bool adapted) {
  const std::string n = adapted ? std::to_string(static_cast<long>(s.complexity))
                                : std::to_string(s.cells) + "x" + std::to_string(s.cells);
  const std::string c = adapted ? std::to_string(std::lround(s.metric_complexity)) : "";
  std::string note;
  if (!s.converged) {
    note = " (adapt2d did not converge: ";
    note += s.stall_reason;
    note += ")";
  }
  std::printf("  %8s %9zu %9zu %11.4e %11.4e %11.4e %9s %6.2fs%s\n", n.c_str(), s.vertices,
              s.triangles, s.errors.l1, s.errors.l2, s.errors.linf, c.c_str(), s.seconds,
              note.c_str());
  std::fflush(stdout);
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

void print_slopes(const char* what, const LoopSlopes& s, double fit_from) {
  std::string range;
  if (fit_from > 0) {
    range = ", N >= ";
    range += json_number(fit_from);
  }
  std::printf("  fitted slope, %s (error ∝ vertices^s%s): L1 %.3f  L2 %.3f  Linf %.3f\n", what,
              range.c_str(), s.l1, s.l2, s.linf);
}

std::string json_steps(const std::vector<LoopStep>& steps, bool adapted) {
  std::string o = "[";
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const LoopStep& s = steps[i];
    if (i) o += ", ";
    o += "{";
    if (adapted) {
      o += "\"complexity\": " + json_number(s.complexity);
      o += ", \"metric_complexity\": " + json_number(s.metric_complexity);
      o += s.converged ? ", \"converged\": true" : ", \"converged\": false";
    } else {
      o += "\"cells\": " + std::to_string(s.cells);
    }
    o += ", \"vertices\": " + std::to_string(s.vertices);
    o += ", \"triangles\": " + std::to_string(s.triangles);
    o += ", \"l1\": " + json_number(s.errors.l1);
    o += ", \"l2\": " + json_number(s.errors.l2);
    o += ", \"linf\": " + json_number(s.errors.linf);
    o += ", \"seconds\": " + json_number(s.seconds);
    o += "}";
  }
  o += "]";
  return o;
}

std::string json_slopes(const LoopSlopes& s) {
  std::string o = "{\"l1\": ";
  o += json_number(s.l1);
  o += ", \"l2\": ";
  o += json_number(s.l2);
  o += ", \"linf\": ";
  o += json_number(s.linf);
  o += "}";
  return o;
}

std::string to_json(const AnalyticFunction& f, const LoopArgs& a, const LoopResult& r) {
  std::string o = "{\"function\": \"";
  o += f.name;
  o += "\", \"formula\": \"";
  o += f.formula;
  o += "\", \"norm\": ";
  o += json_number(a.opt.norm);
  o += ", \"iterations\": ";
  o += std::to_string(a.opt.iterations);
  o += ", \"fit_from\": ";
  o += json_number(a.opt.fit_from);
  o += ", \"adapted\": ";
  o += json_steps(r.adapted, true);
  o += ", \"uniform\": ";
  o += json_steps(r.uniform, false);
  o += ", \"slopes\": {\"adapted\": ";
  o += json_slopes(r.adapted_slopes);
  o += ", \"uniform\": ";
  o += json_slopes(r.uniform_slopes);
  o += "}}\n";
  return o;
}

/// L2 errors against vertex counts, adapted (solid) and uniform (dashed), slopes in the legend.
void write_plot(const AnalyticFunction& f, const LoopArgs& a, const LoopResult& r) {
  LogLogPlot p;
  p.title = "riemesh loop: ";
  p.title += f.name;
  p.title += ", L";
  p.title += json_number(a.opt.norm);
  p.title += " metric";
  if (a.opt.fit_from > 0) {
    p.title += ", slopes for N >= ";
    p.title += json_number(a.opt.fit_from);
  }
  p.x_label = "vertices";
  p.y_label = "interpolation error";
  auto add = [&p](const std::vector<LoopStep>& steps, const LoopSlopes& s, bool adapted) {
    const char* kind = adapted ? "adapted" : "uniform";
    const char* names[3] = {"L1", "L2", "Linf"};
    const double slopes[3] = {s.l1, s.l2, s.linf};
    for (int k = 0; k < 3; ++k) {
      PlotSeries ps;
      char label[96];
      std::snprintf(label, sizeof label, "%s %s, slope %.2f", kind, names[k], slopes[k]);
      ps.label = label;
      for (const LoopStep& st : steps) {
        ps.x.push_back(static_cast<double>(st.vertices));
        ps.y.push_back(k == 0 ? st.errors.l1 : k == 1 ? st.errors.l2 : st.errors.linf);
      }
      ps.color = k;
      ps.dashed = !adapted;
      p.series.push_back(ps);
    }
  };
  add(r.adapted, r.adapted_slopes, true);
  // The optimal rate, N^−1, through the first adapted L2 error.
  if (r.adapted.size() >= 2) {
    const double x0 = static_cast<double>(r.adapted.front().vertices);
    const double x1 = static_cast<double>(r.adapted.back().vertices);
    const double y0 = r.adapted.front().errors.l2;
    p.series.push_back({"slope -1 (optimal)", {x0, x1}, {y0, y0 * x0 / x1}, 7, true});
  }
  if (!r.uniform.empty()) add(r.uniform, r.uniform_slopes, false);
  plot_loglog(p, a.plot);
}

void run(LoopArgs& a) {
  const AnalyticFunction& f = analytic_function(a.function);
  a.opt.complexities = parse_numbers(a.complexities, "--complexities");
  a.opt.recovery = parse_recovery_method(a.recovery);
  a.opt.uniform = a.uniform || !a.plot.empty();
  a.opt.validate();
  if (!a.plot.empty()) require_image_output(a.plot);  // before the loop, not after
  LoopCallback on_step;
  bool uniform_header = false;
  if (!a.json) {
    std::printf("riemesh loop: %s, u = %s\n", std::string(f.name).c_str(),
                std::string(f.formula).c_str());
    std::printf("adapted: L%g metric, %s recovery, %d iterations per complexity N, sizes in "
                "[%g, %g], hgrad %g\n",
                a.opt.norm, a.recovery.c_str(), a.opt.iterations, a.opt.hmin, a.opt.hmax,
                a.opt.hgrad);
    print_header(true);
    on_step = [&uniform_header](const LoopStep& s, bool adapted) {
      if (!adapted && !uniform_header) {
        std::printf("uniform: [-1,1]² in n x n squares cut in two\n");
        print_header(false);
        uniform_header = true;
      }
      print_step(s, adapted);
    };
  }
  const LoopResult r = adaptation_loop(f, a.opt, on_step);
  if (!a.plot.empty()) write_plot(f, a, r);
  if (a.json) {
    std::fputs(to_json(f, a, r).c_str(), stdout);
    return;
  }
  print_slopes("adapted", r.adapted_slopes, a.opt.fit_from);
  if (!r.uniform.empty()) print_slopes("uniform", r.uniform_slopes, a.opt.fit_from);
  if (!a.plot.empty()) std::printf("wrote %s\n", a.plot.c_str());
}

}  // namespace

void register_loop(CLI::App& app) {
  auto a = std::make_shared<LoopArgs>();
  std::string names;
  for (const AnalyticFunction& f : analytic_functions()) {
    if (!names.empty()) names += ", ";
    names += f.name;
  }
  auto* cmd = app.add_subcommand(
      "loop", "Adaptation loop on an analytic function of [-1,1]²: metric from the recovered "
              "Hessian, adapt, repeat at rising complexities; interpolation errors and slopes");
  cmd->add_option("--function", a->function, "Test function: " + names)->capture_default_str();
  cmd->add_option("--norm", a->opt.norm, "p of the Lp-optimal metric (>= 1)")->capture_default_str();
  cmd->add_option("--complexities", a->complexities, "Target complexities N, rising (comma list)")
      ->capture_default_str();
  cmd->add_option("--iterations", a->opt.iterations, "Fixed-point iterations per complexity")
      ->capture_default_str();
  cmd->add_option("--recovery", a->recovery, "Hessian recovery: lsq, l2 or green")
      ->capture_default_str();
  cmd->add_option("--hmin", a->opt.hmin, "Smallest size")->capture_default_str();
  cmd->add_option("--hmax", a->opt.hmax, "Largest size")->capture_default_str();
  cmd->add_option("--aniso-max", a->opt.aniso_max, "Largest anisotropy ratio h_max/h_min");
  cmd->add_option("--hgrad", a->opt.hgrad, "Gradation of adapt (0: off)")->capture_default_str();
  cmd->add_option("--fit-from", a->opt.fit_from,
                  "Fit the slopes over the steps with N >= this (0: all; the coarsest meshes do "
                  "not resolve the fronts yet)")
      ->capture_default_str();
  cmd->add_flag("--uniform", a->uniform, "Also uniform meshes of matching vertex counts");
  cmd->add_option("--plot", a->plot, "Write the errors against vertices, log-log (.png or .svg; "
                                     "implies --uniform)");
  cmd->add_flag("--json", a->json, "Print one JSON object (keys function, formula, norm, "
                                   "iterations, adapted, uniform, slopes)");
  cmd->callback([a] { run(*a); });
}

}  // namespace riemesh::cli
