#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "metric/geometric.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

namespace {

constexpr double kPi = std::numbers::pi;

// Derivatives of a torus ((R + r cos v) cos u, (R + r cos v) sin u, r sin v) at (u, v), with the
// reparametrisation u = k s (so σ_s = k σ_u, σ_ss = k² σ_uu, σ_sv = k σ_uv).
struct Derivs {
  Vec3 su, sv, suu, suv, svv;
};
Derivs torus(double big_r, double r, double u, double v, double k) {
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  const double w = big_r + r * cv;
  return {k * Vec3{{-w * su, w * cu, 0.0}}, Vec3{{-r * sv * cu, -r * sv * su, r * cv}},
          k * k * Vec3{{-w * cu, -w * su, 0.0}}, k * Vec3{{r * sv * su, -r * sv * cu, 0.0}},
          Vec3{{-r * cv * cu, -r * cv * su, -r * sv}}};
}
SurfaceGeometry geometry(const Derivs& d) {
  return surface_geometry(d.su, d.sv, d.suu, d.suv, d.svv);
}

// Angle-free parallelism test: |a × b| relative to |a||b|.
double sin_between(const Vec3& a, const Vec3& b) { return norm(cross(a, b)) / (norm(a) * norm(b)); }

// Twisted cubic (t, t², t³) and its derivatives.
CurveGeometry<3> cubic(double t) {
  return curve_geometry<3>(Vec3{{1.0, 2 * t, 3 * t * t}}, Vec3{{0.0, 2.0, 6 * t}},
                           Vec3{{0.0, 0.0, 6.0}});
}
Vec3 cubic_point(double t) { return {{t, t * t, t * t * t}}; }

// Radius of the sphere through four points: centre c solves 2(pᵢ − p₀)·c = |pᵢ|² − |p₀|².
double sphere_radius(const Vec3 (&p)[4]) {
  Mat3 a{};
  Vec3 b{};
  for (int i = 0; i < 3; ++i) {
    const Vec3 d = p[i + 1] - p[0];
    for (int k = 0; k < 3; ++k) a(i, k) = 2.0 * d[k];
    b[i] = dot(p[i + 1], p[i + 1]) - dot(p[0], p[0]);
  }
  return norm(inverse(a) * b - p[0]);
}

}  // namespace

TEST(GeometricAlpha, Formulas) {
  // ε = 1 gives the diameter: α = 2; θ = 30° gives α = 1.
  EXPECT_DOUBLE_EQ(alpha_from_gap(1.0), 2.0);
  EXPECT_NEAR(alpha_from_angle(kPi / 6), 1.0, 1e-15);
  for (const double theta : {0.01, 0.1, 0.5, 1.0, 1.5}) {
    // A chord of length αρ subtends 2θ at the centre: half chord ρ sin θ, sagitta
    // ρ − sqrt(ρ² − (αρ/2)²) = ρ(1 − cos θ) = ερ, so α(θ) = α(ε = 1 − cos θ).
    const double eps = 1.0 - std::cos(theta), rho = 3.7;
    EXPECT_NEAR(alpha_from_angle(theta), alpha_from_gap(eps), 1e-12);
    const double chord = alpha_from_gap(eps) * rho;
    EXPECT_NEAR(rho - std::sqrt(rho * rho - chord * chord / 4), eps * rho, 1e-12);
    EXPECT_NEAR((GeometricTolerance{GeometricTolerance::kAngle, theta}.relative_gap()), eps, 1e-15);
  }
  EXPECT_THROW(alpha_from_gap(0.0), InputError);
  EXPECT_THROW(alpha_from_gap(1.5), InputError);
  EXPECT_THROW(alpha_from_angle(2.0), InputError);
  EXPECT_THROW((GeometricTolerance{GeometricTolerance::kRelativeGap, -1.0}.alpha()), InputError);
}

