// The 3D Delaunay kernel: the Delaunay property and the hull checked with the exact predicates on
// random, grid (cospherical), spherical, clustered and duplicated points, in every order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/delaunay3d.hpp"
#include "generate/delaunay3d_check.hpp"
#include "generate/filtered_predicates3d.hpp"

namespace riemesh {
namespace {

using test::expect_delaunay;
using test::total_volume;

constexpr InsertionOrder kOrders[] = {InsertionOrder::kAsGiven, InsertionOrder::kHilbert,
                                      InsertionOrder::kBrio, InsertionOrder::kRounds,
                                      InsertionOrder::kCoarseFirst};

std::vector<double> random_points(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz(3 * n);
  for (double& x : xyz) x = u(rng);
  return xyz;
}

/// The (n+1)^3 nodes of a unit grid: every cell's 8 corners are cospherical.
std::vector<double> grid_points(int n) {
  std::vector<double> xyz;
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) xyz.insert(xyz.end(), {double(i) / n, double(j) / n, double(k) / n});
  return xyz;
}

TEST(Delaunay3d, FilteredSignsAgreeWithExactOnes) {
  // Random points, then near-degenerate ones: coplanar up to one ulp and grid cospherical.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  detail::StaticFilter3d box;  // the static stage over [-2, 2]^3, which holds every point below
  const double lo[3] = {-2, -2, -2}, hi[3] = {2, 2, 2};
  box.extend(lo);
  box.extend(hi);
  box.update();
  for (int trial = 0; trial < 20000; ++trial) {
    double p[5][3];
    for (auto& q : p)
      for (double& x : q) x = u(rng);
    if (trial % 3 == 1)  // p[3] on the plane of p[0..2], rounded
      for (int k = 0; k < 3; ++k) p[3][k] = p[0][k] + 0.3 * (p[1][k] - p[0][k]) + 0.5 * (p[2][k] - p[0][k]);
    if (trial % 3 == 2)  // integer points: exact zeros are frequent
      for (auto& q : p)
        for (double& x : q) x = std::round(2 * x);
    const auto sign = [](double x) { return (x > 0) - (x < 0); };
    ASSERT_EQ(detail::orient3d_sign(p[0], p[1], p[2], p[3]),
              sign(exact::orient3d(p[0], p[1], p[2], p[3])));
    ASSERT_EQ(detail::insphere_sign(p[0], p[1], p[2], p[3], p[4]),
              sign(exact::insphere(p[0], p[1], p[2], p[3], p[4])));
    ASSERT_EQ(detail::orient3d_sign(box, p[0], p[1], p[2], p[3]),
              sign(exact::orient3d(p[0], p[1], p[2], p[3])));
    ASSERT_EQ(detail::insphere_sign(box, p[0], p[1], p[2], p[3], p[4]),
              sign(exact::insphere(p[0], p[1], p[2], p[3], p[4])));
  }
}

TEST(Delaunay3d, VectorInsphereDeterminantIsBitwiseTheScalarOne) {
  // The static filter's bound holds for the scalar evaluation order only.
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20000; ++trial) {
    double p[5][3];
    const double scale = std::ldexp(1.0, trial % 40 - 20);
    for (auto& q : p)
      for (double& x : q) x = 3.0 + scale * u(rng);
    const double vector = detail::insphere_det(p[0], p[1], p[2], p[3], p[4]);
    const double scalar = detail::insphere_det_scalar(p[0], p[1], p[2], p[3], p[4]);
    ASSERT_EQ(std::memcmp(&vector, &scalar, sizeof(double)), 0) << vector << " " << scalar;
  }
}

#if defined(RIEMESH_HAVE_AVX2_KERNELS)
TEST(Delaunay3d, Avx2InsphereDeterminantIsBitwiseTheScalarOne) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "no AVX2";
  std::mt19937_64 rng(10);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  alignas(32) double r[4][4];  // records of 4 doubles, the 4th never computed with
  for (int trial = 0; trial < 20000; ++trial) {
    double e[3];
    const double scale = std::ldexp(1.0, trial % 40 - 20);
    for (auto& q : r) {
      for (int i = 0; i < 3; ++i) q[i] = 3.0 + scale * u(rng);
      q[3] = trial % 2 ? std::nan("") : 1e-310;  // a NaN or a denormal: not read
    }
    for (double& x : e) x = 3.0 + scale * u(rng);
    const double vector =
        detail::insphere_det_avx2(detail::InsphereQuery(e), r[0], r[1], r[2], r[3]);
    const double scalar = detail::insphere_det_scalar(r[0], r[1], r[2], r[3], e);
    ASSERT_EQ(std::memcmp(&vector, &scalar, sizeof(double)), 0) << vector << " " << scalar;
  }
}
#endif

