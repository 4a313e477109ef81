// `riemesh metric calc ...`: a metric calculator on metrics given as packed coefficients.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/metric_report.hpp"
#include "apps/parse.hpp"
#include "metric/element.hpp"
#include "metric/interpolation.hpp"
#include "metric/intersection.hpp"

namespace riemesh::cli {
namespace {

struct CalcArgs {
  bool json = false;
  std::string scheme = "log";
  double t = 0.5;
  bool sequential = false;
  std::string metric;
  std::vector<std::string> operands;
};

template <int D>
SymMat<D> to_metric(const std::vector<double>& c, const std::string& what) {
  SymMat<D> m{};
  for (int k = 0; k < SymMat<D>::kSize; ++k) m.c[k] = c[k];
  require_metric(m, what);
  return m;
}

/// Parses metrics given as packed coefficients; all must have the same dimension.
/// Returns the dimension (2 or 3) and the coefficient lists.
int parse_metrics(const std::vector<std::string>& texts, std::vector<std::vector<double>>& out) {
  int dim = 0;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const std::string what = "metric " + std::to_string(i + 1) + " '" + texts[i] + "'";
    std::vector<double> c = parse_numbers(texts[i], what);
    const int d = c.size() == 3 ? 2 : c.size() == 6 ? 3 : 0;
    if (d == 0)
      throw InputError(what + ": expected 3 (m11,m12,m22) or 6 (m11,m12,m22,m13,m23,m33) numbers, got " +
                       std::to_string(c.size()));
    if (dim != 0 && d != dim) throw InputError(what + ": mixes 2D and 3D metrics");
    dim = d;
    out.push_back(std::move(c));
  }
  return dim;
}

template <int D>
void print_metric(const SymMat<D>& m, bool json) {
  const MetricSummary<D> s = summarize(m);
  // NaN and inf were printed (invalid JSON too), with exit 0.
  bool finite = is_finite(m) && std::isfinite(s.anisotropy) && std::isfinite(s.det) && s.det > 0.0;
  for (int i = 0; i < D; ++i) finite = finite && std::isfinite(s.sizes[i]);
  if (!finite)
    throw InputError("the resulting metric (or its determinant) is out of the range of doubles");
  std::fputs(json ? (to_json(s) + "\n").c_str() : to_text(s).c_str(), stdout);
}

template <int D>
void run_interp(const CalcArgs& a, const std::vector<std::vector<double>>& c) {
  const InterpScheme scheme = parse_interp_scheme(a.scheme);
  // CLI::Range lets NaN through (no comparison fails): the result was NaN, printed as `nan`.
  if (!(a.t >= 0.0 && a.t <= 1.0)) throw InputError("--t must be in [0, 1]");
  const SymMat<D> m = interpolate(scheme, to_metric<D>(c[0], "metric 1"),
                                  to_metric<D>(c[1], "metric 2"), a.t);
  print_metric(m, a.json);
}

template <int D>
void run_intersect(const CalcArgs& a, const std::vector<std::vector<double>>& c) {
  std::vector<SymMat<D>> ms;
  for (std::size_t i = 0; i < c.size(); ++i)
    ms.push_back(to_metric<D>(c[i], "metric " + std::to_string(i + 1)));
  SymMat<D> m = ms[0];
  if (ms.size() == 2)
    m = intersect(ms[0], ms[1]);
  else if (a.sequential)
    m = intersect_sequential<D>(ms);
  else
    m = intersect_max_volume<D>(ms);
  print_metric(m, a.json);
}

template <int D>
void run_element(const CalcArgs& a, const std::vector<std::vector<double>>& pts) {
  // Computed on the simplex scaled to a unit longest edge L, then divided by L²: the sums of
  // v vᵀ over edges of 1e78 overflowed (NaN) though the answer, 1e-156, is a double.
  Vec<D> p[D + 1];
  double longest = 0.0;  // the largest coordinate difference (no squares: 1e200 overflowed)
  for (int i = 0; i <= D; ++i)
    for (int j = i + 1; j <= D; ++j)
      for (int k = 0; k < D; ++k) longest = std::max(longest, std::abs(pts[i][k] - pts[j][k]));
  if (!(longest > 0.0) || !std::isfinite(longest))
    throw InputError("element: the points must be distinct and their distances finite");
  for (int i = 0; i <= D; ++i)
    for (int k = 0; k < D; ++k) p[i][k] = (pts[i][k] - pts[0][k]) / longest;
  SymMat<D> m = element_metric<D>(p);
  for (double& c : m.c) c = c / longest / longest;
  print_metric(m, a.json);  // (which refuses an answer out of the doubles' range)
}

template <int D>
void run_length(const CalcArgs& a, const std::vector<double>& coeffs, const std::vector<double>& v) {
  const SymMat<D> m = to_metric<D>(coeffs, "--metric");
  Vec<D> u{};
  for (int k = 0; k < D; ++k) u[k] = v[k];
  // |u|_M = s |u/s|_M with s the largest |u_k|: uᵀ M u overflowed for u = (1e300, 0).
  double scale = 0.0;
  for (int k = 0; k < D; ++k) scale = std::max(scale, std::abs(u[k]));
  const double l = scale > 0.0 ? scale * length(m, (1.0 / scale) * u) : 0.0;
  if (!std::isfinite(l)) throw InputError("length: the answer is out of the range of doubles");
  if (a.json)
    std::printf("{\"length\": %.17g}\n", l);
  else
    std::printf("length : %.17g\n", l);
}

void interp(const CalcArgs& a) {
  if (a.operands.size() != 2) throw InputError("interp: expected two metrics A B");
  std::vector<std::vector<double>> c;
  const int dim = parse_metrics(a.operands, c);
  dim == 2 ? run_interp<2>(a, c) : run_interp<3>(a, c);
}

void intersection(const CalcArgs& a) {
  if (a.operands.size() < 2) throw InputError("intersect: expected at least two metrics");
  std::vector<std::vector<double>> c;
  const int dim = parse_metrics(a.operands, c);
  dim == 2 ? run_intersect<2>(a, c) : run_intersect<3>(a, c);
}

void element(const CalcArgs& a) {
  const std::size_t n = a.operands.size();
  if (n != 3 && n != 4) throw InputError("element: expected 3 points (2D) or 4 points (3D)");
  const int dim = static_cast<int>(n) - 1;
  std::vector<std::vector<double>> pts;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string what = "point " + std::to_string(i + 1) + " '" + a.operands[i] + "'";
    pts.push_back(parse_numbers(a.operands[i], what));
    if (static_cast<int>(pts.back().size()) != dim)
      throw InputError(what + ": expected " + std::to_string(dim) + " coordinates for a " +
                       (dim == 2 ? "triangle" : "tetrahedron"));
  }
  dim == 2 ? run_element<2>(a, pts) : run_element<3>(a, pts);
}

