// Interpolation error norms: exact zeros for piecewise-linear functions, the closed-form error of
// a quadratic on one triangle, the analytic functions' definitions, and the power-law fit.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "remesh/analytic_functions.hpp"
#include "remesh/interpolation_error.hpp"

using namespace riemesh;

TEST(InterpolationError, LinearFunctionHasNoError) {
  const Mesh m = unit_square(5, 3);
  const ErrorNorms e = interpolation_error(m, [](Vec2 p) { return 3.0 * p[0] - 2.0 * p[1] + 0.5; });
  EXPECT_LT(e.l1, 1e-14);
  EXPECT_LT(e.l2, 1e-14);
  EXPECT_LT(e.linf, 1e-14);
}

TEST(InterpolationError, QuadraticOnOneTriangle) {
  // u = x² on (0,0), (1,0), (0,1): Π u = x, e = x² − x = −x(1 − x). Over the triangle
  // ∫ x(1−x)·(1−x) dx = B(2,3) = 1/12 (L1), ∫ x²(1−x)²·(1−x) dx = B(3,4) = 1/60 (L2²),
  // max x(1 − x) = 1/4 at x = 1/2 (a lattice point). Degree ≤ 4: exact with the degree-5 rule.
  const Vec2 p[3] = {Vec2{{0, 0}}, Vec2{{1, 0}}, Vec2{{0, 1}}};
  for (int levels : {0, 1, 2}) {
    const ErrorNorms e = triangle_interpolation_error(p, [](Vec2 q) { return q[0] * q[0]; },
                                                      ErrorQuadrature{levels, 8});
    EXPECT_NEAR(e.l1, 1.0 / 12, 1e-15) << levels;
    EXPECT_NEAR(e.l2, 1.0 / 60, 1e-15) << levels;
    EXPECT_NEAR(e.linf, 0.25, 1e-15) << levels;
  }
}

TEST(InterpolationError, QuadraticOnAMeshScalesAsHSquared) {
  // u = x² + y² on unit_square(n): on each right triangle of legs h the L2² error is
  // h⁶·(1/60 + 1/60 + cross term) — whatever the constant, halving h divides L2 by 4.
  auto u = [](Vec2 q) { return q[0] * q[0] + q[1] * q[1]; };
  const ErrorNorms a = interpolation_error(unit_square(4, 4), u);
  const ErrorNorms b = interpolation_error(unit_square(8, 8), u);
  EXPECT_NEAR(a.l2 / b.l2, 4.0, 1e-12);
  EXPECT_NEAR(a.l1 / b.l1, 4.0, 1e-12);
  EXPECT_NEAR(a.linf / b.linf, 4.0, 1e-12);
}

TEST(InterpolationError, RejectsOtherMeshesAndQuadratures) {
  auto u = [](Vec2) { return 0.0; };
  EXPECT_THROW(interpolation_error(unit_cube(1), u), InputError);
  EXPECT_THROW(interpolation_error(unit_square(1, 1), u, ErrorQuadrature{-1, 8}), InputError);
  EXPECT_THROW(interpolation_error(unit_square(1, 1), u, ErrorQuadrature{2, 0}), InputError);
}

TEST(PowerLaw, RecoversSyntheticSlope) {
  // y = 3 x^−1, perturbed by ±1% alternately: slope within 0.01.
  std::vector<double> x, y;
  for (int i = 0; i < 6; ++i) {
    x.push_back(500.0 * std::pow(2.0, i));
    y.push_back(3.0 / x.back() * (i % 2 ? 1.01 : 0.99));
  }
  const PowerFit f = fit_power_law(x, y);
  EXPECT_NEAR(f.slope, -1.0, 0.01);
  EXPECT_NEAR(f.coefficient, 3.0, 0.1);
  const std::vector<double> exact_x = {1, 10, 100}, exact_y = {2, 0.02, 0.0002};
  EXPECT_NEAR(fit_power_law(exact_x, exact_y).slope, -2.0, 1e-12);
  EXPECT_NEAR(fit_power_law(exact_x, exact_y).coefficient, 2.0, 1e-12);
}

TEST(PowerLaw, RejectsBadData) {
  const std::vector<double> one = {1}, two = {1, 2}, same = {2, 2}, neg = {1, -1};
  EXPECT_THROW(fit_power_law(one, one), InputError);
  EXPECT_THROW(fit_power_law(two, one), InputError);
  EXPECT_THROW(fit_power_law(same, two), InputError);
  EXPECT_THROW(fit_power_law(two, neg), InputError);
}

TEST(AnalyticFunctions, NamesAndValues) {
  ASSERT_EQ(analytic_functions().size(), 5u);
  for (const AnalyticFunction& f : analytic_functions()) {
    EXPECT_EQ(&analytic_function(f.name), &f);
    EXPECT_FALSE(f.formula.empty());
    for (double x : {-1.0, -0.3, 0.0, 0.7, 1.0})
      for (double y : {-1.0, 0.2, 1.0}) EXPECT_TRUE(std::isfinite(f.value(x, y))) << f.name;
  }
  EXPECT_THROW(analytic_function("nope"), InputError);
  // Spot values from the formulas.
  EXPECT_NEAR(analytic_function("hyperbolic").value(0.1, 0.2), std::sin(1.0), 1e-15);
  EXPECT_NEAR(analytic_function("boundary-layer").value(-1.0, 1.0), 1.0 + std::exp(-200.0), 1e-15);
  // tanh: at (x, y) = (0, −1), x' = 1/2, y' = 0: tanh(0) − tanh(0) = 0.
  EXPECT_NEAR(analytic_function("tanh").value(0.0, -1.0), 0.0, 1e-15);
  // The continuous branch of atan(0.1/t): at t = 0 it is π/2, not a jump.
  EXPECT_NEAR(analytic_function("multiscale").value(0.0, 0.0), std::numbers::pi / 2, 1e-15);
  const double left = analytic_function("multiscale").value(-1e-9, 0.0);
  const double right = analytic_function("multiscale").value(1e-9, 0.0);
  EXPECT_NEAR(left, right, 1e-6);
}
