// Robust predicates on the inputs where plain floating point fails: Kettner et al.'s "classroom
// examples" (CGTA 40, 2008) — a point moved over a 64 × 64 grid of one-ulp steps around a point of
// a line, circle, plane or sphere through exactly representable points. Naive evaluation gets
// many of those signs wrong; the predicates must match an independent exact reference: every
// coordinate is an integer multiple of u = 2^-53, so the determinants are integers (in units of
// u^degree), computed here with 384-bit two's-complement integers (a tiny schoolbook bignum,
// independent of the library's expansion arithmetic).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "core/predicates.hpp"

using namespace riemesh;

namespace {

__extension__ typedef unsigned __int128 U128;

/// A 384-bit integer, two's complement; + − × are exact while results stay within ±2^383.
struct Big {
  std::array<std::uint64_t, 6> w{};
  static Big of(std::int64_t v) {
    Big b;
    for (auto& x : b.w) x = v < 0 ? ~0ull : 0ull;
    b.w[0] = static_cast<std::uint64_t>(v);
    return b;
  }
  friend Big operator+(const Big& a, const Big& b) {
    Big r;
    U128 carry = 0;
    for (int i = 0; i < 6; ++i) {
      const U128 s = U128(a.w[i]) + b.w[i] + carry;
      r.w[i] = static_cast<std::uint64_t>(s);
      carry = s >> 64;
    }
    return r;
  }
  friend Big operator-(const Big& a) {
    Big r;
    for (int i = 0; i < 6; ++i) r.w[i] = ~a.w[i];
    return r + of(1);
  }
  friend Big operator-(const Big& a, const Big& b) { return a + (-b); }
  friend Big operator*(const Big& a, const Big& b) {  // modulo 2^384: exact for signed values
    Big r;
    for (int i = 0; i < 6; ++i) {
      U128 carry = 0;
      for (int j = 0; i + j < 6; ++j) {
        const U128 p = U128(a.w[i]) * b.w[j] + r.w[i + j] + carry;
        r.w[i + j] = static_cast<std::uint64_t>(p);
        carry = p >> 64;
      }
    }
    return r;
  }
  int sign() const {
    if (w[5] >> 63) return -1;
    for (auto x : w)
      if (x) return 1;
    return 0;
  }
};

constexpr double kU = 0x1p-53;

/// A coordinate in units of u (exact: every coordinate used is a multiple of u below 2^9).
std::int64_t units(double x) {
  const double n = x / kU;
  EXPECT_EQ(std::fabs(n), std::floor(std::fabs(n)));
  return static_cast<std::int64_t>(n);
}

Big diff(const double* p, const double* q, int k) { return Big::of(units(p[k]) - units(q[k])); }

Big det2(const Big& a, const Big& b, const Big& c, const Big& d) { return a * d - b * c; }
Big det3(const Big m[3][3]) {
  return m[0][0] * det2(m[1][1], m[1][2], m[2][1], m[2][2]) -
         m[0][1] * det2(m[1][0], m[1][2], m[2][0], m[2][2]) +
         m[0][2] * det2(m[1][0], m[1][1], m[2][0], m[2][1]);
}

int ref_orient2d(const double* a, const double* b, const double* c) {
  return det2(diff(b, a, 0), diff(b, a, 1), diff(c, a, 0), diff(c, a, 1)).sign();
}
int ref_incircle(const double* a, const double* b, const double* c, const double* d) {
  const double* p[3] = {a, b, c};
  Big m[3][3];
  for (int i = 0; i < 3; ++i) {
    m[i][0] = diff(p[i], d, 0), m[i][1] = diff(p[i], d, 1);
    m[i][2] = m[i][0] * m[i][0] + m[i][1] * m[i][1];
  }
  return det3(m).sign();  // det[p − d, |p − d|²] > 0 inside for ccw abc
}
int ref_orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double* p[3] = {b, c, d};
  Big m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = diff(p[i], a, k);
  return det3(m).sign();  // det(b − a, c − a, d − a)
}
int ref_insphere(const double* a, const double* b, const double* c, const double* d,
                 const double* e) {
  // −det[p − e, |p − e|²] over p = a, b, c, d (see test_predicates.cpp), by Laplace along the
  // lifted column.
  const double* p[4] = {a, b, c, d};
  Big q[4][3], l[4];
  for (int i = 0; i < 4; ++i) {
    for (int k = 0; k < 3; ++k) q[i][k] = diff(p[i], e, k);
    l[i] = q[i][0] * q[i][0] + q[i][1] * q[i][1] + q[i][2] * q[i][2];
  }
  Big det = Big::of(0);
  for (int i = 0; i < 4; ++i) {
    Big m[3][3];
    for (int j = 0, r = 0; j < 4; ++j) {
      if (j == i) continue;
      for (int k = 0; k < 3; ++k) m[r][k] = q[j][k];
      ++r;
    }
    const Big term = l[i] * det3(m);
    det = (i % 2 == 1) ? det + term : det - term;  // sign (−1)^(i+3)
  }
  return (-det).sign();
}

