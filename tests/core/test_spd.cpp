// Functions of SPD tensors: log/exp round trips, sqrt and powers, the SPD check and projection.
#include <gtest/gtest.h>

#include <limits>

#include "core/random_metrics.hpp"
#include "core/spd.hpp"

using namespace riemesh;

namespace {
template <int D>
double rel_diff(const SymMat<D>& a, const SymMat<D>& b) {
  return frobenius(a - b) / frobenius(b);
}
}  // namespace

TEST(Spd, LogOfDiagonal) {
  const SymMat3 l = log_spd(SymMat3{{std::exp(1.0), 0, std::exp(-2.0), 0, 0, 1.0}});
  EXPECT_NEAR(l(0, 0), 1.0, 1e-15);
  EXPECT_NEAR(l(1, 1), -2.0, 1e-15);
  EXPECT_NEAR(l(2, 2), 0.0, 1e-15);
}

TEST(Spd, LogExpRoundTrip) {
  std::mt19937_64 rng(3);
  for (int s = 0; s < 1000; ++s) {
    const SymMat3 m = test_support::random_spd<3>(rng, 1e6);
    EXPECT_LT(rel_diff(exp_sym(log_spd(m)), m), 1e-12);
    const SymMat2 m2 = test_support::random_spd<2>(rng, 1e6);
    EXPECT_LT(rel_diff(exp_sym(log_spd(m2)), m2), 1e-12);
  }
}

TEST(Spd, LogOfRotatedTensorIsRotatedLog) {
  // log(R diag(λ) Rᵀ) = R diag(log λ) Rᵀ.
  std::mt19937_64 rng(5);
  const Mat3 r = test_support::random_rotation<3>(rng);
  const Vec3 l{{0.01, 1.0, 400.0}};
  const SymMat3 expected = compose(r, Vec3{{std::log(0.01), 0.0, std::log(400.0)}});
  EXPECT_LT(frobenius(log_spd(compose(r, l)) - expected), 1e-13);
}

TEST(Spd, SqrtSquaresBack) {
  std::mt19937_64 rng(9);
  for (int s = 0; s < 200; ++s) {
    const SymMat3 m = test_support::random_spd<3>(rng, 1e4);
    const Mat3 h = sqrt_spd(m).to_mat();
    EXPECT_LT(rel_diff(SymMat3::from_mat(h * h), m), 1e-12);
  }
}

TEST(Spd, PowerMinusHalfIsInverseSqrt) {
  // M^{-1/2} M M^{-1/2} = I.
  std::mt19937_64 rng(13);
  for (int s = 0; s < 200; ++s) {
    const SymMat2 m = test_support::random_spd<2>(rng, 1e4);
    const Mat2 p = pow_spd(m, -0.5).to_mat();
    const SymMat2 i = SymMat2::from_mat(p * m.to_mat() * p);
    EXPECT_LT(frobenius(i - SymMat2::identity()), 1e-11);
  }
}

TEST(Spd, IsSpd) {
  EXPECT_TRUE(is_spd(SymMat2{{1.0, 0.5, 1.0}}));
  EXPECT_FALSE(is_spd(SymMat2{{1.0, 2.0, 1.0}}));   // eigenvalues -1 and 3
  EXPECT_FALSE(is_spd(SymMat2{{1.0, 1.0, 1.0}}));   // singular
  EXPECT_FALSE(is_spd(SymMat3{{1, 0, 1, 0, 0, 0}}));  // semi-definite
  EXPECT_FALSE(is_spd(SymMat3{{1, 0, std::numeric_limits<double>::quiet_NaN(), 0, 0, 1}}));
  EXPECT_FALSE(is_spd(SymMat3{{1, 0, std::numeric_limits<double>::infinity(), 0, 0, 1}}));
  EXPECT_TRUE(is_spd(SymMat3{{1e12, 0, 1, 0, 0, 1e-12}}));
}

TEST(Spd, ProjectionClipsEigenvalues) {
  // [[1,2],[2,1]] has eigenvalues -1 and 3 along (1,-1) and (1,1); clipping to [0.5, 2]
  // gives 0.5 (1,-1)(1,-1)ᵀ/2 + 2 (1,1)(1,1)ᵀ/2 = [[1.25, 0.75], [0.75, 1.25]].
  const SymMat2 p = project_spd(SymMat2{{1.0, 2.0, 1.0}}, 0.5, 2.0);
  EXPECT_NEAR(p(0, 0), 1.25, 1e-15);
  EXPECT_NEAR(p(0, 1), 0.75, 1e-15);
  EXPECT_NEAR(p(1, 1), 1.25, 1e-15);
  EXPECT_TRUE(is_spd(p));
}

TEST(Spd, SeriesExponentialIsTheSpectralOne) {
  // exp(R diag(l) Rᵀ) = R diag(exp l) Rᵀ, for log-eigenvalue spreads up to 24 (anisotropy 1.6e5
  // in sizes, as in a boundary layer) and any scale.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-12.0, 12.0);
  double worst3 = 0.0, worst2 = 0.0;
  for (int s = 0; s < 2000; ++s) {
    const Mat3 r = test_support::random_rotation<3>(rng);
    const Vec3 l{{u(rng), u(rng), u(rng)}};
    const SymMat3 expected = compose(r, Vec3{{std::exp(l[0]), std::exp(l[1]), std::exp(l[2])}});
    worst3 = std::max(worst3, rel_diff(exp_sym_series(compose(r, l)), expected));
    const Mat2 r2 = test_support::random_rotation<2>(rng);
    const Vec2 l2{{u(rng), u(rng)}};
    const SymMat2 expected2 = compose(r2, Vec2{{std::exp(l2[0]), std::exp(l2[1])}});
    worst2 = std::max(worst2, rel_diff(exp_sym_series(compose(r2, l2)), expected2));
  }
  EXPECT_LT(worst3, 1e-10);
  EXPECT_LT(worst2, 1e-10);
  // Isotropic: the scalar exponential, exactly in its trace-free part.
  const SymMat3 e = exp_sym_series(SymMat3::diagonal(-3.0));
  EXPECT_NEAR(e(0, 0), std::exp(-3.0), 1e-15);
  EXPECT_EQ(e(0, 1), 0.0);
}
