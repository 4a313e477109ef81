// The 3D operators on small cubes: each keeps the mesh valid (symmetric adjacency, listed faces,
// positive volumes), the domain's volume and its boundary, and refuses what it must.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/ops3d.hpp"
#include "tet_test_util.hpp"

using namespace riemesh;
using riemesh::test::volume;
using riemesh::test::worst_quality;

namespace {

TetMesh cube_tet_mesh(int n, double h) {
  const Mesh cube = unit_cube(n);
  TetMesh m = build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(h)));
  return m;
}

/// Two tets on the triangle (0,0,0) (1,0,0) (0,1,0), apexes below and above it.
TetMesh bipyramid() {
  Mesh in;
  in.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, -0.8, 0.3, 0.3, 0.8};
  in.tets = {0, 2, 1, 3, 0, 1, 2, 4};
  in.tet_ref = {1, 1};
  return build_tet_mesh(in, std::vector<SymMat3>(5, SymMat3::identity()));
}

NewVertex3 at(const TetMesh& m, const Vec3& p) {
  NewVertex3 nv;
  nv.p = p;
  nv.metric = m.metric[0];
  return nv;
}

/// The metric with eigenvalues `eig` on the axes turned by `angle` about z.
SymMat3 turned_about_z(double angle, const Vec3& eig) {
  Mat3 r = Mat3::identity();
  r(0, 0) = std::cos(angle), r(0, 1) = -std::sin(angle);
  r(1, 0) = std::sin(angle), r(1, 1) = std::cos(angle);
  return compose(r, eig);
}

}  // namespace

TEST(TetOps, SplitInteriorEdgeThenCollapseBack) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  std::vector<Id> shell;
  collect_shell(m, 13, 0, shell);
  ASSERT_EQ(shell.size(), 6u);
  Id x = kNoId;
  ASSERT_EQ(split_edge(m, 13, 0, at(m, 0.5 * (m.xyz[13] + m.xyz[0])), 0.0, &x), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 48u + 6u);
  EXPECT_NEAR(volume(m), 1.0, 1e-14);
  // The new vertex is interior: it goes back into either end.
  EXPECT_EQ(m.vkind[x], VertexKind::kInterior);
  EXPECT_EQ(collapse_edge(m, x, 0, {0.0, 100.0}), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 48u);
  EXPECT_EQ(m.num_live_vertices(), 27u);
  EXPECT_NEAR(volume(m), 1.0, 1e-14);
}

TEST(TetOps, SplitRefusesAPointOffTheEdgeThatInvertsATet) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  const std::size_t tets = m.num_live_tets(), verts = m.num_live_vertices();
  EXPECT_EQ(split_edge(m, 13, 0, at(m, Vec3{{2.0, 2.0, -1.0}}), 0.0, nullptr),
            Outcome::kRejectedGeometry);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), tets);
  EXPECT_EQ(m.num_live_vertices(), verts);
}

TEST(TetOps, SplitBoundaryEdgeSplitsItsFacesWithTheirRefs) {
  TetMesh m = cube_tet_mesh(1, 0.5);
  // Edge 0-1 runs along y = z = 0: on the faces of refs 3 (y=0) and 5 (z=0).
  Id x = kNoId;
  NewVertex3 nv = at(m, 0.5 * (m.xyz[0] + m.xyz[1]));
  nv.kind = VertexKind::kRidge;
  ASSERT_EQ(split_edge(m, 0, 1, nv, 0.0, &x), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  const Mesh out = to_mesh(m);
  EXPECT_TRUE(check_mesh(out).valid());
  EXPECT_EQ(out.num_triangles(), 12u + 2u);
  int on_x = 0;
  for (std::size_t f = 0; f < out.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k)
      if (out.triangles[3 * f + k] == static_cast<Id>(out.num_vertices() - 1)) {
        ++on_x;
        EXPECT_TRUE(out.tri_ref[f] == 3 || out.tri_ref[f] == 5);
      }
  EXPECT_EQ(on_x, 4);
}

TEST(TetOps, CollapseObeysTheBoundaryRules) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  // A fixed vertex never goes.
  EXPECT_EQ(collapse_edge(m, 1, 0, {0.0, 100.0}), Outcome::kRejectedTopology);
  // An interior vertex may not leave through a boundary edge... it has none; but a planar vertex
  // may not collapse along an edge leaving its plane: vertex 4 = (1,1,0) on z=0 (ref 5) into the
  // centre 13.
  m.vkind[4] = VertexKind::kPlanar;
  m.vplane[8] = m.vplane[9] = 5;
  EXPECT_EQ(collapse_edge(m, 4, 13, {0.0, 100.0}), Outcome::kRejectedTopology);
  EXPECT_EQ(check_tet_mesh(m), "");
}

