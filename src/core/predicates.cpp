#include "core/predicates.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace riemesh {

namespace {

// ---------------------------------------------------------------------------------------------
// Expansion arithmetic (Shewchuk 1997, §2). An expansion is a sum of doubles that do not overlap
// (their significant bits occupy disjoint ranges), stored by increasing magnitude with zeros
// removed; the empty expansion is zero. Exact as long as nothing overflows or underflows.

using Expansion = std::vector<double>;

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

/// e + f: merge by magnitude, then a chain of two-sums (Shewchuk's Fast-Expansion-Sum, which
/// needs round-to-nearest-even; zero components are dropped).
Expansion add(const Expansion& e, const Expansion& f) {
  if (e.empty()) return f;
  if (f.empty()) return e;
  Expansion g(e.size() + f.size());
  std::merge(e.begin(), e.end(), f.begin(), f.end(), g.begin(),
             [](double u, double v) { return std::fabs(u) < std::fabs(v); });
  Expansion h;
  h.reserve(g.size());
  double q = g[0];
  for (std::size_t i = 1; i < g.size(); ++i) {
    double sum, err;
    two_sum(q, g[i], sum, err);
    if (err != 0.0) h.push_back(err);
    q = sum;
  }
  if (q != 0.0) h.push_back(q);
  return h;
}

Expansion negate(Expansion e) {
  for (double& c : e) c = -c;
  return e;
}

/// e * b (Shewchuk's Scale-Expansion, zero components dropped).
Expansion scale(const Expansion& e, double b) {
  Expansion h;
  if (e.empty() || b == 0.0) return h;
  h.reserve(2 * e.size());
  double q, err;
  two_product(e[0], b, q, err);
  if (err != 0.0) h.push_back(err);
  for (std::size_t i = 1; i < e.size(); ++i) {
    double p_hi, p_lo, sum;
    two_product(e[i], b, p_hi, p_lo);
    two_sum(q, p_lo, sum, err);
    if (err != 0.0) h.push_back(err);
    fast_two_sum(p_hi, sum, q, err);
    if (err != 0.0) h.push_back(err);
  }
  if (q != 0.0) h.push_back(q);
  return h;
}

/// e * f: one scaled copy of the longer expansion per component of the shorter, summed.
Expansion multiply(const Expansion& e, const Expansion& f) {
  const Expansion& longer = e.size() >= f.size() ? e : f;
  const Expansion& shorter = e.size() >= f.size() ? f : e;
  Expansion result;
  for (double c : shorter) result = add(result, scale(longer, c));
  return result;
}

/// The sign of an expansion is the sign of its largest component; returned as an approximation
/// of its value.
inline double approximate(const Expansion& e) { return e.empty() ? 0.0 : e.back(); }

// ---------------------------------------------------------------------------------------------
// Exact determinants: Laplace expansion along the first column, entries as expansions. The
// matrices are small (at most 5 x 5) and the exact path is rare, so clarity wins over speed.

constexpr int kMaxOrder = 5;
using Matrix = Expansion[kMaxOrder][kMaxOrder];

/// The determinant of m restricted to columns [col, n) and the rows set in row_mask.
Expansion minor_det(const Matrix& m, int n, int col, unsigned row_mask) {
  if (col == n - 1) {
    for (int r = 0; r < n; ++r)
      if (row_mask & (1u << r)) return m[r][col];
  }
  Expansion result;
  bool positive = true;
  for (int r = 0; r < n; ++r) {
    if (!(row_mask & (1u << r))) continue;
    const Expansion& entry = m[r][col];
    if (!entry.empty()) {
      const Expansion term = multiply(entry, minor_det(m, n, col + 1, row_mask & ~(1u << r)));
      result = add(result, positive ? term : negate(term));
    }
    positive = !positive;
  }
  return result;
}

/// Rows are the points; columns: [|p|² (if lifted)], coordinates, 1.
Expansion lifted_det(const double* const* pts, int npts, int dim, bool lifted) {
  Matrix m;
  const int n = npts;
  for (int r = 0; r < npts; ++r) {
    int c = 0;
    if (lifted) {
      Expansion lift;
      for (int k = 0; k < dim; ++k) {
        double hi, lo;
        two_product(pts[r][k], pts[r][k], hi, lo);
        Expansion sq;
        if (lo != 0.0) sq.push_back(lo);
        if (hi != 0.0) sq.push_back(hi);
        lift = add(lift, sq);
      }
      m[r][c++] = lift;
    }
    for (int k = 0; k < dim; ++k)
      m[r][c++] = pts[r][k] != 0.0 ? Expansion{pts[r][k]} : Expansion{};
    m[r][c++] = Expansion{1.0};
  }
  return minor_det(m, n, 0, (1u << n) - 1);
}

/// Rescales the points by a power of two so that the largest coordinate is in [1, 2) (exact,
/// keeps every sign), evaluates the exact determinant of the given degree and scales it back.
double exact_rescaled(const double* const* pts, int npts, int dim, bool lifted, int degree,
                      double sign) {
  double largest = 0.0;
  for (int i = 0; i < npts; ++i)
    for (int k = 0; k < dim; ++k) {
      RIEMESH_CHECK(std::isfinite(pts[i][k]));
      largest = std::max(largest, std::fabs(pts[i][k]));
    }
  if (largest == 0.0) return 0.0;  // all points at the origin
  const int shift = -std::ilogb(largest);
  double scaled[kMaxOrder][3];
  const double* rows[kMaxOrder];
  for (int i = 0; i < npts; ++i) {
    for (int k = 0; k < dim; ++k) scaled[i][k] = std::ldexp(pts[i][k], shift);
    rows[i] = scaled[i];
  }
  const double value = sign * approximate(lifted_det(rows, npts, dim, lifted));
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
  const double* pts[] = {a, b, c};
  return exact_rescaled(pts, 3, 2, false, 2, 1.0);
}

double incircle(const double* a, const double* b, const double* c, const double* d) {
  // det[|p|², x, y, 1] = det[x, y, |p|², 1] (cyclic column shift), > 0 inside for ccw abc.
  const double* pts[] = {a, b, c, d};
  return exact_rescaled(pts, 4, 2, true, 4, 1.0);
}

double orient3d(const double* a, const double* b, const double* c, const double* d) {
  // det[x, y, z, 1] = −det(b − a, c − a, d − a).
  const double* pts[] = {a, b, c, d};
  return exact_rescaled(pts, 4, 3, false, 3, -1.0);
}

double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e) {
  // det[x, y, z, |p|², 1] > 0 inside when det[x, y, z, 1] > 0, i.e. when orient3d < 0; moving
  // the lifted column first is an odd permutation, so det[|p|², x, y, z, 1] has our sign.
  const double* pts[] = {a, b, c, d, e};
  return exact_rescaled(pts, 5, 3, true, 5, 1.0);
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
  const double adx = a[0] - d[0], ady = a[1] - d[1];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det =
      alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
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
