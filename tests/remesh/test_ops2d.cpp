// The 2D operators on small meshes of the unit square: each keeps the mesh valid (adjacency,
// feature data, positive areas), the domain's area and its boundary, and refuses what it must.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "metric/metric.hpp"
#include "remesh/ops2d.hpp"
#include "remesh/square_tri_mesh.hpp"

using namespace riemesh;
using riemesh::test_support::square_tri_mesh;
using riemesh::test_support::total_area;

namespace {

/// The first live edge slot joining a and b.
Id slot_of(const TriMesh& m, Id a, Id b) {
  for (std::size_t s = 0; s < m.tadj.size(); ++s)
    if (m.tri_alive(static_cast<Id>(s / 3)) && m.edge_from(static_cast<Id>(s)) == a &&
        m.edge_to(static_cast<Id>(s)) == b)
      return static_cast<Id>(s);
  return kNoId;
}

}  // namespace

TEST(TriMesh, BuildsFromUnitSquare) {
  const TriMesh m = square_tri_mesh(4, SymMat2::identity());
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_EQ(m.num_live_triangles(), 32u);
  EXPECT_EQ(m.num_live_vertices(), 25u);
  EXPECT_NEAR(total_area(m), 1.0, 1e-15);
  // Vertex 0 is the corner (0,0): two triangles around... its ball is open.
  Ball b;
  collect_ball(m, 6, b);  // interior vertex (1,1) of a 4x4 grid: 6 triangles
  EXPECT_TRUE(b.closed);
  EXPECT_EQ(b.tris.size(), 6u);
  collect_ball(m, 2, b);  // bottom side vertex (2,0): 3 triangles
  EXPECT_FALSE(b.closed);
  EXPECT_EQ(b.tris.size(), 3u);
}

TEST(TriMesh, RoundTripToMesh) {
  const TriMesh m = square_tri_mesh(3, SymMat2::identity());
  std::vector<SymMat2> met;
  const Mesh out = to_mesh(m, &met);
  EXPECT_EQ(out.num_vertices(), 16u);
  EXPECT_EQ(out.num_triangles(), 18u);
  EXPECT_EQ(out.num_edges(), 12u);
  EXPECT_EQ(met.size(), 16u);
  int corners = 0;
  for (auto t : out.vert_tag) corners += (t & kTagCorner) ? 1 : 0;
  EXPECT_EQ(corners, 4);
}

TEST(Split, InteriorEdgeAddsTwoTriangles) {
  TriMesh m = square_tri_mesh(2, SymMat2::identity());
  // Vertex 4 is the centre (0.5, 0.5); vertex 5 is (1, 0.5). Split edge 4 -> 5 in the middle.
  Id s = slot_of(m, 4, 5);
  if (s == kNoId) s = slot_of(m, 5, 4);
  ASSERT_NE(s, kNoId);
  Id n = kNoId;
  ASSERT_EQ(split_edge(m, s, {Vec2{{0.75, 0.5}}, SymMat2::identity()}, 0.0, &n),
            Outcome::kApplied);
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_EQ(m.num_live_triangles(), 10u);
  EXPECT_NEAR(total_area(m), 1.0, 1e-15);
  EXPECT_FALSE(m.on_curve(n));
}

TEST(Split, BoundaryEdgeCreatesCurveVertex) {
  TriMesh m = square_tri_mesh(2, SymMat2::identity());
  const Id s = slot_of(m, 0, 1);  // bottom side, (0,0) -> (0.5,0)
  ASSERT_NE(s, kNoId);
  Id n = kNoId;
  ASSERT_EQ(split_edge(m, s, {Vec2{{0.25, 0.0}}, SymMat2::identity(), 0, 0.25}, 0.0, &n),
            Outcome::kApplied);
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_EQ(m.num_live_triangles(), 9u);
  EXPECT_TRUE(m.on_curve(n));
  EXPECT_EQ(m.vparam[n], 0.25);
  EXPECT_EQ(to_mesh(m).num_edges(), 9u);  // 8 boundary edges + 1
}