TEST(CurveGeometry, CircleUnderAnyParametrisation) {
  // γ(t) = (r cos 3t, r sin 3t): γ' = 3r(−sin, cos), γ'' = −9r(cos, sin), γ''' = 27r(sin, −cos);
  // |γ' × γ''| = 27r², |γ'|³ = 27r³, so κ = 1/r whatever the speed; ρ' = 0.
  const double r = 2.5, t = 0.4, c = std::cos(3 * t), s = std::sin(3 * t);
  const CurveGeometry<2> g =
      curve_geometry<2>(Vec2{{-3 * r * s, 3 * r * c}}, Vec2{{-9 * r * c, -9 * r * s}},
                        Vec2{{27 * r * s, -27 * r * c}});
  EXPECT_NEAR(g.curvature, 1.0 / r, 1e-15);
  EXPECT_NEAR(g.radius, r, 1e-14);
  EXPECT_NEAR(g.radius_derivative, 0.0, 1e-14);
  EXPECT_EQ(g.torsion, 0.0);
  EXPECT_NEAR(g.osculating_sphere_radius, r, 1e-14);
  // Size α r, clamped.
  const double alpha = alpha_from_gap(0.01);
  EXPECT_NEAR(curve_size(g, alpha, 1e-3, 10.0, false), alpha * r, 1e-14);
  EXPECT_EQ(curve_size(g, alpha, 1.0, 10.0, true), 1.0);
  EXPECT_EQ(curve_size(g, alpha, 1e-3, 0.1, false), 0.1);
}

TEST(CurveGeometry, HelixHasConstantCurvatureAndTorsion) {
  // (a cos t, a sin t, b t): κ = a/(a²+b²), τ = b/(a²+b²); ρ' = 0 so the osculating sphere is
  // the osculating circle's: R = ρ.
  const double a = 2.0, b = 0.7, t = 1.3, c = std::cos(t), s = std::sin(t);
  const CurveGeometry<3> g = curve_geometry<3>(Vec3{{-a * s, a * c, b}}, Vec3{{-a * c, -a * s, 0}},
                                               Vec3{{a * s, -a * c, 0}});
  EXPECT_NEAR(g.curvature, a / (a * a + b * b), 1e-15);
  EXPECT_NEAR(g.torsion, b / (a * a + b * b), 1e-15);
  EXPECT_NEAR(g.radius_derivative, 0.0, 1e-14);
  EXPECT_NEAR(g.osculating_sphere_radius, g.radius, 1e-14);
}

TEST(CurveGeometry, RadiusDerivativeMatchesFiniteDifferences) {
  // Ellipse (a cos t, b sin t): dρ/ds ≈ (ρ(t+h) − ρ(t−h)) / (2h |γ'(t)|).
  const double a = 3.0, b = 1.0, h = 1e-5;
  auto ellipse = [&](double t) {
    return curve_geometry<2>(Vec2{{-a * std::sin(t), b * std::cos(t)}},
                             Vec2{{-a * std::cos(t), -b * std::sin(t)}},
                             Vec2{{a * std::sin(t), -b * std::cos(t)}});
  };
  for (const double t : {0.3, 1.0, 2.0, 4.0}) {
    const double speed = std::hypot(a * std::sin(t), b * std::cos(t));
    const double fd = (ellipse(t + h).radius - ellipse(t - h).radius) / (2 * h * speed);
    EXPECT_NEAR(ellipse(t).radius_derivative, fd, 1e-7 * (1 + std::abs(fd)));
    // κ = ab / (a² sin² t + b² cos² t)^{3/2}.
    EXPECT_NEAR(ellipse(t).curvature, a * b / std::pow(speed, 3), 1e-14);
  }
  // Twisted cubic: τ = 3/(9t⁴ + 9t² + 1) (from γ'×γ'' = (6t², −6t, 2), triple product 12).
  for (const double t : {-0.8, 0.2, 0.5, 1.1}) {
    const double speed = norm(Vec3{{1.0, 2 * t, 3 * t * t}});
    const double fd = (cubic(t + h).radius - cubic(t - h).radius) / (2 * h * speed);
    EXPECT_NEAR(cubic(t).radius_derivative, fd, 1e-7 * (1 + std::abs(fd)));
    EXPECT_NEAR(cubic(t).torsion, 3.0 / (9 * t * t * t * t + 9 * t * t + 1), 1e-14);
  }
}

