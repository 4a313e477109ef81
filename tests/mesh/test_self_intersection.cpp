// Self-intersection test of triangle surfaces: crossing, touching and separate pairs, shared
// vertices and edges, a sphere and a sphere with one vertex pushed through the other side.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/self_intersection.hpp"

using namespace riemesh;

namespace {

Mesh two_triangles(const std::vector<double>& coords, const std::vector<Id>& tris) {
  Mesh m;
  m.dim = 3;
  m.coords = coords;
  m.triangles = tris;
  m.tri_ref.assign(tris.size() / 3, 1);
  return m;
}

TEST(SelfIntersection, Pairs) {
  // A triangle in z = 0 and one standing across it (x = 0.25 plane, through its interior).
  const std::vector<double> flat = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::vector<double> c = flat;
  c.insert(c.end(), {0.25, 0.2, -1, 0.25, 0.2, 1, 0.25, 0.6, 0});
  EXPECT_EQ(find_self_intersections(two_triangles(c, {0, 1, 2, 3, 4, 5})).pairs, 1u);
  // The same triangle lifted above: separate.
  c = flat;
  c.insert(c.end(), {0.25, 0.2, 0.5, 0.25, 0.2, 1, 0.25, 0.6, 0.7});
  EXPECT_EQ(find_self_intersections(two_triangles(c, {0, 1, 2, 3, 4, 5})).pairs, 0u);
  // Sharing vertex 0 and nothing else: not an intersection.
  c = flat;
  c.insert(c.end(), {0, 0, 1, -1, 0, 1});
  EXPECT_EQ(find_self_intersections(two_triangles(c, {0, 1, 2, 0, 3, 4})).pairs, 0u);
  // Sharing vertex 0, the other's far edge piercing the first: an intersection.
  c = flat;
  c.insert(c.end(), {0.3, 0.3, -1, 0.3, 0.3, 1});
  EXPECT_EQ(find_self_intersections(two_triangles(c, {0, 1, 2, 0, 3, 4})).pairs, 1u);
  // Sharing an edge: never tested (even folded onto each other).
  c = flat;
  c.insert(c.end(), {0.5, 0.4, 0});
  EXPECT_EQ(find_self_intersections(two_triangles(c, {0, 1, 2, 1, 0, 3})).pairs, 0u);
}

// With `coplanar` (for meshing a volume from its surface), triangles in one plane whose
// interiors overlap count, whatever they share; touching ones do not.
TEST(SelfIntersection, CoplanarOverlaps) {
  const auto pairs = [](const std::vector<double>& c, const std::vector<Id>& t, bool coplanar) {
    return find_self_intersections(two_triangles(c, t), 1000, coplanar).pairs;
  };
  // The unit square cut along each diagonal: its two triangulations, listed together.
  const std::vector<double> sq = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<Id> both = {0, 1, 2, 0, 2, 3, 0, 1, 3, 1, 2, 3};
  EXPECT_EQ(pairs(sq, both, false), 0u);
  EXPECT_EQ(pairs(sq, both, true), 4u);                // each of one cut overlaps both of the other
  EXPECT_EQ(pairs(sq, {0, 1, 2, 0, 2, 3}, true), 0u);  // one cut: neighbours across the diagonal
  // Sharing an edge, folded onto each other in the plane; sharing a vertex, one inside the
  // other's angle; no common vertex, one inside the other; side by side, touching at a point.
  std::vector<double> c = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.4, 0};
  EXPECT_EQ(pairs(c, {0, 1, 2, 1, 0, 3}, true), 1u);
  c = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.1, 0, 0.1, 0.3, 0};
  EXPECT_EQ(pairs(c, {0, 1, 2, 0, 3, 4}, true), 1u);
  c = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.1, 0.1, 0, 0.3, 0.1, 0, 0.1, 0.3, 0};
  EXPECT_EQ(pairs(c, {0, 1, 2, 3, 4, 5}, true), 1u);
  c = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 2, 0, 0, 1, 1, 0};
  EXPECT_EQ(pairs(c, {0, 1, 2, 3, 4, 5}, true), 0u);
}

TEST(SelfIntersection, NearlyCoplanarNeighboursSharingAVertex) {
  // Two triangles of a remeshed rotor sharing vertex 0, nearly coplanar (the far corner of the
  // first lies 4e-12 from the second's plane), whose sectors at the shared vertex are 2.3
  // degrees apart: they touch only there (exact arithmetic says so). The floating-point
  // segment test used before reported them crossing.
  const std::vector<double> c = {0.056451599999999998, 0.24193500000000001, 0.37175599999999998,
                                 -0.060491361875923508, 0.3037768219264379, 0.31204727108152386,
                                 -0.060491857805562731, 0.27496675078545019, 0.34595345524189275,
                                 -0.072662883605472975, 0.27363970116184327, 0.34681099461490755,
                                 0.032109699999999998, 0.23928099999999999, 0.373471};
  EXPECT_EQ(find_self_intersections(two_triangles(c, {0, 1, 2, 3, 4, 0})).pairs, 0u);
  // The second one's far edge moved across the first (its corner 3 pushed through): crossing.
  std::vector<double> d = c;
  d[9] = -0.02, d[10] = 0.28, d[11] = 0.3;  // below the first triangle, across its sector
  d[12] = -0.02, d[13] = 0.28, d[14] = 0.4;
  EXPECT_EQ(find_self_intersections(two_triangles(d, {0, 1, 2, 3, 4, 0})).pairs, 1u);
}

TEST(SelfIntersection, SphereAndADentThroughIt) {
  Mesh m = sphere_surface(3);
  EXPECT_EQ(find_self_intersections(m).pairs, 0u);
  // Vertex 0 moved to the antipode's far side: its triangles cross the other hemisphere.
  for (int c = 0; c < 3; ++c) m.coords[c] *= -1.5;
  const SelfIntersections s = find_self_intersections(m);
  EXPECT_GT(s.pairs, 0u);
  EXPECT_NE(s.first_a, kNoId);
  EXPECT_THROW(find_self_intersections(unit_square(2, 2)), InputError);
}

}  // namespace
