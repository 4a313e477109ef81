#pragma once
// Filtered 3D orientation and in-sphere signs for the Delaunay kernel. Each sign is first decided
// in double precision with a semi-static error bound (Meyer & Pion's FPG bounds, the constants
// CGAL's static filters use for this evaluation order); when the determinant is within the bound
// the exact predicates of core/predicates.hpp decide. Inline so that the kernel's inner loops pay
// no call for the common case.
#include <cmath>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define RIEMESH_HAVE_AVX2_KERNELS 1
#endif

namespace riemesh::detail {

/// Exact signs behind the filters (core/predicates.hpp, adapted to the conventions below).
int orient3d_exact_sign(const double* a, const double* b, const double* c, const double* d);
int insphere_exact_sign(const double* a, const double* b, const double* c, const double* d,
                        const double* e);
/// orient3d_sign / insphere_sign below, out of line: the later stages behind the static filters,
/// so that the static stage inlines into the kernels' loops.
int orient3d_filtered_sign(const double* a, const double* b, const double* c, const double* d);
int insphere_filtered_sign(const double* a, const double* b, const double* c, const double* d,
                           const double* e);

inline double det3(double a00, double a01, double a02, double a10, double a11, double a12,
                   double a20, double a21, double a22) {
  const double m01 = a00 * a11 - a10 * a01;
  const double m02 = a00 * a21 - a20 * a01;
  const double m12 = a10 * a21 - a20 * a11;
  return m01 * a22 - m02 * a12 + m12 * a02;
}

inline double det4(double a00, double a01, double a02, double a03, double a10, double a11,
                   double a12, double a13, double a20, double a21, double a22, double a23,
                   double a30, double a31, double a32, double a33) {
  const double m01 = a10 * a01 - a00 * a11;
  const double m02 = a20 * a01 - a00 * a21;
  const double m03 = a30 * a01 - a00 * a31;
  const double m12 = a20 * a11 - a10 * a21;
  const double m13 = a30 * a11 - a10 * a31;
  const double m23 = a30 * a21 - a20 * a31;
  const double m012 = m12 * a02 - m02 * a12 + m01 * a22;
  const double m013 = m13 * a02 - m03 * a12 + m01 * a32;
  const double m023 = m23 * a02 - m03 * a22 + m02 * a32;
  const double m123 = m23 * a12 - m13 * a22 + m12 * a32;
  return m123 * a03 - m023 * a13 + m013 * a23 - m012 * a33;
}

/// max without std::fmax's NaN handling, which compiles to a libm call (inputs are finite).
inline double max2(double a, double b) { return a > b ? a : b; }

inline void sort3(double& lo, double& mid, double& hi) {
  if (lo > hi) std::swap(lo, hi);
  if (mid > hi)
    std::swap(mid, hi);
  else if (mid < lo)
    std::swap(lo, mid);
}

/// Sign of det(b - a, c - a, d - a): +1 when d is on the positive side of the plane (a, b, c),
/// i.e. the tetrahedron (a, b, c, d) has positive volume (the Medit/Riemesh convention).
inline int orient3d_sign(const double* a, const double* b, const double* c, const double* d) {
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  const double det = det3(bx, by, bz, cx, cy, cz, dx, dy, dz);
  double mx = max2(std::fabs(bx), max2(std::fabs(cx), std::fabs(dx)));
  double my = max2(std::fabs(by), max2(std::fabs(cy), std::fabs(dy)));
  double mz = max2(std::fabs(bz), max2(std::fabs(cz), std::fabs(dz)));
  sort3(mx, my, mz);
  // Outside [1e-97, 1e102] the bound itself could underflow or the determinant overflow.
  if (mx > 1e-97 && mz < 1e102) {
    const double eps = 5.1107127829973299e-15 * mx * my * mz;
    if (det > eps) return 1;
    if (det < -eps) return -1;
  }
  return orient3d_exact_sign(a, b, c, d);
}

/// +1 when e is strictly inside the circumsphere of the positively oriented tetrahedron
/// (a, b, c, d), -1 strictly outside, 0 on the sphere.
inline int insphere_sign(const double* a, const double* b, const double* c, const double* d,
                         const double* e) {
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  const double a2 = ax * ax + ay * ay + az * az;
  const double b2 = bx * bx + by * by + bz * bz;
  const double c2 = cx * cx + cy * cy + cz * cz;
  const double d2 = dx * dx + dy * dy + dz * dz;
  // Rows a, c, b, d: the order for which a positive determinant means "inside".
  const double det = det4(ax, ay, az, a2, cx, cy, cz, c2, bx, by, bz, b2, dx, dy, dz, d2);
  double mx = max2(max2(std::fabs(ax), std::fabs(bx)),
                        max2(std::fabs(cx), std::fabs(dx)));
  double my = max2(max2(std::fabs(ay), std::fabs(by)),
                        max2(std::fabs(cy), std::fabs(dy)));
  double mz = max2(max2(std::fabs(az), std::fabs(bz)),
                        max2(std::fabs(cz), std::fabs(dz)));
  sort3(mx, my, mz);
  if (mx > 1e-58 && mz < 1e61) {
    const double eps = 1.2466136531027298e-13 * mx * my * mz * (mz * mz);
    if (det > eps) return 1;
    if (det < -eps) return -1;
  }
  return insphere_exact_sign(a, b, c, d, e);
}

/// Static filter bounds (a first stage, before the per-call bounds above): every coordinate
/// difference between points of a box is at most the box's side along that axis, so the FPG
/// bounds evaluated at the sides hold for every call on points of the box. Cheaper than the
/// per-call bounds (no maxima), looser on small configurations, which then go to the next stage.
struct StaticFilter3d {
  double orient = HUGE_VAL;  // HUGE_VAL: the stage is off
  double insphere = HUGE_VAL;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
  double hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