TEST(TetOps, CollapseKeepsTheBallsWorstQuality) {
  // The centre of a 2x2x2 cube into its neighbour 12 = (0,0.5,0.5): the merged tets are worse
  // than the Kuhn tets, so a floor at the old worst quality refuses it.
  TetMesh m = cube_tet_mesh(2, 0.5);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  m.vkind[13] = VertexKind::kInterior;
  EXPECT_EQ(collapse_edge(m, 13, 12, {0.99, 100.0}), Outcome::kRejectedQuality);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 48u);
  EXPECT_EQ(collapse_edge(m, 13, 12, {0.0, 100.0}), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_NEAR(volume(m), 1.0, 1e-14);
}

TEST(TetOps, CollapseRefusesLongEdges) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  m.vkind[13] = VertexKind::kInterior;
  // Into the corner along the diagonal: new edges of length 2 in the metric (h = 0.5).
  EXPECT_EQ(collapse_edge(m, 13, 0, {0.0, 1.5}), Outcome::kRejectedQuality);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 48u);
  // Allowed lengths: the centre's 6 tets on the diagonal go, the others now hold the corner.
  EXPECT_EQ(collapse_edge(m, 13, 0, {0.0, 100.0}), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 42u);
  EXPECT_NEAR(volume(m), 1.0, 1e-14);
  std::vector<Id> ball;
  collect_ball(m, 13, ball);
  EXPECT_TRUE(ball.empty());
}

TEST(TetOps, FaceSwapThenEdgeSwapBack) {
  TetMesh m = bipyramid();
  ASSERT_EQ(check_tet_mesh(m), "");
  const double q2 = std::min(tet_quality(m, 0), tet_quality(m, 1));
  // The shared face is slot 4*0 + 3 (opposite vertex 3 of tet 0).
  ASSERT_EQ(m.tadj[3] / 4, 1);
  ASSERT_EQ(swap_face(m, 3, -1.0, 100.0), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 3u);
  EXPECT_NEAR(volume(m), 2.0 * 0.5 * 0.8 / 3.0, 1e-14);
  // Back: the 3 tets around edge (3, 4) become 2 again, with the old quality.
  ASSERT_EQ(swap_edge(m, 3, 4, -1.0, 100.0), Outcome::kApplied);
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 2u);
  double q = 1.0;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t))) q = std::min(q, tet_quality(m, static_cast<Id>(t)));
  EXPECT_NEAR(q, q2, 1e-12);
  // Swaps that do not gain are refused; a boundary edge has no closed shell.
  EXPECT_EQ(swap_edge(m, 0, 1, 0.0, 100.0), Outcome::kRejectedTopology);
  EXPECT_NE(swap_face(m, m.tv[0] == kNoId ? 7 : 3, 0.5, 100.0), Outcome::kApplied);
}

TEST(TetOps, EdgeSwapPicksTheBestRingTriangulation) {
  // Refine a cube, then check that every applied swap raises the shell's worst quality.
  TetMesh m = cube_tet_mesh(3, 0.2);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  int applied = 0;
  for (Id a = 0; a < 64; ++a)
    for (Id b = a + 1; b < 64; ++b) {
      std::vector<Id> shell;
      collect_shell(m, a, b, shell);
      if (shell.empty()) continue;
      double before = 1.0;
      for (const Id t : shell) before = std::min(before, tet_quality(m, t));
      const std::size_t n = m.num_live_tets();
      if (swap_edge(m, a, b, 1e-3, 100.0) != Outcome::kApplied) continue;
      ++applied;
      EXPECT_EQ(m.num_live_tets(), n + shell.size() - 4);
      EXPECT_EQ(check_tet_mesh(m), "");
    }
  EXPECT_NEAR(volume(m), 1.0, 1e-13);
  (void)applied;
}

