// Geometric metrics of curves and surfaces (BOOK.md §1 "Geometric metrics").
#include "metric/geometric.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/eigen.hpp"
#include "core/error.hpp"

namespace riemesh {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Below this relative size a cross product is rounding noise: the derivatives are parallel.
constexpr double kParallel = 1e-12;

void check_size_bounds(double hmin, double hmax) {
  if (!(hmin > 0.0) || !(hmax >= hmin) || !std::isfinite(hmax))
    throw InputError("geometric metric: need 0 < hmin <= hmax < inf");
}

template <int D>
bool all_finite(const Vec<D>& v) {
  for (int i = 0; i < D; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

}  // namespace

double alpha_from_gap(double eps) {
  if (!(eps > 0.0 && eps <= 1.0)) throw InputError("relative gap must be in (0, 1]");
  return 2.0 * std::sqrt(eps * (2.0 - eps));
}

double alpha_from_angle(double theta) {
  if (!(theta > 0.0 && theta <= 0.5 * std::numbers::pi))
    throw InputError("angular deviation must be in (0, pi/2]");
  return 2.0 * std::sin(theta);
}

double GeometricTolerance::alpha() const {
  return kind == kAngle ? alpha_from_angle(value) : alpha_from_gap(value);
}

double GeometricTolerance::relative_gap() const {
  if (kind == kAngle) {
    alpha_from_angle(value);  // range check
    return 1.0 - std::cos(value);
  }
  alpha_from_gap(value);
  return value;
}

template <int D>
CurveGeometry<D> curve_geometry(const Vec<D>& d1, const Vec<D>& d2, const Vec<D>& d3) {
  static_assert(D == 2 || D == 3);
  const double s = norm(d1);  // ds/dt
  if (!(s > 0.0) || !all_finite(d1) || !all_finite(d2) || !all_finite(d3))
    throw InputError("singular parametrisation");
  // c = γ' × γ'' (a scalar in 2D), |c| and its t-derivative: dc/dt = γ' × γ''' since
  // γ'' × γ'' = 0.
  double c_norm, dc_norm, triple = 0.0;
  if constexpr (D == 2) {
    const double c = cross(d1, d2);
    c_norm = std::abs(c);
    dc_norm = std::copysign(1.0, c) * cross(d1, d3);
  } else {
    const Vec3 c = cross(d1, d2);
    c_norm = norm(c);
    dc_norm = c_norm > 0.0 ? dot(c, cross(d1, d3)) / c_norm : 0.0;
    triple = dot(c, d3);
  }
  CurveGeometry<D> g;
  if (c_norm <= kParallel * s * norm(d2)) {  // straight: no curvature, no osculating circle
    g.radius = g.osculating_sphere_radius = kInf;
    return g;
  }
  const double s3 = s * s * s;
  g.curvature = c_norm / s3;
  g.radius = 1.0 / g.curvature;
  // dκ/dt = d|c|/dt / s³ − 3|c| (γ'·γ'') / s⁵, and dρ/ds = −(dκ/dt) / (κ² s).
  const double dk_dt = dc_norm / s3 - 3.0 * c_norm * dot(d1, d2) / (s3 * s * s);
  g.radius_derivative = -dk_dt / (g.curvature * g.curvature * s);
  if (D == 3 && std::abs(triple) > kParallel * c_norm * norm(d3))
    g.torsion = triple / (c_norm * c_norm);
  // Osculating sphere (centre γ + ρN + ρ'σB, σ = 1/τ): R² = ρ² + (ρ'σ)². A planar curve has
  // none of finite radius unless ρ' = 0; we keep the osculating circle there (R = ρ).
  g.osculating_sphere_radius =
      g.torsion != 0.0 ? std::hypot(g.radius, g.radius_derivative / g.torsion) : g.radius;
  return g;
}

template <int D>
double curve_size(const CurveGeometry<D>& g, double alpha, double hmin, double hmax,
                  bool torsion_aware) {
  check_size_bounds(hmin, hmax);
  if (!(alpha > 0.0) || !std::isfinite(alpha)) throw InputError("curve_size: alpha must be > 0");
  const double r = torsion_aware ? g.osculating_sphere_radius : g.radius;
  return std::clamp(alpha * r, hmin, hmax);  // inf (straight) clamps to hmax
}

template CurveGeometry<2> curve_geometry<2>(const Vec2&, const Vec2&, const Vec2&);
template CurveGeometry<3> curve_geometry<3>(const Vec3&, const Vec3&, const Vec3&);
template double curve_size<2>(const CurveGeometry<2>&, double, double, double, bool);
template double curve_size<3>(const CurveGeometry<3>&, double, double, double, bool);

SurfaceGeometry surface_geometry(const Vec3& su, const Vec3& sv, const Vec3& suu, const Vec3& suv,
                                 const Vec3& svv) {
  const Vec3 c = cross(su, sv);
  const double cn = norm(c);
  if (!(cn > kParallel * norm(su) * norm(sv)) || !all_finite(c) || !all_finite(suu) ||
      !all_finite(suv) || !all_finite(svv))
    throw InputError("singular parametrisation");
  SurfaceGeometry g{};
  g.normal = c / cn;
  g.first_form = SymMat2{{dot(su, su), dot(su, sv), dot(sv, sv)}};
  g.second_form = SymMat2{{dot(suu, g.normal), dot(suv, g.normal), dot(svv, g.normal)}};
  g.weingarten = inverse(g.first_form.to_mat()) * g.second_form.to_mat();
  // The eigenproblem N x = κ M x made symmetric: S = M^{-1/2} N M^{-1/2} = Q diag(κ) Qᵀ, and
  // x = M^{-1/2} q are M-orthonormal, so Dσ x are orthonormal in space even at umbilics.
  const SymEigen<2> em = eigen(g.first_form);
  const Vec2 inv_root{{1.0 / std::sqrt(em.values[0]), 1.0 / std::sqrt(em.values[1])}};
  const Mat2 m_inv_half = congruence_diag(em.vectors, inv_root).to_mat();
  const SymEigen<2> es = eigen(congruence(m_inv_half, g.second_form));
  const int i1 = std::abs(es.values[0]) >= std::abs(es.values[1]) ? 0 : 1, i2 = 1 - i1;
  g.k1 = es.values[i1];
  g.k2 = es.values[i2];
  g.rho1 = g.k1 != 0.0 ? 1.0 / std::abs(g.k1) : kInf;
  g.rho2 = g.k2 != 0.0 ? 1.0 / std::abs(g.k2) : kInf;
  g.w1_uv = m_inv_half * es.vectors.column(i1);
  g.w2_uv = m_inv_half * es.vectors.column(i2);
  if (dot(cross(su * g.w1_uv[0] + sv * g.w1_uv[1], su * g.w2_uv[0] + sv * g.w2_uv[1]), g.normal) <
      0.0)
    g.w2_uv = -g.w2_uv;  // right-handed (w1, w2, n)
  g.w1 = su * g.w1_uv[0] + sv * g.w1_uv[1];
  g.w2 = su * g.w2_uv[0] + sv * g.w2_uv[1];
  return g;
}

SymMat3 surface_metric_isotropic(const SurfaceGeometry& g, const GeometricTolerance& tol,
                                 double hmin, double hmax) {
  check_size_bounds(hmin, hmax);
  const double h = std::clamp(tol.alpha() * g.rho1, hmin, hmax);  // ρ1 = min(ρ1, ρ2)
  return SymMat3::diagonal(1.0 / (h * h));
}

SymMat3 surface_metric_anisotropic(const SurfaceGeometry& g, const GeometricTolerance& tol,
                                   double hmin, double hmax, double beta_prime_fraction) {
  check_size_bounds(hmin, hmax);
  const double f = beta_prime_fraction;
  if (!(f >= 0.0 && f <= 1.0)) throw InputError("beta_prime_fraction must be in [0, 1]");
  const double alpha = tol.alpha(), eps = tol.relative_gap();
  const double h1 = std::clamp(alpha * g.rho1, hmin, hmax);
  // βρ2 with β = 2 sqrt(ε'(2 − ε')), ε' = ερ1/ρ2, written as 2 sqrt(ερ1 (2ρ2 − ερ1)) so that a
  // flat direction (ρ2 = inf) gives inf, not 0·inf. It is >= αρ1 since ρ2 >= ρ1.
  const double h2_full =
      std::isinf(g.rho1) ? kInf : 2.0 * std::sqrt(eps * g.rho1 * (2.0 * g.rho2 - eps * g.rho1));
  // Interpolate between the clamped sizes: stays in [h1, hmax] and avoids f·inf.
  const double h2 = h1 + f * (std::clamp(h2_full, hmin, hmax) - h1);
  const double hn = h1;
  const Mat3 frame = Mat3::from_columns({g.w1, g.w2, g.normal});
  return congruence_diag(frame, Vec3{{1.0 / (h1 * h1), 1.0 / (h2 * h2), 1.0 / (hn * hn)}});
}

SymMat2 induced_metric(const SymMat3& m, const Vec3& su, const Vec3& sv) {
  return SymMat2{{bilinear(m, su, su), bilinear(m, su, sv), bilinear(m, sv, sv)}};
}

}  // namespace riemesh
