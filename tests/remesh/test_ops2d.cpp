// The 2D operators on small meshes of the unit square: each keeps the mesh valid (adjacency,
// feature data, positive areas), the domain's area and its boundary, and refuses what it must.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <tuple>

#include "mesh/hilbert.hpp"
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

// Renumbering the vertices created by splits (and the triangles) keeps the mesh: the same
// triangles by their corners, valid adjacency and feature data, the head's ids in place, the
// dead slots dropped, the tail in Hilbert order and the triangles by their smallest vertex.
TEST(TriMesh, RenumberTailKeepsTheMesh) {
  TriMesh m = square_tri_mesh(3, isotropic_metric<2>(0.05));
  const Id head = static_cast<Id>(m.vertex_capacity());  // 16
  // Each live triangle as its corners' coordinates, from the lexicographically smallest corner
  // (counter-clockwise order kept), sorted: equal for the same triangles under any numbering.
  auto corners = [](const TriMesh& x) {
    std::vector<std::array<double, 6>> out;
    for (std::size_t t = 0; t < x.triangle_capacity(); ++t) {
      if (!x.tri_alive(static_cast<Id>(t))) continue;
      std::array<double, 6> best{};
      for (int r = 0; r < 3; ++r) {
        std::array<double, 6> c;
        for (int i = 0; i < 3; ++i) {
          const Vec2& p = x.xy[x.tv[3 * t + (r + i) % 3]];
          c[2 * i] = p[0], c[2 * i + 1] = p[1];
        }
        if (r == 0 || c < best) best = c;
      }
      out.push_back(best);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  // Three split sweeps, then a collapse: new vertices at the end, dead slots in the tail.
  for (int sweep = 0; sweep < 3; ++sweep) {
    const std::size_t n = m.tadj.size();
    for (std::size_t s = 0; s < n; s += 2) {
      const Id si = static_cast<Id>(s);
      if (!m.tri_alive(si / 3)) continue;
      const Id a = m.edge_from(si), b = m.edge_to(si);
      NewVertex nv{0.5 * (m.xy[a] + m.xy[b]), m.metric[a]};
      if (m.is_feature(si)) nv.curve = m.ecurve[si];
      Id created;
      split_edge(m, si, nv, 0.0, &created);
    }
  }
  // The last interior vertex that collapses into a neighbour.
  const CollapseLimits loose{0.0, 10.0};
  Id gone = kNoId;
  for (Id v = static_cast<Id>(m.vertex_capacity()) - 1; v >= head && gone == kNoId; --v) {
    if (m.on_curve(v)) continue;
    Ball ball;
    collect_ball(m, v, ball);
    for (const Id t : ball.tris) {
      const Id to = m.tv[3 * t + (vertex_index(m, t, v) + 1) % 3];
      if (collapse_edge(m, find_edge_slot(m, v, to), v, to, loose) == Outcome::kApplied) {
        gone = v;
        break;
      }
    }
  }
  ASSERT_NE(gone, kNoId);
  ASSERT_EQ(check_tri_mesh(m), "");
  ASSERT_FALSE(m.free_verts.empty());
  const TriMesh before = m;

  const std::vector<Id> old2new = renumber_tail(m, head);
  EXPECT_EQ(check_tri_mesh(m), "");
  EXPECT_EQ(corners(m), corners(before));
  EXPECT_EQ(m.num_live_vertices(), before.num_live_vertices());
  EXPECT_EQ(m.vertex_capacity(), before.num_live_vertices());  // no dead slot left in the tail
  EXPECT_TRUE(m.free_tris.empty());
  EXPECT_EQ(old2new[gone], kNoId);
  for (Id v = 0; v < head; ++v) EXPECT_EQ(old2new[v], v);
  for (std::size_t v = 0; v < old2new.size(); ++v) {
    if (old2new[v] == kNoId) continue;
    EXPECT_EQ(m.xy[old2new[v]], before.xy[v]);
    EXPECT_EQ(m.vcurve[old2new[v]], before.vcurve[v]);
    EXPECT_EQ(m.vparam[old2new[v]], before.vparam[v]);
    EXPECT_EQ(m.vtag[old2new[v]], before.vtag[v]);
  }
  std::vector<double> tail;
  for (std::size_t v = static_cast<std::size_t>(head); v < m.vertex_capacity(); ++v)
    tail.insert(tail.end(), {m.xy[v][0], m.xy[v][1]});
  const std::vector<Id> order = hilbert_order(tail, 2);
  for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], static_cast<Id>(i));
  for (std::size_t k = 1; k < m.triangle_capacity(); ++k) {
    const Id* p = &m.tv[3 * (k - 1)];
    const Id* q = &m.tv[3 * k];
    EXPECT_LE(*std::min_element(p, p + 3), *std::min_element(q, q + 3));
  }
  // Once ordered, a second renumbering changes nothing.
  const TriMesh once = m;
  const std::vector<Id> again = renumber_tail(m, head);
  for (std::size_t v = 0; v < again.size(); ++v) EXPECT_EQ(again[v], static_cast<Id>(v));
  EXPECT_EQ(m.tv, once.tv);
  EXPECT_EQ(m.tadj, once.tadj);
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
