// Fixtures: counts, measures, orientation and boundary refs in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/vec.hpp"
#include "mesh/fixtures.hpp"

using namespace riemesh;

namespace {

Vec3 point3(const Mesh& m, Id v) {
  return {{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
}

}  // namespace

TEST(Fixtures, UnitSquare) {
  const int nx = 4, ny = 3;
  const Mesh m = unit_square(nx, ny);
  EXPECT_EQ(m.kind(), MeshKind::kPlanar);
  EXPECT_EQ(m.num_vertices(), static_cast<std::size_t>((nx + 1) * (ny + 1)));
  EXPECT_EQ(m.num_triangles(), static_cast<std::size_t>(2 * nx * ny));
  EXPECT_EQ(m.num_edges(), static_cast<std::size_t>(2 * (nx + ny)));
  double area = 0.0;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const Id* v = &m.triangles[3 * t];
    const Vec2 p0{{m.coords[2 * v[0]], m.coords[2 * v[0] + 1]}};
    const Vec2 p1{{m.coords[2 * v[1]], m.coords[2 * v[1] + 1]}};
    const Vec2 p2{{m.coords[2 * v[2]], m.coords[2 * v[2] + 1]}};
    const double a = 0.5 * cross(p1 - p0, p2 - p0);
    EXPECT_NEAR(a, 0.5 / (nx * ny), 1e-15);  // counter-clockwise, half a cell
    area += a;
  }
  EXPECT_NEAR(area, 1.0, 1e-13);
  // Edge refs 1..4 = y=0, x=1, y=1, x=0: both ends lie on that side.
  std::map<int, int> per_ref;
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const int ref = m.edge_ref[e];
    ++per_ref[ref];
    for (int i = 0; i < 2; ++i) {
      const Id v = m.edges[2 * e + i];
      const double x = m.coords[2 * v], y = m.coords[2 * v + 1];
      const double on = ref == 1 ? y : ref == 2 ? x - 1 : ref == 3 ? y - 1 : x;
      EXPECT_EQ(on, 0.0) << "edge " << e << " ref " << ref;
    }
  }
  EXPECT_EQ(per_ref, (std::map<int, int>{{1, nx}, {2, ny}, {3, nx}, {4, ny}}));
  int corners = 0;
  for (auto t : m.vert_tag) corners += (t & kTagCorner) ? 1 : 0;
  EXPECT_EQ(corners, 4);
  EXPECT_EQ(m.vert_tag[static_cast<std::size_t>((nx + 1) * (ny + 1) - 1)], kTagCorner);
}

TEST(Fixtures, UnitCube) {
  const int n = 3;
  const Mesh m = unit_cube(n);
  EXPECT_EQ(m.kind(), MeshKind::kVolume);
  EXPECT_EQ(m.num_vertices(), 64u);
  EXPECT_EQ(m.num_tets(), 6u * 27u);
  double volume = 0.0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const Id* v = &m.tets[4 * t];
    const Vec3 p0 = point3(m, v[0]);
    const double vol =
        dot(point3(m, v[1]) - p0, cross(point3(m, v[2]) - p0, point3(m, v[3]) - p0)) / 6.0;
    EXPECT_NEAR(vol, 1.0 / (6 * n * n * n), 1e-15);  // positive, a sixth of a cell
    volume += vol;
  }
  EXPECT_NEAR(volume, 1.0, 1e-13);
  // 12 n² boundary triangles, 2n² per side, outward, on their side.
  ASSERT_EQ(m.num_triangles(), static_cast<std::size_t>(12 * n * n));
  std::map<int, int> per_ref;
  std::map<int, double> area_per_ref;
  for (std::size_t f = 0; f < m.num_triangles(); ++f) {
    const int ref = m.tri_ref[f];
    ++per_ref[ref];
    const int axis = (ref - 1) / 2;
    const double side = (ref - 1) % 2;
    const Vec3 p0 = point3(m, m.triangles[3 * f]);
    const Vec3 normal =
        cross(point3(m, m.triangles[3 * f + 1]) - p0, point3(m, m.triangles[3 * f + 2]) - p0);
    EXPECT_GT(normal[axis] * (side == 0 ? -1.0 : 1.0), 0.0) << "not outward";
    area_per_ref[ref] += 0.5 * norm(normal);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(m.coords[3 * m.triangles[3 * f + i] + axis], side);
  }
  for (int ref = 1; ref <= 6; ++ref) {
    EXPECT_EQ(per_ref[ref], 2 * n * n);
    EXPECT_NEAR(area_per_ref[ref], 1.0, 1e-13);
  }
  // 12 ridges of n segments, 8 corners.
  EXPECT_EQ(m.num_edges(), static_cast<std::size_t>(12 * n));
  int corners = 0, ridge_vertices = 0;
  for (auto t : m.vert_tag) {
    corners += (t & kTagCorner) ? 1 : 0;
    ridge_vertices += (t & kTagRidge) ? 1 : 0;
  }
  EXPECT_EQ(corners, 8);
  EXPECT_EQ(ridge_vertices, 8 + 12 * (n - 1));
}

TEST(Fixtures, SphereSurface) {
  for (int s : {0, 1, 3}) {
    const Mesh m = sphere_surface(s);
    EXPECT_EQ(m.kind(), MeshKind::kSurface);
    const std::size_t p = std::size_t{1} << (2 * s);
    EXPECT_EQ(m.num_vertices(), 10 * p + 2);
    EXPECT_EQ(m.num_triangles(), 20 * p);
    double area = 0.0, volume = 0.0;
    for (std::size_t v = 0; v < m.num_vertices(); ++v)
      EXPECT_NEAR(norm(point3(m, static_cast<Id>(v))), 1.0, 1e-15);
    for (std::size_t f = 0; f < m.num_triangles(); ++f) {
      const Vec3 a = point3(m, m.triangles[3 * f]), b = point3(m, m.triangles[3 * f + 1]),
                 c = point3(m, m.triangles[3 * f + 2]);
      const Vec3 normal = cross(b - a, c - a);
      EXPECT_GT(dot(normal, a + b + c), 0.0) << "not outward";
      area += 0.5 * norm(normal);
      volume += dot(a, cross(b, c)) / 6.0;  // divergence theorem, outward faces
    }
    // Inscribed polyhedra approach 4π and 4π/3 from below.
    EXPECT_LT(area, 4 * M_PI);
    EXPECT_LT(volume, 4 * M_PI / 3);
    if (s == 3) {
      EXPECT_NEAR(area, 4 * M_PI, 0.02 * 4 * M_PI);
      EXPECT_NEAR(volume, 4 * M_PI / 3, 0.03 * 4 * M_PI / 3);
    }
  }
}