TEST(CurveGeometry, OsculatingSphereIsTheLimitOfSpheresThroughFourPoints) {
  // Four points of the curve within δ of γ(t) determine a sphere converging to the osculating
  // one (contact of order 3) as δ → 0; error O(δ).
  for (const double t : {0.2, 0.5, 1.0}) {
    const double delta = 2e-3;
    const Vec3 p[4] = {cubic_point(t - 1.5 * delta), cubic_point(t - 0.5 * delta),
                       cubic_point(t + 0.5 * delta), cubic_point(t + 1.5 * delta)};
    const CurveGeometry<3> g = cubic(t);
    EXPECT_NEAR(sphere_radius(p) / g.osculating_sphere_radius, 1.0, 1e-2) << "t = " << t;
    EXPECT_GT(g.osculating_sphere_radius, g.radius);
  }
}

TEST(CurveGeometry, StraightAndSingular) {
  const CurveGeometry<3> line =
      curve_geometry<3>(Vec3{{1, 2, 3}}, Vec3{{2, 4, 6}}, Vec3{{0, 0, 0}});
  EXPECT_EQ(line.curvature, 0.0);
  EXPECT_TRUE(std::isinf(line.radius));
  EXPECT_EQ(curve_size(line, 0.5, 0.01, 2.0, true), 2.0);
  EXPECT_THROW(curve_geometry<2>(Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 0}}), InputError);
  EXPECT_THROW(curve_size(line, 0.5, 0.0, 2.0, false), InputError);
  // A planar curve in 3D (circle of radius 2 in a tilted plane): τ = 0, R = ρ.
  const Vec3 e1{{1, 0, 0}}, e2{{0, std::sqrt(0.5), std::sqrt(0.5)}};
  const double t = 0.9;
  const CurveGeometry<3> g = curve_geometry<3>(2 * (-std::sin(t) * e1 + std::cos(t) * e2),
                                               -2 * (std::cos(t) * e1 + std::sin(t) * e2),
                                               2 * (std::sin(t) * e1 - std::cos(t) * e2));
  EXPECT_EQ(g.torsion, 0.0);
  EXPECT_NEAR(g.radius, 2.0, 1e-14);
  EXPECT_NEAR(g.osculating_sphere_radius, 2.0, 1e-14);
}

TEST(SurfaceGeometry, SphereIsUmbilic) {
  // R (cos u cos v, sin u cos v, sin v): κ1 = κ2 = ±1/R, any orthonormal tangent pair.
  const double big_r = 1.7, u = 0.4, v = 0.3;
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  const SurfaceGeometry g =
      surface_geometry(big_r * Vec3{{-su * cv, cu * cv, 0}}, big_r * Vec3{{-cu * sv, -su * sv, cv}},
                       big_r * Vec3{{-cu * cv, -su * cv, 0}}, big_r * Vec3{{su * sv, -cu * sv, 0}},
                       big_r * Vec3{{-cu * cv, -su * cv, -sv}});
  EXPECT_NEAR(std::abs(g.k1), 1.0 / big_r, 1e-14);
  EXPECT_NEAR(std::abs(g.k2), 1.0 / big_r, 1e-14);
  EXPECT_NEAR(g.rho1, big_r, 1e-13);
  EXPECT_NEAR(dot(g.w1, g.w2), 0.0, 1e-14);
  EXPECT_NEAR(norm(g.w1), 1.0, 1e-14);
  EXPECT_NEAR(dot(g.w1, g.normal), 0.0, 1e-14);
  EXPECT_NEAR(dot(cross(g.w1, g.w2), g.normal), 1.0, 1e-14);
  // Anisotropic = isotropic on a sphere (ε' = ε, β = α) for every f.
  const GeometricTolerance tol{GeometricTolerance::kRelativeGap, 0.01};
  const SymMat3 iso = surface_metric_isotropic(g, tol, 1e-3, 10.0);
  const SymMat3 aniso = surface_metric_anisotropic(g, tol, 1e-3, 10.0, 1.0);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(aniso.c[k], iso.c[k], 1e-10 * iso.c[0]);
  EXPECT_NEAR(iso.c[0], 1.0 / std::pow(tol.alpha() * big_r, 2), 1e-10 * iso.c[0]);
}

