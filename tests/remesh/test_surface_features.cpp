// Surface analysis: vertex normals, feature edges and corners, sectors (cube, sphere, open grid,
// ref changes, given entities, and the fandisk whose count of edges with a dihedral angle above
// 45° is given in ../shared/data/SOURCES.md by an independent script).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/surface_features.hpp"
#include "surface_test_meshes.hpp"

using namespace riemesh;
using namespace riemesh::test;

namespace {

double worst_normal_error(const Mesh& m) {
  const auto n = vertex_normals(m, build_adjacency(m));
  double worst = 0.0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
    worst = std::max(worst, norm(n[v] - normalize(p)));
  }
  return worst;
}

TEST(SurfaceFeatures, SphereNormalsAreRadialAndNoFeatures) {
  // Angle-weighted normals on the icosphere: error O(h) on this irregular mesh (measured
  // 5.2e-3 at s = 3, 2.6e-3 at s = 4: a factor 2 per halving of h).
  const double e3 = worst_normal_error(sphere_mesh(3, 2.0));
  const double e4 = worst_normal_error(sphere_mesh(4, 2.0));
  EXPECT_LT(e3, 6e-3);
  EXPECT_LT(e4, e3 / 1.8);
  const Mesh m = sphere_mesh(3, 2.0);
  const Adjacency adj = build_adjacency(m);
  const SurfaceFeatures f = detect_features(m, adj, {});
  EXPECT_EQ(f.num_feature_edges, 0u);
  EXPECT_EQ(f.num_corners, 0u);
  const SurfaceSectors s = surface_sectors(m, adj, f);
  EXPECT_EQ(s.num_sectors(), m.num_vertices());
}

TEST(SurfaceFeatures, SectorNormalsIgnoreHowTrianglesAreListed) {
  // Every third triangle of the sphere listed the other way round (volume meshes list their
  // boundary triangles in any orientation): each sector normal is the same up to its sign
  // (the normals of a flipped triangle and its neighbours cancelled: tangent sector normals).
  const Mesh m = sphere_mesh(3, 2.0);
  Mesh flipped = m;
  for (std::size_t t = 0; t < flipped.num_triangles(); t += 3)
    std::swap(flipped.triangles[3 * t + 1], flipped.triangles[3 * t + 2]);
  auto sectors = [](const Mesh& x) {
    const Adjacency adj = build_adjacency(x);
    return surface_sectors(x, adj, detect_features(x, adj, {}));
  };
  const SurfaceSectors a = sectors(m), b = sectors(flipped);
  ASSERT_EQ(a.num_sectors(), b.num_sectors());
  for (std::size_t k = 0; k < a.num_sectors(); ++k)
    EXPECT_NEAR(std::abs(dot(a.normal[k], b.normal[k])), 1.0, 1e-12) << k;
}

TEST(SurfaceFeatures, AngleWeightedNormalIgnoresTriangulationOfAPlane) {
  // A fan around (0,0,0) in the plane z = 0 with very unequal triangles, plus one tilted
  // triangle: the normal is the angle-weighted mean, here (0,0,1) in the plane part.
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 1, 0, 0, 1, 0.01, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0};
  m.triangles = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 1};
  m.tri_ref.assign(5, 1);
  const Adjacency adj = build_adjacency(m);
  const auto n = vertex_normals(m, adj);
  EXPECT_NEAR(n[0][2], 1.0, 1e-15);
}