TEST(Delaunay3d, KernelWithAndWithoutAvx2GivesTheSameTets) {
  for (const std::vector<double>& xyz : {random_points(3000, 12), grid_points(6)}) {
    Tetrahedralization out[2];
    for (int avx2 = 0; avx2 < 2; ++avx2) {
      std::vector<Id> order = insertion_order(xyz, InsertionOrder::kBrio);
      Delaunay3d kernel(&xyz, order);
      kernel.set_avx2(avx2 == 1);
      for (std::size_t k = 4; k < order.size(); ++k) kernel.insert(order[k]);
      out[avx2] = kernel.result();
    }
    EXPECT_EQ(out[0].tets, out[1].tets);
    EXPECT_EQ(out[0].tet2tet, out[1].tet2tet);
  }
}

TEST(Delaunay3d, InsphereSignConvention) {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  const double in[3] = {0.25, 0.25, 0.25}, out[3] = {2, 2, 2}, on[3] = {1, 1, 1};
  EXPECT_EQ(detail::orient3d_sign(a, b, c, d), 1);
  EXPECT_EQ(detail::insphere_sign(a, b, c, d, in), 1);
  EXPECT_EQ(detail::insphere_sign(a, b, c, d, out), -1);
  EXPECT_EQ(detail::insphere_sign(a, b, c, d, on), 0);  // (1,1,1) is on the sphere
}

