#pragma once
// Volume of the intersection of two tetrahedra by convex clipping, the 3D kernel of the
// conservative P0 transfer (BOOK.md §8). Pure functions of the coordinates, plain doubles.
//
// The polyhedron is kept as its face polygons (cyclic order, any orientation). Clipping by a
// plane clips every face (Sutherland–Hodgman, as in polygon_clip.hpp) and closes the cut with a
// cap: the points on the plane, in angular order about their mean, repeated points merged. The
// volume is
// Σ_faces Σ_fan |det(p0 − c, pi − c, pi+1 − c)| / 6 with c the mean of the vertices, which lies in
// the convex polyhedron, so no face orientation is needed. Signed distances within 1e-14 of the
// scale of the tetrahedra count as 0 (a shared face or vertex is then kept, not cut into
// slivers); errors are at round-off level relative to the volumes either way.
#include <algorithm>
#include <cmath>

#include "core/vec.hpp"

namespace riemesh::clip {

// A triangle clipped by 4 planes has at most 7 vertices (one more per plane, the polygon being
// convex); with distances snapped to 0 near the plane rounding does not add sign changes. The
// capacity is a guard: points beyond it are dropped (never written out of bounds).
inline constexpr int kMaxFaceVerts = 12;
inline constexpr int kMaxFaces = 8;       // 4 faces of a tetrahedron + 4 caps

struct Face {
  Vec3 p[kMaxFaceVerts];
  int n = 0;
};

struct Polyhedron {
  Face f[kMaxFaces];
  int n = 0;
};

/// The four faces of tetrahedron x.
inline Polyhedron tetrahedron(const Vec3 x[4]) {
  Polyhedron t;
  t.n = 4;
  for (int i = 0; i < 4; ++i) {
    t.f[i].n = 3;
    for (int k = 0; k < 3; ++k) t.f[i].p[k] = x[(i + 1 + k) % 4];
  }
  return t;
}

/// A monotone stand-in for atan2(y, x) in (−2, 2] (the "diamond angle"), enough to sort.
inline double pseudo_angle(double y, double x) {
  const double l1 = std::abs(x) + std::abs(y);
  if (l1 == 0.0) return 0.0;
  const double p = x / l1;
  return y < 0.0 ? p - 1.0 : 1.0 - p;
}

/// `out` = the part of `poly` where dot(normal, p − a) >= 0 (|value| <= tol counts as 0).
/// Returns false, leaving `out` untouched, when nothing lies beyond the plane (then the answer
/// is `poly` itself).
inline bool clip_plane(const Polyhedron& poly, const Vec3& a, const Vec3& normal, double tol,
                       Polyhedron& out) {
  // Nothing on the negative side: nothing to cut (and no cap, which would double a face lying
  // on the plane).
  bool cut = false;
  for (int fi = 0; fi < poly.n && !cut; ++fi)
    for (int i = 0; i < poly.f[fi].n; ++i)
      if (dot(normal, poly.f[fi].p[i] - a) < -tol) {
        cut = true;
        break;
      }
  if (!cut) return false;
  Vec3 cap[kMaxFaces * kMaxFaceVerts];
  int nc = 0;
  out.n = 0;
  for (int fi = 0; fi < poly.n; ++fi) {
    const Face& in = poly.f[fi];
    double d[kMaxFaceVerts];
    for (int i = 0; i < in.n; ++i) {
      d[i] = dot(normal, in.p[i] - a);
      if (std::abs(d[i]) <= tol) d[i] = 0.0;
    }
    if (out.n == kMaxFaces - 1) break;  // keep room for the cap
    Face& g = out.f[out.n];
    g.n = 0;
    for (int i = 0; i < in.n; ++i) {
      const int j = i + 1 == in.n ? 0 : i + 1;
      if (d[i] >= 0.0 && g.n < kMaxFaceVerts) g.p[g.n++] = in.p[i];
      if (d[i] == 0.0 && nc < kMaxFaces * kMaxFaceVerts) cap[nc++] = in.p[i];
      if ((d[i] > 0.0 && d[j] < 0.0) || (d[i] < 0.0 && d[j] > 0.0)) {
        const Vec3 q = in.p[i] + (d[i] / (d[i] - d[j])) * (in.p[j] - in.p[i]);
        if (g.n < kMaxFaceVerts) g.p[g.n++] = q;
        if (nc < kMaxFaces * kMaxFaceVerts) cap[nc++] = q;
      }
    }
    if (g.n >= 3) ++out.n;
  }
  if (nc >= 3 && out.n > 0) {
    // The cap: points on the plane sorted by angle about their mean. Its polygon is convex, so
    // the angular order is its cyclic order.
    Vec3 m = Vec3::zero();
    for (int i = 0; i < nc; ++i) m += cap[i];
    m *= 1.0 / nc;
    const Vec3 u0 = std::abs(normal[0]) < 0.6 * norm(normal) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(normal, u0), v = cross(normal, u);
    double angle[kMaxFaces * kMaxFaceVerts];
    int order[kMaxFaces * kMaxFaceVerts];
    for (int i = 0; i < nc; ++i) {
      angle[i] = pseudo_angle(dot(v, cap[i] - m), dot(u, cap[i] - m));
      order[i] = i;
    }
    std::sort(order, order + nc, [&angle](int i, int j) { return angle[i] < angle[j]; });
    // Each point comes once per face through it (twice for a cut edge, three times for a vertex
    // on the plane): neighbours in angular order closer than 1e-12 of the cap's radius merge.
    double radius = 0.0;
    for (int i = 0; i < nc; ++i) radius = std::max(radius, norm(cap[i] - m));
    const double merge = 1e-12 * radius;
    Face& c = out.f[out.n++];
    c.n = 0;
    for (int i = 0; i < nc && c.n < kMaxFaceVerts; ++i)
      if (c.n == 0 || norm(cap[order[i]] - c.p[c.n - 1]) > merge) c.p[c.n++] = cap[order[i]];
  }
  return true;
}

/// Volume of a convex polyhedron given by its faces (>= 0).
inline double volume(const Polyhedron& poly) {
  Vec3 c = Vec3::zero();
  int count = 0;
  for (int fi = 0; fi < poly.n; ++fi)
    for (int i = 0; i < poly.f[fi].n; ++i) c += poly.f[fi].p[i], ++count;
  if (count == 0) return 0.0;
  c *= 1.0 / count;
  double six = 0.0;
  for (int fi = 0; fi < poly.n; ++fi) {
    const Face& f = poly.f[fi];
    for (int i = 1; i + 1 < f.n; ++i)
      six += std::abs(dot(f.p[0] - c, cross(f.p[i] - c, f.p[i + 1] - c)));
  }
  return six / 6.0;
}

/// The intersection of tetrahedra t and s (each with positive signed volume) as a polyhedron:
/// t clipped by the four faces of s. Empty (n == 0) when they are apart.
inline Polyhedron intersect_tetrahedra(const Vec3 t[4], const Vec3 s[4]) {
  Polyhedron buf[2];  // ping-pong: no copies of the (2 kB) polyhedra between clips
  buf[0] = tetrahedron(t);
  int cur = 0;
  double scale = 0.0;
  for (int i = 1; i < 4; ++i) scale = std::max({scale, norm(s[i] - s[0]), norm(t[i] - t[0])});
  for (int i = 0; i < 4 && buf[cur].n > 0; ++i) {
    // Face opposite s[i]; the normal points towards s[i] (inside).
    const Vec3& a = s[(i + 1) % 4];
    const Vec3& b = s[(i + 2) % 4];
    const Vec3& c = s[(i + 3) % 4];
    Vec3 n = cross(b - a, c - a);
    if (dot(n, s[i] - a) < 0.0) n = -1.0 * n;
    if (clip_plane(buf[cur], a, n, 1e-14 * norm(n) * scale, buf[1 - cur])) cur = 1 - cur;
  }
  return buf[cur];
}

/// Volume of the intersection of two positively oriented tetrahedra.
inline double overlap_volume(const Vec3 t[4], const Vec3 s[4]) {
  return volume(intersect_tetrahedra(t, s));
}

}  // namespace riemesh::clip