TEST(SurfaceFeatures, CubeRidgesAndCorners) {
  for (int n : {1, 3}) {
    const Mesh m = cube_surface(n);
    const Adjacency adj = build_adjacency(m);
    const SurfaceFeatures f = detect_features(m, adj, {});
    EXPECT_EQ(f.num_feature_edges, 12u * n);  // the 12 cube edges, n segments each
    EXPECT_EQ(f.num_angle_edges, 12u * n);
    EXPECT_EQ(f.num_corners, 8u);
    const SurfaceSectors s = surface_sectors(m, adj, f);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      int sectors = 0;
      for (Id x : s.sector2vert) sectors += x == static_cast<Id>(v);
      const int expect = f.vert_tag[v] & kTagCorner ? 3 : (f.vert_tag[v] & kTagRidge) ? 2
                         : ball(adj, static_cast<Id>(v)).empty()                ? 0
                                                                                : 1;
      EXPECT_EQ(sectors, expect) << "vertex " << v;
    }
    // A sector normal at a ridge vertex is the normal of its face: an axis vector.
    for (const Vec3& x : s.normal)
      EXPECT_NEAR(std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]), 1.0, 1e-12);
  }
  // Above 90° nothing on a cube is a ridge (its dihedral angles are exactly 90°).
  const Mesh m = cube_surface(2);
  const Adjacency adj = build_adjacency(m);
  FeatureOptions o;
  o.angle_deg = 91.0;
  EXPECT_EQ(detect_features(m, adj, o).num_feature_edges, 0u);
  o.angle_deg = 45.0;
  o.detect_angle = false;
  EXPECT_EQ(detect_features(m, adj, o).num_feature_edges, 0u);
}

TEST(SurfaceFeatures, RefChangesGivenEdgesAndCorners) {
  Mesh m = cube_surface(2);
  const Adjacency adj = build_adjacency(m);
  FeatureOptions o;
  o.detect_angle = false;
  // Refs by the face of the cube the triangle lies on: the 12 cube edges are ref changes.
  const Mesh c = unit_cube(2);
  m.tri_ref = c.tri_ref;
  SurfaceFeatures f = detect_features(m, adj, o);
  EXPECT_EQ(f.num_feature_edges, 24u);
  for (std::uint8_t bits : f.edge_feature) EXPECT_TRUE(bits == 0 || bits == kFeatureRefChange);
  EXPECT_EQ(f.num_corners, 8u);
  // One given edge on face z = 0 and a given corner: the ends of an isolated feature segment
  // (feature degree 1) are corners. Ids (k(n+1)+j)(n+1)+i: 1 = (½,0,0), 4 = (½,½,0).
  m.tri_ref.assign(m.num_triangles(), 1);
  const Id a = 1, b = 4;
  m.edges = {a, b};
  m.edge_ref = {7};
  m.edge_tag = {kTagRidge};
  m.vert_tag[static_cast<std::size_t>(0)] = kTagCorner;
  f = detect_features(m, adj, o);
  EXPECT_EQ(f.num_feature_edges, 1u);
  EXPECT_EQ(f.edge_feature[static_cast<std::size_t>(find_edge(adj, a, b))], kFeatureGiven);
  EXPECT_EQ(f.num_corners, 3u);  // both ends (degree 1) and the given corner 0
  EXPECT_TRUE(f.vert_tag[0] & kTagCorner);
}

TEST(SurfaceFeatures, OpenBoundaryAndNonManifoldEdges) {
  // Three triangles sharing the edge 0-1 (a "book" of 3 pages).
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, -1, 0};
  m.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  m.tri_ref.assign(3, 1);
  const Adjacency adj = build_adjacency(m);
  const SurfaceFeatures f = detect_features(m, adj, {});
  EXPECT_EQ(f.edge_feature[static_cast<std::size_t>(find_edge(adj, 0, 1))], kFeatureNonManifold);
  EXPECT_EQ(f.edge_feature[static_cast<std::size_t>(find_edge(adj, 1, 2))], kFeatureOpen);
  EXPECT_EQ(f.num_feature_edges, 7u);
  // 0 and 1 have feature degree 4: corners; 2, 3, 4 have 2 with a turn of 90° or more.
  EXPECT_EQ(f.feature_degree[0], 4);
  EXPECT_TRUE(f.vert_tag[0] & kTagCorner);
  EXPECT_TRUE(f.vert_tag[1] & kTagCorner);
}

