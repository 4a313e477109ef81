#include "remesh/interpolation_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace riemesh {
namespace {

// The 7-point degree-5 rule on a triangle (Strang & Fix 1973, Dunavant 1985): barycentrics and
// weights (summing to 1) from a = (9 ∓ 2√15)/21, b = (6 ± √15)/21, w = (155 ± √15)/1200.
struct QuadPoint {
  double l0, l1, l2, w;
};
constexpr double kA1 = 0.059715871789769820, kB1 = 0.47014206410511509, kW1 = 0.13239415278850619;
constexpr double kA2 = 0.79742698535308732, kB2 = 0.10128650732345634, kW2 = 0.12593918054482715;
constexpr QuadPoint kRule[7] = {
    {1.0 / 3, 1.0 / 3, 1.0 / 3, 0.225}, {kA1, kB1, kB1, kW1}, {kB1, kA1, kB1, kW1},
    {kB1, kB1, kA1, kW1},               {kA2, kB2, kB2, kW2}, {kB2, kA2, kB2, kW2},
    {kB2, kB2, kA2, kW2}};

Vec2 combine(const Vec2 (&p)[3], double l0, double l1, double l2) {
  return Vec2{{l0 * p[0][0] + l1 * p[1][0] + l2 * p[2][0], l0 * p[0][1] + l1 * p[1][1] + l2 * p[2][1]}};
}

/// Accumulates ∫|e|, ∫e² and max|e| of e = u − Π_h u over the sub-triangle with barycentric
/// corners s[0..2] (in the parent triangle), |sub| = area of the sub-triangle.
void integrate_sub(const Vec2 (&p)[3], const double (&up)[3], const double (&s)[3][3],
                   double sub_area, const std::function<double(Vec2)>& u, ErrorNorms& acc) {
  for (const QuadPoint& qp : kRule) {
    double l[3];
    for (int k = 0; k < 3; ++k) l[k] = qp.l0 * s[0][k] + qp.l1 * s[1][k] + qp.l2 * s[2][k];
    const double e = u(combine(p, l[0], l[1], l[2])) - (l[0] * up[0] + l[1] * up[1] + l[2] * up[2]);
    acc.l1 += qp.w * sub_area * std::abs(e);
    acc.l2 += qp.w * sub_area * e * e;
    acc.linf = std::max(acc.linf, std::abs(e));
  }
}

void validate(const ErrorQuadrature& q) {
  if (q.levels < 0 || q.levels > 6)
    throw InputError("error quadrature: levels must be in 0..6, got " + std::to_string(q.levels));
  if (q.samples < 1 || q.samples > 64)
    throw InputError("error quadrature: samples must be in 1..64, got " + std::to_string(q.samples));
}

}  // namespace

ErrorNorms triangle_interpolation_error(const Vec2 (&p)[3], const std::function<double(Vec2)>& u,
                                        const ErrorQuadrature& q) {
  const double up[3] = {u(p[0]), u(p[1]), u(p[2])};
  const double area = 0.5 * std::abs((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                                     (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]));
  ErrorNorms acc;
  // Uniform subdivision into n² sub-triangles (n = 2^levels) on the barycentric lattice (i, j):
  // the "upward" ones (i, j), (i+1, j), (i, j+1) and the "downward" ones beside them.
  const int n = 1 << q.levels;
  const double sub_area = area / (static_cast<double>(n) * n);
  auto bary = [n](int i, int j, double (&b)[3]) {
    b[1] = static_cast<double>(i) / n;
    b[2] = static_cast<double>(j) / n;
    b[0] = 1.0 - b[1] - b[2];
  };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i + j < n; ++i) {
      double s[3][3];
      bary(i, j, s[0]);
      bary(i + 1, j, s[1]);
      bary(i, j + 1, s[2]);
      integrate_sub(p, up, s, sub_area, u, acc);
      if (i + j + 1 < n) {
        bary(i + 1, j, s[0]);
        bary(i + 1, j + 1, s[1]);
        bary(i, j + 1, s[2]);
        integrate_sub(p, up, s, sub_area, u, acc);
      }
    }
  }
  // L∞: also the lattice of `samples` intervals (its corners have zero error).
  const int m = q.samples;
  for (int j = 0; j <= m; ++j) {
    for (int i = 0; i + j <= m; ++i) {
      const double l1 = static_cast<double>(i) / m, l2 = static_cast<double>(j) / m;
      const double l0 = 1.0 - l1 - l2;
      const double e = u(combine(p, l0, l1, l2)) - (l0 * up[0] + l1 * up[1] + l2 * up[2]);
      acc.linf = std::max(acc.linf, std::abs(e));
    }
  }
  return acc;
}

ErrorNorms interpolation_error(const Mesh& mesh, const std::function<double(Vec2)>& u,
                               const ErrorQuadrature& q) {
  if (mesh.kind() != MeshKind::kPlanar)
    throw InputError("interpolation error: expected a planar triangle mesh");
  validate(q);
  ErrorNorms total;
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
    Vec2 p[3];
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = static_cast<std::size_t>(mesh.triangles[3 * t + k]);
      p[k] = Vec2{{mesh.coords[2 * v], mesh.coords[2 * v + 1]}};
    }
    const ErrorNorms e = triangle_interpolation_error(p, u, q);
    total.l1 += e.l1;
    total.l2 += e.l2;
    total.linf = std::max(total.linf, e.linf);
  }
  total.l2 = std::sqrt(total.l2);
  return total;
}

PowerFit fit_power_law(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw InputError("power-law fit: x and y differ in size");
  if (x.size() < 2) throw InputError("power-law fit: needs at least two points");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0.0) || !(y[i] > 0.0) || !std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw InputError("power-law fit: values must be positive and finite");
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double n = static_cast<double>(x.size());
  const double var = sxx - sx * sx / n;
  if (!(var > 1e-12 * std::max(1.0, sxx))) throw InputError("power-law fit: all x are equal");
  PowerFit f;
  f.slope = (sxy - sx * sy / n) / var;
  f.coefficient = std::exp((sy - f.slope * sx) / n);
  return f;
}

}  // namespace riemesh
