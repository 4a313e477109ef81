// metric/complexity.hpp: ∫_K sqrt(det M(x)) dx — analytic for the log-Euclidean field,
// degree-5 quadrature otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/random_metrics.hpp"
#include "metric/complexity.hpp"

using namespace riemesh;

namespace {

/// ∫ over the unit simplex of Π λᵢ^pᵢ, divided by its measure: D! Π pᵢ! / (D + Σpᵢ)!.
double monomial_mean(const int* p, int d) {
  double num = std::tgamma(d + 1.0), sum = 0.0;
  for (int i = 0; i <= d; ++i) {
    num *= std::tgamma(p[i] + 1.0);
    sum += p[i];
  }
  return num / std::tgamma(d + sum + 1.0);
}

template <int D>
void check_rule_exactness() {
  using Rule = detail::SimplexRule<D>;
  int p[D + 1] = {};
  // All exponent tuples with total degree <= 5.
  for (int code = 0; code < 6 * 6 * 6 * 6; ++code) {
    int c = code, total = 0;
    for (int i = 0; i <= D; ++i) total += (p[i] = c % 6), c /= 6;
    if (c != 0 || total > 5) continue;
    double sum = 0.0;
    for (int q = 0; q < Rule::kPoints; ++q) {
      double v = Rule::kWeight[q];
      for (int i = 0; i <= D; ++i) v *= std::pow(Rule::kPoint[q][i], p[i]);
      sum += v;
    }
    EXPECT_NEAR(sum, monomial_mean(p, D), 1e-15);
  }
}

}  // namespace

TEST(Complexity, QuadratureRulesAreExactToDegreeFive) {
  check_rule_exactness<2>();
  check_rule_exactness<3>();
}

TEST(Complexity, ConstantMetric) {
  // sqrt(det M) |K| for every scheme.
  const Vec3 p[4] = {{{0, 0, 0}}, {{2, 0, 0}}, {{0, 1, 0}}, {{0, 0, 3}}};  // |K| = 1
  const SymMat3 m = SymMat3::diagonal(Vec3{{4, 9, 25}});                  // sqrt det = 30
  const SymMat3 ms[4] = {m, m, m, m};
  EXPECT_NEAR(complexity<3>(p, ms), 30.0, 1e-13);
  EXPECT_NEAR(complexity<3>(p, ms, InterpScheme::kLinear), 30.0, 1e-13);
  EXPECT_NEAR(complexity<3>(p, ms, InterpScheme::kSimredGeometric), 30.0, 1e-12);
  // Orientation does not matter.
  const Vec3 q[4] = {p[1], p[0], p[2], p[3]};
  EXPECT_NEAR(complexity<3>(q, ms), 30.0, 1e-13);
}

TEST(Complexity, LogEuclideanAnalytic2D) {
  // Unit right triangle (|K| = 1/2), sizes 1, 1/2, 1/10: sqrt(det Mᵢ) = 1, 4, 100, so
  // aᵢ = 0, ln 4, ln 100 and C = 2! |K| exp[a₀, a₁, a₂] with
  //   exp[a₀, a₁] = 3/ln 4, exp[a₁, a₂] = 96/ln 25, exp[a₀, a₁, a₂] = (96/ln 25 - 3/ln 4)/ln 100.
  const Vec2 p[3] = {{{0, 0}}, {{1, 0}}, {{0, 1}}};
  const SymMat2 m[3] = {isotropic_metric<2>(1.0), isotropic_metric<2>(0.5),
                        isotropic_metric<2>(0.1)};
  const double expect = (96.0 / std::log(25.0) - 3.0 / std::log(4.0)) / std::log(100.0);
  EXPECT_NEAR(complexity<2>(p, m), expect, 1e-13 * expect);
  // The iso-geometric field has the same sqrt(det M) = exp(affine); its degree-5 rule agrees
  // to the rule's accuracy for this variation (a factor 100 across the element: ~1e-3).
  EXPECT_NEAR(complexity<2>(p, m, InterpScheme::kIsoGeometric), expect, 2e-3 * expect);
}

TEST(Complexity, LogEuclideanAnalytic3DWithRepeatedValues) {
  // a = (0, 0, 0, s) on the unit tetrahedron (|K| = 1/6):
  //   ∫ exp(s λ₃) = 3! |K| exp[0,0,0,s] = (e^s - 1 - s - s²/2)/s³.
  const Vec3 p[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  for (double s : {1e-7, 1e-3, 0.5, 1.0, 3.0, 20.0}) {
    const double h = std::exp(-s / 3.0);  // sqrt(det(I/h²)) = h^{-3} = e^s
    const SymMat3 m[4] = {SymMat3::identity(), SymMat3::identity(), SymMat3::identity(),
                          isotropic_metric<3>(h)};
    // Series for small s: 1/6 + s/24 + s²/120 + s³/720 ...
    const double expect = s < 1e-2 ? 1.0 / 6 + s / 24 + s * s / 120 + s * s * s / 720
                                    : (std::exp(s) - 1 - s - s * s / 2) / (s * s * s);
    EXPECT_NEAR(complexity<3>(p, m), expect, 1e-12 * expect) << s;
  }
}

TEST(Complexity, LogEuclideanMatchesQuadratureForMildRandomFields) {
  // Anisotropic metrics whose determinants vary by up to e across the element: the analytic
  // value and the degree-5 rule on the log-Euclidean field itself agree closely.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  const Vec3 p[4] = {{{0, 0, 0}}, {{1, 0.1, 0}}, {{0.2, 1, 0.1}}, {{0.1, 0.3, 0.9}}};
  for (int k = 0; k < 20; ++k) {
    SymMat3 m[4];
    for (auto& mi : m) {
      const SymMat3 base = test_support::random_spd<3>(rng, 100.0);
      mi = std::exp(u(rng)) * std::pow(det(base), -1.0 / 3) * base;
    }
    const double analytic = complexity<3>(p, m);
    double quad = 0.0;
    using Rule = detail::SimplexRule<3>;
    for (int q = 0; q < Rule::kPoints; ++q)
      quad += Rule::kWeight[q] *
              std::sqrt(det(interpolate(InterpScheme::kLogEuclidean, m, Rule::kPoint[q])));
    quad *= std::abs(simplex_measure(p));
    EXPECT_NEAR(analytic, quad, 1e-6 * analytic);
  }
}

TEST(Complexity, ExpDividedDifferenceIsContinuousAcrossTheSeriesSwitch) {
  // Spread just below and above 1 (series vs recurrence); reference values from the recurrence
  // in 30-digit arithmetic (mpmath).
  const double below[3] = {0.0, 0.3, 1.0 - 1e-12}, above[3] = {0.0, 0.3, 1.0 + 1e-12};
  EXPECT_NEAR(detail::exp_divided_difference(below, 2), 0.788694004579271785, 1e-15);
  EXPECT_NEAR(detail::exp_divided_difference(above, 2), 0.788694004579875516, 1e-15);
  // exp[0, 1] = e - 1; exp[0, 1, 2] = (e - 1)²/2.
  const double x[3] = {0.0, 1.0, 2.0};
  EXPECT_NEAR(detail::exp_divided_difference(x, 1), std::exp(1.0) - 1, 1e-15);
  EXPECT_NEAR(detail::exp_divided_difference(x, 2), std::pow(std::exp(1.0) - 1, 2) / 2, 1e-14);
}