int sign_of(double v) { return v > 0 ? 1 : v < 0 ? -1 : 0; }

/// Cases checked and exactly degenerate ones among them. (With the filter's error bounds set to
/// zero — plain floating point — these four tests fail: the grids are hard.)
struct Tally {
  int checked = 0, zero = 0;
};

}  // namespace

TEST(PredicateGrids, BigIntegerReferenceKnowsTheSigns) {
  const double a[] = {0, 0, 0}, b[] = {1, 0, 0}, c[] = {0, 1, 0}, d[] = {0, 0, 1};
  const double in[] = {0.25, 0.25, 0.25}, far[] = {2, 2, 2};
  EXPECT_EQ(ref_orient2d(a, b, c), 1);
  EXPECT_EQ(ref_incircle(a, b, c, in), 1);
  EXPECT_EQ(ref_incircle(a, b, c, far), -1);
  EXPECT_EQ(ref_orient3d(a, b, c, d), 1);
  EXPECT_EQ(ref_insphere(a, b, c, d, in), 1);
  EXPECT_EQ(ref_insphere(a, b, c, d, far), -1);
  EXPECT_EQ((Big::of(-3) * Big::of(5) + Big::of(15)).sign(), 0);
}

TEST(PredicateGrids, Orient2dNearALine) {
  // Kettner's example: p near (0.5, 0.5) on the line through q = (12, 12) and r = (24, 24).
  const double q[] = {12, 12}, r[] = {24, 24};
  Tally t;
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) {
      const double p[] = {0.5 + i * kU, 0.5 + j * kU};
      const int expected = ref_orient2d(p, q, r);
      ASSERT_EQ(sign_of(orient2d(p, q, r)), expected) << i << " " << j;
      ASSERT_EQ(sign_of(orient2d(q, r, p)), expected);
      ++t.checked, t.zero += expected == 0;
    }
  EXPECT_EQ(t.zero, 64);  // the diagonal i = j
}

TEST(PredicateGrids, IncircleNearACircle) {
  // Circle of centre (0.5, 12.5) and radius 12 through b, c, d; the query near (0.5, 0.5).
  const double b[] = {12.5, 12.5}, c[] = {0.5, 24.5}, d[] = {-11.5, 12.5};
  Tally t;
  for (int i = -32; i < 32; ++i)
    for (int j = -32; j < 32; ++j) {
      const double p[] = {0.5 + i * kU, 0.5 + j * kU};
      const int expected = ref_incircle(b, c, d, p);
      ASSERT_EQ(sign_of(incircle(b, c, d, p)), expected) << i << " " << j;
      ASSERT_EQ(sign_of(incircle(p, b, c, d)), -expected) << i << " " << j;  // odd permutation
      ++t.checked, t.zero += expected == 0;
    }
  EXPECT_GE(t.zero, 1);  // (0.5, 0.5) itself is on the circle
}

TEST(PredicateGrids, Orient3dNearAPlane) {
  // The plane x + y + z = 1.5 through a, b, c; the query near (0.5, 0.5, 0.5).
  const double a[] = {1.5, 0, 0}, b[] = {0, 1.5, 0}, c[] = {0, 0, 1.5};
  Tally t;
  for (int i = -32; i < 32; ++i)
    for (int j = -32; j < 32; ++j) {
      const double p[] = {0.5 + i * kU, 0.5 + j * kU, 0.5 - (i + j) / 2 * kU};
      const int expected = ref_orient3d(a, b, c, p);
      ASSERT_EQ(sign_of(orient3d(a, b, c, p)), expected) << i << " " << j;
      ASSERT_EQ(sign_of(orient3d(p, a, b, c)), -expected) << i << " " << j;
      ++t.checked, t.zero += expected == 0;
    }
  EXPECT_GE(t.zero, 32);
}

TEST(PredicateGrids, InsphereNearASphere) {
  // Sphere of centre (0.5, 12.5, 0.5) and radius 12 through a, b, c, d; query near (0.5, 0.5, 0.5).
  const double a[] = {12.5, 12.5, 0.5}, b[] = {0.5, 24.5, 0.5}, c[] = {-11.5, 12.5, 0.5},
               d[] = {0.5, 12.5, 12.5};
  const double o = orient3d(a, b, c, d);
  ASSERT_NE(o, 0);
  Tally t;
  for (int i = -32; i < 32; ++i)
    for (int j = -32; j < 32; ++j) {
      const double p[] = {0.5 + i * kU, 0.5 + j * kU, 0.5 + ((i * j) % 3) * kU};
      const int expected = ref_insphere(a, b, c, d, p);
      ASSERT_EQ(sign_of(insphere(a, b, c, d, p)), expected) << i << " " << j;
      ++t.checked, t.zero += expected == 0;
    }
  EXPECT_GE(t.zero, 1);
}
