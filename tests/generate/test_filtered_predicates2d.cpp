// The inline 2D filters of the Delaunay kernel against the exact predicates (expansion
// arithmetic, no filter): the signs must agree on random points, on exactly degenerate ones
// (collinear, cocircular: the filter must pass them on) and on nearly degenerate ones (rounded
// onto a line or circle, moved by one ulp), at ordinary, tiny and huge scales. The in-circle sign
// with the static filter (incircle_sign_in_box) too, with the points' own box.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/predicates.hpp"
#include "generate/filtered_predicates2d.hpp"

using namespace riemesh;

namespace {

int sign(double x) { return (x > 0) - (x < 0); }

/// The static in-circle filter with the tightest box of the four points, and with a looser one.
void expect_static_agrees(const double (&p)[4][2], int exact_sign) {
  double extent = 0;
  for (int c = 0; c < 2; ++c) {
    double lo = p[0][c], hi = p[0][c];
    for (const auto& q : p) lo = std::min(lo, q[c]), hi = std::max(hi, q[c]);
    extent = std::max(extent, hi - lo);
  }
  for (const double e : {extent, 4 * extent})
    EXPECT_EQ(detail::incircle_sign_in_box(p[0], p[1], p[2], p[3], true,
                                           detail::incircle_static_bound(e)),
              exact_sign)
        << "extent " << e;
}

/// Both filtered signs against the exact ones; returns how many of the two are exactly zero.
int expect_agree(const double (&p)[4][2]) {
  const int o = sign(exact::orient2d(p[0], p[1], p[2]));
  const int i = sign(exact::incircle(p[0], p[1], p[2], p[3]));
  EXPECT_EQ(detail::orient2d_sign(p[0], p[1], p[2]), o)
      << p[0][0] << " " << p[0][1] << " " << p[1][0] << " " << p[1][1] << " " << p[2][0] << " "
      << p[2][1];
  EXPECT_EQ(detail::incircle_sign(p[0], p[1], p[2], p[3]), i) << p[3][0] << " " << p[3][1];
  expect_static_agrees(p, i);
  return (o == 0) + (i == 0);
}

}  // namespace

TEST(FilteredPredicates2d, KnownSigns) {
  const double a[2] = {0, 0}, b[2] = {1, 0}, c[2] = {0, 1};
  const double in[2] = {0.25, 0.25}, out[2] = {2, 2}, on[2] = {1, 1};
  EXPECT_EQ(detail::orient2d_sign(a, b, c), 1);
  EXPECT_EQ(detail::orient2d_sign(a, c, b), -1);
  EXPECT_EQ(detail::orient2d_sign(a, b, out), 1);
  EXPECT_EQ(detail::orient2d_sign(a, on, out), 0);  // (0,0), (1,1), (2,2)
  EXPECT_EQ(detail::incircle_sign(a, b, c, in), 1);
  EXPECT_EQ(detail::incircle_sign(a, b, c, out), -1);
  EXPECT_EQ(detail::incircle_sign(a, b, c, on), 0);   // (1,1) is on the circle through a, b, c
  EXPECT_EQ(detail::incircle_sign(a, c, b, in), -1);  // clockwise: the sign flips
  const double box = detail::incircle_static_bound(2.0);
  EXPECT_EQ(detail::incircle_sign_in_box(a, b, c, in, true, box), 1);
  EXPECT_EQ(detail::incircle_sign_in_box(a, b, c, out, true, box), -1);
  EXPECT_EQ(detail::incircle_sign_in_box(a, b, c, on, true, box), 0);
  EXPECT_EQ(detail::incircle_sign_in_box(a, b, c, in, false, box), 1);
  EXPECT_EQ(detail::incircle_static_bound(HUGE_VAL), HUGE_VAL);  // nothing passes
  EXPECT_EQ(detail::incircle_static_bound(1e300), HUGE_VAL);     // overflow: nothing passes
}

TEST(FilteredPredicates2d, RandomPointsAtEveryScale) {
  // Small configurations far from the origin (the kernel's small triangles of a large domain),
  // and scales down to 1e-300 and up to 1e300, where the bounds underflow or the products
  // overflow and the exact predicates must take over.
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int t = 0; t < 40000; ++t) {
    const double scale = std::ldexp(1.0, (t % 41) * 50 - 1000);
    const double size = t % 3 == 0 ? 1e-6 : 1.0, offset = t % 5 == 0 ? 3.0 : 0.0;
    double p[4][2];
    for (auto& q : p)
      for (double& x : q) x = scale * (offset + size * u(rng));
    expect_agree(p);
  }
}

TEST(FilteredPredicates2d, CollinearAndCocircularPoints) {
  // Exactly degenerate: points of an integer grid (collinear along rows, diagonals; the corners
  // of any axis-aligned rectangle are cocircular), scaled by powers of two (exact), then the
  // same moved by one ulp. No zero coordinate: one ulp of zero is a subnormal, outside the exact
  // predicates' range (core/predicates.hpp).
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<int> g(12, 20);
  int degenerate = 0;
  for (int t = 0; t < 20000; ++t) {
    const double scale = std::ldexp(1.0, (t % 9) * 100 - 450);
    double p[4][2];
    if (t % 2) {  // rectangle corners a, b, c (ccw or not) and d: cocircular
      const double x0 = g(rng), y0 = g(rng), w = g(rng) - 11, h = g(rng) - 11;
      const double r[4][2] = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
      const int k = t % 4;
      for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 2; ++c) p[i][c] = r[(i + k) % 4][c];
    } else {
      for (auto& q : p)
        for (double& x : q) x = g(rng);
    }
    for (auto& q : p)
      for (double& x : q) x *= scale;
    degenerate += expect_agree(p) > 0;
    const int i = static_cast<int>(rng() % 4), c = static_cast<int>(rng() % 2);
    p[i][c] = std::nextafter(p[i][c], rng() % 2 ? HUGE_VAL : -HUGE_VAL);
    expect_agree(p);
  }
  EXPECT_GT(degenerate, 8000);  // the exact path is exercised
}

TEST(FilteredPredicates2d, NearlyDegeneratePoints) {
  // A point rounded onto the segment of two others, and a point rounded onto the unit circle
  // through three others: the determinants are a few ulps from zero, where a wrong filter bound
  // would give the wrong sign.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int t = 0; t < 40000; ++t) {
    const double centre[2] = {t % 2 ? 0.0 : 1e3 * u(rng), t % 2 ? 0.0 : 1e3 * u(rng)};
    double p[4][2];
    for (int i = 0; i < 4; ++i) {
      const double th = 6.283185307179586 * (0.5 + 0.5 * u(rng));
      p[i][0] = centre[0] + std::cos(th), p[i][1] = centre[1] + std::sin(th);
    }
    const double s = u(rng);
    if (t % 3 == 0) {
      for (int c = 0; c < 2; ++c) p[2][c] = p[0][c] + s * (p[1][c] - p[0][c]);
    }
    expect_agree(p);
  }
}
