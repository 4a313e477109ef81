// metric/interpolation.hpp: the interpolation schemes of BOOK.md §1 — analytic values,
// endpoints, isotropy, rotation invariance, the maximum principle and its counterexamples.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <type_traits>

#include "core/error.hpp"
#include "core/random_metrics.hpp"
#include "core/spd.hpp"
#include "metric/intersection.hpp"
#include "metric/interpolation.hpp"
#include "metric/metric.hpp"

using namespace riemesh;
using test_support::random_rotation;
using test_support::random_spd;

namespace {

constexpr InterpScheme kAll[] = {
    InterpScheme::kLinear,          InterpScheme::kIsoLinear,    InterpScheme::kIsoGeometric,
    InterpScheme::kIsoHarmonic,     InterpScheme::kSimredLinear, InterpScheme::kSimredGeometric,
    InterpScheme::kPower,           InterpScheme::kLogEuclidean, InterpScheme::kCholesky,
    InterpScheme::kCholeskyGeometric};

bool rotation_invariant(InterpScheme s) {
  return s != InterpScheme::kCholesky && s != InterpScheme::kCholeskyGeometric;
}

template <int D>
double rel_err(const SymMat<D>& x, const SymMat<D>& ref) {
  return frobenius(x - ref) / frobenius(ref);
}

template <class T>
class InterpolationTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(InterpolationTest, Dims);

}  // namespace

TEST(Interpolation, SchemeNamesRoundTrip) {
  for (InterpScheme s : kAll) EXPECT_EQ(parse_interp_scheme(scheme_name(s)), s);
  EXPECT_EQ(parse_interp_scheme("log"), InterpScheme::kLogEuclidean);
  try {
    parse_interp_scheme("logeuclid");
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("logeuclid"), std::string::npos);
    EXPECT_NE(what.find("cholesky-geometric"), std::string::npos);  // lists the valid names
  }
}

TEST(Interpolation, CrossedDiagonalPairAnalytic) {
  // a = diag(1, 4), b = diag(4, 1) at t = 1/2 (commuting, so every scheme acts per axis):
  //   log:   exp((log a + log b)/2) = diag(√(1·4), √(4·1)) = 2I;
  //   simred-geometric: sizes (1, 1/2), (1/2, 1) -> geometric means 1/√2 -> 2I as well;
  //   linear: (a + b)/2 = 2.5 I;
  //   simred-linear: sizes averaged to 3/4 -> I/(3/4)² = (16/9) I;
  //   power: ((a^{-1/2} + b^{-1/2})/2)^{-2} = (3/4 I)^{-2} = (16/9) I, the same here.
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 4}}), b = SymMat2::diagonal(Vec2{{4, 1}});
  const auto at_half = [&](InterpScheme s) { return interpolate(s, a, b, 0.5); };
  EXPECT_LE(rel_err(at_half(InterpScheme::kLogEuclidean), SymMat2::diagonal(2.0)), 1e-15);
  EXPECT_LE(rel_err(at_half(InterpScheme::kSimredGeometric), SymMat2::diagonal(2.0)), 1e-15);
  EXPECT_LE(rel_err(at_half(InterpScheme::kCholeskyGeometric), SymMat2::diagonal(2.0)), 1e-15);
  EXPECT_LE(rel_err(at_half(InterpScheme::kLinear), SymMat2::diagonal(2.5)), 1e-15);
  EXPECT_LE(rel_err(at_half(InterpScheme::kSimredLinear), SymMat2::diagonal(16.0 / 9)), 1e-15);
  EXPECT_LE(rel_err(at_half(InterpScheme::kPower), SymMat2::diagonal(16.0 / 9)), 1e-15);
  // Both have det 4 and h_iso = 4^{-1/4}; all iso schemes give I/h² = 2I.
  EXPECT_LE(rel_err(at_half(InterpScheme::kIsoHarmonic), SymMat2::diagonal(2.0)), 1e-15);
}

TEST(Interpolation, IsotropicSchemesAnalytic) {
  // h = 1 and h = 1/4 at t = 1/2: linear 5/8, geometric 1/2, harmonic 2/(1 + 4) = 2/5.
  const SymMat2 a = isotropic_metric<2>(1.0), b = isotropic_metric<2>(0.25);
  EXPECT_NEAR(interpolate(InterpScheme::kIsoLinear, a, b, 0.5).c[0], 1.0 / (0.625 * 0.625), 1e-13);
  EXPECT_NEAR(interpolate(InterpScheme::kIsoGeometric, a, b, 0.5).c[0], 4.0, 1e-13);
  EXPECT_NEAR(interpolate(InterpScheme::kIsoHarmonic, a, b, 0.5).c[0], 6.25, 1e-13);
}

