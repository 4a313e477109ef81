// The 2D Delaunay kernel, tested by properties: a valid triangulation of the super-triangle
// (counter-clockwise triangles, symmetric adjacency, 2n + 1 triangles for n distinct points) that
// is Delaunay — no vertex strictly inside the circumcircle of a neighbouring triangle (locally
// Delaunay everywhere ⇒ Delaunay, Delaunay's lemma), and for small sets no point strictly inside
// any circumcircle at all (brute force). All checks use the exact predicates. Random, grid
// (everything cocircular), clustered and duplicated points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <algorithm>
#include <array>
#include <set>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/delaunay2d.hpp"

using namespace riemesh;

namespace {

const double* pt(const Triangulation2d& t, Id v) { return &t.xy[2 * static_cast<std::size_t>(v)]; }

/// Structural checks, then the local Delaunay property over every interior edge.
void expect_delaunay(const Triangulation2d& t, std::size_t distinct) {
  const std::size_t nt = t.num_triangles();
  ASSERT_EQ(nt, 2 * distinct + 1);  // Euler: a triangulated triangle with n inner points
  ASSERT_EQ(t.nbr.size(), 3 * nt);
  std::size_t hull = 0;
  for (std::size_t k = 0; k < nt; ++k) {
    const Id* v = &t.tri[3 * k];
    ASSERT_GT(orient2d(pt(t, v[0]), pt(t, v[1]), pt(t, v[2])), 0) << "triangle " << k;
    for (int e = 0; e < 3; ++e) {
      const Id h = t.nbr[3 * k + e];
      if (h == kNoId) {
        ++hull;
        continue;
      }
      ASSERT_EQ(t.nbr[h], static_cast<Id>(3 * k + e));  // symmetric
      const Id* w = &t.tri[3 * (h / 3)];
      const int j = h % 3;
      // The shared edge is (v[e+1], v[e+2]) here and (w[j+2], w[j+1]) there.
      ASSERT_EQ(v[(e + 1) % 3], w[(j + 2) % 3]);
      ASSERT_EQ(v[(e + 2) % 3], w[(j + 1) % 3]);
      EXPECT_LE(incircle(pt(t, v[0]), pt(t, v[1]), pt(t, v[2]), pt(t, w[j])), 0)
          << "vertex " << w[j] << " inside the circumcircle of triangle " << k;
    }
  }
  EXPECT_EQ(hull, 3u);  // only the super-triangle's sides
}

/// No input point strictly inside the circumcircle of any triangle (quadratic: small inputs).
void expect_empty_circles(const Triangulation2d& t) {
  for (std::size_t k = 0; k < t.num_triangles(); ++k) {
    const Id* v = &t.tri[3 * k];
    for (std::size_t p = 0; p < t.num_points; ++p)
      ASSERT_LE(incircle(pt(t, v[0]), pt(t, v[1]), pt(t, v[2]), pt(t, static_cast<Id>(p))), 0)
          << "point " << p << " in triangle " << k << "'s circle";
  }
}

std::vector<double> random_points(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xy(2 * n);
  for (double& x : xy) x = u(rng);
  return xy;
}

}  // namespace

TEST(Delaunay2d, RandomPointsAllOrders) {
  const std::vector<double> xy = random_points(3000, 1);
  for (InsertionOrder o :
       {InsertionOrder::kBrio, InsertionOrder::kHilbert, InsertionOrder::kAsGiven,
        InsertionOrder::kRounds, InsertionOrder::kCoarseFirst}) {
    const Triangulation2d t = delaunay2d(xy, o);
    expect_delaunay(t, 3000);
    expect_empty_circles(t);
  }
}

TEST(Delaunay2d, BrioRoundsKeepTheOrderInsideHalvingRounds) {
  // A reversed sequence of 20,000 ids: a permutation of it, each id once; inside each round
  // (a maximal run going down, the sequence's order) the order kept; rounds growing about
  // twofold to a last one of about half the points; the same again (deterministic).
  const std::size_t n = 20000;
  std::vector<Id> along(n);
  for (std::size_t k = 0; k < n; ++k) along[k] = static_cast<Id>(n - 1 - k);
  const std::vector<Id> order = brio_rounds(along);
  ASSERT_EQ(order.size(), n);
  std::vector<int> seen(n, 0);
  for (const Id v : order) ++seen[static_cast<std::size_t>(v)];
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(n));
  std::vector<std::size_t> rounds{1};
  for (std::size_t k = 1; k < n; ++k) {
    if (order[k] < order[k - 1])
      ++rounds.back();
    else
      rounds.push_back(1);
  }
  ASSERT_GE(rounds.size(), 4u);
  ASSERT_LE(rounds.size(), 6u);  // rounds down to about 1000 points: 20000 / 2^4 = 1250
  EXPECT_NEAR(static_cast<double>(rounds.back()), n / 2.0, 0.05 * n);
  for (std::size_t r = 1; r + 1 < rounds.size(); ++r)
    EXPECT_NEAR(static_cast<double>(rounds[r + 1]) / static_cast<double>(rounds[r]), 2.0, 0.3);
  EXPECT_EQ(order, brio_rounds(along));
}