TEST(Delaunay3d, SingleTetrahedron) {
  const std::vector<double> xyz = {0, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 0};
  const Tetrahedralization tz = delaunay3d(xyz);
  ASSERT_EQ(tz.num_tets(), 1u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(tz.tet2tet[i], kNoId);
  expect_delaunay(xyz, tz);
  EXPECT_DOUBLE_EQ(total_volume(xyz, tz), 1.0 / 6);
}

TEST(Delaunay3d, RandomPointsInEveryOrder) {
  const std::vector<double> xyz = random_points(3000, 1);
  for (InsertionOrder order : kOrders) {
    const Tetrahedralization tz = delaunay3d(xyz, order);
    expect_delaunay(xyz, tz);
    // About 6.5 tets per point for uniform points in a cube (fewer near the hull).
    EXPECT_GT(tz.num_tets(), 5u * 3000);
    EXPECT_LT(tz.num_tets(), 7u * 3000);
  }
}

TEST(Delaunay3d, GridPointsAreCosphericalEverywhere) {
  // Every cell of the grid is cut into tets whose circumspheres hold the cell's 8 corners on
  // them; the tets fill the cube exactly.
  const std::vector<double> xyz = grid_points(8);
  for (InsertionOrder order : kOrders) {
    const Tetrahedralization tz = delaunay3d(xyz, order);
    expect_delaunay(xyz, tz);
    EXPECT_NEAR(total_volume(xyz, tz), 1.0, 1e-12);
    // 512 cells, 5 or 6 tets each (flat tets would have failed expect_delaunay).
    EXPECT_GE(tz.num_tets(), 5u * 512);
    EXPECT_LE(tz.num_tets(), 6u * 512);
  }
}

TEST(Delaunay3d, IntegerPointsOfOneSphere) {
  // All integer points with x² + y² + z² = 11² (exactly cospherical) and the centre.
  std::vector<double> xyz;
  for (int x = -11; x <= 11; ++x)
    for (int y = -11; y <= 11; ++y)
      for (int z = -11; z <= 11; ++z)
        if (x * x + y * y + z * z == 121) xyz.insert(xyz.end(), {double(x), double(y), double(z)});
  ASSERT_GT(xyz.size() / 3, 30u);
  for (InsertionOrder order : kOrders) expect_delaunay(xyz, delaunay3d(xyz, order));
  xyz.insert(xyz.end(), {0.0, 0.0, 0.0});
  for (InsertionOrder order : kOrders) expect_delaunay(xyz, delaunay3d(xyz, order));
}

TEST(Delaunay3d, CentreOfPointsOnASphereEmptiesEveryTet) {
  // Points on a sphere (up to rounding), then its centre: every tet is in the centre's cavity,
  // whose boundary has every point on it, more than the kernel's edge table takes (the cavity's
  // edges are then sorted instead).
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g;
  std::vector<double> xyz;
  for (int k = 0; k < 1500; ++k) {
    const double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    xyz.insert(xyz.end(), {x / r, y / r, z / r});
  }
  xyz.insert(xyz.end(), {0.0, 0.0, 0.0});
  const Tetrahedralization tz = delaunay3d(xyz, InsertionOrder::kAsGiven);
  expect_delaunay(xyz, tz);
  std::size_t through_centre = 0;
  for (Id v : tz.tets) through_centre += v == 1500;
  EXPECT_GT(through_centre, 2000u);  // one tet per hull face: about 2 * 1500
}

TEST(Delaunay3d, ClusteredPoints) {
  // Tight clusters 1e-6 wide around a few centres, and points on coordinate planes.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> xyz;
  for (int c = 0; c < 6; ++c) {
    const double centre[3] = {u(rng), u(rng), u(rng)};
    for (int k = 0; k < 300; ++k)
      for (int i = 0; i < 3; ++i) xyz.push_back(centre[i] + 1e-6 * u(rng));
  }
  for (int k = 0; k < 300; ++k) xyz.insert(xyz.end(), {u(rng), u(rng), 0.0});
  for (InsertionOrder order : kOrders) expect_delaunay(xyz, delaunay3d(xyz, order));
}

TEST(Delaunay3d, DuplicatesAreReportedNotInserted) {
  std::vector<double> xyz = grid_points(3);
  const std::size_t n = xyz.size() / 3;
  for (std::size_t v = 0; v < n; v += 5) xyz.insert(xyz.end(), xyz.begin() + 3 * v, xyz.begin() + 3 * v + 3);
  for (InsertionOrder order : kOrders) {
    const Tetrahedralization tz = delaunay3d(xyz, order);
    expect_delaunay(xyz, tz);
    std::size_t duplicates = 0;
    for (std::size_t q = 0; q < xyz.size() / 3; ++q) {
      const Id d = tz.duplicate_of[q];
      if (d == kNoId) continue;
      ++duplicates;
      for (int i = 0; i < 3; ++i) EXPECT_EQ(xyz[3 * q + i], xyz[3 * static_cast<std::size_t>(d) + i]);
    }
    EXPECT_EQ(duplicates, (n + 4) / 5);
  }
}

TEST(Delaunay3d, CoplanarOrTooFewPointsAreInputErrors) {
  EXPECT_THROW(delaunay3d({0, 0, 0, 1, 0, 0, 0, 1, 0}), InputError);
  EXPECT_THROW(delaunay3d({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0}), InputError);
  EXPECT_THROW(delaunay3d({0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3}), InputError);
}

TEST(Delaunay3d, Deterministic) {
  const std::vector<double> xyz = random_points(2000, 11);
  const Tetrahedralization a = delaunay3d(xyz);
  const Tetrahedralization b = delaunay3d(xyz);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.tet2tet, b.tet2tet);
}

TEST(Delaunay3d, IncrementalKernelWithGrowingPoints) {
  // As boundary recovery uses it: points appended to the coordinates between insertions (the
  // vector reallocates), duplicates refused, and far points whose cavities hold many ghosts and
  // hundreds of boundary faces; the conflict marks of every insertion must be cleared.
  std::vector<double> xyz = random_points(500, 21);
  std::vector<Id> order(xyz.size() / 3);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Id>(i);
  Delaunay3d kernel(&xyz, order);
  for (std::size_t k = 4; k < order.size(); ++k) ASSERT_TRUE(kernel.insert(order[k]));
  std::vector<Id> duplicate_of(order.size(), kNoId);
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  for (int k = 0; k < 300; ++k) {
    const Id id = static_cast<Id>(xyz.size() / 3);
    if (k % 50 == 49) {  // far outside: the whole hull side is in conflict
      const double s = 10.0 * (k / 50 + 1);
      xyz.insert(xyz.end(), {s * u(rng), s * u(rng), s});
    } else if (k % 7 == 3) {  // a duplicate of an earlier point
      const std::size_t q = static_cast<std::size_t>(rng() % static_cast<std::uint64_t>(id));
      xyz.insert(xyz.end(), {xyz[3 * q], xyz[3 * q + 1], xyz[3 * q + 2]});
    } else {
      xyz.insert(xyz.end(), {u(rng), u(rng), u(rng)});
    }
    Id same = kNoId;
    const bool inserted = kernel.insert(id, &same);
    EXPECT_EQ(inserted, k % 50 == 49 || k % 7 != 3) << k;
    duplicate_of.push_back(inserted ? kNoId : same);
  }
  Tetrahedralization tz = kernel.result();
  tz.duplicate_of = duplicate_of;
  expect_delaunay(xyz, tz);
  EXPECT_GT(kernel.stats().insphere_tests, kernel.stats().cavity_tets);
}