TEST(Interpolation, CholeskyDependsOnTheFrame) {
  // The Cholesky factor is not rotation equivariant: rotating the inputs by 30° changes the
  // result by more than a rotation.
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 100}});
  const SymMat2 b{{50.0, 20.0, 30.0}};
  const double c = std::cos(0.5), s = std::sin(0.5);
  const Mat2 r{{{c, -s}, {s, c}}};
  const SymMat2 direct = congruence(r, interpolate(InterpScheme::kCholesky, a, b, 0.5));
  const SymMat2 rotated =
      interpolate(InterpScheme::kCholesky, congruence(r, a), congruence(r, b), 0.5);
  EXPECT_GT(rel_err(rotated, direct), 1e-3);
}

TYPED_TEST(InterpolationTest, EndpointsAreExactForEveryScheme) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(1);
  const SymMat<D> m[3] = {random_spd<D>(rng), random_spd<D>(rng), random_spd<D>(rng)};
  for (InterpScheme s : kAll) {
    EXPECT_EQ(interpolate(s, m[0], m[1], 0.0), m[0]) << scheme_name(s);
    EXPECT_EQ(interpolate(s, m[0], m[1], 1.0), m[1]) << scheme_name(s);
    const double w[3] = {0.0, 0.0, 1.0};
    EXPECT_EQ(interpolate(s, m, w), m[2]) << scheme_name(s);
    // And continuous there: t = 1e-9 stays within ~1e-6 of the end (anisotropy up to 1e3).
    // Not the iso schemes: they return an isotropic metric inside the edge, so they are
    // continuous at the ends only for isotropic inputs (their intended use).
    if (s == InterpScheme::kIsoLinear || s == InterpScheme::kIsoGeometric ||
        s == InterpScheme::kIsoHarmonic)
      continue;
    EXPECT_LE(rel_err(interpolate(s, m[0], m[1], 1e-9), m[0]), 1e-5) << scheme_name(s);
  }
}

TYPED_TEST(InterpolationTest, EqualEndsGiveTheirMetricExactly) {
  // Inside an edge whose ends carry the same metric every scheme gives that metric, to the last
  // bit (a constant field stays constant: riemesh mesh and adapt2d then skip the background).
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(3);
  const SymMat<D> m = random_spd<D>(rng), iso = isotropic_metric<D>(0.01);
  for (InterpScheme s : kAll)
    for (const double t : {0.25, 0.5, 0.7}) {
      EXPECT_EQ(interpolate(s, m, m, t), m) << scheme_name(s) << " " << t;
      EXPECT_EQ(interpolate(s, iso, iso, t), iso) << scheme_name(s) << " " << t;
    }
}

TYPED_TEST(InterpolationTest, IsotropicInputsGiveIsotropicOutputs) {
  constexpr int D = TypeParam::value;
  const SymMat<D> m[3] = {isotropic_metric<D>(1.0), isotropic_metric<D>(0.1),
                          isotropic_metric<D>(0.3)};
  const double w[3] = {0.2, 0.5, 0.3};
  // Geometric size mean: h = 1^0.2 · 0.1^0.5 · 0.3^0.3.
  const double h_geo = std::pow(0.1, 0.5) * std::pow(0.3, 0.3);
  for (InterpScheme s : kAll) {
    const SymMat<D> r = interpolate(s, m, w);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j)
        EXPECT_NEAR(r(i, j), i == j ? r(0, 0) : 0.0, 1e-12 * r(0, 0)) << scheme_name(s);
  }
  for (InterpScheme s : {InterpScheme::kLogEuclidean, InterpScheme::kIsoGeometric,
                         InterpScheme::kSimredGeometric, InterpScheme::kCholeskyGeometric})
    EXPECT_NEAR(interpolate(s, m, w)(0, 0) * h_geo * h_geo, 1.0, 1e-13) << scheme_name(s);
}

TYPED_TEST(InterpolationTest, LogEuclideanOfCommutingMetricsIsTheGeometricMean) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(2);
  const Mat<D> r = random_rotation<D>(rng);
  Vec<D> l0{}, l1{}, l2{}, expect{};
  for (int i = 0; i < D; ++i) {
    l0[i] = std::pow(10.0, i);
    l1[i] = std::pow(10.0, -i);
    l2[i] = 3.0 + i;
    expect[i] = std::pow(l0[i], 0.5) * std::pow(l1[i], 0.25) * std::pow(l2[i], 0.25);
  }
  const SymMat<D> m[3] = {compose(r, l0), compose(r, l1), compose(r, l2)};
  const double w[3] = {0.5, 0.25, 0.25};
  EXPECT_LE(rel_err(interpolate(InterpScheme::kLogEuclidean, m, w), compose(r, expect)), 1e-13);
  // The fast path from stored logarithms gives the same.
  const SymMat<D> logs[3] = {log_spd(m[0]), log_spd(m[1]), log_spd(m[2])};
  EXPECT_LE(rel_err(interpolate_log_euclidean_logs<D>(logs, w), compose(r, expect)), 1e-13);
}