TEST(SurfaceGeometry, CylinderCurvesAlongTheCircle) {
  // (R cos u, R sin u, 3v): κ = 1/R around, 0 along the axis; w1 = ±(−sin u, cos u, 0).
  const double big_r = 0.5, u = 2.0;
  const SurfaceGeometry g = surface_geometry(
      Vec3{{-big_r * std::sin(u), big_r * std::cos(u), 0}}, Vec3{{0, 0, 3}},
      Vec3{{-big_r * std::cos(u), -big_r * std::sin(u), 0}}, Vec3{{0, 0, 0}}, Vec3{{0, 0, 0}});
  EXPECT_NEAR(std::abs(g.k1), 1.0 / big_r, 1e-14);
  EXPECT_EQ(g.k2, 0.0);
  EXPECT_TRUE(std::isinf(g.rho2));
  EXPECT_NEAR(sin_between(g.w1, Vec3{{-std::sin(u), std::cos(u), 0}}), 0.0, 1e-14);
  EXPECT_NEAR(sin_between(g.w2, Vec3{{0, 0, 1}}), 0.0, 1e-14);
  // Anisotropic: h1 = αR around the circle and along the normal, hmax along the axis (flat).
  const GeometricTolerance tol{GeometricTolerance::kAngle, 0.1};
  const double h1 = tol.alpha() * big_r, hmax = 4.0;
  const SymMat3 m = surface_metric_anisotropic(g, tol, 1e-4, hmax, 1.0);
  EXPECT_NEAR(length(m, g.w1), 1.0 / h1, 1e-10 / h1);
  EXPECT_NEAR(length(m, g.w2), 1.0 / hmax, 1e-10);
  EXPECT_NEAR(length(m, g.normal), 1.0 / h1, 1e-10 / h1);
  // f = 0 is the isotropic metric; f = 1/2 halfway in size.
  const SymMat3 m0 = surface_metric_anisotropic(g, tol, 1e-4, hmax, 0.0);
  const SymMat3 iso = surface_metric_isotropic(g, tol, 1e-4, hmax);
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(m0.c[k], iso.c[k], 1e-10 * iso.c[0]);
  const SymMat3 mh = surface_metric_anisotropic(g, tol, 1e-4, hmax, 0.5);
  EXPECT_NEAR(1.0 / length(mh, g.w2), 0.5 * (h1 + hmax), 1e-10);
  EXPECT_THROW(surface_metric_anisotropic(g, tol, 1e-4, hmax, 1.5), InputError);
}

TEST(SurfaceGeometry, SaddleAtTheOrigin) {
  // z = xy, σ = (u, v, uv) at 0: I = identity, n = e3, II = [[0,1],[1,0]], κ = ±1 along
  // (1, ±1, 0)/√2.
  const SurfaceGeometry g = surface_geometry(Vec3{{1, 0, 0}}, Vec3{{0, 1, 0}}, Vec3{{0, 0, 0}},
                                             Vec3{{0, 0, 1}}, Vec3{{0, 0, 0}});
  EXPECT_NEAR(std::abs(g.k1), 1.0, 1e-15);
  EXPECT_NEAR(g.k1 + g.k2, 0.0, 1e-15);
  const Vec3 plus{{1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0}};
  const Vec3 minus{{1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0}};
  EXPECT_NEAR(sin_between(g.k1 > 0 ? g.w1 : g.w2, plus), 0.0, 1e-14);
  EXPECT_NEAR(sin_between(g.k1 > 0 ? g.w2 : g.w1, minus), 0.0, 1e-14);
  // Weingarten matrix = I⁻¹ II = II here.
  EXPECT_NEAR(g.weingarten(0, 1), 1.0, 1e-15);
  EXPECT_NEAR(g.weingarten(0, 0), 0.0, 1e-15);
}

