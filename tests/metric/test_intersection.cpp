// metric/intersection.hpp: two-metric intersection, sequential and maximal-volume intersection
// of several metrics, containment and equality tests (BOOK.md §1, "Intersection").
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "core/random_metrics.hpp"
#include "metric/intersection.hpp"
#include "metric/metric.hpp"

using namespace riemesh;
using test_support::random_rotation;
using test_support::random_spd;

namespace {

template <class T>
class IntersectionTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(IntersectionTest, Dims);

/// A random metric of unit determinant, so that intersections are not simply nested.
template <int D>
SymMat<D> random_unit_volume(std::mt19937_64& rng, double ratio) {
  const SymMat<D> m = random_spd<D>(rng, ratio);
  return std::pow(det(m), -1.0 / D) * m;
}

}  // namespace

TEST(Intersection, ContainmentAndEquality) {
  const SymMat2 fine = SymMat2::diagonal(4.0), coarse = SymMat2::identity();
  EXPECT_TRUE(contained_in(fine, coarse));  // radius 1/2 inside radius 1
  EXPECT_FALSE(contained_in(coarse, fine));
  EXPECT_TRUE(contained_in(fine, fine));
  EXPECT_TRUE(metrics_equal(fine, fine));
  EXPECT_FALSE(metrics_equal(fine, (1 + 1e-9) * fine));
  EXPECT_TRUE(metrics_equal(fine, (1 + 1e-9) * fine, 1e-8));
  // Crossed ellipses: neither contains the other.
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 100}}), b = SymMat2::diagonal(Vec2{{100, 1}});
  EXPECT_FALSE(contained_in(a, b));
  EXPECT_FALSE(contained_in(b, a));
}

TEST(Intersection, OrthogonalAnisotropicMetrics) {
  // Sizes (1, 0.1) and (0.1, 1): the largest ellipse inside both is the disc of radius 0.1.
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 100}}), b = SymMat2::diagonal(Vec2{{100, 1}});
  const SymMat2 r = intersect(a, b);
  EXPECT_TRUE(metrics_equal(r, SymMat2::diagonal(100.0), 1e-14));
  // The same in 3D, rotated: sizes (1, 1, 0.1) and (0.1, 1, 1) give (0.1, 1, 0.1).
  std::mt19937_64 rng(1);
  const Mat3 rot = random_rotation<3>(rng);
  const SymMat3 r3 = intersect(compose(rot, Vec3{{1, 1, 100}}), compose(rot, Vec3{{100, 1, 1}}));
  EXPECT_TRUE(metrics_equal(r3, compose(rot, Vec3{{100, 1, 100}}), 1e-12));
}

TYPED_TEST(IntersectionTest, NestedAndIdenticalMetrics) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(2);
  for (int k = 0; k < 100; ++k) {
    const SymMat<D> a = random_spd<D>(rng);
    // b = a + (PSD) is finer than a everywhere: the intersection is b, exactly.
    Vec<D> extra{};
    for (int i = 0; i < D; ++i) extra[i] = 0.5 * (i + 1) * frobenius(a);
    const SymMat<D> b = a + compose(random_rotation<D>(rng), extra);
    EXPECT_EQ(intersect(a, b), b);
    EXPECT_EQ(intersect(b, a), b);
    EXPECT_TRUE(metrics_equal(intersect(a, a), a));
    EXPECT_TRUE(metrics_equal(intersect(2.0 * a, a), 2.0 * a));
  }
}

TYPED_TEST(IntersectionTest, RandomPairsContainBothAndAreSymmetric) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(3);
  for (int k = 0; k < 500; ++k) {
    const SymMat<D> a = random_spd<D>(rng), b = random_spd<D>(rng);
    const SymMat<D> r = intersect(a, b);
    EXPECT_TRUE(contained_in(r, a, 1e-10));
    EXPECT_TRUE(contained_in(r, b, 1e-10));
    EXPECT_TRUE(metrics_equal(r, intersect(b, a), 1e-9));
    // In the common basis max(mu_a, mu_b) <= mu_a + mu_b: r ⪯ a + b.
    EXPECT_TRUE(contained_in(a + b, r, 1e-10));
  }
}

TEST(Intersection, EmptyListIsAnInputError) {
  EXPECT_THROW(intersect_sequential<2>(std::span<const SymMat2>()), InputError);
  EXPECT_THROW(intersect_max_volume<3>(std::span<const SymMat3>()), InputError);
}