TYPED_TEST(InterpolationTest, RandomPropertiesSpdAndRotationInvariance) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const SymMat<D> m[3] = {random_spd<D>(rng), random_spd<D>(rng), random_spd<D>(rng)};
    const double a = u01(rng), b = u01(rng) * (1 - a);
    const double w[3] = {a, b, 1 - a - b};
    const Mat<D> rot = random_rotation<D>(rng);
    const SymMat<D> mr[3] = {congruence(rot, m[0]), congruence(rot, m[1]), congruence(rot, m[2])};
    for (InterpScheme s : kAll) {
      const SymMat<D> r = interpolate(s, m, w);
      EXPECT_TRUE(is_spd(r)) << scheme_name(s);
      if (rotation_invariant(s)) {
        EXPECT_TRUE(metrics_equal(interpolate(s, mr, w), congruence(rot, r), 1e-8))
            << scheme_name(s);
      }
    }
  }
}

TYPED_TEST(InterpolationTest, MaximumPrincipleOnDeterminant) {
  // det M between min and max of det Mᵢ: log-Euclidean (det exp(ΣwᵢlogMᵢ) = Π det Mᵢ^wᵢ),
  // simred-geometric (pairs, sequentially), cholesky-geometric and the iso schemes.
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const SymMat<D> m[3] = {random_spd<D>(rng), random_spd<D>(rng), random_spd<D>(rng)};
    const double a = u01(rng), b = u01(rng) * (1 - a);
    const double w[3] = {a, b, 1 - a - b};
    const double lo = std::min({det(m[0]), det(m[1]), det(m[2])});
    const double hi = std::max({det(m[0]), det(m[1]), det(m[2])});
    for (InterpScheme s :
         {InterpScheme::kLogEuclidean, InterpScheme::kSimredGeometric,
          InterpScheme::kCholeskyGeometric, InterpScheme::kIsoLinear, InterpScheme::kIsoGeometric,
          InterpScheme::kIsoHarmonic}) {
      const double d = det(interpolate(s, m, w));
      EXPECT_GE(d, lo * (1 - 1e-9)) << scheme_name(s);
      EXPECT_LE(d, hi * (1 + 1e-9)) << scheme_name(s);
    }
  }
}

TEST(Interpolation, MaximumPrincipleCounterexamples) {
  // a = diag(1, 100), b = diag(100, 1), both det 100, t = 1/2 (sizes (1, 0.1) and (0.1, 1)):
  //   linear: (a + b)/2 = 50.5 I, det 2550.25 > 100 (too fine: anisotropy lost upwards);
  //   simred-linear: sizes (0.55, 0.55) -> I/0.3025, det 1/0.3025² ≈ 10.93 < 100;
  //   power: ((diag(1, .1) + diag(.1, 1))/2)^{-2} = the same I/0.3025;
  //   cholesky: L = ((diag(1,.1) + diag(.1,1))/2)^{-1} = I/0.55, the same again;
  //   log: exp(diag(ln 10, ln 10)) = 10 I, det exactly 100.
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 100}}), b = SymMat2::diagonal(Vec2{{100, 1}});
  EXPECT_NEAR(det(interpolate(InterpScheme::kLinear, a, b, 0.5)), 2550.25, 1e-9);
  const double diluted = 1.0 / (0.3025 * 0.3025);
  EXPECT_NEAR(det(interpolate(InterpScheme::kSimredLinear, a, b, 0.5)), diluted, 1e-9);
  EXPECT_NEAR(det(interpolate(InterpScheme::kPower, a, b, 0.5)), diluted, 1e-9);
  EXPECT_NEAR(det(interpolate(InterpScheme::kCholesky, a, b, 0.5)), diluted, 1e-9);
  EXPECT_NEAR(det(interpolate(InterpScheme::kLogEuclidean, a, b, 0.5)), 100.0, 1e-11);
  EXPECT_NEAR(det(interpolate(InterpScheme::kSimredGeometric, a, b, 0.5)), 100.0, 1e-11);
}

TYPED_TEST(InterpolationTest, SimredIsOrderDependentLogIsNot) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(5);
  const SymMat<D> m[3] = {random_spd<D>(rng, 100), random_spd<D>(rng, 100), random_spd<D>(rng, 100)};
  const double w[3] = {0.3, 0.3, 0.4};
  const SymMat<D> log_abc = interpolate(InterpScheme::kLogEuclidean, m, w);
  const SymMat<D> sim_abc = interpolate(InterpScheme::kSimredGeometric, m, w);
  // The same metrics and weights, listed in the order (m₂, m₀, m₁).
  const SymMat<D> perm[3] = {m[2], m[0], m[1]};
  const double wp[3] = {w[2], w[0], w[1]};
  EXPECT_TRUE(metrics_equal(interpolate(InterpScheme::kLogEuclidean, perm, wp), log_abc, 1e-12));
  EXPECT_FALSE(
      metrics_equal(interpolate(InterpScheme::kSimredGeometric, perm, wp), sim_abc, 1e-6));
  // Simred-geometric's determinant is still order independent: Π det^wᵢ either way.
  EXPECT_NEAR(det(interpolate(InterpScheme::kSimredGeometric, perm, wp)) / det(sim_abc), 1.0,
              1e-10);
}
