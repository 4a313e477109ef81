// Robust predicates: signs on configurations with a known answer, then degenerate and nearly
// degenerate inputs (collinear, cocircular, coplanar, cospherical, perturbed by one ulp; huge and
// tiny coordinates) checked against an independent exact reference: integer coordinates, where the
// determinants are computed exactly with __int128. Doubles built from integers times a power of two
// are exact, and scaling by 2^k multiplies each determinant by a positive number, so the reference
// sign stays valid at any scale.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/predicates.hpp"

using namespace riemesh;

namespace {

using I = std::int64_t;
__extension__ typedef __int128 W;  // GCC/Clang extension, exact to 2^127

int sign_of(W v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }
int sign_of(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

// References: the determinants of the header, in integers.
W ref_orient2d(const I* a, const I* b, const I* c) {
  return W(b[0] - a[0]) * (c[1] - a[1]) - W(b[1] - a[1]) * (c[0] - a[0]);
}
W ref_det3(const I* u, const I* v, const I* w) {  // det of three integer vectors
  return W(u[0]) * (W(v[1]) * w[2] - W(v[2]) * w[1]) - W(u[1]) * (W(v[0]) * w[2] - W(v[2]) * w[0]) +
         W(u[2]) * (W(v[0]) * w[1] - W(v[1]) * w[0]);
}
W ref_orient3d(const I* a, const I* b, const I* c, const I* d) {
  const I u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const I v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  const I w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
  return ref_det3(u, v, w);
}
// incircle = det[p − d, |p − d|²] over p = a, b, c (rows), > 0 inside for ccw abc.
W ref_incircle(const I* a, const I* b, const I* c, const I* d) {
  const I* p[3] = {a, b, c};
  I x[3], y[3];
  W l[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = p[i][0] - d[0], y[i] = p[i][1] - d[1];
    l[i] = W(x[i]) * x[i] + W(y[i]) * y[i];
  }
  return l[0] * (W(x[1]) * y[2] - W(x[2]) * y[1]) - l[1] * (W(x[0]) * y[2] - W(x[2]) * y[0]) +
         l[2] * (W(x[0]) * y[1] - W(x[1]) * y[0]);
}
// insphere = −det[p − e, |p − e|²] over p = a, b, c, d (the lifted column last); the minus sign
// is checked by InsphereKnownSigns below, independently of the library.
W ref_insphere(const I* a, const I* b, const I* c, const I* d, const I* e) {
  const I* p[4] = {a, b, c, d};
  I q[4][3];
  W l[4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) q[i][k] = p[i][k] - e[k];
    l[i] = W(q[i][0]) * q[i][0] + W(q[i][1]) * q[i][1] + W(q[i][2]) * q[i][2];
  }
  // Laplace along the lifted column: det = Σ_i (−1)^(i+3) l_i det(rows ≠ i).
  W det = 0;
  for (int i = 0; i < 4; ++i) {
    const I* r[3];
    int n = 0;
    for (int j = 0; j < 4; ++j)
      if (j != i) r[n++] = q[j];
    const W m = ref_det3(r[0], r[1], r[2]);
    det += ((i + 3) % 2 == 0 ? 1 : -1) * l[i] * m;
  }
  return -det;
}

/// Integer points as doubles times 2^shift (exact).
struct Pts {
  double p[5][3] = {};
  Pts(const I (*pts)[3], int n, int shift) {
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) p[i][k] = std::ldexp(double(pts[i][k]), shift);
  }
};

constexpr int kShifts[] = {0, -30, 30, -700, 700, -1000, 950};