  bool contains(const double* p) const {
    return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
           p[2] <= hi[2];
  }
  /// Grows the box to hold p (call update() after).
  void extend(const double* p) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = p[i] < lo[i] ? p[i] : lo[i];
      hi[i] = p[i] > hi[i] ? p[i] : hi[i];
    }
  }
  /// The bounds of the current box.
  void update() {
    double mx = hi[0] - lo[0], my = hi[1] - lo[1], mz = hi[2] - lo[2];
    sort3(mx, my, mz);
    const bool ok = mx > 1e-58 && mz < 1e61;
    orient = ok ? 5.1107127829973299e-15 * mx * my * mz : HUGE_VAL;
    insphere = ok ? 1.2466136531027298e-13 * mx * my * mz * (mz * mz) : HUGE_VAL;
  }
};

/// orient3d_sign for points of the filter's box.
inline int orient3d_sign(const StaticFilter3d& f, const double* a, const double* b,
                         const double* c, const double* d) {
  const double det = det3(b[0] - a[0], b[1] - a[1], b[2] - a[2], c[0] - a[0], c[1] - a[1],
                          c[2] - a[2], d[0] - a[0], d[1] - a[1], d[2] - a[2]);
  if (det > f.orient) return 1;
  if (det < -f.orient) return -1;
  return orient3d_filtered_sign(a, b, c, d);
}

/// The in-sphere determinant of insphere_sign (rows a, c, b, d), evaluated as written.
inline double insphere_det_scalar(const double* a, const double* b, const double* c,
                                  const double* d, const double* e) {
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  return det4(ax, ay, az, ax * ax + ay * ay + az * az, cx, cy, cz, cx * cx + cy * cy + cz * cz,
              bx, by, bz, bx * bx + by * by + bz * bz, dx, dy, dz, dx * dx + dy * dy + dz * dz);
}

/// insphere_det_scalar two lanes at a time (SSE2, which every x86-64 has): each lane performs
/// the scalar operations in the scalar order, so the value is bitwise the same (no fused
/// multiply-adds: the filter's error bound counts every rounding). Rows r0..r3 = a, c, b, d and
/// columns X, Y, Z, W (W the squared norms); x01 holds column X of rows 0 and 1, etc.
/// The point e of in-sphere tests, its coordinates broadcast to both lanes once for all the
/// tests against it (the cavity search tests one point against dozens of tets).
struct InsphereQuery {
  const double* e;
#if defined(__SSE2__)
  __m128d ex, ey, ez;
  explicit InsphereQuery(const double* p)
      : e(p), ex(_mm_set1_pd(p[0])), ey(_mm_set1_pd(p[1])), ez(_mm_set1_pd(p[2])) {}
#else
  explicit InsphereQuery(const double* p) : e(p) {}
#endif
};