TEST(Intersection, MaxVolumeOfSymmetricTripleIsADisc) {
  // Three ellipses with sizes (1, 1/√k) at 0°, 60°, 120°: the set is invariant under the 120°
  // rotation and the optimum is unique, so it is a disc; the largest disc inside an ellipse
  // has its smallest radius 1/√k, so M = k I. Sequential intersection is anisotropic instead.
  const double k = 25.0;
  std::array<SymMat2, 3> ms{};
  for (int i = 0; i < 3; ++i) {
    const double t = i * std::numbers::pi / 3, c = std::cos(t), s = std::sin(t);
    ms[i] = compose(Mat2{{{c, -s}, {s, c}}}, Vec2{{1, k}});
  }
  const SymMat2 best = intersect_max_volume<2>(ms);
  EXPECT_TRUE(metrics_equal(best, SymMat2::diagonal(k), 1e-9));
  EXPECT_LT(det(best), det(intersect_sequential<2>(ms)) * (1 - 1e-3));
}

TEST(Intersection, MaxVolumeIgnoresAMetricContainingTheOthersIntersection) {
  // c = I/4 (ball of radius 2) contains the intersection of a and b (radius <= 1): the result is
  // intersect(a, b).
  const SymMat2 a = SymMat2::diagonal(Vec2{{1, 100}}), b{{30.0, 12.0, 9.0}};
  const std::array<SymMat2, 3> ms{a, SymMat2::diagonal(0.25), b};
  EXPECT_TRUE(metrics_equal(intersect_max_volume<2>(ms), intersect(a, b), 1e-9));
}

TYPED_TEST(IntersectionTest, MaxVolumeOfTwoEqualsSimultaneousReduction) {
  // In the simred basis both metrics are diagonal; the problem is symmetric under x_i -> -x_i,
  // so the unique optimum is diagonal there too: mu_i = max(mu_a,i, mu_b,i).
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(4);
  for (int k = 0; k < 50; ++k) {
    const std::array<SymMat<D>, 2> ms{random_unit_volume<D>(rng, 1e3),
                                      random_unit_volume<D>(rng, 1e3)};
    EXPECT_TRUE(metrics_equal(intersect_max_volume<D>(ms), intersect(ms[0], ms[1]), 1e-9));
  }
}

// Agreement between the 6 orders. 2D: to rounding (in practice 1e-14). 3D: the barrier path is
// extrapolated to ε = 0 and reaches ~1e-12 for most triples, but where a constraint is active
// with a partly zero multiplier (non-strict complementarity, ~10% of random 3D triples) the
// path is not analytic in ε and the result is only within ~5e-7 (a deviation in shape at
// an unchanged volume: log det differs by < 1e-12).
template <int D>
constexpr double kPermutationTol = D == 2 ? 1e-9 : 2e-6;

TYPED_TEST(IntersectionTest, SequentialIsOrderDependentMaxVolumeIsNot) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(5);
  int order_dependent = 0;
  for (int k = 0; k < 30; ++k) {
    std::array<SymMat<D>, 3> ms{random_unit_volume<D>(rng, 100), random_unit_volume<D>(rng, 100),
                                random_unit_volume<D>(rng, 100)};
    std::array<int, 3> order{0, 1, 2};
    const SymMat<D> ref = intersect_max_volume<D>(ms);
    const SymMat<D> seq_ref = intersect_sequential<D>(ms);
    bool differs = false;
    do {
      const std::array<SymMat<D>, 3> p{ms[order[0]], ms[order[1]], ms[order[2]]};
      const SymMat<D> best = intersect_max_volume<D>(p), seq = intersect_sequential<D>(p);
      EXPECT_TRUE(metrics_equal(best, ref, kPermutationTol<D>));
      for (const SymMat<D>& m : ms) {
        EXPECT_TRUE(contained_in(best, m, 1e-12));
        EXPECT_TRUE(contained_in(seq, m, 1e-10));
      }
      // Maximal volume = minimal det among metrics containing all inputs; every sequential
      // result is such a metric.
      EXPECT_LE(det(best), det(seq) * (1 + 1e-12));
      differs = differs || !metrics_equal(seq, seq_ref, 1e-6);
    } while (std::next_permutation(order.begin(), order.end()));
    order_dependent += differs;
  }
  EXPECT_GT(order_dependent, 15);  // sequential intersection depends on the order, usually
}

TYPED_TEST(IntersectionTest, MaxVolumeOfManyMetricsIsValid) {
  constexpr int D = TypeParam::value;
  std::mt19937_64 rng(6);
  std::vector<SymMat<D>> ms;
  for (int k = 0; k < 12; ++k) ms.push_back(random_unit_volume<D>(rng, 1e3));
  const SymMat<D> best = intersect_max_volume<D>(ms);
  for (const SymMat<D>& m : ms) EXPECT_TRUE(contained_in(best, m, 1e-12));
  EXPECT_LE(det(best), det(intersect_sequential<D>(ms)) * (1 + 1e-12));
  std::reverse(ms.begin(), ms.end());
  EXPECT_TRUE(metrics_equal(intersect_max_volume<D>(ms), best, kPermutationTol<D>));
}
