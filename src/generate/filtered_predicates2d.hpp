#pragma once
// Filtered 2D orientation and in-circle signs for the Delaunay kernel. Each sign is first decided
// in double precision with Shewchuk's semi-static error bound (the determinant's permanent times
// ccwerrboundA / iccerrboundA, the bounds core/predicates.cpp uses for exactly these expression
// trees); when the determinant is within the bound the exact predicates of core/predicates.hpp
// decide. Inline so that the kernel's inner loops pay no call for the common case (the 2D
// determinants are so cheap that the call and the duplicated filter cost as much as the test).
//
// Products must be rounded one by one (the bounds count every rounding): compile the users with
// -ffp-contract=off (src/CMakeLists.txt; x86-64 without -march has no fused multiply-add anyway).
#include <cmath>

#include "core/predicates.hpp"

namespace riemesh::detail {

/// Exact signs behind the filters (core/predicates.hpp, same conventions), out of line.
int orient2d_exact_sign(const double* a, const double* b, const double* c);
int incircle_exact_sign(const double* a, const double* b, const double* c, const double* d);

/// incircle_sign out of line, for the rare cases a static filter cannot decide (cold: the callers'
/// loops keep their registers).
[[gnu::cold]] int incircle_sign_cold(const double* a, const double* b, const double* c,
                                     const double* d);

/// Absolute slack covering products that underflow (each loses < 2^-1074): inputs that tiny fail
/// the filter and go to the exact predicate, which rescales them. An overflowing (infinite or NaN)
/// determinant or permanent never passes either (comparisons with NaN or ∞ bounds are false).
inline constexpr double kUnderflowSlack2d = 0x1p-1000;

/// +1 when a, b, c turn counter-clockwise, -1 clockwise, 0 collinear (the sign of
/// core/predicates.hpp's orient2d).
inline int orient2d_sign(const double* a, const double* b, const double* c) {
  const double left = (a[0] - c[0]) * (b[1] - c[1]);
  const double right = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = left - right;
  // ccwerrboundA = (3 + 16 ε) ε, ε = 2^-53.
  const double bound =
      (3.0 + 16.0 * 0x1p-53) * 0x1p-53 * (std::fabs(left) + std::fabs(right)) + kUnderflowSlack2d;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return orient2d_exact_sign(a, b, c);
}

/// +1 when d is strictly inside the circle through the counter-clockwise a, b, c, -1 strictly
/// outside, 0 on it (the sign of core/predicates.hpp's incircle).
inline int incircle_sign(const double* a, const double* b, const double* c, const double* d) {
  const auto [det, permanent] = incircle_terms(a, b, c, d);
  // iccerrboundA = (10 + 96 ε) ε.
  const double bound = (10.0 + 96.0 * 0x1p-53) * 0x1p-53 * permanent + kUnderflowSlack2d;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return incircle_exact_sign(a, b, c, d);
}

/// A static error bound for incircle_sign_in_box: valid for any four points whose coordinates
/// differ by at most `extent` in x and in y. Each coordinate difference is then at most extent in
/// magnitude (rounding is monotonic), so the permanent incircle_terms computes is at most
/// 12 extent^4 (1 + ε)^7; the bound is the semi-static one for that permanent, doubled to cover
/// this and its own roundings. An infinite or NaN extent gives a bound nothing passes.
inline double incircle_static_bound(double extent) {
  const double e2 = extent * extent;
  const double bound = 2.0 * 12.0 * (10.0 + 96.0 * 0x1p-53) * 0x1p-53 * (e2 * e2);
  return bound == bound ? bound + kUnderflowSlack2d : HUGE_VAL;
}

/// incircle_sign with a static filter first, for points known to lie in a box of side `extent`
/// (`in_box`, static_bound = incircle_static_bound(extent)): the determinant alone decides when
/// it is larger than the bound, without the permanent; otherwise incircle_sign does (its
/// semi-static filter, then the exact predicate).
inline int incircle_sign_in_box(const double* a, const double* b, const double* c, const double* d,
                                bool in_box, double static_bound) {
  const double adx = a[0] - d[0], ady = a[1] - d[1];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1];
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                     clift * (adx * bdy - bdx * ady);
  if (in_box && std::fabs(det) > static_bound) [[likely]]
    return det > 0 ? 1 : -1;
  return incircle_sign_cold(a, b, c, d);
}

}  // namespace riemesh::detail
