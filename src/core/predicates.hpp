#pragma once
// Robust geometric predicates on double coordinates: the sign of each result is exact.
//
// Method (Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", DCG 18, 1997): the determinant is first evaluated in plain floating point together
// with a bound on its rounding error (semi-static filter: a constant times the permanent, i.e. the
// same expression with absolute values). When |det| exceeds the bound its sign is certain. Otherwise
// the determinant is recomputed exactly with floating-point expansions (sums of non-overlapping
// doubles built by two-sum and fma two-product); the sign of an expansion is the sign of its
// largest component.
//
// Sign conventions (all four agree with a mesh's positive orientation):
//   orient2d(a, b, c)       > 0  when a, b, c turn counter-clockwise  (= det(b − a, c − a))
//   incircle(a, b, c, d)    > 0  when d is inside the circle through a, b, c, if they turn
//                                counter-clockwise (the sign flips if they turn clockwise)
//   orient3d(a, b, c, d)    > 0  when d lies on the side of plane abc from which a, b, c are seen
//                                counter-clockwise (= det(b − a, c − a, d − a) = 6 × the signed
//                                volume of tetrahedron abcd)
//   insphere(a, b, c, d, e) > 0  when e is inside the sphere through a, b, c, d, if
//                                orient3d(a, b, c, d) > 0 (the sign flips otherwise)
// and 0 exactly when the points are collinear / cocircular / coplanar / cospherical.
//
// The magnitude returned is an approximation of the determinant (the value itself when the filter
// decides); only the sign is guaranteed. Points are given as pointers to 2 or 3 doubles.
// Preconditions: finite coordinates. Coordinates of any magnitude are handled (inputs are rescaled
// by a power of two when products would overflow or underflow), but exactness needs the products
// of coordinate differences not to fall below the smallest normal double after that rescaling,
// i.e. coordinates whose differences span less than about 10^±60 of the largest coordinate
// (always true for meshes).
#include <cmath>

namespace riemesh {

/// The in-circle determinant in plain doubles and its permanent (the same expression with
/// absolute values), on which the filters' error bounds are stated (incircle here, and the
/// Delaunay kernel's inline filter). Inline: the users compile with -ffp-contract=off.
struct DeterminantTerms {
  double det, permanent;
};
inline DeterminantTerms incircle_terms(const double* a, const double* b, const double* c,
                                       const double* d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  return {alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady),
          (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
              (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
              (std::fabs(adxbdy) + std::fabs(bdxady)) * clift};
}

double orient2d(const double* a, const double* b, const double* c);
double incircle(const double* a, const double* b, const double* c, const double* d);
double orient3d(const double* a, const double* b, const double* c, const double* d);
double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e);

/// The same predicates without the filter: always the exact sign by expansion arithmetic (for
/// tests and for checking the filter; slow).
namespace exact {
double orient2d(const double* a, const double* b, const double* c);
double incircle(const double* a, const double* b, const double* c, const double* d);
double orient3d(const double* a, const double* b, const double* c, const double* d);
double insphere(const double* a, const double* b, const double* c, const double* d,
                const double* e);
}  // namespace exact

}  // namespace riemesh