TEST(Delaunay2d, CoarseFirstTakesEightfoldRoundsOfSamples) {
  // 3,000 ids in a scrambled order: 8 · 64 <= n < 8^2 · 64, so J = 1: the ids at positions
  // divisible by 8 first, then the others, each part in the sequence's order.
  std::vector<Id> along(3000);
  for (std::size_t k = 0; k < along.size(); ++k) along[k] = static_cast<Id>((k * 7919) % 3000);
  std::vector<Id> expected;
  for (std::size_t k = 0; k < along.size(); k += 8) expected.push_back(along[k]);
  for (std::size_t k = 0; k < along.size(); ++k) {
    if (k % 8 != 0) expected.push_back(along[k]);
  }
  EXPECT_EQ(coarse_first(along), expected);
  // 20,000 ids: 8^2 · 64 = 4,096 <= n < 32,768, so J = 2: multiples of 64, then of 8, then the
  // rest.
  std::vector<Id> longer(20000);
  for (std::size_t k = 0; k < longer.size(); ++k) longer[k] = static_cast<Id>(k);
  const std::vector<Id> order = coarse_first(longer);
  ASSERT_EQ(order.size(), longer.size());
  std::size_t i = 0;
  for (std::size_t k = 0; k < longer.size(); k += 64) EXPECT_EQ(order[i++], static_cast<Id>(k));
  for (std::size_t k = 0; k < longer.size(); k += 8) {
    if (k % 64 != 0) {
      EXPECT_EQ(order[i++], static_cast<Id>(k));
    }
  }
  for (std::size_t k = 0; k < longer.size(); ++k) {
    if (k % 8 != 0) {
      EXPECT_EQ(order[i++], static_cast<Id>(k));
    }
  }
  EXPECT_TRUE(coarse_first({}).empty());
  EXPECT_EQ(coarse_first({3, 1, 2}), (std::vector<Id>{3, 1, 2}));
}

TEST(Delaunay2d, LargeRandomSet) {
  const Triangulation2d t = delaunay2d(random_points(200000, 2));
  expect_delaunay(t, 200000);
}

TEST(Delaunay2d, GridIsFullyCocircular) {
  // Every unit square of the grid has four cocircular corners: the exact predicates must keep
  // the walk and the cavities consistent. Also a grid rotated by 45° and shifted (inexact).
  std::vector<double> grid, rotated;
  const int n = 60;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      grid.insert(grid.end(), {double(i), double(j)});
      rotated.insert(rotated.end(), {0.1 + (i - j) * std::sqrt(0.5), 1e3 + (i + j) * std::sqrt(0.5)});
    }
  for (const auto* pts : {&grid, &rotated}) {
    for (InsertionOrder o :
         {InsertionOrder::kBrio, InsertionOrder::kAsGiven, InsertionOrder::kRounds,
          InsertionOrder::kCoarseFirst, InsertionOrder::kHilbert}) {
      const Triangulation2d t = delaunay2d(*pts, o);
      expect_delaunay(t, n * n);
      expect_empty_circles(t);
      EXPECT_EQ(delaunay_triangles(t).size() / 3, std::size_t(2 * (n - 1) * (n - 1)));
    }
  }
}

TEST(Delaunay2d, ClusteredPointsAndTinyScale) {
  // Gaussian clusters of very different spreads, and the whole set scaled down to 1e-200.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> xy;
  for (int c = 0; c < 10; ++c) {
    const double cx = 10.0 * g(rng), cy = 10.0 * g(rng), s = std::pow(10.0, -1 - c);
    for (int k = 0; k < 300; ++k) xy.insert(xy.end(), {cx + s * g(rng), cy + s * g(rng)});
  }
  expect_delaunay(delaunay2d(xy), 3000);
  for (double& x : xy) x *= 1e-200;
  expect_delaunay(delaunay2d(xy), 3000);
}

