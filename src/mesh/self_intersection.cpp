#include "mesh/self_intersection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "mesh/distance.hpp"

namespace riemesh {
namespace {

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

/// Whether the closed segment pq meets the closed triangle abc, exactly (robust orient3d): the
/// segment reaches the plane (its ends not strictly on one side) and its line passes through
/// the triangle (the three edge orientations not of opposite signs). A segment lying in the
/// triangle's plane does not count (coplanar overlaps are outside this test).
bool segment_meets(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const double sp = orient3d(a.x, b.x, c.x, p.x);
  const double sq = orient3d(a.x, b.x, c.x, q.x);
  if ((sp > 0.0 && sq > 0.0) || (sp < 0.0 && sq < 0.0) || (sp == 0.0 && sq == 0.0)) return false;
  const double o1 = orient3d(p.x, q.x, a.x, b.x);
  const double o2 = orient3d(p.x, q.x, b.x, c.x);
  const double o3 = orient3d(p.x, q.x, c.x, a.x);
  const bool some_pos = o1 > 0.0 || o2 > 0.0 || o3 > 0.0;
  const bool some_neg = o1 < 0.0 || o2 < 0.0 || o3 < 0.0;
  return !(some_pos && some_neg);
}

/// Whether an edge of triangle x meets triangle y. With a shared vertex (x[shared], a local
/// index in x, or -1) the edges from it are skipped: such an edge touches y's plane at the
/// shared vertex, so it meets y elsewhere only if it lies in that plane (not counted).
bool edges_hit(const Vec3 (&x)[3], const Vec3 (&y)[3], int shared) {
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (shared == i || shared == j) continue;
    if (segment_meets(x[i], x[j], y[0], y[1], y[2])) return true;
  }
  return false;
}

/// Whether x and y, in one plane (exactly), overlap in their interiors: no edge line of either
/// has the other triangle on its closed outer side (separating axes of two convex polygons),
/// decided by exact orientations in the coordinate plane across x's largest normal component
/// (a projection that keeps or turns all orientations alike).
bool coplanar_overlap(const Vec3 (&x)[3], const Vec3 (&y)[3]) {
  const Vec3 n = cross(x[1] - x[0], x[2] - x[0]);
  const int k = std::abs(n[0]) >= std::abs(n[1]) && std::abs(n[0]) >= std::abs(n[2]) ? 0
                : std::abs(n[1]) >= std::abs(n[2])                                   ? 1
                                                                                     : 2;
  const auto flat = [k](const Vec3& p) {
    return std::array<double, 2>{p[(k + 1) % 3], p[(k + 2) % 3]};
  };
  std::array<double, 2> a[3], b[3];
  for (int i = 0; i < 3; ++i) a[i] = flat(x[i]), b[i] = flat(y[i]);
  const auto separates = [](const std::array<double, 2>(&s)[3],
                            const std::array<double, 2>(&o)[3]) {
    const double turn = orient2d(s[0].data(), s[1].data(), s[2].data());
    for (int i = 0; i < 3; ++i) {
      bool outside = true;
      for (int j = 0; j < 3 && outside; ++j) {
        const double side = orient2d(s[i].data(), s[(i + 1) % 3].data(), o[j].data());
        outside = turn > 0.0 ? side <= 0.0 : side >= 0.0;
      }
      if (outside) return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

bool in_one_plane(const Vec3 (&x)[3], const Vec3 (&y)[3]) {
  for (int i = 0; i < 3; ++i)
    if (orient3d(x[0].x, x[1].x, x[2].x, y[i].x) != 0.0) return false;
  return true;
}

}  // namespace

SelfIntersections find_self_intersections(const Mesh& mesh, std::size_t max_pairs, bool coplanar) {
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
      if (common >= 2 && !coplanar) continue;
      Vec3 y[3];
      for (int i = 0; i < 3; ++i) y[i] = vertex_at(mesh, tb[i]);
      const bool hit = common >= 2 ? in_one_plane(x, y) && coplanar_overlap(x, y)
                                   : edges_hit(x, y, common ? sa : -1) ||
                                         edges_hit(y, x, common ? sb : -1) ||
                                         (coplanar && in_one_plane(x, y) && coplanar_overlap(x, y));
      if (hit) {
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