/// Checks the four predicates (fast and exact paths) against the references on integer points
/// pts[0..4], at every scale of kShifts. Returns the number of exactly degenerate cases seen.
int check_all(const I (*q)[3]) {
  const int s2 = sign_of(ref_orient2d(q[0], q[1], q[2]));
  const int sc = sign_of(ref_incircle(q[0], q[1], q[2], q[3]));
  const int s3 = sign_of(ref_orient3d(q[0], q[1], q[2], q[3]));
  const int ss = sign_of(ref_insphere(q[0], q[1], q[2], q[3], q[4]));
  for (int shift : kShifts) {
    const Pts d(q, 5, shift);
    const double* p[5] = {d.p[0], d.p[1], d.p[2], d.p[3], d.p[4]};
    EXPECT_EQ(sign_of(orient2d(p[0], p[1], p[2])), s2) << "shift " << shift;
    EXPECT_EQ(sign_of(exact::orient2d(p[0], p[1], p[2])), s2) << "shift " << shift;
    EXPECT_EQ(sign_of(incircle(p[0], p[1], p[2], p[3])), sc) << "shift " << shift;
    EXPECT_EQ(sign_of(exact::incircle(p[0], p[1], p[2], p[3])), sc) << "shift " << shift;
    EXPECT_EQ(sign_of(orient3d(p[0], p[1], p[2], p[3])), s3) << "shift " << shift;
    EXPECT_EQ(sign_of(exact::orient3d(p[0], p[1], p[2], p[3])), s3) << "shift " << shift;
    EXPECT_EQ(sign_of(insphere(p[0], p[1], p[2], p[3], p[4])), ss) << "shift " << shift;
    EXPECT_EQ(sign_of(exact::insphere(p[0], p[1], p[2], p[3], p[4])), ss) << "shift " << shift;
  }
  return (s2 == 0) + (sc == 0) + (s3 == 0) + (ss == 0);
}

}  // namespace

TEST(Predicates, KnownSigns2d) {
  const double a[] = {0, 0}, b[] = {1, 0}, c[] = {0, 1};
  EXPECT_GT(orient2d(a, b, c), 0);  // counter-clockwise
  EXPECT_LT(orient2d(a, c, b), 0);
  EXPECT_EQ(orient2d(a, b, b), 0);
  EXPECT_DOUBLE_EQ(orient2d(a, b, c), 1.0);  // det(b − a, c − a)
  const double in[] = {0.4, 0.4}, out[] = {1, 1}, on[] = {1, 1};
  EXPECT_GT(incircle(a, b, c, in), 0);
  EXPECT_LT(incircle(a, c, b, in), 0);  // clockwise abc flips the sign
  EXPECT_EQ(incircle(a, b, c, on), 0);  // (1, 1) is on the circle through a, b, c
  const double far[] = {3, 3};
  EXPECT_LT(incircle(a, b, c, far), 0);
  (void)out;
}

TEST(Predicates, KnownSigns3d) {
  const double a[] = {0, 0, 0}, b[] = {1, 0, 0}, c[] = {0, 1, 0}, d[] = {0, 0, 1};
  EXPECT_DOUBLE_EQ(orient3d(a, b, c, d), 1.0);  // det(b − a, c − a, d − a) = det(I)
  EXPECT_LT(orient3d(a, c, b, d), 0);
  const double centroid[] = {0.25, 0.25, 0.25}, far[] = {2, 2, 2}, on[] = {1, 1, 1};
  EXPECT_GT(insphere(a, b, c, d, centroid), 0);
  EXPECT_LT(insphere(a, c, b, d, centroid), 0);
  EXPECT_LT(insphere(a, b, c, d, far), 0);
  EXPECT_EQ(insphere(a, b, c, d, on), 0);  // (1, 1, 1) is on the sphere through a, b, c, d
}

TEST(Predicates, ReferencesHaveTheDocumentedSigns) {
  // The integer references themselves, on the configurations above (times 4).
  const I a[] = {0, 0, 0}, b[] = {4, 0, 0}, c[] = {0, 4, 0}, d[] = {0, 0, 4};
  const I in2[] = {1, 1, 0}, in3[] = {1, 1, 1}, far[] = {8, 8, 8};
  EXPECT_GT(ref_orient2d(a, b, c), 0);
  EXPECT_GT(ref_incircle(a, b, c, in2), 0);
  EXPECT_LT(ref_incircle(a, b, c, far), 0);
  EXPECT_GT(ref_orient3d(a, b, c, d), 0);
  EXPECT_GT(ref_insphere(a, b, c, d, in3), 0);
  EXPECT_LT(ref_insphere(a, b, c, d, far), 0);
}