inline double insphere_det(const InsphereQuery& query, const double* a, const double* b,
                           const double* c, const double* d) {
#if defined(__SSE2__)
  const __m128d ex = query.ex, ey = query.ey, ez = query.ez;
  const __m128d x01 = _mm_sub_pd(_mm_setr_pd(a[0], c[0]), ex);
  const __m128d x23 = _mm_sub_pd(_mm_setr_pd(b[0], d[0]), ex);
  const __m128d y01 = _mm_sub_pd(_mm_setr_pd(a[1], c[1]), ey);
  const __m128d y23 = _mm_sub_pd(_mm_setr_pd(b[1], d[1]), ey);
  const __m128d z01 = _mm_sub_pd(_mm_setr_pd(a[2], c[2]), ez);
  const __m128d z23 = _mm_sub_pd(_mm_setr_pd(b[2], d[2]), ez);
  const __m128d w01 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x01, x01), _mm_mul_pd(y01, y01)),
                                 _mm_mul_pd(z01, z01));
  const __m128d w23 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x23, x23), _mm_mul_pd(y23, y23)),
                                 _mm_mul_pd(z23, z23));
  // 2x2 minors of columns X, Y: mij = Xj Yi - Xi Yj (rows i < j), as in det4.
  const __m128d m02_03 = _mm_sub_pd(_mm_mul_pd(x23, _mm_unpacklo_pd(y01, y01)),
                                    _mm_mul_pd(_mm_unpacklo_pd(x01, x01), y23));
  const __m128d m12_13 = _mm_sub_pd(_mm_mul_pd(x23, _mm_unpackhi_pd(y01, y01)),
                                    _mm_mul_pd(_mm_unpackhi_pd(x01, x01), y23));
  const __m128d m01_23 =
      _mm_sub_pd(_mm_mul_pd(_mm_unpackhi_pd(x01, x23), _mm_unpacklo_pd(y01, y23)),
                 _mm_mul_pd(_mm_unpacklo_pd(x01, x23), _mm_unpackhi_pd(y01, y23)));
  // 3x3 minors of columns X, Y, Z: [m012, m013] and [m023, m123].
  const __m128d m012_013 =
      _mm_add_pd(_mm_sub_pd(_mm_mul_pd(m12_13, _mm_unpacklo_pd(z01, z01)),
                            _mm_mul_pd(m02_03, _mm_unpackhi_pd(z01, z01))),
                 _mm_mul_pd(_mm_unpacklo_pd(m01_23, m01_23), z23));
  const __m128d m023_123 =
      _mm_add_pd(_mm_sub_pd(_mm_mul_pd(_mm_unpackhi_pd(m01_23, m01_23), z01),
                            _mm_mul_pd(_mm_unpackhi_pd(m02_03, m12_13), _mm_unpacklo_pd(z23, z23))),
                 _mm_mul_pd(_mm_unpacklo_pd(m02_03, m12_13), _mm_unpackhi_pd(z23, z23)));
  // det = ((m123 W0 - m023 W1) + m013 W2) - m012 W3.
  const __m128d p = _mm_mul_pd(m023_123, _mm_shuffle_pd(w01, w01, 1));  // m023 W1, m123 W0
  const __m128d q = _mm_mul_pd(m012_013, _mm_shuffle_pd(w23, w23, 1));  // m012 W3, m013 W2
  const double p0 = _mm_cvtsd_f64(p), p1 = _mm_cvtsd_f64(_mm_unpackhi_pd(p, p));
  const double q0 = _mm_cvtsd_f64(q), q1 = _mm_cvtsd_f64(_mm_unpackhi_pd(q, q));
  return ((p1 - p0) + q1) - q0;
#else
  return insphere_det_scalar(a, b, c, d, query.e);
#endif
}

inline double insphere_det(const double* a, const double* b, const double* c, const double* d,
                           const double* e) {
  return insphere_det(InsphereQuery(e), a, b, c, d);
}