TEST(SurfaceGeometry, TorusPrincipalCurvatures) {
  // κ along the meridian (v) is 1/r; along the parallel cos v/(R + r cos v) (0 on top).
  const double big_r = 3.0, r = 1.0;
  for (const double k : {1.0, 2.0, 0.3}) {  // parametrisation speed in u
    const SurfaceGeometry out = geometry(torus(big_r, r, 0.7, 0.0, k));
    EXPECT_NEAR(std::abs(out.k1), 1.0 / r, 1e-14);
    EXPECT_NEAR(std::abs(out.k2), 1.0 / (big_r + r), 1e-14);
    EXPECT_GT(out.k1 * out.k2, 0.0);  // elliptic outside
    const Derivs d = torus(big_r, r, 0.7, 0.0, k);
    EXPECT_NEAR(sin_between(out.w1, d.sv), 0.0, 1e-13);
    EXPECT_NEAR(sin_between(out.w2, d.su), 0.0, 1e-13);
    const SurfaceGeometry in = geometry(torus(big_r, r, 0.7, kPi, k));
    EXPECT_NEAR(std::abs(in.k2), 1.0 / (big_r - r), 1e-14);
    EXPECT_LT(in.k1 * in.k2, 0.0);  // hyperbolic inside
    const SurfaceGeometry top = geometry(torus(big_r, r, 0.7, kPi / 2, k));
    EXPECT_NEAR(top.k2, 0.0, 1e-15);
    // Parameter-space directions map to the spatial ones.
    EXPECT_NEAR(norm(d.su * out.w1_uv[0] + d.sv * out.w1_uv[1] - out.w1), 0.0, 1e-14);
  }
}

TEST(SurfaceGeometry, FlatAndSingular) {
  const SurfaceGeometry g = surface_geometry(Vec3{{2, 0, 0}}, Vec3{{0, 3, 0}}, Vec3{{0, 0, 0}},
                                             Vec3{{0, 0, 0}}, Vec3{{0, 0, 0}});
  EXPECT_TRUE(std::isinf(g.rho1));
  const GeometricTolerance tol;
  const SymMat3 m = surface_metric_anisotropic(g, tol, 0.01, 0.5, 1.0);
  for (int k = 0; k < 6; ++k)
    EXPECT_NEAR(m.c[k], SymMat3::diagonal(4.0).c[k], 1e-12);  // hmax = 0.5 everywhere
  // Induced metric of I/h² on σ = (2u, 3v, 0) is diag(4, 9)/h².
  const SymMat2 mi = induced_metric(SymMat3::diagonal(4.0), Vec3{{2, 0, 0}}, Vec3{{0, 3, 0}});
  EXPECT_NEAR(mi.c[0], 16.0, 1e-14);
  EXPECT_NEAR(mi.c[1], 0.0, 1e-14);
  EXPECT_NEAR(mi.c[2], 36.0, 1e-14);
  EXPECT_THROW(surface_geometry(Vec3{{1, 0, 0}}, Vec3{{2, 0, 0}}, Vec3{{0, 0, 0}}, Vec3{{0, 0, 0}},
                                Vec3{{0, 0, 0}}),
               InputError);
}

TEST(SurfaceGeometry, InducedMetricMeasuresParameterSteps) {
  // For any parameter step δ, ‖δ‖ in the induced metric = ‖Dσ δ‖ in M (first order).
  const Derivs d = torus(3.0, 1.0, 0.4, 1.1, 2.0);
  const SurfaceGeometry g = geometry(d);
  const SymMat3 m = surface_metric_anisotropic(g, GeometricTolerance{}, 1e-3, 1.0, 0.7);
  const SymMat2 mi = induced_metric(m, d.su, d.sv);
  for (const Vec2 delta : {Vec2{{1, 0}}, Vec2{{0.3, -2}}, g.w1_uv, g.w2_uv})
    EXPECT_NEAR(length(mi, delta), length(m, d.su * delta[0] + d.sv * delta[1]), 1e-12);
  // Along w1 (unit in space) the induced metric gives 1/h1 = 1/(α ρ1).
  EXPECT_NEAR(length(mi, g.w1_uv), 1.0 / (GeometricTolerance{}.alpha() * g.rho1), 1e-10);
}