TEST(Split, RejectsPointThatInvertsATriangle) {
  TriMesh m = square_tri_mesh(2, SymMat2::identity());
  const Id s = slot_of(m, 0, 1);
  Id n = kNoId;
  // Far below the bottom side: the triangle above it would turn over... no: it stays valid.
  // Far above the edge (y = 0.6) crosses the opposite vertex: geometry rejection.
  EXPECT_EQ(split_edge(m, s, {Vec2{{0.25, 0.6}}, SymMat2::identity(), 0, 0.25}, 0.0, &n),
            Outcome::kRejectedGeometry);
  EXPECT_EQ(check_tri_mesh(m), "");
}

TEST(Collapse, InteriorVertexIntoNeighbour) {
  TriMesh m = square_tri_mesh(4, SymMat2::identity());
  // Vertex 6 = (0.25, 0.25) interior; collapse it into 7 = (0.5, 0.25).
  Id s = slot_of(m, 6, 7);
  if (s == kNoId) s = slot_of(m, 7, 6);
  ASSERT_NE(s, kNoId);
  ASSERT_EQ(collapse_edge(m, s, 6, 7, {0.0, 100.0}), Outcome::kApplied);
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_EQ(m.num_live_triangles(), 30u);
  EXPECT_EQ(m.num_live_vertices(), 24u);
  EXPECT_NEAR(total_area(m), 1.0, 1e-15);
}

TEST(Collapse, CornerNeverGoes) {
  TriMesh m = square_tri_mesh(4, SymMat2::identity());
  const Id s = slot_of(m, 0, 1);
  EXPECT_EQ(collapse_edge(m, s, 0, 1, {0.0, 100.0}), Outcome::kRejectedTopology);
}

TEST(Collapse, BoundaryVertexOnlyAlongItsCurve) {
  TriMesh m = square_tri_mesh(4, SymMat2::identity());
  // Vertex 2 = (0.5, 0) on the bottom side. Inward (to 7 = (0.5, 0.25)): refused.
  Id in = slot_of(m, 2, 7);
  if (in == kNoId) in = slot_of(m, 7, 2);
  ASSERT_NE(in, kNoId);
  EXPECT_EQ(collapse_edge(m, in, 2, 7, {0.0, 100.0}), Outcome::kRejectedTopology);
  // Along the side (to 1 = (0.25, 0)): accepted, the boundary keeps its ref.
  const Id along = slot_of(m, 1, 2);
  ASSERT_NE(along, kNoId);
  ASSERT_EQ(collapse_edge(m, along, 2, 1, {0.0, 100.0}), Outcome::kApplied);
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_NEAR(total_area(m), 1.0, 1e-15);
  const Mesh out = to_mesh(m);
  EXPECT_EQ(out.num_edges(), 15u);
  for (auto r : out.edge_ref) EXPECT_TRUE(r >= 1 && r <= 4);
}

TEST(Collapse, RespectsQualityAndLengthLimits) {
  TriMesh m = square_tri_mesh(4, SymMat2::identity());
  Id s = slot_of(m, 6, 7);
  if (s == kNoId) s = slot_of(m, 7, 6);
  // New edges would be longer than 0.3 (the grid spacing is 0.25, diagonals 0.354).
  EXPECT_EQ(collapse_edge(m, s, 6, 7, {0.0, 0.3}), Outcome::kRejectedQuality);
  EXPECT_EQ(check_tri_mesh(m), "");
}