TEST(Predicates, RandomSmallIntegersAreOftenDegenerate) {
  // Coordinates in [-3, 3]: collinear, cocircular, coplanar and cospherical sets are frequent.
  std::mt19937_64 rng(1);
  std::uniform_int_distribution<I> coord(-3, 3);
  int degenerate = 0;
  for (int t = 0; t < 3000; ++t) {
    I q[5][3];
    for (auto& p : q)
      for (I& x : p) x = coord(rng);
    degenerate += check_all(q);
  }
  EXPECT_GT(degenerate, 500);  // the test does exercise the exact path
}

TEST(Predicates, RandomLargeIntegers) {
  // Up to 2^20: the int128 references cannot overflow (insphere ≲ 2^111).
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<I> coord(-(I(1) << 20), I(1) << 20);
  for (int t = 0; t < 3000; ++t) {
    I q[5][3];
    for (auto& p : q)
      for (I& x : p) x = coord(rng);
    check_all(q);
  }
}

TEST(Predicates, CollinearPointsPerturbedByOneUlp) {
  // Integers in [2^52, 2^53) are doubles whose ulp is 1: the points (t, t + k·s) lie on a line,
  // and moving the last one by ±1 is a one-ulp perturbation.
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<I> base(I(1) << 52, (I(1) << 52) + (I(1) << 40));
  std::uniform_int_distribution<I> step(-(I(1) << 20), I(1) << 20);
  int zero = 0, plus = 0, minus = 0;
  for (int t = 0; t < 2000; ++t) {
    const I x0 = base(rng), y0 = base(rng), dx = step(rng), dy = step(rng);
    const I k1 = step(rng) % 1000, k2 = step(rng) % 1000;
    I q[5][3] = {{x0, y0, 0}, {x0 + k1 * dx, y0 + k1 * dy, 0}, {x0 + k2 * dx, y0 + k2 * dy, 0}};
    const int bump = int(t % 3) - 1;
    q[2][1] += bump;
    const int expected = sign_of(ref_orient2d(q[0], q[1], q[2]));
    zero += expected == 0, plus += expected > 0, minus += expected < 0;
    for (int shift : {0, -52, -1000, 900}) {
      const Pts d(q, 3, shift);
      EXPECT_EQ(sign_of(orient2d(d.p[0], d.p[1], d.p[2])), expected);
    }
  }
  EXPECT_GT(zero, 100);
  EXPECT_GT(plus, 100);
  EXPECT_GT(minus, 100);
}

TEST(Predicates, CocircularAndCosphericalPointsPerturbedByOneUlp) {
  // Points on the circle x² + y² = 65² (65² has several sums of two squares) and on the sphere
  // x² + y² + z² = 9 (permutations of (1, 2, 2) and (3, 0, 0)), scaled by 2^20 and centred near
  // 2^52 where the ulp is 1; the last point then moves by −1, 0 or +1 along each axis.
  const I circle[][2] = {{16, 63}, {-33, 56}, {-39, -52}, {60, -25}, {65, 0}, {0, -65}, {-63, 16}};
  const I sphere[][3] = {{1, 2, 2}, {-2, 1, 2}, {2, -2, 1}, {-1, -2, -2}, {3, 0, 0}, {0, 0, -3},
                         {2, 2, -1}, {-2, -1, 2}};
  const I centre = (I(1) << 52) + 12345, unit = I(1) << 20;
  std::mt19937_64 rng(4);
  int degenerate = 0;
  for (int t = 0; t < 400; ++t) {
    I q[5][3];
    for (int i = 0; i < 5; ++i) {
      const auto& s = sphere[(t + 3 * i) % 8];
      for (int k = 0; k < 3; ++k) q[i][k] = centre + 100 * k + s[k] * unit;
    }
    for (int k = 0; k < 3; ++k) q[4][k] += int(rng() % 3) - 1;
    I c2[5][3];
    for (int i = 0; i < 4; ++i) {
      const auto& c = circle[(t + 2 * i) % 7];
      c2[i][0] = centre + c[0] * unit, c2[i][1] = centre - 7 + c[1] * unit, c2[i][2] = 0;
    }
    c2[3][0] += int(t % 3) - 1, c2[3][1] += int((t / 3) % 3) - 1;
    c2[4][0] = c2[4][1] = c2[4][2] = 0;
    const int sc = sign_of(ref_incircle(c2[0], c2[1], c2[2], c2[3]));
    const int ss = sign_of(ref_insphere(q[0], q[1], q[2], q[3], q[4]));
    degenerate += (sc == 0) + (ss == 0);
    for (int shift : {0, -60, -1000, 950}) {
      const Pts dc(c2, 4, shift), ds(q, 5, shift);
      EXPECT_EQ(sign_of(incircle(dc.p[0], dc.p[1], dc.p[2], dc.p[3])), sc) << t << " " << shift;
      EXPECT_EQ(sign_of(insphere(ds.p[0], ds.p[1], ds.p[2], ds.p[3], ds.p[4])), ss)
          << t << " " << shift;
    }
  }
  EXPECT_GT(degenerate, 50);
}

