// Sliver removal (remesh/sliver3d.hpp) on a perturbed cube: the vertex optimisation raises the
// worst quality of a ball, the sweeps raise the mesh's worst quality and keep it valid, the
// domain's volume and its boundary planes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/sliver3d.hpp"
#include "tet_test_util.hpp"

using namespace riemesh;
using riemesh::test::volume;
using riemesh::test::worst_quality;

namespace {

/// The live tet of worst quality.
Id worst_tet(const TetMesh& m) {
  Id best = kNoId;
  double q = 2.0;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t)) && tet_quality(m, static_cast<Id>(t)) < q)
      q = tet_quality(m, static_cast<Id>(t)), best = static_cast<Id>(t);
  return best;
}

double ball_worst(const TetMesh& m, Id v) {
  std::vector<Id> ball;
  collect_ball(m, v, ball);
  double q = 1.0;
  for (const Id t : ball) q = std::min(q, tet_quality(m, t));
  return q;
}

Remesh3dContext perturbed_cube_context() {
  const Mesh cube = perturbed_unit_cube(4, 0.1, 7);
  return Remesh3dContext(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(0.25)),
                         Adapt3dOptions{});
}

}  // namespace

TEST(Sliver3d, OptimiseVertexRaisesTheWorstQualityOfItsBall) {
  Remesh3dContext ctx = perturbed_cube_context();
  TetMesh& m = ctx.mesh();
  const Id t = worst_tet(m);
  ASSERT_NE(t, kNoId);
  int applied = 0;
  for (int i = 0; i < 4; ++i) {
    const Id v = m.tv[4 * t + i];
    const double before = ball_worst(m, v);
    const VertexKind kind = m.vkind[v];
    const Vec3 p = m.xyz[v];
    const Outcome o = optimise_vertex(ctx, v);
    if (o == Outcome::kApplied) {
      ++applied;
      EXPECT_GT(ball_worst(m, v), before);
    } else {
      EXPECT_EQ(m.xyz[v][0], p[0]);
      EXPECT_EQ(m.xyz[v][1], p[1]);
      EXPECT_EQ(m.xyz[v][2], p[2]);
    }
    if (kind == VertexKind::kFixed) {
      EXPECT_NE(o, Outcome::kApplied);
    }
  }
  EXPECT_GE(applied, 1);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
}

TEST(Sliver3d, SweepsRaiseTheWorstQualityAndKeepTheMeshValid) {
  Remesh3dContext ctx = perturbed_cube_context();
  TetMesh& m = ctx.mesh();
  const double before = worst_quality(m);
  SliverLimits limits;
  limits.target = 0.7;
  PassStats st;
  const long done = sliver_sweeps(ctx, limits, st);
  EXPECT_GT(done, 0);
  EXPECT_GT(st.swaps + st.moves + st.collapses, 0);
  EXPECT_GT(worst_quality(m), before + 0.05) << "from " << before;
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_NEAR(volume(m), 1.0, 1e-12);
  // The quality cache the sweeps used is up to date after their swaps, moves and collapses.
  std::size_t cached = 0;
  for (std::size_t t = 0; t < m.tet_capacity() && t < m.quality.size(); ++t) {
    if (!m.tet_alive(static_cast<Id>(t)) || std::isnan(m.quality[t])) continue;
    ++cached;
    EXPECT_EQ(m.quality[t], tet_quality(m, static_cast<Id>(t))) << "tet " << t;
  }
  EXPECT_GT(cached, m.num_live_tets() / 2);
  // Boundary vertices stayed on their planes (the cube's faces).
  for (std::size_t v = 0; v < m.vertex_capacity(); ++v) {
    if (!m.vert_alive(static_cast<Id>(v)) || m.vkind[v] == VertexKind::kInterior) continue;
    const Vec3& p = m.xyz[v];
    const bool on_face = std::min({p[0], p[1], p[2], 1 - p[0], 1 - p[1], 1 - p[2]}) < 1e-12;
    EXPECT_TRUE(on_face) << "vertex " << v;
  }
}

TEST(Sliver3d, SweepsAreBoundedAndDeterministic) {
  Remesh3dContext a = perturbed_cube_context(), b = perturbed_cube_context();
  SliverLimits limits;
  limits.target = 0.99;  // unreachable: every sweep finds work, the count stops them
  limits.sweeps = 2;
  PassStats sa, sb;
  sliver_sweeps(a, limits, sa);
  sliver_sweeps(b, limits, sb);
  EXPECT_EQ(a.mesh().tv, b.mesh().tv);
  EXPECT_EQ(a.mesh().xyz.size(), b.mesh().xyz.size());
  for (std::size_t v = 0; v < a.mesh().xyz.size(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(a.mesh().xyz[v][k], b.mesh().xyz[v][k]);
  EXPECT_EQ(check_tet_mesh(a.mesh()), "");
}

// The compass search from a vertex pushed off its place in a regular grid: it climbs back to
// nearly the grid's quality, its figure is the mesh's own measure (tet_quality) at the point it
// returns, no edge at the vertex leaves the band, and the mesh is not changed.
TEST(Sliver3d, CompassSearchClimbsBackToTheGridPlace) {
  const Mesh cube = perturbed_unit_cube(4, 0.0, 7);
  // Size 0.31 on the 0.25 grid: its edges (0.81, 1.14, 1.40) in the band.
  Remesh3dContext ctx(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(0.31)),
                      Adapt3dOptions{});
  TetMesh& m = ctx.mesh();
  Id v = kNoId;
  for (std::size_t i = 0; i < m.vertex_capacity(); ++i)
    if (std::abs(m.xyz[i][0] - 0.5) + std::abs(m.xyz[i][1] - 0.5) + std::abs(m.xyz[i][2] - 0.5) < 1e-9)
      v = static_cast<Id>(i);
  ASSERT_NE(v, kNoId);
  const Vec3 grid_p = m.xyz[v];
  const double grid = ball_worst(m, v);
  const auto worst_with_v_at = [&](const Vec3& p) {
    m.xyz[v] = p;
    const double q = ball_worst(m, v);
    m.xyz[v] = grid_p;
    return q;
  };
  std::vector<Id> ball;
  collect_ball(m, v, ball);
  Vec3 p = grid_p + Vec3{{0.03, -0.02, 0.025}};
  const double pushed = worst_with_v_at(p);
  ASSERT_LT(pushed, 0.9 * grid);
  const double found = compass_search(ctx, v, ball, p, pushed);
  EXPECT_GT(found, 0.97 * grid) << "grid " << grid << ", pushed " << pushed;
  EXPECT_NEAR(found, worst_with_v_at(p), 1e-12);
  EXPECT_EQ(m.xyz[v][0], grid_p[0]);
  EXPECT_EQ(m.xyz[v][1], grid_p[1]);
  EXPECT_EQ(m.xyz[v][2], grid_p[2]);
  m.xyz[v] = p;
  for (const Id t : ball)
    for (int i = 0; i < 4; ++i)
      if (m.tv[4 * t + i] != v) {
        EXPECT_GE(edge_length(m, v, m.tv[4 * t + i]), 0.70710678118654752);
        EXPECT_LE(edge_length(m, v, m.tv[4 * t + i]), 1.4142135623730951);
      }
  EXPECT_EQ(check_tet_mesh(m), "");
}