#if defined(RIEMESH_HAVE_AVX2_KERNELS)
/// insphere_det four lanes at a time, for callers compiled for AVX2 (who checked the CPU has it):
/// a, b, c, d point to records of 4 doubles (x, y, z, anything) aligned to 32 bytes; the 4th
/// double is never computed with. The 2x2 and 3x3 minors are each computed by the scalar
/// operations in the scalar order (some twice), so the value is bitwise insphere_det_scalar's
/// (no fused multiply-adds: AVX2 alone does not enable them).
__attribute__((target("avx2"))) inline double insphere_det_avx2(const InsphereQuery& query,
                                                                const double* a, const double* b,
                                                                const double* c, const double* d) {
  // Rows r0..r3 = a, c, b, d as in det4: lanes 0..3 of the columns X, Y, Z.
  const __m256d ra = _mm256_load_pd(a), rb = _mm256_load_pd(b);
  const __m256d rc = _mm256_load_pd(c), rd = _mm256_load_pd(d);
  const __m256d lo_ac = _mm256_unpacklo_pd(ra, rc);  // ax cx az cz
  const __m256d lo_bd = _mm256_unpacklo_pd(rb, rd);  // bx dx bz dz
  const __m256d hi_ac = _mm256_unpackhi_pd(ra, rc);  // ay cy (4th doubles)
  const __m256d hi_bd = _mm256_unpackhi_pd(rb, rd);  // by dy
  const __m256d x =
      _mm256_sub_pd(_mm256_permute2f128_pd(lo_ac, lo_bd, 0x20), _mm256_set1_pd(query.e[0]));
  const __m256d y =
      _mm256_sub_pd(_mm256_permute2f128_pd(hi_ac, hi_bd, 0x20), _mm256_set1_pd(query.e[1]));
  const __m256d z =
      _mm256_sub_pd(_mm256_permute2f128_pd(lo_ac, lo_bd, 0x31), _mm256_set1_pd(query.e[2]));
  const __m256d w =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x, x), _mm256_mul_pd(y, y)), _mm256_mul_pd(z, z));
  // Lanes (i, j) of the rows of the minors mij = Xj Yi - Xi Yj, in the arrangements the 3x3
  // minors below take: U = (m12, m13, m23, m23), V = (m02, m03, m03, m13), T = (m01, m01, m02,
  // m12). Index patterns 0001, 1122, 2333.
  constexpr int k0001 = 0x40, k1122 = 0xA5, k2333 = 0xFE;
  const __m256d x0001 = _mm256_permute4x64_pd(x, k0001), y0001 = _mm256_permute4x64_pd(y, k0001);
  const __m256d x1122 = _mm256_permute4x64_pd(x, k1122), y1122 = _mm256_permute4x64_pd(y, k1122);
  const __m256d x2333 = _mm256_permute4x64_pd(x, k2333), y2333 = _mm256_permute4x64_pd(y, k2333);
  const __m256d u = _mm256_sub_pd(_mm256_mul_pd(x2333, y1122), _mm256_mul_pd(x1122, y2333));
  const __m256d v = _mm256_sub_pd(_mm256_mul_pd(x2333, y0001), _mm256_mul_pd(x0001, y2333));
  const __m256d t = _mm256_sub_pd(_mm256_mul_pd(x1122, y0001), _mm256_mul_pd(x0001, y1122));
  // (m012, m013, m023, m123): (m12 Z0 - m02 Z1) + m01 Z2, (m13 Z0 - m03 Z1) + m01 Z3,
  // (m23 Z0 - m03 Z2) + m02 Z3, (m23 Z1 - m13 Z2) + m12 Z3.
  const __m256d m3 = _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(u, _mm256_permute4x64_pd(z, k0001)),
                                                 _mm256_mul_pd(v, _mm256_permute4x64_pd(z, k1122))),
                                   _mm256_mul_pd(t, _mm256_permute4x64_pd(z, k2333)));
  // det = ((m123 W0 - m023 W1) + m013 W2) - m012 W3.
  const __m256d q = _mm256_mul_pd(m3, _mm256_permute4x64_pd(w, 0x1B));  // W3, W2, W1, W0
  const __m128d q01 = _mm256_castpd256_pd128(q), q23 = _mm256_extractf128_pd(q, 1);
  const double q0 = _mm_cvtsd_f64(q01), q1 = _mm_cvtsd_f64(_mm_unpackhi_pd(q01, q01));
  const double q2 = _mm_cvtsd_f64(q23), q3 = _mm_cvtsd_f64(_mm_unpackhi_pd(q23, q23));
  return ((q3 - q2) + q1) - q0;
}

/// insphere_sign of the filter's box with insphere_det_avx2 (same conventions).
__attribute__((target("avx2"))) inline int insphere_sign_avx2(const StaticFilter3d& f,
                                                              const InsphereQuery& query,
                                                              const double* a, const double* b,
                                                              const double* c, const double* d) {
  const double det = insphere_det_avx2(query, a, b, c, d);
  if (det > f.insphere) return 1;
  if (det < -f.insphere) return -1;
  return insphere_filtered_sign(a, b, c, d, query.e);
}
#endif

/// insphere_sign for points of the filter's box.
inline int insphere_sign(const StaticFilter3d& f, const InsphereQuery& query, const double* a,
                         const double* b, const double* c, const double* d) {
  const double det = insphere_det(query, a, b, c, d);
  if (det > f.insphere) return 1;
  if (det < -f.insphere) return -1;
  return insphere_filtered_sign(a, b, c, d, query.e);
}

inline int insphere_sign(const StaticFilter3d& f, const double* a, const double* b,
                         const double* c, const double* d, const double* e) {
  return insphere_sign(f, InsphereQuery(e), a, b, c, d);
}

}  // namespace riemesh::detail
