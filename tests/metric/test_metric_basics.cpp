// metric/metric.hpp: lengths, angles, measures, sizes and constructors (BOOK.md §1).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

TEST(MetricBasics, LengthInAnisotropicMetric) {
  // M = diag(1/h1², 1/h2²) with h = (2, 0.5): u = (2, 0) is one size long, v = (0, 1) two.
  const SymMat2 m = SymMat2::diagonal(Vec2{{0.25, 4.0}});
  EXPECT_DOUBLE_EQ(length(m, Vec2{{2.0, 0.0}}), 1.0);
  EXPECT_DOUBLE_EQ(length(m, Vec2{{0.0, 1.0}}), 2.0);
  // (2, 1): sqrt(4·0.25 + 1·4) = sqrt(5).
  EXPECT_DOUBLE_EQ(length(m, Vec2{{2.0, 1.0}}), std::sqrt(5.0));
}

TEST(MetricBasics, AngleIsMeasuredInTheMetric) {
  // In M = diag(1, 4) the vectors (1, 0) and (0, 1) stay orthogonal, while (1, 1) and (1, -1)
  // have <u,v>_M = 1 - 4 = -3, |u|² = |v|² = 5: cos θ = -3/5.
  const SymMat2 m = SymMat2::diagonal(Vec2{{1.0, 4.0}});
  EXPECT_NEAR(angle(m, Vec2{{1.0, 0.0}}, Vec2{{0.0, 1.0}}), std::numbers::pi / 2, 1e-15);
  EXPECT_NEAR(angle(m, Vec2{{1.0, 1.0}}, Vec2{{1.0, -1.0}}), std::acos(-0.6), 1e-15);
}

TEST(MetricBasics, SimplexMeasures) {
  const Vec2 tri[3] = {{{0, 0}}, {{2, 0}}, {{0, 3}}};
  EXPECT_DOUBLE_EQ(simplex_measure(tri), 3.0);  // 2·3/2
  const Vec3 tet[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  EXPECT_DOUBLE_EQ(simplex_measure(tet), 1.0 / 6.0);
  // In M = diag(4, 9, 1), volumes scale by sqrt(det M) = 6.
  EXPECT_DOUBLE_EQ(simplex_measure(SymMat3::diagonal(Vec3{{4, 9, 1}}), tet), 1.0);
}

TEST(MetricBasics, SizesAndAnisotropyFromConstructors) {
  const double c = std::cos(0.3), s = std::sin(0.3);
  const Mat2 r{{{c, -s}, {s, c}}};
  const SymMat2 m = metric_from_sizes(r, Vec2{{0.5, 2.0}});
  const MetricSizes<2> sz = sizes(m);
  EXPECT_NEAR(sz.sizes[0], 2.0, 1e-14);  // largest size first
  EXPECT_NEAR(sz.sizes[1], 0.5, 1e-14);
  // The direction of size 2 is the second column of r (up to sign).
  EXPECT_NEAR(std::abs(dot(sz.directions.column(0), r.column(1))), 1.0, 1e-14);
  EXPECT_NEAR(anisotropy(m), 4.0, 1e-13);
  EXPECT_EQ(isotropic_metric<3>(0.5), SymMat3::diagonal(4.0));
  EXPECT_NEAR(length(m, 2.0 * r.column(1)), 1.0, 1e-14);
}

TEST(MetricBasics, RequireMetricRejectsBadInput) {
  EXPECT_NO_THROW(require_metric(SymMat2::identity(), "m"));
  EXPECT_THROW(require_metric(SymMat2{{1.0, 2.0, 1.0}}, "m"), InputError);  // eigenvalues -1, 3
  EXPECT_THROW(require_metric(SymMat2{{1.0, NAN, 1.0}}, "m"), InputError);
  EXPECT_THROW(require_metric(SymMat3::zero(), "m"), InputError);
  // Finite coefficients whose determinant overflows (sizes 1e-154): a tensor of 1e308 in a .sol
  // made `riemesh metric combine` write infinities (internal error) and `adapt` crash.
  EXPECT_THROW(require_metric(SymMat2{{1e308, 0.0, 1e308}}, "m"), InputError);
  EXPECT_THROW(require_metric(SymMat3::diagonal(1e110), "m"), InputError);
  EXPECT_NO_THROW(require_metric(SymMat3::diagonal(1e100), "m"));  // det 1e300
  // Whose determinant underflows (sizes 1e150): the background mesh took it for not SPD and
  // blamed the mesh file.
  try {
    require_metric(SymMat2{{1e-300, 0.0, 1e-300}}, "m");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "m: metric too small (its determinant underflows)");
  }
  EXPECT_NO_THROW(require_metric(SymMat3::diagonal(1e-100), "m"));  // det 1e-300
  // SPD but ill-conditioned: the cofactor determinant cancels (eigenvalues 1.2e-6, 2.3e-5, 5e4);
  // it was said to be "too small".
  try {
    require_metric(SymMat3{{6464.821874137391, -15934.760581379865, 39276.65756418232,
                            5223.905612717553, -12876.098797617155, 4221.182031972738}},
                   "m");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("too ill-conditioned"), std::string::npos) << e.what();
  }
  try {
    require_metric(SymMat2{{-1.0, 0.0, 1.0}}, "vertex 7");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 7"), std::string::npos);
  }
}

TEST(MetricBasics, RequireMetricSaysSubnormalIsOutOfRange) {
  // Subnormal entries (1e-310) were "not positive definite": positive, they are out of range
  // (a size of 1e155); a subnormal off-diagonal next to unit ones is negligible, accepted (the
  // 2D eigen solver gave NaN for it). QA hunt 5 F15.
  for (const SymMat2& m : {SymMat2{{1e-310, 0.0, 1e-310}}, SymMat2{{1.0, 0.0, 1e-310}}}) {
    try {
      require_metric(m, "f.sol: vertex 5");
      FAIL();
    } catch (const InputError& e) {
      EXPECT_EQ(
          std::string(e.what()).rfind("f.sol: vertex 5: metric out of range: a size of 1e+155", 0),
          0u)
          << e.what();
    }
  }
  EXPECT_NO_THROW(require_metric(SymMat2{{1.0, 1e-310, 1.0}}, "m"));
  EXPECT_NO_THROW(require_metric(SymMat2{{1.0, 1e-170, 1.0}}, "m"));
  try {
    require_metric(SymMat2{{1.0, 0.0, -1e-310}}, "m");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "m: metric is not positive definite");
  }
}

TEST(MetricBasics, SameMetricOnlyWhenEveryEntryIsEqual) {
  EXPECT_FALSE(same_metric<2>({}).has_value());
  const std::vector<SymMat2> same = {isotropic_metric<2>(0.1), isotropic_metric<2>(0.1)};
  ASSERT_TRUE(same_metric<2>(same).has_value());
  EXPECT_EQ(*same_metric<2>(same), isotropic_metric<2>(0.1));
  const std::vector<SymMat2> apart = {isotropic_metric<2>(0.1), isotropic_metric<2>(0.1 + 1e-16)};
  EXPECT_FALSE(same_metric<2>(apart).has_value());
  const std::vector<SymMat3> three(5, isotropic_metric<3>(2.0));
  EXPECT_TRUE(same_metric<3>(three).has_value());
}
