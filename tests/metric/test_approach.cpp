// The staged approach to a metric (metric/approach.hpp): the stage count from the longest edge,
// the fields at t = 0, 1/2 and 1 against their closed forms, vertices in no simplex, bad
// arguments.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/spd.hpp"
#include "metric/approach.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

namespace {

SymMat3 sizes(double hx, double hy, double hz) {
  return SymMat3::diagonal(Vec3{{1 / (hx * hx), 1 / (hy * hy), 1 / (hz * hz)}});
}

void expect_near(const SymMat3& a, const SymMat3& b, double rel) {
  for (int k = 0; k < SymMat3::kSize; ++k)
    EXPECT_NEAR(a.c[k], b.c[k], rel * std::abs(b.c[k]) + 1e-12) << "component " << k;
}

}  // namespace

TEST(MetricApproach, StagesFromTheLongestEdge) {
  // Edges 100 long in the target: ceil(ln 100 / ln 4) = ceil(3.32) = 4 stages; growth 10:
  // exactly 2; edges no longer than the growth: one stage.
  EXPECT_EQ(approach_stages(100.0, 4.0), 4);
  EXPECT_EQ(approach_stages(100.0, 10.0), 2);
  EXPECT_EQ(approach_stages(3.9, 4.0), 1);
  EXPECT_EQ(approach_stages(0.01, 4.0), 1);  // coarsening
  EXPECT_EQ(approach_stages(INFINITY, 4.0), 64);
  EXPECT_THROW(approach_stages(10.0, 1.0), InputError);
  EXPECT_THROW(approach_stages(10.0, std::nan("")), InputError);
}

TEST(MetricApproach, FieldsInterpolateTheLogs) {
  const std::vector<SymMat3> implied{sizes(0.1, 0.1, 0.1)};
  const std::vector<SymMat3> target{sizes(0.4, 0.1, 0.001)};
  const MetricApproach<3> a({log_spd(implied[0])}, {true}, target);
  expect_near(a.field(0.0)[0], implied[0], 1e-12);
  EXPECT_EQ(a.field(1.0)[0].c[5], target[0].c[5]);  // exactly the target
  // Halfway: the geometric mean of the sizes, direction by direction.
  expect_near(a.field(0.5)[0], sizes(0.2, 0.1, 0.01), 1e-12);
  // A rotated pair: the interpolation follows the eigenvectors (log-Euclidean).
  const SymMat2 t2{{5.0, 3.0, 5.0}};  // eigenvalues 8 and 2 along (1, 1) and (1, -1)
  const MetricApproach<2> b({SymMat2::zero()}, {true}, std::vector<SymMat2>{t2});  // from I
  const SymMat2 half = b.field(0.5)[0];  // sqrt(t2): eigenvalues sqrt 8 and sqrt 2
  const double s8 = std::sqrt(8.0), s2 = std::sqrt(2.0);
  EXPECT_NEAR(half.c[0], 0.5 * (s8 + s2), 1e-12);
  EXPECT_NEAR(half.c[1], 0.5 * (s8 - s2), 1e-12);
  EXPECT_NEAR(half.c[2], 0.5 * (s8 + s2), 1e-12);
}

TEST(MetricApproach, VerticesInNoSimplexGoStraightToTheTarget) {
  const std::vector<SymMat3> target{sizes(0.001, 0.001, 0.001), sizes(0.1, 0.1, 0.1)};
  // Vertex 0 unknown (its "implied" log is a placeholder zero): at the target at every stage.
  const MetricApproach<3> a({SymMat3::zero(), log_spd(sizes(0.2, 0.2, 0.2))}, {false, true},
                            target);
  expect_near(a.field(0.0)[0], target[0], 1e-12);
  expect_near(a.field(0.0)[1], sizes(0.2, 0.2, 0.2), 1e-12);
}

TEST(MetricApproach, MismatchedSizesAreRefused) {
  const std::vector<SymMat3> target{sizes(0.1, 0.1, 0.1)};
  EXPECT_THROW(MetricApproach<3>({}, {}, target), InputError);
  EXPECT_THROW(MetricApproach<3>({SymMat3::zero()}, {}, target), InputError);
}
