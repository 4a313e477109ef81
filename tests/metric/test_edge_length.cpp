// metric/edge_length.hpp: metric length of an edge, geometric closed form and quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "core/random_metrics.hpp"
#include "metric/edge_length.hpp"

using namespace riemesh;
using test_support::random_spd;

namespace {
constexpr InterpScheme kAll[] = {
    InterpScheme::kLinear,          InterpScheme::kIsoLinear,    InterpScheme::kIsoGeometric,
    InterpScheme::kIsoHarmonic,     InterpScheme::kSimredLinear, InterpScheme::kSimredGeometric,
    InterpScheme::kPower,           InterpScheme::kLogEuclidean, InterpScheme::kCholesky,
    InterpScheme::kCholeskyGeometric};

/// A thin layer's metric (size hr across, ht along) with its stiff axis turned by `angle` from x.
SymMat2 turned_layer_metric(double hr, double ht, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Mat2 r;
  r(0, 0) = c, r(0, 1) = -s, r(1, 0) = s, r(1, 1) = c;
  return compose(r, Vec2{{1 / (hr * hr), 1 / (ht * ht)}});
}

}  // namespace

TEST(EdgeLength, GaussLegendreTablesAreExactToDegree2nMinus1) {
  // ∫₀¹ t^k dt = 1/(k + 1) for k <= 2n - 1.
  for (int n = 1; n <= 8; ++n) {
    const detail::GaussNode* rule = detail::kGaussLegendre01 + n * (n - 1) / 2;
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double sum = 0.0;
      for (int q = 0; q < n; ++q) sum += rule[q].w * std::pow(rule[q].t, k);
      EXPECT_NEAR(sum, 1.0 / (k + 1), 1e-15) << "n=" << n << " k=" << k;
    }
  }
}

TEST(EdgeLength, ConstantMetricGivesTheMetricNorm) {
  // M ≡ M_A: every scheme interpolates to M_A, and ‖AB‖_M = sqrt(ABᵀ M AB).
  std::mt19937_64 rng(1);
  const SymMat3 m = random_spd<3>(rng, 100.0);
  const Vec3 ab{{0.3, -1.2, 0.7}};
  const double expect = std::sqrt(quadratic(m, ab));
  EXPECT_NEAR(edge_length_geometric(m, m, ab), expect, 1e-15 * expect);
  for (InterpScheme s : kAll) {
    if (s == InterpScheme::kIsoLinear || s == InterpScheme::kIsoGeometric ||
        s == InterpScheme::kIsoHarmonic)
      continue;  // these replace M by the isotropic metric of the same volume
    for (int n = 1; n <= 8; ++n)
      EXPECT_NEAR(edge_length_quadrature(m, m, ab, s, n), expect, 1e-12 * expect)
          << scheme_name(s) << " n=" << n;
  }
}

TEST(EdgeLength, GeometricClosedFormAnalytic) {
  // Sizes 1 at A and 0.1 at B along a unit edge: l_A = 1, l_B = 10 and
  // l = (l_A - l_B)/ln(l_A/l_B) = 9/ln 10.
  const SymMat2 a = isotropic_metric<2>(1.0), b = isotropic_metric<2>(0.1);
  const Vec2 ab{{1.0, 0.0}};
  EXPECT_NEAR(edge_length_geometric(a, b, ab), 9.0 / std::log(10.0), 1e-14);
  EXPECT_NEAR(edge_length_geometric(b, a, ab), 9.0 / std::log(10.0), 1e-14);  // symmetric
  // Equal lengths: l_A.
  EXPECT_EQ(edge_length_geometric(a, a, ab), 1.0);
  EXPECT_EQ(edge_length_geometric(a, b, Vec2::zero()), 0.0);
}

TEST(EdgeLength, GeometricFormHasNoCancellationNearEqualLengths) {
  // l_B = l_A (1 + δ): the logarithmic mean δ/ln(1 + δ) = 1 + δ/2 - δ²/12 + δ³/24 - 19δ⁴/720
  // + O(δ⁵) (inverting the series of ln(1 + δ)/δ); the naive
  // quotient (l_A - l_B)/ln(l_A/l_B) would lose about |log10 δ| digits.
  for (double delta : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const SymMat2 a = SymMat2::identity(), b = SymMat2::diagonal((1 + delta) * (1 + delta));
    const double d2 = delta * delta;
    const double expect = 1.0 + delta / 2 - d2 / 12 + d2 * delta / 24 - 19 * d2 * d2 / 720;
    EXPECT_NEAR(edge_length_geometric(a, b, Vec2{{1.0, 0.0}}), expect, 1e-15) << delta;
  }
}