TEST(Swap, FlipsWhenTheMetricPrefersTheOtherDiagonal) {
  // One cell split along (0,0)-(1,1). In a metric with size 0.2 along (1,1) and 1 across, that
  // diagonal has length 5√2 and the other one √2: the other diagonal gives better triangles.
  const double c = std::sqrt(0.5);
  const SymMat2 m_aniso = compose(Mat2{{{c, -c}, {c, c}}}, Vec2{{25.0, 1.0}});
  TriMesh m = square_tri_mesh(1, m_aniso);
  Id s = slot_of(m, 0, 3);
  if (s == kNoId) s = slot_of(m, 3, 0);
  ASSERT_NE(s, kNoId);
  EXPECT_EQ(swap_edge(m, s, 0.01), Outcome::kApplied);
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_NEAR(total_area(m), 1.0, 1e-15);
  // Flipping back makes it worse: refused.
  Id s2 = slot_of(m, 1, 2);
  if (s2 == kNoId) s2 = slot_of(m, 2, 1);
  ASSERT_NE(s2, kNoId);
  EXPECT_EQ(swap_edge(m, s2, 0.01), Outcome::kRejectedQuality);
}

TEST(Swap, NeverFlipsAFeatureEdge) {
  TriMesh m = square_tri_mesh(2, SymMat2::identity());
  EXPECT_EQ(swap_edge(m, slot_of(m, 0, 1), 0.0), Outcome::kRejectedTopology);
}

TEST(Move, KeepsValidityAndQuality) {
  TriMesh m = square_tri_mesh(2, SymMat2::identity());
  // The centre moves a little: fine; across its neighbours: refused.
  EXPECT_EQ(move_vertex(m, 4, Vec2{{0.52, 0.5}}, SymMat2::identity(), 0.0, 0.0),
            Outcome::kApplied);
  EXPECT_EQ(move_vertex(m, 4, Vec2{{1.5, 0.5}}, SymMat2::identity(), 0.0, 0.0),
            Outcome::kRejectedGeometry);
  EXPECT_EQ(move_vertex(m, 0, Vec2{{0.1, 0.0}}, SymMat2::identity(), 0.0, 0.0),
            Outcome::kRejectedTopology);
  EXPECT_EQ(check_tri_mesh(m), "");
}

TEST(Split, LongestFirstSweepsRefineUniformly) {
  // Splitting the edges longer than √2 at their midpoints, longest first, sweep after sweep, in a
  // uniform metric of size 0.1 on one cell: all edges end in [√2/2 · 1/2, √2], none degenerate.
  TriMesh m = square_tri_mesh(1, isotropic_metric<2>(0.1));
  auto len = [&m](Id a, Id b) {
    return edge_length_geometric(m.metric[a], m.metric[b], m.xy[b] - m.xy[a]);
  };
  for (int sweep = 0; sweep < 12; ++sweep) {
    std::vector<std::tuple<double, Id, Id>> list;
    for (std::size_t s = 0; s < m.tadj.size(); ++s) {
      const Id si = static_cast<Id>(s);
      if (!m.tri_alive(si / 3) || (m.tadj[si] != kNoId && m.tadj[si] < si)) continue;
      const Id a = m.edge_from(si), b = m.edge_to(si);
      if (len(a, b) > std::sqrt(2.0)) list.emplace_back(-len(a, b), a, b);
    }
    std::sort(list.begin(), list.end());
    for (const auto& [l, a, b] : list) {
      const Id si = find_edge_slot(m, a, b);
      ASSERT_NE(si, kNoId);
      NewVertex nv{0.5 * (m.xy[a] + m.xy[b]), m.metric[a]};
      if (m.is_feature(si)) nv.curve = m.ecurve[si];
      Id created;
      ASSERT_EQ(split_edge(m, si, nv, 0.0, &created), Outcome::kApplied);
    }
    ASSERT_EQ(check_tri_mesh(m), "") << "sweep " << sweep;
    if (list.empty()) break;
  }
  double lmin = 1e300, lmax = 0;
  for (std::size_t s = 0; s < m.tadj.size(); ++s) {
    if (!m.tri_alive(static_cast<Id>(s / 3))) continue;
    const double l = len(m.edge_from(static_cast<Id>(s)), m.edge_to(static_cast<Id>(s)));
    lmin = std::min(lmin, l), lmax = std::max(lmax, l);
  }
  EXPECT_LE(lmax, std::sqrt(2.0));
  EXPECT_GE(lmin, 0.3);
  EXPECT_NEAR(total_area(m), 1.0, 1e-13);
}
