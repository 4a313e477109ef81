#pragma once
// The analytic metric fields of the benchmark cases (../shared/PEERS.md, after the UGAWG
// benchmark): linear, polar and polar-2 in 2D. Used by the demo, the tests and the benchmarks;
// the shared Python harness (../shared/bench/metrics.py) defines the same fields.
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"
#include "metric/metric.hpp"

namespace riemesh {

enum class AnalyticField { kLinear, kPolar, kPolar2 };

struct AnalyticCase {
  AnalyticField field = AnalyticField::kLinear;
  double h0 = 0.001;   ///< smallest size (at y = 0.5, or r = 0.5)
  double hmax = 0.1;   ///< largest size
  double scale = 1.0;  ///< multiplies every size (the harness's s)
};

/// "linear2d", "polar2d", "polar2d-2" (h0 = 0.001) and the "-mild" variants (h0 = 0.01).
inline AnalyticCase analytic_case(const std::string& name) {
  if (name == "linear2d") return {AnalyticField::kLinear, 0.001};
  if (name == "linear2d-mild") return {AnalyticField::kLinear, 0.01};
  if (name == "polar2d") return {AnalyticField::kPolar, 0.001};
  if (name == "polar2d-mild") return {AnalyticField::kPolar, 0.01};
  if (name == "polar2d-2") return {AnalyticField::kPolar2, 0.001};
  throw InputError("unknown analytic case '" + name +
                   "' (linear2d, linear2d-mild, polar2d, polar2d-mild, polar2d-2)");
}

/// M(p) = R diag(1/h_i²) Rᵀ of the case at p in the unit square:
///   linear: hx = hmax, hy = h0 + 2(hmax − h0)|y − 0.5|;
///   polar:  r = |p|, radial hr = h0 + 2(hmax − h0)|r − 0.5|, tangential ht = hmax;
///   polar2: as polar with ht = hmax d0 + 0.025 (1 − d0), d0 = min(10|r − 0.5|, 1).
inline SymMat2 analytic_metric(const AnalyticCase& c, const Vec2& p) {
  auto hvar = [&c](double t) { return c.scale * (c.h0 + 2.0 * (c.hmax - c.h0) * std::abs(t - 0.5)); };
  if (c.field == AnalyticField::kLinear) {
    const double hx = c.scale * c.hmax, hy = hvar(p[1]);
    return SymMat2{{1.0 / (hx * hx), 0.0, 1.0 / (hy * hy)}};
  }
  const double r = std::hypot(p[0], p[1]);
  const double co = r > 1e-300 ? p[0] / r : 1.0, si = r > 1e-300 ? p[1] / r : 0.0;
  double ht = c.scale * c.hmax;
  if (c.field == AnalyticField::kPolar2) {
    const double d0 = std::min(10.0 * std::abs(r - 0.5), 1.0);
    ht = c.scale * (c.hmax * d0 + 0.025 * (1.0 - d0));
  }
  return metric_from_sizes(Mat2{{{co, -si}, {si, co}}}, Vec2{{hvar(r), ht}});
}

/// The case's metric at every vertex of a planar mesh.
inline std::vector<SymMat2> analytic_metrics(const AnalyticCase& c, const Mesh& m) {
  std::vector<SymMat2> out;
  out.reserve(m.num_vertices());
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    out.push_back(analytic_metric(c, Vec2{{m.coords[2 * v], m.coords[2 * v + 1]}}));
  return out;
}

}  // namespace riemesh
