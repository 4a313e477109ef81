// Interior points of a volume meshed from its boundary: sizes from the boundary edges, and the
// filled mesh valid, of the same volume, with the recovered boundary kept and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "core/error.hpp"
#include "generate/boundary_recovery3d.hpp"
#include "generate/volume_fill3d.hpp"
#include "mesh/check.hpp"
#include "remesh/surface_test_meshes.hpp"

namespace riemesh {
namespace {

double tet_volume_sum(const Mesh& m) {
  double s = 0.0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    double p[4][3];
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) p[i][c] = m.coords[3 * static_cast<std::size_t>(m.tets[4 * t + i]) + c];
    double a[3], b[3], d[3];
    for (int c = 0; c < 3; ++c) {
      a[c] = p[1][c] - p[0][c];
      b[c] = p[2][c] - p[0][c];
      d[c] = p[3][c] - p[0][c];
    }
    s += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
          a[2] * (b[0] * d[1] - b[1] * d[0])) / 6.0;
  }
  return s;
}

std::set<std::array<double, 3>> boundary_points(const Mesh& m) {
  std::set<std::array<double, 3>> out;
  for (Id v : m.triangles) {
    const auto k = 3 * static_cast<std::size_t>(v);
    out.insert({m.coords[k], m.coords[k + 1], m.coords[k + 2]});
  }
  return out;
}

TEST(VolumeFill3d, BoundarySizesAreTheMeanEdgeLengths) {
  const RecoveredVolume r = recover_volume(test::cube_surface(4));
  const std::vector<double> h = boundary_sizes(r.volume);
  ASSERT_EQ(h.size(), r.volume.num_vertices());
  for (double x : h) {
    EXPECT_GE(x, 0.125 - 1e-12);  // Steiner points halve some edges of the 0.25 grid
    EXPECT_LE(x, 0.25 * std::sqrt(2.0) + 1e-12);
  }
}

TEST(VolumeFill3d, FilledCubeIsValidAndKeepsItsBoundary) {
  const RecoveredVolume r = recover_volume(test::cube_surface(3));
  const auto before = boundary_points(r.volume);
  Adapt3dOptions o;
  Mesh copy = r.volume;
  const Adapt3dResult f = fill_volume(std::move(copy), 0.25, o);
  EXPECT_TRUE(check_mesh(f.mesh).valid());
  EXPECT_NEAR(tet_volume_sum(f.mesh), 1.0, 1e-12);
  EXPECT_EQ(boundary_points(f.mesh), before);  // the recovered boundary, unchanged
  EXPECT_EQ(f.mesh.num_triangles(), r.volume.num_triangles());
  EXPECT_GT(f.mesh.num_vertices(), r.volume.num_vertices() + 5);  // interior points
  EXPECT_GT(f.report.passes.back().q_min, 0.2);
  Mesh again = r.volume;
  const Adapt3dResult g = fill_volume(std::move(again), 0.25, o);
  EXPECT_EQ(g.mesh.coords, f.mesh.coords);
  EXPECT_EQ(g.mesh.tets, f.mesh.tets);
}

TEST(VolumeFill3d, BadSizeIsAnError) {
  RecoveredVolume r = recover_volume(test::cube_surface(2));
  EXPECT_THROW(fill_volume(std::move(r.volume), -1.0, Adapt3dOptions{}), InputError);
}

}  // namespace
}  // namespace riemesh