TEST(Delaunay3d, CocircularQuadsFlipToTheirOtherDiagonal) {
  // Every unit square of a grid is a cocircular quad: the flip turns its diagonal to the other
  // one where four tets surround it, and the tetrahedralisation stays Delaunay (ghosts: the
  // squares on the hull).
  const int n = 5;
  const std::vector<double> xyz = grid_points(n);
  std::vector<Id> order(xyz.size() / 3);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<Id>(i);
  Delaunay3d kernel(&xyz, order);
  for (std::size_t k = 4; k < order.size(); ++k) ASSERT_TRUE(kernel.insert(order[k]));
  const auto edges_of = [](const Tetrahedralization& tz) {
    std::set<std::pair<Id, Id>> e;
    for (std::size_t t = 0; t < tz.num_tets(); ++t)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          e.insert(std::minmax(tz.tets[4 * t + i], tz.tets[4 * t + j]));
    return e;
  };
  const std::set<std::pair<Id, Id>> before = edges_of(kernel.result());
  // Squares normal to z: corners (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1) at height k.
  const auto id = [&](int i, int j, int k) {
    return static_cast<Id>((k * (n + 1) + j) * (n + 1) + i);
  };
  std::vector<std::array<Id, 4>> quads;  // a, b, c, d: (b, d) the diagonal there, (a, c) wanted
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Id p00 = id(i, j, k), p10 = id(i + 1, j, k), p11 = id(i + 1, j + 1, k),
                 p01 = id(i, j + 1, k);
        if (before.count(std::minmax(p00, p11)))
          quads.push_back({p10, p00, p01, p11});
        else
          quads.push_back({p00, p10, p11, p01});
      }
  const std::size_t flipped = kernel.flip_cocircular(quads);
  EXPECT_GT(flipped, quads.size() / 4);
  Tetrahedralization tz = kernel.result();
  tz.duplicate_of.assign(xyz.size() / 3, kNoId);
  expect_delaunay(xyz, tz);
  EXPECT_NEAR(total_volume(xyz, tz), 1.0, 1e-12);
  const std::set<std::pair<Id, Id>> after = edges_of(tz);
  std::size_t turned = 0;
  for (const auto& q : quads)
    if (after.count(std::minmax(q[0], q[2])) && !after.count(std::minmax(q[1], q[3]))) ++turned;
  EXPECT_EQ(turned, flipped);
  // Quads that are no cocircular ties are left alone: the flips back and forth of a random
  // point set's tets (any four vertices of a tet, as a quad) change nothing.
  const std::vector<double> random = random_points(300, 5);
  std::vector<Id> ids(random.size() / 3);
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<Id>(i);
  Delaunay3d other(&random, ids);
  for (std::size_t k = 4; k < ids.size(); ++k) ASSERT_TRUE(other.insert(ids[k]));
  const Tetrahedralization r = other.result();
  std::vector<std::array<Id, 4>> tets;
  for (std::size_t t = 0; t < r.num_tets(); ++t)
    tets.push_back({r.tets[4 * t], r.tets[4 * t + 1], r.tets[4 * t + 2], r.tets[4 * t + 3]});
  EXPECT_EQ(other.flip_cocircular(tets), 0u);
  EXPECT_EQ(other.result().tets, r.tets);
}

TEST(Delaunay3d, BrioIsAPermutation) {
  const std::vector<double> xyz = random_points(5000, 5);
  std::vector<Id> order = insertion_order(xyz, InsertionOrder::kBrio);
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i) ASSERT_EQ(order[i], static_cast<Id>(i));
}

}  // namespace
}  // namespace riemesh
