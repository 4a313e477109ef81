// Mesh statistics: counts, references, measures and histograms on meshes built in code, against
// values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/stats.hpp"

using namespace riemesh;

TEST(Stats, SummaryMinMaxMean) {
  const std::vector<double> v{3.0, -1.0, 4.0};
  const Summary s = summarize(v);
  EXPECT_EQ(s.count, 3u);
  EXPECT_EQ(s.min, -1.0);
  EXPECT_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(s.sum, 6.0);
  EXPECT_DOUBLE_EQ(s.mean(), 2.0);
  EXPECT_EQ(Summary{}.mean(), 0.0);
}

TEST(Stats, HistogramBinsAndClamping) {
  // Bins [0,0.5) [0.5,1]: 0.5 is in the second bin, 1 (the closed end) too, -3 and 7 clamp.
  const std::vector<double> v{0.0, 0.25, 0.5, 1.0, -3.0, 7.0};
  const Histogram h = histogram({0.0, 0.5, 1.0}, v);
  ASSERT_EQ(h.counts.size(), 2u);
  EXPECT_EQ(h.counts[0], 3u);
  EXPECT_EQ(h.counts[1], 3u);
  EXPECT_EQ(h.total(), v.size());
}

TEST(Stats, UniformHistogramEdges) {
  const Histogram h = uniform_histogram(0.0, 1.0, 10);
  ASSERT_EQ(h.edges.size(), 11u);
  EXPECT_DOUBLE_EQ(h.edges[3], 0.3);
  EXPECT_EQ(h.edges.back(), 1.0);
  EXPECT_THROW(make_histogram({1.0}), InputError);
  EXPECT_THROW(make_histogram({0.0, 0.0}), InputError);
}

TEST(Stats, CountsOfUnitSquare) {
  // unit_square(2, 3): 3x4 = 12 vertices, 12 triangles; unique edges by Euler for a disk:
  // V - E + F = 1 -> E = 12 + 12 - 1 = 23; boundary edges 2(2+3) = 10; 4 corners.
  const Mesh m = unit_square(2, 3);
  const MeshCounts c = count_entities(m);
  EXPECT_EQ(c.vertices, 12u);
  EXPECT_EQ(c.triangles, 12u);
  EXPECT_EQ(c.tetrahedra, 0u);
  EXPECT_EQ(c.edges, 23u);
  EXPECT_EQ(c.boundary_edges, 10u);
  EXPECT_EQ(c.boundary_triangles, 0u);
  EXPECT_EQ(c.corners, 4u);
  const MeshRefs r = distinct_refs(m);
  EXPECT_EQ(r.edges, (std::vector<std::int32_t>{1, 2, 3, 4}));
  EXPECT_EQ(r.triangles, (std::vector<std::int32_t>{1}));
}

TEST(Stats, CountsOfUnitCube) {
  // unit_cube(1): 8 vertices, 6 tets; edges: 12 cube edges + 6 face diagonals + 1 main
  // diagonal = 19; 12 boundary triangles.
  const MeshCounts c = count_entities(unit_cube(1));
  EXPECT_EQ(c.vertices, 8u);
  EXPECT_EQ(c.tetrahedra, 6u);
  EXPECT_EQ(c.edges, 19u);
  EXPECT_EQ(c.boundary_triangles, 12u);
  EXPECT_EQ(c.corners, 8u);
}

TEST(Stats, MeasuresPlanarVolumeSurface) {
  // Two right triangles of the unit square: 1/2 each, counter-clockwise so positive.
  for (double a : element_measures(unit_square(1, 1))) EXPECT_DOUBLE_EQ(a, 0.5);
  // Kuhn subdivision of the unit cube: six tets of volume 1/6.
  for (double v : element_measures(unit_cube(1))) EXPECT_NEAR(v, 1.0 / 6.0, 1e-15);
  // A clockwise planar triangle has a negative area.
  Mesh m = unit_square(1, 1);
  std::swap(m.triangles[1], m.triangles[2]);
  EXPECT_DOUBLE_EQ(element_measures(m)[0], -0.5);
  // Icosphere: positive areas summing to a bit less than 4π (inscribed polyhedron).
  double total = 0.0;
  for (double a : element_measures(sphere_surface(3))) {
    EXPECT_GT(a, 0.0);
    total += a;
  }
  EXPECT_LT(total, 4.0 * std::numbers::pi);
  EXPECT_GT(total, 0.98 * 4.0 * std::numbers::pi);
}
