// Point–triangle distance, the AABB tree against brute force, and sampled Hausdorff distances on
// analytic cases (parallel planes, nested squares, sphere vs inflated sphere).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "mesh/distance.hpp"
#include "mesh/fixtures.hpp"

using namespace riemesh;

namespace {

/// The square [0, s]² at height z, n x n cells, each split along one diagonal (`flip` picks
/// the other one, so that two such meshes do not share their triangles).
Mesh square(int n, double s, double z, bool flip) {
  Mesh m = unit_square(n, n);
  Mesh out;
  out.dim = 3;
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    out.coords.insert(out.coords.end(), {s * m.coords[2 * v], s * m.coords[2 * v + 1], z});
  out.triangles = m.triangles;
  if (flip) {
    out.triangles.clear();
    const auto id = [n](int i, int j) { return static_cast<Id>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        out.triangles.insert(out.triangles.end(), {id(i, j), id(i + 1, j), id(i, j + 1),
                                                   id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  }
  out.tri_ref.assign(out.num_triangles(), 1);
  return out;
}

Mesh sphere(int s, double r) {
  Mesh m = sphere_surface(s);
  for (double& c : m.coords) c *= r;
  return m;
}

TEST(Distance, ClosestPointRegions) {
  const Vec3 a{{0, 0, 0}}, b{{1, 0, 0}}, c{{0, 1, 0}};
  auto near = [](const Vec3& x, const Vec3& y) { return norm(x - y) < 1e-15; };
  EXPECT_TRUE(near(closest_point_on_triangle({{0.2, 0.3, 5}}, a, b, c), {{0.2, 0.3, 0}}));  // face
  EXPECT_TRUE(near(closest_point_on_triangle({{-1, -2, 1}}, a, b, c), a));                  // vertex
  EXPECT_TRUE(near(closest_point_on_triangle({{3, -0.5, 0}}, a, b, c), b));
  EXPECT_TRUE(near(closest_point_on_triangle({{-0.1, 4, 0}}, a, b, c), c));
  EXPECT_TRUE(near(closest_point_on_triangle({{0.5, -1, 2}}, a, b, c), {{0.5, 0, 0}}));     // edge ab
  EXPECT_TRUE(near(closest_point_on_triangle({{-3, 0.25, 0}}, a, b, c), {{0, 0.25, 0}}));   // edge ac
  EXPECT_TRUE(near(closest_point_on_triangle({{1, 1, 0}}, a, b, c), {{0.5, 0.5, 0}}));      // edge bc
  // Degenerate triangles: a segment and a point.
  EXPECT_TRUE(near(closest_point_on_triangle({{0.5, 1, 0}}, a, b, 0.5 * b), {{0.5, 0, 0}}));
  EXPECT_TRUE(near(closest_point_on_triangle({{0.5, 1, 0}}, a, a, a), a));
}

// Needle triangles (aspect 1e6) with exactly representable corners, and points whose closest
// point is known exactly: Ericson's region tests subtract products of dot products that cancel
// there (QA hunt 6 G6: a point inside such a triangle was put 0.66 away from it).
TEST(Distance, ClosestPointOnNeedles) {
  auto expect_closest = [](const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c,
                           const Vec3& want) {
    for (const Vec3& q :
         {closest_point_on_triangle(p, a, b, c), TriangleProbe(a, b, c).closest(p),
          closest_point_on_triangle(p, c, a, b), closest_point_on_triangle(p, b, a, c)})
      EXPECT_LT(norm(q - want), 1e-9) << "p (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  };
  {
    // The hunt's case: a cap (obtuse angle near 180°) of the face y = 1 of a box 1e6 × 1 × 1.
    const Vec3 a{{5e5, 1, 0}}, b{{0, 1, 1}}, c{{1e6, 1, 1}};
    expect_closest({{437500, 1, 0.5625}}, a, b, c, {{437500, 1, 0.5625}});    // inside: 0
    expect_closest({{437500, 1.5, 0.5625}}, a, b, c, {{437500, 1, 0.5625}});  // above: 0.5
    expect_closest({{6e5, -2, 0.95}}, a, b, c, {{6e5, 1, 0.95}});  // below, near the long side
    expect_closest({{2.5e5, 1, 1.25}}, a, b, c, {{2.5e5, 1, 1}});  // beside the long side bc
    expect_closest({{1e6 + 7, 1, 2}}, a, b, c, c);                 // beyond the corner c
    expect_closest({{5e5, 1, -3}}, a, b, c, a);                    // below the obtuse corner
  }
  {
    // A sliver (one short edge ac of length 1) tilted 45° about z: the plane x = y.
    const Vec3 a{{0, 0, 0}}, b{{1e6, 1e6, 0}}, c{{0, 0, 1}};
    const Vec3 x{{2.5e5, 2.5e5, 0.5}};                              // 1/4 b + 1/2 c: inside
    expect_closest(x + Vec3{{3, -3, 0}}, a, b, c, x);               // 3√2 off the plane
    expect_closest(x + Vec3{{-3, 3, 0}}, a, b, c, x);               // the other side
    expect_closest({{5e5, 5e5, -2}}, a, b, c, {{5e5, 5e5, 0}});     // beside edge ab
    expect_closest({{-1, -1, 0.5}}, a, b, c, {{0, 0, 0.5}});        // beside edge ac
    expect_closest({{1e6 + 10, 1e6 + 10, 0.25}}, a, b, c, b);       // beyond b
    expect_closest({{5e5, 5e5, 0.5}}, a, b, c, {{5e5, 5e5, 0.5}});  // on the edge bc
  }
}

// Two triangulations of one rectangle 1e6 × 1 (4 × 4 cells, diagonals either way): the
// distance is 0 both ways (QA hunt 6 G6: `riemesh distance` reported 0.4375 for such a box).
TEST(Distance, NeedleTrianglesOfOnePlane) {
  Mesh a = square(4, 1.0, 0.0, false), b = square(4, 1.0, 0.0, true);
  for (Mesh* m : {&a, &b})
    for (std::size_t v = 0; v < m->num_vertices(); ++v) m->coords[3 * v] *= 1e6;
  const HausdorffDistance h = hausdorff_distance(a, b, {});
  EXPECT_LT(h.two_sided(), 1e-9);
}

TEST(Distance, TreeMatchesBruteForce) {
  // A bumpy sphere and random points inside, on and outside it.
  Mesh m = sphere(3, 1.0);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> bump(-0.05, 0.05), box(-1.5, 1.5);
  for (double& c : m.coords) c += bump(rng);
  const TriangleTree tree(m);
  for (int k = 0; k < 500; ++k) {
    const Vec3 p{{box(rng), box(rng), box(rng)}};
    double brute = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < m.num_triangles(); ++t) {
      Vec3 v[3];
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) v[i][c] = m.coords[3 * m.triangles[3 * t + i] + c];
      // (the tree's kernel: its probes; the function without them agrees to rounding)
      const Vec3 q = TriangleProbe(v[0], v[1], v[2]).closest(p);
      EXPECT_LT(norm(q - closest_point_on_triangle(p, v[0], v[1], v[2])), 1e-14);
      brute = std::min(brute, norm(p - q));
    }
    const auto q = tree.nearest(p, k % 2 ? static_cast<Id>(k) : kNoId);
    EXPECT_EQ(q.distance, brute) << k;
    EXPECT_NEAR(norm(q.point - p), q.distance, 1e-15);
  }
}

TEST(Distance, TiesGoToTheLowestTriangle) {
  // A vertex is at distance 0 of every triangle of its ball: the lowest id wins, whatever the
  // hint (the highest of the ball, tried first) and the lower bounds that skip triangles.
  Mesh m = sphere(3, 1.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> bump(-0.05, 0.05);
  for (double& c : m.coords) c += bump(rng);
  const TriangleTree tree(m);
  std::vector<Id> lowest(m.num_vertices(), kNoId), highest(m.num_vertices(), kNoId);
  for (std::size_t t = 0; t < m.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const auto v = static_cast<std::size_t>(m.triangles[3 * t + i]);
      if (lowest[v] == kNoId) lowest[v] = static_cast<Id>(t);
      highest[v] = static_cast<Id>(t);
    }
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (lowest[v] == kNoId) continue;
    const Vec3 p{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
    for (const Id hint : {kNoId, highest[v]}) {
      const auto q = tree.nearest(p, hint);
      EXPECT_EQ(q.distance, 0.0) << v;
      EXPECT_EQ(q.triangle, lowest[v]) << v;
    }
  }
}

TEST(Distance, ProbeAgreesWithTheClosestPoint) {
  // TriangleProbe::within (plane and edge-band rejections, inside shortcut) answers as the exact
  // distance does, on random triangles (some needle-like or degenerate) and points near them.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int near = 0, far = 0;
  for (int k = 0; k < 400; ++k) {
    Vec3 a{{u(rng), u(rng), u(rng)}}, b{{u(rng), u(rng), u(rng)}}, c{{u(rng), u(rng), u(rng)}};
    if (k % 10 == 0) c = a + 0.5 * (b - a);                  // collinear
    if (k % 10 == 1) c = a + 1e-9 * Vec3{{u(rng), u(rng), u(rng)}};  // needle
    if (k % 10 == 2) b = a;                                   // two equal corners
    const TriangleProbe probe(a, b, c);
    for (int j = 0; j < 50; ++j) {
      const Vec3 p{{u(rng), u(rng), u(rng)}};
      const double d = norm(p - closest_point_on_triangle(p, a, b, c));
      for (double r : {0.05, 0.2, 0.5}) {
        if (std::abs(d - r) < 1e-12) continue;  // rounding may go either way
        EXPECT_EQ(probe.within(p, r, r * r), d <= r) << k << " " << j << " " << r;
        (d <= r ? near : far) += 1;
      }
    }
  }
  EXPECT_GT(near, 1000);  // both answers are exercised
  EXPECT_GT(far, 1000);
}

TEST(Distance, ParallelPlanes) {
  // Two squares 0.1 apart, triangulated differently: every sample is exactly 0.1 away.
  const Mesh a = square(5, 1.0, 0.0, false), b = square(7, 1.0, 0.1, true);
  const HausdorffDistance h = hausdorff_distance(a, b, {});
  EXPECT_NEAR(h.a_to_b.max, 0.1, 1e-15);
  EXPECT_NEAR(h.a_to_b.mean, 0.1, 1e-15);
  EXPECT_NEAR(h.b_to_a.max, 0.1, 1e-15);
  EXPECT_NEAR(h.two_sided(), 0.1, 1e-15);
  EXPECT_EQ(h.a_to_b.samples, 50u * 15u);  // 2·5² triangles, 15 lattice points (order 4)
}

TEST(Distance, OneSidedIsNotSymmetric) {
  // [0,1]² inside [0,2]² in one plane: A → B is 0; B → A is √2, at the corner (2, 2).
  const Mesh a = square(4, 1.0, 0.0, false), b = square(4, 2.0, 0.0, true);
  const HausdorffDistance h = hausdorff_distance(a, b, {});
  EXPECT_EQ(h.a_to_b.max, 0.0);
  EXPECT_NEAR(h.b_to_a.max, std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(h.b_to_a.where[0], 2.0, 1e-14);
  EXPECT_NEAR(h.b_to_a.where[1], 2.0, 1e-14);
  // Mean of the distance to [0,1]² over [0,2]²: (∫∫ dist)/4, with the three outer unit
  // squares: two of mean 1/2 (distance to an edge) and one of mean E|(x,y)| on [0,1]² ≈ 0.7652.
  // (2·0.5 + 0.7652)/4 = 0.4413; the order-4 lattice per triangle approximates it within 2%.
  EXPECT_NEAR(h.b_to_a.mean, 0.4413, 0.01);
}

TEST(Distance, SphereAndInflatedSphere) {
  // Icospheres of radius 1 and 1.1 (different subdivisions): the exact spheres are 0.1 apart,
  // and each mesh lies within its sagitta δ = R − (distance of the flattest triangle's plane
  // to the centre) inside its sphere; so every distance is within 0.1 ± (δa + δb).
  const Mesh a = sphere(3, 1.0), b = sphere(4, 1.1);
  auto sagitta = [](const Mesh& m, double r) {
    double d = 0.0;
    for (std::size_t t = 0; t < m.num_triangles(); ++t) {
      Vec3 v[3];
      for (int i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c) v[i][c] = m.coords[3 * m.triangles[3 * t + i] + c];
      const Vec3 n = normalize(cross(v[1] - v[0], v[2] - v[0]));
      d = std::max(d, r - dot(n, v[0]));
    }
    return d;
  };
  const double delta = sagitta(a, 1.0) + sagitta(b, 1.1);
  EXPECT_LT(delta, 0.01);
  DistanceOptions o;
  o.samples = 6;
  const HausdorffDistance h = hausdorff_distance(a, b, o);
  EXPECT_GT(h.a_to_b.max, 0.1 - delta);
  EXPECT_LT(h.a_to_b.max, 0.1 + delta);
  EXPECT_GT(h.b_to_a.max, 0.1 - delta);
  EXPECT_LT(h.two_sided(), 0.1 + delta);
  EXPECT_NEAR(h.a_to_b.mean, 0.1, delta);
  // Identical surfaces: zero both ways.
  EXPECT_LT(hausdorff_distance(a, a, o).two_sided(), 1e-15);  // rounding of the lattice points
}

TEST(Distance, SpacingRefinesTheLattice) {
  const Mesh a = square(1, 1.0, 0.0, false), b = square(1, 1.0, 0.0, true);
  DistanceOptions o;
  o.samples = 1;
  o.spacing = 0.1;  // longest edge √2: order ceil(14.1) = 15, 136 points per triangle
  EXPECT_EQ(one_sided_distance(a, TriangleTree(b), o).samples, 2u * 136u);
  o.spacing = -1.0;
  EXPECT_THROW(o.validate(), InputError);
  o.spacing = 0.0;
  o.samples = 0;
  EXPECT_THROW(o.validate(), InputError);
  EXPECT_THROW(TriangleTree(unit_square(2, 2)), InputError);  // 2D
}

// `riemesh distance --spacing 1e-300` ran for hours: 4096² / 2 points on each triangle. Over 10^8
// sample points in all is an InputError, raised before sampling.
TEST(Distance, SpacingAskingTooManySamplesIsAnInputError) {
  const Mesh a = square(10, 1.0, 0.0, false), b = square(1, 1.0, 0.0, true);
  DistanceOptions o;
  o.spacing = 1e-300;  // order capped at 4096 on each of 200 triangles: 1.7e9 points
  try {
    one_sided_distance(a, TriangleTree(b), o);
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("spacing"), std::string::npos) << e.what();
  }
}

}  // namespace
