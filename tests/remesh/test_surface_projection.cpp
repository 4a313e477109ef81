// SurfaceProjection's check points: the lattice the surface remesher follows (surface_ops.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "mesh/distance.hpp"
#include "remesh/surface_projection.hpp"
#include "surface_test_meshes.hpp"

namespace riemesh {
namespace {

/// Every check point once (vertices used by a triangle, 3 per edge, 3 inside each triangle),
/// each on the triangle named as its owner, and the same set as the grid's check_points.
void expect_owned_lattice(const Mesh& mesh) {
  const SurfaceProjection geo(mesh, FeatureOptions{},
                              std::vector<SymMat3>(mesh.num_vertices(), SymMat3::identity()), 0.01);
  std::vector<Vec3> pts;
  std::vector<Id> owner;
  geo.check_points_by_triangle(pts, &owner);
  std::size_t used = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
    used += ball(geo.adjacency(), static_cast<Id>(v)).empty() ? 0 : 1;
  EXPECT_EQ(pts.size(), used + 3 * geo.adjacency().num_edges() + 3 * mesh.num_triangles());
  ASSERT_EQ(owner.size(), pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    ASSERT_GE(owner[k], 0);
    ASSERT_LT(static_cast<std::size_t>(owner[k]), mesh.num_triangles());
    const Id* t = &mesh.triangles[3 * static_cast<std::size_t>(owner[k])];
    auto at = [&](Id v) {
      const double* c = &mesh.coords[3 * static_cast<std::size_t>(v)];
      return Vec3{{c[0], c[1], c[2]}};
    };
    EXPECT_LT(norm(pts[k] - closest_point_on_triangle(pts[k], at(t[0]), at(t[1]), at(t[2]))),
              1e-12);
  }
  std::vector<Vec3> all;
  geo.check_points({{-10.0, -10.0, -10.0}}, {{10.0, 10.0, 10.0}}, all);
  EXPECT_EQ(all.size(), pts.size());
}

TEST(SurfaceProjection, CheckPointsLieOnTheirOwners) {
  expect_owned_lattice(test::sphere_mesh(2, 1.0));
  expect_owned_lattice(test::cube_surface(3));  // interior vertices of no triangle: not points
}

}  // namespace
}  // namespace riemesh
