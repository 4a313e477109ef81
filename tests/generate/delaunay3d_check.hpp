#pragma once
// Property checks of a 3D Delaunay tetrahedralisation, all with the exact predicates: positive
// tets, symmetric adjacency, empty circumspheres across every interior face (local Delaunay,
// which implies global), convex hull containing every point, every distinct point used, Euler
// characteristic of a ball (V - E + F - T = 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

#include "core/predicates.hpp"
#include "generate/delaunay3d.hpp"

namespace riemesh::test {

inline const double* point(const std::vector<double>& xyz, Id v) {
  return xyz.data() + 3 * static_cast<std::size_t>(v);
}

/// The tet's vertices with vertex i replaced by q, as point pointers.
inline std::array<const double*, 4> with_vertex(const std::vector<double>& xyz, const Id* t, int i,
                                                const double* q) {
  std::array<const double*, 4> p{};
  for (int k = 0; k < 4; ++k) p[k] = k == i ? q : point(xyz, t[k]);
  return p;
}

inline void expect_delaunay(const std::vector<double>& xyz, const Tetrahedralization& tz) {
  const std::size_t nt = tz.num_tets();
  const std::size_t np = xyz.size() / 3;
  ASSERT_EQ(tz.tets.size(), 4 * nt);
  ASSERT_EQ(tz.tet2tet.size(), 4 * nt);
  ASSERT_EQ(tz.duplicate_of.size(), np);
  std::size_t bad_volume = 0, bad_adjacency = 0, not_delaunay = 0, outside_hull = 0;
  std::set<std::pair<Id, Id>> edges;
  std::size_t faces2 = 0, hull_faces = 0;
  std::vector<char> used(np, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    const Id* v = &tz.tets[4 * t];
    if (orient3d(point(xyz, v[0]), point(xyz, v[1]), point(xyz, v[2]), point(xyz, v[3])) <= 0)
      ++bad_volume;
    for (int i = 0; i < 4; ++i) {
      used[static_cast<std::size_t>(v[i])] = 1;
      for (int j = i + 1; j < 4; ++j) edges.insert(std::minmax(v[i], v[j]));
      const Id n = tz.tet2tet[4 * t + i];
      if (n == kNoId) {
        ++hull_faces;
        // No point strictly beyond a hull face: the hull is convex and holds every point.
        for (std::size_t q = 0; q < np; ++q) {
          const auto p = with_vertex(xyz, v, i, point(xyz, static_cast<Id>(q)));
          if (orient3d(p[0], p[1], p[2], p[3]) < 0) ++outside_hull;
        }
        continue;
      }
      ++faces2;
      // The neighbour shares the face (the 3 vertices other than v[i]) and points back.
      const Id* w = &tz.tets[4 * static_cast<std::size_t>(n)];
      int shared = 0, apex = -1;
      for (int k = 0; k < 4; ++k) {
        if (std::find(v, v + 4, w[k]) != v + 4 && w[k] != v[i])
          ++shared;
        else
          apex = k;
      }
      if (shared != 3 || apex < 0 ||
          tz.tet2tet[4 * static_cast<std::size_t>(n) + apex] != static_cast<Id>(t)) {
        ++bad_adjacency;
        continue;
      }
      if (insphere(point(xyz, v[0]), point(xyz, v[1]), point(xyz, v[2]), point(xyz, v[3]),
                   point(xyz, w[apex])) > 0)
        ++not_delaunay;
    }
  }
  EXPECT_EQ(bad_volume, 0u);
  EXPECT_EQ(bad_adjacency, 0u);
  EXPECT_EQ(not_delaunay, 0u);
  EXPECT_EQ(outside_hull, 0u);
  std::size_t used_count = 0, distinct = 0;
  for (std::size_t q = 0; q < np; ++q) {
    used_count += used[q];
    const bool duplicate = tz.duplicate_of[q] != kNoId;
    distinct += !duplicate;
    EXPECT_NE(static_cast<bool>(used[q]), duplicate) << "point " << q;
  }
  EXPECT_EQ(used_count, distinct);
  // Euler characteristic of a triangulated ball: V - E + F - T = 1.
  const std::size_t faces = faces2 / 2 + hull_faces;
  EXPECT_EQ(static_cast<long long>(used_count) - static_cast<long long>(edges.size()) +
                static_cast<long long>(faces) - static_cast<long long>(nt),
            1);
}

/// The sum of the tets' volumes.
inline double total_volume(const std::vector<double>& xyz, const Tetrahedralization& tz) {
  double sum = 0;
  for (std::size_t t = 0; t < tz.num_tets(); ++t) {
    const Id* v = &tz.tets[4 * t];
    sum += orient3d(point(xyz, v[0]), point(xyz, v[1]), point(xyz, v[2]), point(xyz, v[3])) / 6;
  }
  return sum;
}

}  // namespace riemesh::test
