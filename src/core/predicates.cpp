#include "core/predicates.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/error.hpp"

namespace riemesh {

namespace {

// ---------------------------------------------------------------------------------------------
// Expansion arithmetic (Shewchuk 1997, §2). An expansion is a sum of doubles that do not overlap
// (their significant bits occupy disjoint ranges), stored by increasing magnitude with zeros
// removed; the empty expansion is zero. Exact as long as nothing overflows or underflows.
// Expansions live in fixed-size arrays on the stack: the capacity N is a compile-time bound on
// the length (each operation's result type carries the bound of its operands), so the exact path
// never allocates.

template <int N>
struct Expansion {
  int n = 0;
  double c[N];  // c[0..n) are the components; the rest is never read
};

/// x + y = a + b exactly, x = fl(a + b) (Knuth's branch-free two-sum).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

/// Same, valid when |a| >= |b| (Dekker).
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

/// x + y = a * b exactly, x = fl(a * b): the fused multiply-add gives the rounding error.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}

/// e + sign·f (sign = ±1): the components merged by magnitude, then a chain of two-sums
/// (Shewchuk's Fast-Expansion-Sum, which needs round-to-nearest-even; zero components dropped).
template <int A, int B>
Expansion<A + B> add(const Expansion<A>& e, const Expansion<B>& f, double sign) {
  Expansion<A + B> h;
  int i = 0, j = 0;
  const auto next = [&]() {
    if (j == f.n || (i < e.n && std::fabs(e.c[i]) < std::fabs(f.c[j]))) return e.c[i++];
    return sign * f.c[j++];
  };
  if (e.n + f.n == 0) return h;
  double q = next();
  while (i < e.n || j < f.n) {
    double sum, err;
    two_sum(q, next(), sum, err);
    if (err != 0.0) h.c[h.n++] = err;
    q = sum;
  }
  if (q != 0.0) h.c[h.n++] = q;
  return h;
}

template <int A, int B>
Expansion<A + B> operator+(const Expansion<A>& e, const Expansion<B>& f) {
  return add(e, f, 1.0);
}

template <int A, int B>
Expansion<A + B> operator-(const Expansion<A>& e, const Expansion<B>& f) {
  return add(e, f, -1.0);
}

/// e * b (Shewchuk's Scale-Expansion, zero components dropped).
template <int A>
Expansion<2 * A> operator*(const Expansion<A>& e, double b) {
  Expansion<2 * A> h;
  if (e.n == 0 || b == 0.0) return h;
  double q, err;
  two_product(e.c[0], b, q, err);
  if (err != 0.0) h.c[h.n++] = err;
  for (int i = 1; i < e.n; ++i) {
    double p_hi, p_lo, sum;
    two_product(e.c[i], b, p_hi, p_lo);
    two_sum(q, p_lo, sum, err);
    if (err != 0.0) h.c[h.n++] = err;
    fast_two_sum(p_hi, sum, q, err);
    if (err != 0.0) h.c[h.n++] = err;
  }
  if (q != 0.0) h.c[h.n++] = q;
  return h;
}

/// a * b exactly, as an expansion of at most 2 components.
inline Expansion<2> product(double a, double b) {
  Expansion<2> h;
  double hi, lo;
  two_product(a, b, hi, lo);
  if (lo != 0.0) h.c[h.n++] = lo;
  if (hi != 0.0) h.c[h.n++] = hi;
  return h;
}

/// The sign of an expansion is the sign of its largest component; returned as an approximation
/// of its value.
template <int A>
double approximate(const Expansion<A>& e) {
  return e.n == 0 ? 0.0 : e.c[e.n - 1];
}

// ---------------------------------------------------------------------------------------------
// Exact determinants of the homogeneous matrices whose rows are the points: [x, y, 1] (orient2d),
// [x, y, z, 1] (orient3d), [x² + y², x, y, 1] (incircle), [x² + y² + z², x, y, z, 1]
// (insphere). Laplace expansion: 2 x 2 minors of the (x, y) columns, then 3 x 3 minors with the
// 1 column, then the z column, then the lifted one; each minor is computed once. The capacities
// are Shewchuk's bounds (4, 12, 96, 384 / 5760 components); zero elimination keeps the actual
// lengths short on the integer-like coordinates of degenerate inputs.

/// The (x, y) minors m[i][j] = x_i y_j − x_j y_i, i < j.
template <int P>
void xy_minors(const double (&p)[P][3], Expansion<4> (&m)[P][P]) {
  for (int i = 0; i < P; ++i)
    for (int j = i + 1; j < P; ++j) m[i][j] = product(p[i][0], p[j][1]) - product(p[j][0], p[i][1]);
}

/// det[x, y, 1] over rows i < j < k: m_ij + m_jk − m_ik.
template <int P>
Expansion<12> det_xy1(const Expansion<4> (&m)[P][P], int i, int j, int k) {
  return (m[i][j] + m[j][k]) - m[i][k];
}

/// det[x, y, z, 1] over rows r0 < r1 < r2 < r3, along the z column.
template <int P>
Expansion<96> det_xyz1(const double (&p)[P][3], const Expansion<4> (&m)[P][P], const int (&r)[4]) {
  const Expansion<48> front = det_xy1(m, r[1], r[2], r[3]) * p[r[0]][2] -
                              det_xy1(m, r[0], r[2], r[3]) * p[r[1]][2];
  const Expansion<48> back = det_xy1(m, r[0], r[1], r[3]) * p[r[2]][2] -
                             det_xy1(m, r[0], r[1], r[2]) * p[r[3]][2];
  return front + back;
}

/// |p|² e, by scaling e by each coordinate twice (no expansion product needed).
template <int Dim, int A>
Expansion<(Dim == 2 ? 8 : 12) * A> lift_times(const double* p, const Expansion<A>& e) {
  if constexpr (Dim == 2) {
    return (e * p[0]) * p[0] + (e * p[1]) * p[1];
  } else {
    return ((e * p[0]) * p[0] + (e * p[1]) * p[1]) + (e * p[2]) * p[2];
  }
}

double det_orient2d(const double (&p)[3][3]) {
  Expansion<4> m[3][3];
  xy_minors(p, m);
  return approximate(det_xy1(m, 0, 1, 2));
}

double det_incircle(const double (&p)[4][3]) {
  Expansion<4> m[4][4];
  xy_minors(p, m);
  // Along the lifted column: sum over rows r of (−1)^r |p_r|² det[x, y, 1](other rows).
  const Expansion<192> ab = lift_times<2>(p[0], det_xy1(m, 1, 2, 3)) -
                            lift_times<2>(p[1], det_xy1(m, 0, 2, 3));
  const Expansion<192> cd = lift_times<2>(p[2], det_xy1(m, 0, 1, 3)) -
                            lift_times<2>(p[3], det_xy1(m, 0, 1, 2));
  return approximate(ab + cd);
}

double det_orient3d(const double (&p)[4][3]) {
  Expansion<4> m[4][4];
  xy_minors(p, m);
  return approximate(det_xyz1(p, m, {0, 1, 2, 3}));
}

double det_insphere(const double (&p)[5][3]) {
  Expansion<4> m[5][5];
  xy_minors(p, m);
  const Expansion<2304> ab = lift_times<3>(p[0], det_xyz1(p, m, {1, 2, 3, 4})) -
                             lift_times<3>(p[1], det_xyz1(p, m, {0, 2, 3, 4}));
  const Expansion<2304> cd = lift_times<3>(p[2], det_xyz1(p, m, {0, 1, 3, 4})) -
                             lift_times<3>(p[3], det_xyz1(p, m, {0, 1, 2, 4}));
  const Expansion<3456> cde = cd + lift_times<3>(p[4], det_xyz1(p, m, {0, 1, 2, 3}));
  return approximate(ab + cde);
}

/// Rescales the points by a power of two so that the largest coordinate is in [1, 2) (exact,
/// keeps every sign) and, when every difference to the last point is exact, translates that
/// point to the origin (the determinants are invariant under translation, and the zero row
/// shortens every expansion). `det` evaluates the exact determinant, of the given degree, which
/// is scaled back.
template <int P, class Det>
double exact_rescaled(const double* const (&pts)[P], int dim, int degree, double sign, Det det) {
  double largest = 0.0;
  for (int i = 0; i < P; ++i)
    for (int k = 0; k < dim; ++k) {
      RIEMESH_CHECK(std::isfinite(pts[i][k]));
      largest = std::max(largest, std::fabs(pts[i][k]));
    }
  if (largest == 0.0) return 0.0;  // all points at the origin
  const int shift = -std::ilogb(largest);
  double p[P][3] = {};
  for (int i = 0; i < P; ++i)
    for (int k = 0; k < dim; ++k) p[i][k] = std::ldexp(pts[i][k], shift);
  double moved[P][3] = {};
  bool exact_differences = true;
  for (int i = 0; i + 1 < P; ++i)
    for (int k = 0; k < dim; ++k) {
      double err;
      two_sum(p[i][k], -p[P - 1][k], moved[i][k], err);
      exact_differences = exact_differences && err == 0.0;
    }
  const double value = sign * (exact_differences ? det(moved) : det(p));
  if (value == 0.0) return 0.0;
  const double back = std::ldexp(value, -shift * degree);
  return back != 0.0 ? back : std::copysign(DBL_TRUE_MIN, value);  // keep the sign
}

// Error bounds of the floating-point evaluations below, relative to their permanents (Shewchuk
// 1997, §4.3: ccwerrboundA, o3derrboundA, iccerrboundA, isperrboundA), for exactly these
// expression trees. kEps = 2^-53 is half an ulp of 1.
constexpr double kEps = 0x1p-53;
constexpr double kOrient2dBound = (3.0 + 16.0 * kEps) * kEps;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;
constexpr double kIncircleBound = (10.0 + 96.0 * kEps) * kEps;
constexpr double kInsphereBound = (16.0 + 224.0 * kEps) * kEps;
// Absolute slack covering products that underflow (each loses < 2^-1074). Inputs that tiny fail
// the filter and are rescaled by the exact path.
constexpr double kUnderflowSlack = 0x1p-1000;

/// True when the filtered value certainly has the sign of the exact determinant. Infinite or
/// NaN values (overflow) never pass.
inline bool certain(double det, double permanent, double bound) {
  return std::fabs(det) > bound * permanent + kUnderflowSlack && permanent < DBL_MAX;
}

}  // namespace

namespace exact {

double orient2d(const double* a, const double* b, const double* c) {
  const double* const pts[] = {a, b, c};
  return exact_rescaled(pts, 2, 2, 1.0, det_orient2d);
}

double incircle(const double* a, const double* b, const double* c, const double* d) {
  // det[|p|², x, y, 1] = det[x, y, |p|², 1] (cyclic column shift), > 0 inside for ccw abc.
  const double* const pts[] = {a, b, c, d};
  return exact_rescaled(pts, 2, 4, 1.0, det_incircle);
}

double orient3d(const double* a, const double* b, const double* c, const double* d) {
  // det[x, y, z, 1] = −det(b − a, c − a, d − a).
  const double* const pts[] = {a, b, c, d};
  return exact_rescaled(pts, 3, 3, -1.0, det_orient3d);
}

double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e) {
  // det[x, y, z, |p|², 1] > 0 inside when det[x, y, z, 1] > 0, i.e. when orient3d < 0; moving
  // the lifted column first is an odd permutation, so det[|p|², x, y, z, 1] has our sign.
  const double* const pts[] = {a, b, c, d, e};
  return exact_rescaled(pts, 3, 5, 1.0, det_insphere);
}

}  // namespace exact