TEST(TetOps, MoveImprovesOrRefuses) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  m.vkind[13] = VertexKind::kInterior;
  const Vec3 centre = m.xyz[13];
  m.xyz[13] = Vec3{{0.6, 0.55, 0.45}};
  EXPECT_EQ(move_vertex(m, 13, centre, m.metric[13]), Outcome::kApplied);
  EXPECT_EQ(m.xyz[13], centre);
  EXPECT_EQ(move_vertex(m, 13, Vec3{{1.5, 0.5, 0.5}}, m.metric[13]), Outcome::kRejectedGeometry);
  EXPECT_EQ(m.xyz[13], centre);
  EXPECT_EQ(move_vertex(m, 13, Vec3{{0.6, 0.5, 0.5}}, m.metric[13]), Outcome::kRejectedQuality);
  m.vkind[13] = VertexKind::kFixed;
  EXPECT_EQ(move_vertex(m, 13, Vec3{{0.5, 0.5, 0.55}}, m.metric[13]), Outcome::kRejectedTopology);
  EXPECT_EQ(check_tet_mesh(m), "");
}

TEST(TetOps, MoveWithAFloorMayLowerTheWorstQualityDownToIt) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  m.vkind[13] = VertexKind::kInterior;
  const Vec3 centre = m.xyz[13], off{{0.6, 0.5, 0.5}};
  EXPECT_EQ(move_vertex(m, 13, off, m.metric[13]), Outcome::kRejectedQuality);  // worse
  EXPECT_EQ(move_vertex(m, 13, off, m.metric[13], nullptr, 0.999), Outcome::kRejectedQuality);
  EXPECT_EQ(m.xyz[13], centre);
  EXPECT_EQ(move_vertex(m, 13, off, m.metric[13], nullptr, 0.1), Outcome::kApplied);
  EXPECT_EQ(m.xyz[13], off);
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) EXPECT_GT(tet_quality(m, static_cast<Id>(t)), 0.1);
  // A floor never admits an invalid ball.
  EXPECT_EQ(move_vertex(m, 13, Vec3{{1.5, 0.5, 0.5}}, m.metric[13], nullptr, 0.0),
            Outcome::kRejectedGeometry);
  EXPECT_EQ(check_tet_mesh(m), "");
}

TEST(TetOps, EdgeLengthSeesTheMetricTurn) {
  TetMesh m = bipyramid();
  // A stiff axis turned by ±0.05 rad between the two ends of an edge along y: about 10 |ab| long
  // at its middle (in the log-Euclidean mean), and sqrt(1e6 sin²(0.05) + 100 cos²(0.05)) |ab|
  // ≈ 51 |ab| at its ends; Simpson's rule: (2 ends + 4 middle) / 6.
  const auto turned = [](double angle) { return turned_about_z(angle, Vec3{{1e6, 100.0, 100.0}}); };
  m.set_metric(0, turned(0.05)), m.set_metric(1, turned(-0.05));
  m.xyz[0] = Vec3{{0, 0, 0}}, m.xyz[1] = Vec3{{0, 0.01, 0}};
  const SymMat3 mid_metric = exp_sym(0.5 * (log_spd(turned(0.05)) + log_spd(turned(-0.05))));
  const double ends = 0.01 * std::sqrt(1e6 * std::sin(0.05) * std::sin(0.05) +
                                       100 * std::cos(0.05) * std::cos(0.05));
  const double mid = 0.01 * std::sqrt(quadratic(mid_metric, Vec3{{0, 1, 0}}));
  EXPECT_NEAR(mid, 0.1, 2e-3);
  EXPECT_NEAR(edge_length(m, 0, 1), (2 * ends + 4 * mid) / 6, 1e-9);
  EXPECT_EQ(compare_edge_length(m, 0, 1, 0.5 * ends), -1);
  EXPECT_FALSE(edge_longer_than(m, 0, 1, 0.5 * ends));
  // Axis-aligned metrics (no turn): the closed form, as before.
  const SymMat3 d1 = SymMat3::diagonal(Vec3{{1.0, 4.0, 1e4}}), d2 = SymMat3::diagonal(Vec3{{9.0, 1.0, 1.0}});
  m.set_metric(0, d1), m.set_metric(1, d2);
  EXPECT_EQ(edge_length(m, 0, 1), edge_length_geometric(d1, d2, m.xyz[1] - m.xyz[0]));
}