TEST(SurfaceFeatures, OpenBoundariesAreFeatureLines) {
  // A flat square grid: 4 sides of 8 edges, corners where the boundary turns by 90°.
  const Param plane{[](double u, double v) { return Vec3{{u, v, 0.0}}; }, nullptr};
  Mesh m = param_grid(plane, 8, 8, -1, 1, -1, 1, false, false);
  Adjacency adj = build_adjacency(m);
  SurfaceFeatures f = detect_features(m, adj, {});
  EXPECT_EQ(f.num_feature_edges, 32u);
  EXPECT_EQ(f.num_angle_edges, 0u);
  EXPECT_EQ(f.num_corners, 4u);
  // The saddle z = x² − y² on [-1,1]²: at (−1,−1) the neighbours along the boundary are
  // (−¾,−1,−7/16) and (−1,−¾,7/16); the boundary turns by acos(0.752) = 41° < 45°: no corner.
  m = param_grid(saddle_param(), 8, 8, -1, 1, -1, 1, false, false);
  adj = build_adjacency(m);
  f = detect_features(m, adj, {});
  EXPECT_EQ(f.num_feature_edges, 32u);
  EXPECT_EQ(f.num_corners, 0u);
  FeatureOptions o;
  o.angle_deg = 40.0;
  EXPECT_EQ(detect_features(m, adj, o).num_corners, 4u);
  // An open cylinder: two boundary circles, no corners.
  m = param_grid(cylinder_param(1.0), 16, 4, 0, 2 * std::numbers::pi, 0, 1, true, false);
  adj = build_adjacency(m);
  f = detect_features(m, adj, {});
  EXPECT_EQ(f.num_feature_edges, 32u);
  EXPECT_EQ(f.num_corners, 0u);
  for (std::size_t e = 0; e < adj.num_edges(); ++e)
    EXPECT_TRUE(f.edge_feature[e] == 0 || f.edge_feature[e] == kFeatureOpen);
}

TEST(SurfaceFeatures, Fandisk) {
  const Mesh m = read_medit(RIEMESH_SHARED_DATA "/surf/fandisk.mesh");
  const Adjacency adj = build_adjacency(m);
  const SurfaceFeatures f = detect_features(m, adj, {});
  // SOURCES.md: "dihedral>45deg edges 706" (scripts/surfcheck.py, independent of this code).
  EXPECT_EQ(f.num_angle_edges, 706u);
  EXPECT_EQ(f.num_feature_edges, 706u);  // closed, manifold, one ref: angle features only
  // Every ridge vertex has two sectors unless it is a corner; every corner has at least one
  // feature edge (the fandisk has no isolated given corners).
  const SurfaceSectors s = surface_sectors(m, adj, f);
  std::vector<int> count(m.num_vertices(), 0);
  for (Id v : s.sector2vert) ++count[static_cast<std::size_t>(v)];
  std::size_t ridge_vertices = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (f.feature_degree[v] == 2 && !(f.vert_tag[v] & kTagCorner)) {
      EXPECT_EQ(count[v], 2) << v;
      ++ridge_vertices;
    }
    if (f.feature_degree[v] == 0) {
      EXPECT_EQ(count[v], 1);
    }
    if (f.vert_tag[v] & kTagCorner) {
      EXPECT_GT(f.feature_degree[v], 0);
    }
  }
  EXPECT_GT(ridge_vertices, 600u);
  EXPECT_GE(f.num_corners, 8u);
  EXPECT_LE(f.num_corners, 60u);
}

TEST(SurfaceFeatures, RejectsNonSurfaces) {
  const Mesh c = unit_cube(1);
  EXPECT_THROW(detect_features(c, build_adjacency(c), {}), InputError);
  const Mesh m = cube_surface(1);
  FeatureOptions o;
  o.angle_deg = 0.0;
  EXPECT_THROW(detect_features(m, build_adjacency(m), o), InputError);
}

}  // namespace
