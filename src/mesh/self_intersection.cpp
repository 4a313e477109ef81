#include "mesh/self_intersection.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "mesh/distance.hpp"

namespace riemesh {
namespace {

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

/// Parameter t in [0, 1] where segment q0 q1 meets triangle abc (Möller–Trumbore, boundaries
/// included), or -1 (no hit, or the segment parallel to the plane).
double segment_hits(const Vec3& q0, const Vec3& q1, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, d = q1 - q0;
  const Vec3 p = cross(d, e2);
  const double det = dot(e1, p);
  if (!(std::abs(det) > 1e-12 * norm(e1) * norm(e2) * norm(d))) return -1.0;
  const double inv = 1.0 / det;
  const Vec3 s = q0 - a;
  const double u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  const Vec3 qv = cross(s, e1);
  const double v = dot(d, qv) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  const double t = dot(e2, qv) * inv;
  return t >= 0.0 && t <= 1.0 ? t : -1.0;
}

/// Whether an edge of triangle x meets triangle y, ignoring hits at the shared vertex `shared`
/// (a local index in x, or -1) — within a relative tolerance of the edge length.
bool edges_hit(const Vec3 (&x)[3], const Vec3 (&y)[3], int shared) {
  constexpr double kEnd = 1e-9;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const double t = segment_hits(x[i], x[j], y[0], y[1], y[2]);
    if (t < 0.0) continue;
    if (shared == i && t < kEnd) continue;
    if (shared == j && t > 1.0 - kEnd) continue;
    return true;
  }
  return false;
}

}  // namespace

SelfIntersections find_self_intersections(const Mesh& mesh, std::size_t max_pairs) {
  if (mesh.dim != 3) throw InputError("self-intersections: need a 3D mesh");
  SelfIntersections out;
  if (mesh.triangles.empty()) return out;
  const TriangleTree tree(mesh);
  std::vector<Id> cand;
  for (std::size_t t = 0; t < mesh.num_triangles() && out.pairs < max_pairs; ++t) {
    const Id* ta = &mesh.triangles[3 * t];
    Vec3 x[3];
    Vec3 lo, hi;
    for (int i = 0; i < 3; ++i) x[i] = vertex_at(mesh, ta[i]);
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min({x[0][c], x[1][c], x[2][c]});
      hi[c] = std::max({x[0][c], x[1][c], x[2][c]});
    }
    cand.clear();
    tree.overlapping(lo, hi, cand);
    std::sort(cand.begin(), cand.end());
    for (Id u : cand) {
      if (u <= static_cast<Id>(t)) continue;  // each pair once
      const Id* tb = &mesh.triangles[3 * static_cast<std::size_t>(u)];
      int common = 0, sa = -1, sb = -1;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          if (ta[i] == tb[j]) {
            ++common;
            sa = i;
            sb = j;
          }
      if (common >= 2) continue;
      Vec3 y[3];
      for (int i = 0; i < 3; ++i) y[i] = vertex_at(mesh, tb[i]);
      if (edges_hit(x, y, common ? sa : -1) || edges_hit(y, x, common ? sb : -1)) {
        if (out.pairs == 0) {
          out.first_a = static_cast<Id>(t);
          out.first_b = u;
        }
        if (++out.pairs >= max_pairs) break;
      }
    }
  }
  return out;
}

}  // namespace riemesh