double orient2d(const double* a, const double* b, const double* c) {
  const double left = (a[0] - c[0]) * (b[1] - c[1]);
  const double right = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = left - right;
  if (certain(det, std::fabs(left) + std::fabs(right), kOrient2dBound)) return det;
  return exact::orient2d(a, b, c);
}

double incircle(const double* a, const double* b, const double* c, const double* d) {
  const auto [det, permanent] = incircle_terms(a, b, c, d);
  if (certain(det, permanent, kIncircleBound)) return det;
  return exact::incircle(a, b, c, d);
}

double orient3d(const double* a, const double* b, const double* c, const double* d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  // det(a − d, b − d, c − d) = −orient3d.
  const double det =
      adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  if (certain(det, permanent, kOrient3dBound)) return -det;
  return exact::orient3d(a, b, c, d);
}

double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e) {
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  const double aexbey = aex * bey, bexaey = bex * aey;
  const double bexcey = bex * cey, cexbey = cex * bey;
  const double cexdey = cex * dey, dexcey = dex * cey;
  const double dexaey = dex * aey, aexdey = aex * dey;
  const double aexcey = aex * cey, cexaey = cex * aey;
  const double bexdey = bex * dey, dexbey = dex * bey;
  const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
  const double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  // det[p − e, |p − e|²] over p = a, b, c, d: > 0 inside when det(a−e, b−e, c−e, ...) has
  // Shewchuk's positive orientation, i.e. our orient3d < 0; hence the minus sign below.
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  const double az = std::fabs(aez), bz = std::fabs(bez), cz = std::fabs(cez), dz = std::fabs(dez);
  const double pab = std::fabs(aexbey) + std::fabs(bexaey);
  const double pbc = std::fabs(bexcey) + std::fabs(cexbey);
  const double pcd = std::fabs(cexdey) + std::fabs(dexcey);
  const double pda = std::fabs(dexaey) + std::fabs(aexdey);
  const double pac = std::fabs(aexcey) + std::fabs(cexaey);
  const double pbd = std::fabs(bexdey) + std::fabs(dexbey);
  const double permanent = (pcd * bz + pbd * cz + pbc * dz) * alift +
                           (pda * cz + pac * dz + pcd * az) * blift +
                           (pab * dz + pbd * az + pda * bz) * clift +
                           (pbc * az + pac * bz + pab * cz) * dlift;
  if (certain(det, permanent, kInsphereBound)) return -det;
  return exact::insphere(a, b, c, d, e);
}

}  // namespace riemesh