TEST(TetOps, VertexLogsOnlyOnceAMetricTurns) {
  // Diagonal (isotropic or axis-aligned) metrics: no logarithms kept; the first metric that is
  // not diagonal brings them for every vertex, and they follow every change after.
  TetMesh m = bipyramid();
  EXPECT_TRUE(m.log_metric.empty());
  m.set_metric(2, SymMat3::diagonal(Vec3{{1.0, 4.0, 9.0}}));
  EXPECT_TRUE(m.log_metric.empty());
  const SymMat3 turned{{2.0, 0.5, 3.0, 0.0, 0.1, 4.0}};
  m.set_metric(3, turned);
  ASSERT_EQ(m.log_metric.size(), m.vertex_capacity());
  for (std::size_t v = 0; v < m.vertex_capacity(); ++v)
    for (int k = 0; k < 6; ++k) EXPECT_EQ(m.log_metric[v].c[k], log_spd(m.metric[v]).c[k]);
  const Id x = m.add_vertex(Vec3{{0.2, 0.2, 0.0}}, SymMat3::identity());
  ASSERT_EQ(m.log_metric.size(), m.vertex_capacity());
  for (int k = 0; k < 6; ++k) EXPECT_EQ(m.log_metric[x].c[k], 0.0);
}

TEST(TetOps, TetQualityInTheLogEuclideanMeanWhereTheMetricTurns) {
  // Where the vertex metrics do not commute, a tet is measured in exp(Σ log M_i / 4): the plain
  // mean would add up the turned stiff directions and rate the tet far better than it is.
  TetMesh m = bipyramid();
  const auto turned = [](double angle) { return turned_about_z(angle, Vec3{{400.0, 1.0, 1.0}}); };
  const Id* v = &m.tv[0];
  const double angles[4] = {0.3, -0.3, 0.1, -0.1};
  SymMat3 log_sum = SymMat3::zero(), sum = SymMat3::zero();
  for (int i = 0; i < 4; ++i) {
    m.set_metric(v[i], turned(angles[i]));
    log_sum += log_spd(turned(angles[i])), sum += turned(angles[i]);
  }
  const Vec3 &p0 = m.xyz[v[0]], &p1 = m.xyz[v[1]], &p2 = m.xyz[v[2]], &p3 = m.xyz[v[3]];
  const double log_euclidean = quality_in(exp_sym(0.25 * log_sum), p0, p1, p2, p3);
  const double plain = quality_in(0.25 * sum, p0, p1, p2, p3);
  EXPECT_NEAR(tet_quality(m, 0), log_euclidean, 1e-9 * log_euclidean);
  EXPECT_GT(std::abs(plain - log_euclidean), 0.01);
  // Axis-aligned metrics commute: the plain mean, exactly as before.
  for (int i = 0; i < 4; ++i) m.set_metric(v[i], SymMat3::diagonal(Vec3{{1.0 + i, 4.0, 9.0 * i + 1}}));
  SymMat3 diag_sum = SymMat3::zero();
  for (int i = 0; i < 4; ++i) diag_sum += m.metric[v[i]];
  EXPECT_EQ(tet_quality(m, 0), quality_in(0.25 * diag_sum, p0, p1, p2, p3));
}

TEST(TetOps, RefusedMoveKeepsTheVertexLog) {
  // A trial move sets the vertex's metric and log (the ball is measured with them); a refusal
  // puts both back, also when the trial's metric was the first that is not diagonal.
  TetMesh m = bipyramid();
  m.vkind[3] = VertexKind::kInterior;  // free to try (the test is about the metric, not the kind)
  ASSERT_TRUE(m.log_metric.empty());
  const SymMat3 turned{{2.0, 0.5, 3.0, 0.0, 0.1, 4.0}};
  // Vertex 3 (the lower apex) to the other side of the base: inverts its tet, refused.
  EXPECT_EQ(move_vertex(m, 3, Vec3{{0.3, 0.3, 0.4}}, turned), Outcome::kRejectedGeometry);
  ASSERT_FALSE(m.log_metric.empty());  // the trial started the logs
  EXPECT_EQ(m.metric[3], SymMat3::identity());
  for (std::size_t x = 0; x < m.log_metric.size(); ++x)
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(m.log_metric[x].c[k], log_spd(m.metric[x]).c[k], 1e-15);
  m.set_metric(0, turned);
  EXPECT_EQ(move_vertex(m, 3, Vec3{{0.3, 0.3, 0.4}}, 2.0 * turned), Outcome::kRejectedGeometry);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(m.log_metric[3].c[k], 0.0);
}
