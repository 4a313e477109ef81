#include "remesh/loop2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/format.hpp"
#include "mesh/fixtures.hpp"
#include "metric/hessian_metric.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::vector<double> vertex_values(const Mesh& m, const AnalyticFunction& f) {
  std::vector<double> u(m.num_vertices());
  for (std::size_t v = 0; v < u.size(); ++v) u[v] = f.value(m.coords[2 * v], m.coords[2 * v + 1]);
  return u;
}

ErrorNorms errors_of(const Mesh& m, const AnalyticFunction& f, const ErrorQuadrature& q) {
  return interpolation_error(m, [&f](Vec2 p) { return f.value(p[0], p[1]); }, q);
}

/// One fixed-point iteration: the metric of u's recovered Hessian on m, and m adapted to it.
Adapt2dResult adapt_once(const Mesh& m, const AnalyticFunction& f, double complexity,
                         const LoopOptions& o, MetricReport& report) {
  const std::vector<double> u = vertex_values(m, f);
  const std::vector<SymMat2> hessians = recover_hessian<2>(m, u, o.recovery);
  HessianMetricOptions ho;
  ho.norm = o.norm;
  ho.complexity = complexity;
  ho.hmin = o.hmin;
  ho.hmax = o.hmax;
  ho.aniso_max = o.aniso_max;
  const std::vector<SymMat2> metrics = hessian_metric<2>(m, hessians, ho, &report);
  Adapt2dOptions ao;
  ao.hmin = o.hmin;
  ao.hmax = o.hmax;
  ao.hgrad = o.hgrad;
  return adapt2d(m, metrics, ao);
}

}  // namespace

void LoopOptions::validate() const {
  if (complexities.empty()) throw InputError("loop: no complexity given");
  for (double n : complexities)
    if (!(n >= 10.0 && n <= 1e7))
      throw InputError("loop: complexities must be in 10..1e7, got " + std::to_string(n));
  for (std::size_t i = 1; i < complexities.size(); ++i)
    if (!(complexities[i] > complexities[i - 1]))
      throw InputError("loop: complexities must be rising, got " +
                       std::to_string(complexities[i]) + " after " +
                       std::to_string(complexities[i - 1]));
  if (iterations < 1 || iterations > 20)
    throw InputError("loop: iterations must be in 1..20, got " + std::to_string(iterations));
  if (!(norm >= 1.0) || !std::isfinite(norm))
    throw InputError("loop: the norm p must be finite and >= 1 (the loop targets a complexity)");
  if (!(hmin > 0.0) || !(hmax > hmin) || !std::isfinite(hmax))
    throw InputError("loop: sizes need 0 < hmin < hmax < inf");
  if (!(aniso_max >= 1.0)) throw InputError("loop: aniso_max must be >= 1");
  if (!(fit_from >= 0.0)) throw InputError("loop: fit_from must be >= 0");
  // Checked with the rest, before anything is printed (the header came out first), and a fit
  // range holding fewer than two complexities refused (its slopes printed "nan").
  if (!(hgrad == 0.0 || (hgrad > 1.0 && std::isfinite(hgrad))))
    throw InputError("--hgrad must be 0 (off) or a ratio > 1, got " + format_g(hgrad));
  if (fit_from > 0.0 && std::count_if(complexities.begin(), complexities.end(),
                                      [this](double n) { return n >= fit_from; }) < 2)
    throw InputError("--fit-from " + format_g(fit_from) +
                     " leaves fewer than two complexities to fit a slope to");
  if (start_cells < 2 || start_cells > 1000)
    throw InputError("loop: start_cells must be in 2..1000, got " + std::to_string(start_cells));
}

Mesh square_mesh(int n) {
  Mesh m = unit_square(n, n);
  for (double& c : m.coords) c = 2.0 * c - 1.0;
  return m;
}

LoopSlopes fit_slopes(const std::vector<LoopStep>& steps, std::size_t min_vertices) {
  LoopSlopes s;
  std::vector<double> x, l1, l2, linf;
  for (const LoopStep& st : steps) {
    if (st.vertices < min_vertices) continue;
    x.push_back(static_cast<double>(st.vertices));
    l1.push_back(st.errors.l1);
    l2.push_back(st.errors.l2);
    linf.push_back(st.errors.linf);
  }
  if (x.size() < 2) return s;
  s.l1 = fit_power_law(x, l1).slope;
  s.l2 = fit_power_law(x, l2).slope;
  s.linf = fit_power_law(x, linf).slope;
  return s;
}

LoopResult adaptation_loop(const AnalyticFunction& f, const LoopOptions& o,
                           const LoopCallback& on_step) {
  o.validate();
  LoopResult r;
  Mesh mesh = square_mesh(o.start_cells);
  bool converged = true;
  std::string stall_reason;
  for (double n : o.complexities) {
    const auto t0 = std::chrono::steady_clock::now();
    MetricReport report;
    for (int it = 0; it < o.iterations; ++it) {
      Adapt2dResult a = adapt_once(mesh, f, n, o, report);
      converged = a.report.converged;
      stall_reason = a.report.stall_reason;
      mesh = std::move(a.mesh);
    }
    LoopStep s;
    s.complexity = n;
    s.vertices = mesh.num_vertices();
    s.triangles = mesh.num_triangles();
    s.errors = errors_of(mesh, f, o.quadrature);
    s.metric_complexity = report.complexity;
    s.converged = converged;
    s.stall_reason = stall_reason;
    s.seconds = seconds_since(t0);
    r.adapted.push_back(s);
    if (on_step) on_step(s, true);
  }
  if (o.uniform) {
    for (const LoopStep& a : r.adapted) {
      const auto t0 = std::chrono::steady_clock::now();
      // (cells + 1)² ≈ the adapted vertex count.
      const double side = std::sqrt(static_cast<double>(a.vertices)) - 1.0;
      const int cells = std::max(2, static_cast<int>(std::lround(side)));
      const Mesh u = square_mesh(cells);
      LoopStep s;
      s.cells = cells;
      s.vertices = u.num_vertices();
      s.triangles = u.num_triangles();
      s.errors = errors_of(u, f, o.quadrature);
      s.seconds = seconds_since(t0);
      r.uniform.push_back(s);
      if (on_step) on_step(s, false);
    }
  }
  // The fit range: the adapted steps of complexity >= fit_from, and the uniform meshes matching
  // them (the first such step's index in both tables).
  std::size_t first = 0;
  while (first < r.adapted.size() && r.adapted[first].complexity < o.fit_from) ++first;
  if (first < r.adapted.size()) {
    r.adapted_slopes = fit_slopes(r.adapted, r.adapted[first].vertices);
    if (first < r.uniform.size()) r.uniform_slopes = fit_slopes(r.uniform, r.uniform[first].vertices);
  }
  r.final_mesh = std::move(mesh);
  return r;
}

}  // namespace riemesh
