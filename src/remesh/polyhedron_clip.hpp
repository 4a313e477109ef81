#pragma once
// Volume of the intersection of two tetrahedra by convex clipping, the 3D kernel of the
// conservative P0 transfer (BOOK.md §8). Pure functions of the coordinates, plain doubles.
//
// The polyhedron is kept as its face polygons (cyclic order, any orientation). Clipping by a
// plane clips every face (Sutherland–Hodgman, as in polygon_clip.hpp) and closes the cut with a
// cap: the points on the plane, in angular order about their mean. The volume is
// Σ_faces Σ_fan |det(p0 − c, pi − c, pi+1 − c)| / 6 with c the mean of the vertices, which lies in
// the convex polyhedron, so no face orientation is needed. Signed distances within 1e-14 of the
// scale of the tetrahedra count as 0 (a shared face or vertex is then kept, not cut into
// slivers); errors are at round-off level relative to the volumes either way.
#include <algorithm>
#include <cmath>

#include "core/vec.hpp"

namespace riemesh::clip {

inline constexpr int kMaxFaceVerts = 48;  // each clip at most doubles a face; 3·2⁴
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

/// Keeps the part of `poly` where dot(normal, p − a) >= 0 (|value| <= tol counts as 0).
inline void clip_plane(Polyhedron& poly, const Vec3& a, const Vec3& normal, double tol) {
  // Nothing on the negative side: nothing to cut (and no cap, which would double a face lying
  // on the plane).
  bool cut = false;
  for (int fi = 0; fi < poly.n && !cut; ++fi)
    for (int i = 0; i < poly.f[fi].n; ++i)
      if (dot(normal, poly.f[fi].p[i] - a) < -tol) {
        cut = true;
        break;
      }
  if (!cut) return;
  Vec3 cap[kMaxFaces * kMaxFaceVerts];
  int nc = 0;
  Polyhedron out;
  for (int fi = 0; fi < poly.n; ++fi) {
    const Face& in = poly.f[fi];
    double d[kMaxFaceVerts];
    for (int i = 0; i < in.n; ++i) {
      d[i] = dot(normal, in.p[i] - a);
      if (std::abs(d[i]) <= tol) d[i] = 0.0;
    }
    Face g;
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
    if (g.n >= 3 && out.n < kMaxFaces - 1) out.f[out.n++] = g;
  }
  if (nc >= 3 && out.n > 0) {
    // The cap: points on the plane sorted by angle about their mean, duplicates kept (they only
    // add empty fan triangles). Its polygon is convex, so the order is its cyclic order.
    Vec3 m = Vec3::zero();
    for (int i = 0; i < nc; ++i) m += cap[i];
    m *= 1.0 / nc;
    const Vec3 u0 = std::abs(normal[0]) < 0.6 * norm(normal) ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = cross(normal, u0), v = cross(normal, u);
    double angle[kMaxFaces * kMaxFaceVerts];
    int order[kMaxFaces * kMaxFaceVerts];
    for (int i = 0; i < nc; ++i) {
      angle[i] = std::atan2(dot(v, cap[i] - m), dot(u, cap[i] - m));
      order[i] = i;
    }
    std::sort(order, order + nc, [&angle](int i, int j) { return angle[i] < angle[j]; });
    Face& c = out.f[out.n++];
    c.n = std::min(nc, kMaxFaceVerts);
    for (int i = 0; i < c.n; ++i) c.p[i] = cap[order[i]];
  }
  poly = out;
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
  Polyhedron p = tetrahedron(t);
  double scale = 0.0;
  for (int i = 1; i < 4; ++i) scale = std::max({scale, norm(s[i] - s[0]), norm(t[i] - t[0])});
  for (int i = 0; i < 4 && p.n > 0; ++i) {
    // Face opposite s[i]; the normal points towards s[i] (inside).
    const Vec3& a = s[(i + 1) % 4];
    const Vec3& b = s[(i + 2) % 4];
    const Vec3& c = s[(i + 3) % 4];
    Vec3 n = cross(b - a, c - a);
    if (dot(n, s[i] - a) < 0.0) n = -1.0 * n;
    clip_plane(p, a, n, 1e-14 * norm(n) * scale);
  }
  return p;
}

/// Volume of the intersection of two positively oriented tetrahedra.
inline double overlap_volume(const Vec3 t[4], const Vec3 s[4]) {
  return volume(intersect_tetrahedra(t, s));
}

}  // namespace riemesh::clip