TEST(EdgeLength, GeometricFormMatchesQuadratureOnAGeometricField) {
  // The log-Euclidean field between two metrics with the same eigenvectors has sizes varying
  // geometrically in every direction, so along AB: ‖AB‖_{M(t)} = l_A^{1-t} l_B^t exactly —
  // when AB is an eigenvector. The 8-point rule integrates that exponential to ~1e-12.
  std::mt19937_64 rng(2);
  const Mat3 r = test_support::random_rotation<3>(rng);
  const SymMat3 a = compose(r, Vec3{{1.0, 4.0, 100.0}}), b = compose(r, Vec3{{50.0, 0.5, 2.0}});
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 ab = 0.7 * r.column(axis);
    const double closed = edge_length_geometric(a, b, ab);
    EXPECT_NEAR(edge_length_quadrature(a, b, ab, InterpScheme::kLogEuclidean, 8), closed,
                1e-11 * closed);
    EXPECT_NEAR(edge_length_quadrature(a, b, ab, InterpScheme::kSimredGeometric, 8), closed,
                1e-11 * closed);
  }
}

TEST(EdgeLength, QuadratureConvergesAndRejectsBadPointCounts) {
  std::mt19937_64 rng(3);
  const SymMat3 a = random_spd<3>(rng, 1e3), b = random_spd<3>(rng, 1e3);
  const Vec3 ab{{1.0, 2.0, -0.5}};
  for (InterpScheme s : kAll) {
    const double l8 = edge_length_quadrature(a, b, ab, s, 8);
    EXPECT_GT(l8, 0.0);
    // Anisotropy 1e3 at both ends makes some fields vary sharply: 7 and 8 points agree to ~1%.
    EXPECT_NEAR(edge_length_quadrature(a, b, ab, s, 7), l8, 1e-2 * l8) << scheme_name(s);
    // The simred fast path agrees with the generic interpolation.
    double generic = 0.0;
    const detail::GaussNode* rule = detail::kGaussLegendre01 + 5 * 4 / 2;
    for (int q = 0; q < 5; ++q) generic += rule[q].w * length(interpolate(s, a, b, rule[q].t), ab);
    EXPECT_NEAR(edge_length_quadrature(a, b, ab, s, 5), generic, 1e-10 * generic)
        << scheme_name(s);
  }
  EXPECT_THROW(edge_length_quadrature(a, b, ab, InterpScheme::kLogEuclidean, 0), InputError);
  EXPECT_THROW(edge_length_quadrature(a, b, ab, InterpScheme::kLogEuclidean, 9), InputError);
}

TEST(EdgeLength, CommuteTellsSharedEigenvectors) {
  std::mt19937_64 rng(5);
  const Mat3 r = test_support::random_rotation<3>(rng);
  const SymMat3 a = compose(r, Vec3{{1.0, 4.0, 100.0}}), b = compose(r, Vec3{{50.0, 0.5, 2.0}});
  EXPECT_TRUE(commute(a, b));
  EXPECT_TRUE(commute(SymMat3::diagonal(Vec3{{1.0, 2.0, 3.0}}),
                      SymMat3::diagonal(Vec3{{7.0, 5.0, 3.0}})));
  EXPECT_TRUE(commute(3.0 * SymMat3::identity(), random_spd<3>(rng)));
  EXPECT_FALSE(commute(a, random_spd<3>(rng)));
  const Mat3 s = test_support::random_rotation<3>(rng);
  EXPECT_FALSE(commute(a, compose(s, Vec3{{1.0, 4.0, 100.0}})));
}

TEST(EdgeLength, SimpsonSeesTheMetricTurnAlongAChord) {
  // A chord of a circle across a thin layer: at its ends the metric's stiff (radial) axis is
  // turned by ±phi from the chord's normal, at its middle the chord is tangent. In 2D, the log
  // metrics L(±phi) = R(±phi) diag(α, β) R(±phi)ᵀ average to the diagonal
  // (α + β)/2 I + (α − β)/2 cos(2 phi) diag(1, −1), so along the chord (the y axis)
  // l_M² = |ab|² exp((α + β)/2 − (α − β)/2 cos(2 phi)).
  const double hr = 0.001, ht = 0.1, phi = 0.045, len = 0.045;
  const double alpha = std::log(1 / (hr * hr)), beta = std::log(1 / (ht * ht));
  const auto metric = [&](double angle) { return turned_layer_metric(hr, ht, angle); };
  const SymMat2 ma = metric(phi), mb = metric(-phi);
  const Vec2 ab{{0.0, len}};
  const double l_end = len * std::sqrt(std::sin(phi) * std::sin(phi) / (hr * hr) +
                                       std::cos(phi) * std::cos(phi) / (ht * ht));
  const double l_mid =
      len * std::exp(0.25 * (alpha + beta) - 0.25 * (alpha - beta) * std::cos(2 * phi));
  const double simpson = edge_length_simpson(ma, mb, ab);
  EXPECT_NEAR(simpson, (2 * l_end + 4 * l_mid) / 6, 1e-9 * simpson);
  // The end lengths alone (the closed form) call the chord about twice as long as it is in the
  // interpolated field (8-point Gauss rule: 1.147); Simpson's rule reads the V-shaped integrand
  // 13% short (0.994).
  const double gauss = edge_length_quadrature(ma, mb, ab, InterpScheme::kLogEuclidean, 8);
  EXPECT_GT(edge_length_geometric(ma, mb, ab), 1.8 * gauss);
  EXPECT_NEAR(simpson, gauss, 0.15 * gauss);
}

