// fast_exp against the long-double exponential, and exp_sym_2d (its closed form) against the
// spectral exponential.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "core/fast_exp.hpp"
#include "core/random_metrics.hpp"
#include "core/spd.hpp"

using namespace riemesh;

namespace {
/// |f − e| in units in the last place of e (the double nearest e^x).
double ulps(double f, long double e) {
  const double d = static_cast<double>(e);
  const double ulp = std::nextafter(d, std::numeric_limits<double>::infinity()) - d;
  return static_cast<double>(std::fabs(static_cast<long double>(f) - e)) / ulp;
}
}  // namespace

TEST(FastExp, WithinTwoUlpOverItsRange) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> wide(-700.0, 700.0), metric(-30.0, 30.0),
      small(-1e-3, 1e-3);
  double worst = 0.0;
  for (int i = 0; i < 300000; ++i)
    for (const double x : {wide(rng), metric(rng), small(rng)})
      worst = std::max(worst, ulps(fast_exp(x), std::exp(static_cast<long double>(x))));
  EXPECT_LT(worst, 2.0);
  // Round-to-even boundaries of k (x / ln 2 half-integers) and the range's ends.
  for (int k = -1000; k <= 1000; ++k) {
    const double x = (k + 0.5) * 0.6931471805599453;
    if (std::abs(x) <= 700.0) {
      EXPECT_LT(ulps(fast_exp(x), std::exp(static_cast<long double>(x))), 2.0) << x;
    }
  }
  EXPECT_EQ(fast_exp(0.0), 1.0);
  EXPECT_LT(ulps(fast_exp(700.0), std::exp(700.0L)), 2.0);
  EXPECT_LT(ulps(fast_exp(-700.0), std::exp(-700.0L)), 2.0);
}

TEST(FastExp, OutsideItsRangeItIsStdExp) {
  EXPECT_EQ(fast_exp(710.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(fast_exp(-746.0), 0.0);
  EXPECT_EQ(fast_exp(-710.0), std::exp(-710.0));  // subnormal
  EXPECT_EQ(fast_exp(-std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_TRUE(std::isnan(fast_exp(std::numeric_limits<double>::quiet_NaN())));
}

TEST(ExpSym2d, ClosedFormIsTheSpectralExponential) {
  // exp(R diag(l) Rᵀ) = R diag(exp l) Rᵀ: log-eigenvalue spreads from 0 (the series branch below
  // δ = 1e-3) to 24, any scale.
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-12.0, 12.0), tiny(-2e-3, 2e-3);
  double worst = 0.0;
  for (int s = 0; s < 4000; ++s) {
    const Mat2 r = test_support::random_rotation<2>(rng);
    const double l0 = u(rng), l1 = s % 2 ? u(rng) : l0 + tiny(rng);
    const SymMat2 expected = compose(r, Vec2{{std::exp(l0), std::exp(l1)}});
    const SymMat2 got = exp_sym_2d(compose(r, Vec2{{l0, l1}}));
    worst = std::max(worst, frobenius(got - expected) / frobenius(expected));
  }
  EXPECT_LT(worst, 1e-14);
  // Isotropic: the scalar exponential, no off-diagonal term.
  const SymMat2 e = exp_sym_2d(SymMat2{{-3.0, 0.0, -3.0}});
  EXPECT_NEAR(e(0, 0), std::exp(-3.0), 1e-15);
  EXPECT_EQ(e(0, 1), 0.0);
  EXPECT_EQ(e(0, 0), e(1, 1));
  // exp_sym_series is this form in 2D.
  const SymMat2 m{{0.3, -1.7, 2.5}};
  EXPECT_EQ(frobenius(exp_sym_series(m) - exp_sym_2d(m)), 0.0);
}