TEST(Predicates, CoplanarPointsPerturbedByOneUlp) {
  // d = a + i·u + j·v lies on the plane of a, b = a + u, c = a + v; then ±1 ulp in z.
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<I> base(I(1) << 52, (I(1) << 52) + (I(1) << 40));
  std::uniform_int_distribution<I> step(-(I(1) << 12), I(1) << 12);
  int zero = 0;
  for (int t = 0; t < 2000; ++t) {
    I a[3], u[3], v[3];
    for (int k = 0; k < 3; ++k) a[k] = base(rng), u[k] = step(rng), v[k] = step(rng);
    const I i = step(rng) % 64, j = step(rng) % 64;
    I q[5][3];
    for (int k = 0; k < 3; ++k) {
      q[0][k] = a[k], q[1][k] = a[k] + u[k], q[2][k] = a[k] + v[k];
      q[3][k] = a[k] + i * u[k] + j * v[k];
    }
    q[3][2] += int(t % 3) - 1;
    const int expected = sign_of(ref_orient3d(q[0], q[1], q[2], q[3]));
    zero += expected == 0;
    for (int shift : {0, -52, -1000, 900}) {
      const Pts d(q, 4, shift);
      EXPECT_EQ(sign_of(orient3d(d.p[0], d.p[1], d.p[2], d.p[3])), expected);
    }
  }
  EXPECT_GT(zero, 300);
}

TEST(Predicates, FilterAgreesWithExactOnRandomDoubles) {
  // General doubles (not integers): the filtered result must have the sign of the exact one,
  // including for nearly degenerate sets made by rounding points onto a line or circle.
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int t = 0; t < 20000; ++t) {
    double p[5][3];
    for (auto& x : p)
      for (double& c : x) c = u(rng);
    if (t % 2) {  // nearly degenerate: the last point on the segment/circle, rounded
      const double s = u(rng);
      for (int k = 0; k < 3; ++k) p[2][k] = p[0][k] + s * (p[1][k] - p[0][k]);
      const double th = 3.0 * u(rng);
      p[3][0] = std::cos(th), p[3][1] = std::sin(th);
      p[0][0] = 1, p[0][1] = 0, p[1][0] = 0, p[1][1] = 1;
    }
    EXPECT_EQ(sign_of(orient2d(p[0], p[1], p[2])), sign_of(exact::orient2d(p[0], p[1], p[2])));
    EXPECT_EQ(sign_of(incircle(p[0], p[1], p[2], p[3])),
              sign_of(exact::incircle(p[0], p[1], p[2], p[3])));
    EXPECT_EQ(sign_of(orient3d(p[0], p[1], p[2], p[3])),
              sign_of(exact::orient3d(p[0], p[1], p[2], p[3])));
    EXPECT_EQ(sign_of(insphere(p[0], p[1], p[2], p[3], p[4])),
              sign_of(exact::insphere(p[0], p[1], p[2], p[3], p[4])));
  }
}

TEST(Predicates, AllPointsEqualOrAtTheOrigin) {
  const double o[] = {0, 0, 0}, a[] = {1e-300, 5e-310, 0};
  EXPECT_EQ(orient2d(o, o, o), 0);
  EXPECT_EQ(insphere(o, o, o, o, o), 0);
  EXPECT_EQ(orient2d(a, a, o), 0);
}
