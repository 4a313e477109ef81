#pragma once
// Point-in-simplex kernels for D = 2 (triangles) and D = 3 (tetrahedra), in plain doubles:
// signed measures, barycentric sub-measures and the closest point of a simplex. Pure functions of
// the vertex coordinates (x[0..D]) and the point.
#include <cmath>
#include <limits>

#include "core/predicates.hpp"
#include "core/vec.hpp"

namespace riemesh::simplex {

inline double det(const Vec2& a, const Vec2& b) { return cross(a, b); }
inline double det(const Vec3& a, const Vec3& b, const Vec3& c) { return dot(a, cross(b, c)); }

/// D! times the signed measure: det(x1 − x0, ..., xD − x0) (> 0 for counter-clockwise
/// triangles and positively oriented tetrahedra).
inline double signed_volume(const Vec2 x[3]) { return det(x[1] - x[0], x[2] - x[0]); }
inline double signed_volume(const Vec3 x[4]) { return det(x[1] - x[0], x[2] - x[0], x[3] - x[0]); }

/// A value of the sign of signed_volume in exact arithmetic (core/predicates.hpp): for simplices
/// whose rounded measure is zero or of the wrong sign (flat slivers between nearly cospherical
/// points, which a Delaunay tetrahedralisation may hold). Only its sign is meaningful.
inline double exact_orientation(const Vec2 x[3]) { return orient2d(x[0].x, x[1].x, x[2].x); }
inline double exact_orientation(const Vec3 x[4]) {
  return orient3d(x[0].x, x[1].x, x[2].x, x[3].x);
}

/// Vᵢ = the signed volume with p in place of xᵢ, written (−1)ⁱ det(xⱼ − p, j ≠ i) so that at
/// p = xᵢ every Vⱼ, j ≠ i, has a zero column and is exactly 0. Σ Vᵢ = signed_volume(x) and
/// Vᵢ / signed_volume(x) is the barycentric coordinate of p for vertex i.
inline void sub_volumes(const Vec2 x[3], const Vec2& p, double v[3]) {
  const Vec2 d0 = x[0] - p, d1 = x[1] - p, d2 = x[2] - p;
  v[0] = det(d1, d2);
  v[1] = det(d2, d0);
  v[2] = det(d0, d1);
}
inline void sub_volumes(const Vec3 x[4], const Vec3& p, double v[4]) {
  const Vec3 d0 = x[0] - p, d1 = x[1] - p, d2 = x[2] - p, d3 = x[3] - p;
  v[0] = det(d1, d2, d3);
  v[1] = -det(d0, d2, d3);
  v[2] = det(d0, d1, d3);
  v[3] = -det(d0, d1, d2);
}

/// The point of triangle (a, b, c) closest to p, as barycentric weights w (of a, b, c), and the
/// squared distance. Ericson, Real-Time Collision Detection, §5.1.5 (Voronoi regions of the
/// vertices, edges and face); dot products only, so it serves in 2D and 3D.
template <int D>
double closest_on_triangle(const Vec<D>& p, const Vec<D>& a, const Vec<D>& b, const Vec<D>& c,
                           double w[3]) {
  const Vec<D> ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  auto result = [&](double wa, double wb, double wc) {
    w[0] = wa, w[1] = wb, w[2] = wc;
    const Vec<D> q = wa * a + wb * b + wc * c;
    return dot(p - q, p - q);
  };
  if (d1 <= 0 && d2 <= 0) return result(1, 0, 0);
  const Vec<D> bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return result(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return result(1 - t, t, 0);
  }
  const Vec<D> cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return result(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return result(1 - t, 0, t);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return result(0, 1 - t, t);
  }
  const double inv = 1.0 / (va + vb + vc);
  return result(va * inv, vb * inv, vc * inv);
}

/// The point of triangle x closest to p (bary: its weights); the squared distance.
inline double closest_in_simplex(const Vec2 x[3], const Vec2& p, double bary[3]) {
  return closest_on_triangle<2>(p, x[0], x[1], x[2], bary);
}

/// The point of the boundary of tetrahedron x closest to p (over its four faces, first face on
/// ties): the closest point of the tetrahedron when p is outside (callers test inside first).
inline double closest_in_simplex(const Vec3 x[4], const Vec3& p, double bary[4]) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    const int a = (i + 1) % 4, b = (i + 2) % 4, c = (i + 3) % 4;
    double w[3];
    const double d2 = closest_on_triangle<3>(p, x[a], x[b], x[c], w);
    if (d2 < best) {
      best = d2;
      bary[i] = 0.0, bary[a] = w[0], bary[b] = w[1], bary[c] = w[2];
    }
  }
  return best;
}

}  // namespace riemesh::simplex
