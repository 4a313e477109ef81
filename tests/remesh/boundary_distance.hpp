#pragma once
// The distance between the boundary (Edges) polylines of two planar meshes, sampled: the tests'
// check that a remeshed boundary stays within --hausd of the input's.
#include <algorithm>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::test {

inline Vec2 point2(const Mesh& m, Id v) { return Vec2{{m.coords[2 * v], m.coords[2 * v + 1]}}; }

inline double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return norm(p - (a + t * ab));
}

/// Largest distance from points sampled on the edges of `from` (samples + 1 per edge) to the
/// edge polyline of `to`.
inline double one_sided(const Mesh& from, const Mesh& to, int samples = 8) {
  double worst = 0.0;
  for (std::size_t e = 0; e < from.num_edges(); ++e) {
    const Vec2 a = point2(from, from.edges[2 * e]), b = point2(from, from.edges[2 * e + 1]);
    for (int k = 0; k <= samples; ++k) {
      const Vec2 p = a + (static_cast<double>(k) / samples) * (b - a);
      double best = 1e300;
      for (std::size_t f = 0; f < to.num_edges(); ++f)
        best = std::min(best, segment_distance(p, point2(to, to.edges[2 * f]),
                                               point2(to, to.edges[2 * f + 1])));
      worst = std::max(worst, best);
    }
  }
  return worst;
}

/// The two-sided (Hausdorff) distance between the boundaries, sampled.
inline double boundary_distance(const Mesh& a, const Mesh& b, int samples = 8) {
  return std::max(one_sided(a, b, samples), one_sided(b, a, samples));
}

}  // namespace riemesh::test
