// Degenerate inputs whose coordinate differences are NOT exact in floating point, so that the
// exact predicates cannot translate the points and must work on the raw coordinates: the corners
// of axis-aligned boxes with arbitrary double coordinates (values like i/50 as a mesh's grid
// has, or random doubles of mixed magnitudes and signs). The corners of any box are exactly cospherical (and those of any
// rectangle exactly cocircular), whatever the rounding of the coordinates, because the sphere
// centred at the box's centre passes through all of them; four corners of one face are exactly
// coplanar, three points with one equal coordinate exactly collinear. Moving one corner away from
// the centre by one ulp per coordinate puts it strictly outside that sphere, towards the centre
// strictly inside.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/predicates.hpp"

using namespace riemesh;

namespace {

int sign_of(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

/// A box [lo, hi].
struct Box {
  double lo[3], hi[3];
  /// Corner k: bit i of k picks hi along axis i.
  void corner(int k, double* p) const {
    for (int i = 0; i < 3; ++i) p[i] = (k >> i) & 1 ? hi[i] : lo[i];
  }
};

/// Sides far from their ends' magnitude, so hi − lo is usually not a double (Sterbenz's lemma
/// makes it exact when lo and hi are within a factor 2 of each other, which we avoid).
Box random_box(std::mt19937_64& rng, int t) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Box b;
  for (int i = 0; i < 3; ++i) {
    if (t % 2 == 0) {  // multiples of 1/50, as a mesh's grid has, lo small and hi large
      b.lo[i] = static_cast<double>(1 + rng() % 50) / 50.0;
      b.hi[i] = static_cast<double>(200 + rng() % 5000) / 50.0;
    } else {  // arbitrary doubles of opposite signs and mixed magnitudes
      b.lo[i] = -u(rng) * std::ldexp(1.0, static_cast<int>(rng() % 40) - 20) - 1e-300;
      b.hi[i] = u(rng) * std::ldexp(1.0, static_cast<int>(rng() % 40) - 20) + 1e-300;
    }
  }
  return b;
}

/// True when hi − lo is not exactly representable (the two-sum error term is non-zero).
bool inexact_difference(double hi, double lo) {
  const double d = hi - lo;
  const double bv = d - hi;
  const double av = d - bv;
  return (hi - av) + (-lo - bv) != 0.0;
}

/// p moved by one ulp per coordinate away from (direction +1) or towards (−1) the centre c.
void nudge(double* p, const double* c, int direction) {
  for (int i = 0; i < 3; ++i) {
    const bool away_up = p[i] > c[i];
    const bool up = direction > 0 ? away_up : !away_up;
    p[i] = std::nextafter(p[i], up ? HUGE_VAL : -HUGE_VAL);
  }
}

}  // namespace

TEST(PredicateBoxes, CornersAreExactlyDegenerate) {
  std::mt19937_64 rng(11);
  int inexact = 0;
  for (int t = 0; t < 2000; ++t) {
    const Box b = random_box(rng, t);
    double p[8][3];
    for (int k = 0; k < 8; ++k) b.corner(k, p[k]);
    // The differences must really be inexact for this test to exercise the raw path.
    for (int i = 0; i < 3; ++i) inexact += inexact_difference(b.hi[i], b.lo[i]);
    const int r = static_cast<int>(rng() % 8);  // a different corner choice each time
    const auto c = [&](int k) { return p[(k + r) % 8]; };
    EXPECT_EQ(insphere(c(0), c(1), c(2), c(4), c(7)), 0.0) << t;
    EXPECT_EQ(insphere(c(3), c(5), c(6), c(0), c(1)), 0.0) << t;
    EXPECT_EQ(exact::insphere(c(1), c(2), c(4), c(7), c(3)), 0.0) << t;
    // Corners 0, 1, 2, 3 share their z (the face z = lo): coplanar, and a rectangle in 2D.
    EXPECT_EQ(orient3d(p[0], p[1], p[3], p[2]), 0.0) << t;
    EXPECT_EQ(exact::orient3d(p[5], p[1], p[7], p[3]), 0.0) << t;
    EXPECT_EQ(incircle(p[0], p[1], p[3], p[2]), 0.0) << t;
    EXPECT_EQ(exact::incircle(p[1], p[3], p[2], p[0]), 0.0) << t;
    EXPECT_EQ(orient2d(p[0], p[1], p[5]), 0.0) << t;  // equal y: collinear in the plane
    EXPECT_EQ(exact::orient2d(p[2], p[6], p[3]), 0.0) << t;
  }
  EXPECT_GT(inexact, 1000);
}

TEST(PredicateBoxes, CornerMovedByOneUlpLeavesTheSphere) {
  std::mt19937_64 rng(12);
  for (int t = 0; t < 2000; ++t) {
    const Box b = random_box(rng, t);
    double p[8][3], centre[3];
    for (int k = 0; k < 8; ++k) b.corner(k, p[k]);
    for (int i = 0; i < 3; ++i) centre[i] = 0.5 * b.lo[i] + 0.5 * b.hi[i];
    for (int direction : {1, -1}) {
      double e[3] = {p[7][0], p[7][1], p[7][2]};
      nudge(e, centre, direction);
      // (0, 1, 2, 4) is a corner tetrahedron; inside (−1) gives the sign of its orientation.
      const int o = sign_of(orient3d(p[0], p[1], p[2], p[4]));
      ASSERT_NE(o, 0);
      EXPECT_EQ(sign_of(insphere(p[0], p[1], p[2], p[4], e)), -direction * o) << t;
      EXPECT_EQ(sign_of(exact::insphere(p[0], p[1], p[2], p[4], e)), -direction * o) << t;
      // The same in the plane z = lo: the rectangle 0, 1, 3, 2 and corner 3 moved.
      double f[3] = {p[3][0], p[3][1], p[3][2]};
      nudge(f, centre, direction);
      f[2] = p[3][2];
      const int o2 = sign_of(orient2d(p[0], p[1], p[2]));
      EXPECT_EQ(sign_of(incircle(p[0], p[1], p[2], f)), -direction * o2) << t;
      EXPECT_EQ(sign_of(exact::incircle(p[0], p[1], p[2], f)), -direction * o2) << t;
    }
  }
}
