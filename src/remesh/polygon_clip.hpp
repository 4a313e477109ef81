#pragma once
// Exact-area intersection of two triangles by convex clipping (Sutherland–Hodgman), the kernel of
// the conservative P0 transfer (BOOK.md §8). Pure functions of the coordinates, plain doubles.
//
// Robustness: a vertex is kept when its signed distance to the clipping line is >= 0 and an
// intersection point is made only on an edge whose ends have strictly opposite signs. A shared
// edge or a coincident vertex gives distances that are exactly 0 (the determinant of two equal
// points has a zero column), so it is kept once and never cut, and the overlap of two triangles
// that only touch is a polygon of zero area. Callers translate coordinates to a nearby origin
// first: areas are then computed from differences of the size of the triangles, not of the
// coordinates, and the round-off of each area is relative to the area.
#include <algorithm>
#include <cmath>

#include "core/vec.hpp"

namespace riemesh::clip {

/// Each clip of an n-gon keeps at most n vertices and adds at most one point per edge, so three
/// clips of a triangle stay within 3·2³ points whatever the rounding.
inline constexpr int kMaxPolygon = 24;

/// A polygon, counter-clockwise when it comes from counter-clockwise triangles.
struct Polygon {
  Vec2 p[kMaxPolygon];
  int n = 0;
};

/// The part of `in` on the left of the directed line a→b (cross(b − a, x − a) >= 0).
inline void clip_half_plane(const Polygon& in, const Vec2& a, const Vec2& b, Polygon& out) {
  out.n = 0;
  if (in.n == 0) return;
  const Vec2 ab = b - a;
  double d[kMaxPolygon];
  for (int i = 0; i < in.n; ++i) d[i] = cross(ab, in.p[i] - a);
  for (int i = 0; i < in.n; ++i) {
    const int j = i + 1 == in.n ? 0 : i + 1;
    if (d[i] >= 0.0) out.p[out.n++] = in.p[i];
    if ((d[i] > 0.0 && d[j] < 0.0) || (d[i] < 0.0 && d[j] > 0.0)) {
      const double t = d[i] / (d[i] - d[j]);
      out.p[out.n++] = in.p[i] + t * (in.p[j] - in.p[i]);
    }
  }
}

/// Twice the signed area (shoelace, fanned from p[0]).
inline double twice_area(const Polygon& poly) {
  double s = 0.0;
  for (int i = 1; i + 1 < poly.n; ++i) s += cross(poly.p[i] - poly.p[0], poly.p[i + 1] - poly.p[0]);
  return s;
}

/// The intersection of triangles t and s, both counter-clockwise: t clipped by the three edges
/// of s. Empty (n == 0) or degenerate (n < 3, or zero area) when they only touch or are apart.
inline Polygon intersect_triangles(const Vec2 t[3], const Vec2 s[3]) {
  Polygon a, b;
  a.n = 3;
  for (int i = 0; i < 3; ++i) a.p[i] = t[i];
  clip_half_plane(a, s[0], s[1], b);
  clip_half_plane(b, s[1], s[2], a);
  clip_half_plane(a, s[2], s[0], b);
  return b;
}

/// Area of the intersection of two counter-clockwise triangles (>= 0).
inline double overlap_area(const Vec2 t[3], const Vec2 s[3]) {
  const Polygon p = intersect_triangles(t, s);
  return p.n < 3 ? 0.0 : std::max(0.0, 0.5 * twice_area(p));
}

}  // namespace riemesh::clip