TEST(Delaunay2d, PointsOnACircleAndALine) {
  std::vector<double> xy;
  for (int k = 0; k < 500; ++k) {
    const double th = 2 * M_PI * k / 500;
    xy.insert(xy.end(), {std::cos(th), std::sin(th)});
  }
  for (int k = 0; k < 500; ++k) xy.insert(xy.end(), {-0.5 + k / 500.0, 0.25});
  const Triangulation2d t = delaunay2d(xy);
  expect_delaunay(t, 1000);
  expect_empty_circles(t);
}

TEST(Delaunay2d, CentreOfACircleLast) {
  // Inserted after 600 points of a circle, the centre is inside every circumcircle of the circle's
  // triangles: one cavity of hundreds of triangles (the scratch arrays grow during the search).
  std::vector<double> xy;
  for (int k = 0; k < 600; ++k) {
    const double th = 2 * M_PI * k / 600;
    xy.insert(xy.end(), {std::cos(th), std::sin(th)});
  }
  xy.insert(xy.end(), {0.0, 0.0});
  for (InsertionOrder o : {InsertionOrder::kAsGiven, InsertionOrder::kBrio}) {
    const Triangulation2d t = delaunay2d(xy, o);
    expect_delaunay(t, 601);
    expect_empty_circles(t);
  }
}

TEST(Delaunay2d, DuplicatesAreMergedNotInserted) {
  std::vector<double> xy = random_points(500, 4);
  const std::vector<double> copy(xy.begin(), xy.begin() + 200);
  xy.insert(xy.end(), copy.begin(), copy.end());  // points 500..599 repeat points 0..99
  const Triangulation2d t = delaunay2d(xy);
  expect_delaunay(t, 500);
  for (Id v = 0; v < 600; ++v) {
    const Id r = t.representative[v];
    EXPECT_EQ(t.xy[2 * r], xy[2 * v]);
    EXPECT_EQ(t.xy[2 * r + 1], xy[2 * v + 1]);
    if (v >= 100 && v < 500) {
      EXPECT_EQ(r, v);
    }
  }
  std::set<Id> reps;
  for (Id v = 0; v < 600; ++v) reps.insert(t.representative[v]);
  EXPECT_EQ(reps.size(), 500u);
}

TEST(Delaunay2d, DeterministicAndOrderIndependentMesh) {
  // On points in general position the Delaunay triangulation is unique: every order gives the
  // same set of inner triangles.
  const std::vector<double> xy = random_points(2000, 5);
  auto as_set = [](const Triangulation2d& t) {
    std::set<std::array<Id, 3>> s;
    const std::vector<Id> tri = delaunay_triangles(t);
    for (std::size_t k = 0; k < tri.size(); k += 3) {
      std::array<Id, 3> a{tri[k], tri[k + 1], tri[k + 2]};
      std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
      s.insert(a);
    }
    return s;
  };
  const auto s1 = as_set(delaunay2d(xy, InsertionOrder::kBrio));
  EXPECT_EQ(s1, as_set(delaunay2d(xy, InsertionOrder::kAsGiven)));
  EXPECT_EQ(delaunay2d(xy).tri, delaunay2d(xy).tri);
  EXPECT_GT(s1.size(), 3900u);  // 2n − 2 − hull for the full triangulation, minus a few hull ones
}

// A coordinate of 1e308 (a damaged .mesh) put the enclosing triangle at infinity, and the
// predicates' internal check failed (`riemesh mesh` exit 3): now an InputError.
TEST(Delaunay2d, RejectsCoordinatesTooLargeForTheEnclosingTriangle) {
  std::vector<double> xy = random_points(10, 6);
  xy[6] = 1e308;
  EXPECT_THROW(delaunay2d(xy), InputError);
  xy[6] = -1e308, xy[7] = 1e308;
  EXPECT_THROW(delaunay2d(xy), InputError);
  xy[6] = 1e300, xy[7] = 0.5;  // far, but the enclosing triangle stays finite
  EXPECT_NO_THROW(delaunay2d(xy));
}

TEST(Delaunay2d, RejectsNonFiniteCoordinates) {
  std::vector<double> xy = random_points(10, 6);
  xy[7] = std::nan("");
  EXPECT_THROW(delaunay2d(xy), InputError);
}