TEST(EdgeLength, SimpsonIsTheClosedFormForCommutingMetrics) {
  std::mt19937_64 rng(7);
  const Mat3 r = test_support::random_rotation<3>(rng);
  const SymMat3 a = compose(r, Vec3{{1.0, 4.0, 100.0}}), b = compose(r, Vec3{{50.0, 0.5, 2.0}});
  for (int k = 0; k < 20; ++k) {
    const Vec3 ab{{std::uniform_real_distribution<double>(-1, 1)(rng),
                   std::uniform_real_distribution<double>(-1, 1)(rng),
                   std::uniform_real_distribution<double>(-1, 1)(rng)}};
    EXPECT_EQ(edge_length_simpson(a, b, ab),
              edge_length_geometric(a, b, ab));
  }
  EXPECT_EQ(edge_length_simpson(a, a, Vec3{{0.3, 0.1, 0.2}}),
            length(a, Vec3{{0.3, 0.1, 0.2}}));
}

TEST(EdgeLength, SimpsonTakesTheLogarithmsGivenOrComputesThem) {
  std::mt19937_64 rng(11);
  const SymMat3 a = random_spd<3>(rng), b = random_spd<3>(rng);
  const SymMat3 la = log_spd(a), lb = log_spd(b);
  const Vec3 ab{{0.3, -0.2, 0.5}};
  EXPECT_EQ(edge_length_simpson(a, b, ab, &la, &lb), edge_length_simpson(a, b, ab));
  EXPECT_EQ(compare_edge_length_simpson(a, b, ab, edge_length_simpson(a, b, ab)), 0);
  EXPECT_EQ(compare_edge_length_simpson(a, b, ab, 0.5 * edge_length_simpson(a, b, ab)), 1);
}

TEST(EdgeLength, Gauss3IsTheThreePointRuleOnTheLogEuclideanField) {
  // Where the metrics turn: the 3-point Gauss–Legendre rule of edge_length_quadrature (exp by
  // eigendecomposition there, by its series here: equal to rounding).
  std::mt19937_64 rng(13);
  for (int k = 0; k < 20; ++k) {
    const SymMat2 a = random_spd<2>(rng), b = random_spd<2>(rng);
    const Vec2 ab{{std::uniform_real_distribution<double>(-1, 1)(rng),
                   std::uniform_real_distribution<double>(-1, 1)(rng)}};
    const double g3 = edge_length_quadrature(a, b, ab, InterpScheme::kLogEuclidean, 3);
    EXPECT_NEAR(edge_length_gauss3(a, b, ab), g3, 1e-10 * g3);
    const SymMat2 la = log_spd(a), lb = log_spd(b);
    EXPECT_EQ(edge_length_gauss3(a, b, ab, &la, &lb), edge_length_gauss3(a, b, ab));
  }
  // Commuting metrics: the closed form, as Simpson's rule.
  const SymMat2 d1{{4.0, 0.0, 100.0}}, d2{{50.0, 0.0, 2.0}};
  EXPECT_EQ(edge_length_gauss3(d1, d2, Vec2{{0.3, 0.2}}),
            edge_length_geometric(d1, d2, Vec2{{0.3, 0.2}}));
}

TEST(EdgeLength, Gauss3ReadsTheTurningChordCloserThanSimpson) {
  // The chord of SimpsonSeesTheMetricTurnAlongAChord: the 8-point rule on the interpolated field
  // gives 1.147, Simpson's rule 0.994 (13% short), the 3-point rule 1.106 (3.6% short).
  const double hr = 0.001, ht = 0.1, phi = 0.045, len = 0.045;
  const auto metric = [&](double angle) { return turned_layer_metric(hr, ht, angle); };
  const SymMat2 ma = metric(phi), mb = metric(-phi);
  const Vec2 ab{{0.0, len}};
  const double gauss8 = edge_length_quadrature(ma, mb, ab, InterpScheme::kLogEuclidean, 8);
  const double g3 = edge_length_gauss3(ma, mb, ab);
  EXPECT_NEAR(g3, gauss8, 0.04 * gauss8);
  EXPECT_GT(std::abs(edge_length_simpson(ma, mb, ab) - gauss8), 2.5 * std::abs(g3 - gauss8));
}