void length_cmd(const CalcArgs& a) {
  if (a.operands.size() != 1) throw InputError("length: expected one vector X,Y[,Z]");
  std::vector<std::vector<double>> c;
  const int dim = parse_metrics({a.metric}, c);
  const std::vector<double> v = parse_numbers(a.operands[0], "vector '" + a.operands[0] + "'");
  if (static_cast<int>(v.size()) != dim)
    throw InputError("vector '" + a.operands[0] + "': expected " + std::to_string(dim) +
                     " components to match the " + std::to_string(dim) + "D metric");
  dim == 2 ? run_length<2>(a, c[0], v) : run_length<3>(a, c[0], v);
}

}  // namespace

void register_metric(CLI::App& app) {
  auto* metric = app.add_subcommand("metric", "Metric tools");
  metric->require_subcommand(1);
  auto* calc = metric->add_subcommand(
      "calc",
      "Evaluate one operation on metrics given as packed coefficients: m11,m12,m22 (2D) or "
      "m11,m12,m22,m13,m23,m33 (3D), the .sol order");
  calc->require_subcommand(1);
  auto args = std::make_shared<CalcArgs>();
  calc->add_flag("--json", args->json, "Print one JSON object (keys metric, sizes, directions, anisotropy, det)");

  auto* in = calc->add_subcommand("interp", "Interpolate between metrics A (t=0) and B (t=1)");
  in->add_option("--scheme", args->scheme,
                 "linear, iso-linear, iso-geometric, iso-harmonic, simred-linear, simred-geometric, "
                 "power, log (log-Euclidean), cholesky, cholesky-geometric")
      ->capture_default_str();
  in->add_option("--t", args->t, "Interpolation parameter in [0, 1]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  in->add_option("metrics", args->operands, "A B")->required()->expected(2);
  in->callback([args] { interp(*args); });

  auto* is = calc->add_subcommand(
      "intersect", "Intersect metrics (two: simultaneous reduction; more: maximal-volume ellipsoid)");
  is->add_flag("--sequential", args->sequential,
               "With more than two metrics, intersect them pairwise in the given order");
  is->add_option("metrics", args->operands, "A B [C ...]")->required();
  is->callback([args] { intersection(*args); });

  auto* el = calc->add_subcommand(
      "element", "The metric in which the simplex P1..P3 (2D) or P1..P4 (3D) is unit and regular");
  el->add_option("points", args->operands, "P1 P2 P3 [P4] as x,y or x,y,z")->required();
  el->callback([args] { element(*args); });

  auto* len = calc->add_subcommand("length", "Length of a vector in a metric");
  len->add_option("--metric", args->metric, "The metric (packed coefficients)")->required();
  len->add_option("vector", args->operands, "X,Y or X,Y,Z")->required();
  len->callback([args] { length_cmd(*args); });

  register_metric_hessian(*metric);
  register_metric_geometric(*metric);
}

}  // namespace riemesh::cli
