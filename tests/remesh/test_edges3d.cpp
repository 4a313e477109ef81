// The edge enumeration and the neighbour table of the 3D driver (edges3d.hpp), and the length
// tests that let the collapse sweeps skip ball walks: each must decide as the code it stands for.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <utility>

#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/edges3d.hpp"

using namespace riemesh;

namespace {

TetMesh cube_tet_mesh(int n, double h) {
  const Mesh cube = unit_cube(n);
  return build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(h)));
}

/// Every edge (a < b) with the lowest live tet holding it, by brute force.
std::map<std::pair<Id, Id>, Id> edges_by_brute_force(const TetMesh& m) {
  std::map<std::pair<Id, Id>, Id> out;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
    if (!m.tet_alive(static_cast<Id>(t))) continue;
    for (const auto& [i, j] : kTetEdge) {
      const Id a = m.tv[4 * t + i], b = m.tv[4 * t + j];
      out.try_emplace({std::min(a, b), std::max(a, b)}, static_cast<Id>(t));
    }
  }
  return out;
}

NeighbourTable table_of(TetMesh& m) {
  std::vector<Id> upper;
  std::vector<std::uint32_t> count(m.vertex_capacity(), 0);
  for_each_edge(m, [&](Id a, Id b, Id) { upper.push_back(b), ++count[a]; });
  NeighbourTable nbrs;
  nbrs.build(m, upper, count);
  return nbrs;
}

std::vector<Id> ball_vertices(const TetMesh& m, Id v) {
  std::vector<Id> ball, out;
  collect_ball(m, v, ball);
  for (const Id t : ball)
    for (int i = 0; i < 4; ++i)
      if (m.tv[4 * t + i] != v) out.push_back(m.tv[4 * t + i]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

TEST(Edges3d, EachEdgeOnceInOrderWithItsLowestTet) {
  TetMesh m = cube_tet_mesh(3, 0.3);
  // A collapse frees tets, so that the lowest tet is not always the first one listed.
  m.vkind.assign(m.vertex_capacity(), VertexKind::kInterior);
  ASSERT_EQ(collapse_edge(m, 21, 22, {0.0, 100.0}), Outcome::kApplied);
  const auto expected = edges_by_brute_force(m);
  std::vector<std::pair<std::pair<Id, Id>, Id>> got;
  for_each_edge(m, [&](Id a, Id b, Id t) { got.push_back({{a, b}, t}); });
  ASSERT_EQ(got.size(), expected.size());
  std::size_t k = 0;
  for (const auto& [edge, tet] : expected) {
    EXPECT_EQ(got[k].first, edge);
    EXPECT_EQ(got[k].second, tet);
    ++k;
  }
}

TEST(Edges3d, NeighbourTableHoldsTheBallsAndKnowsWhatCavitiesTouched) {
  TetMesh m = cube_tet_mesh(2, 0.5);
  const NeighbourTable nbrs = table_of(m);
  for (Id v = 0; v < static_cast<Id>(m.vertex_capacity()); ++v) {
    ASSERT_TRUE(nbrs.known(m, v));
    const auto of = nbrs.of(v);
    EXPECT_EQ(std::vector<Id>(of.begin(), of.end()), ball_vertices(m, v));  // sorted
  }
  // The centre into its neighbour 12: its ball's vertices are touched, the others still exact.
  const std::vector<Id> touched = ball_vertices(m, 13);
  m.vkind.assign(m.vertex_capacity(), VertexKind::kFixed);
  m.vkind[13] = VertexKind::kInterior;
  ASSERT_EQ(collapse_edge(m, 13, 12, {0.0, 100.0}), Outcome::kApplied);
  for (Id v = 0; v < static_cast<Id>(m.vertex_capacity()); ++v) {
    const bool in_ball = v == 13 || std::count(touched.begin(), touched.end(), v) > 0;
    EXPECT_EQ(nbrs.known(m, v), !in_ball) << v;
    if (!in_ball && m.vert_alive(v)) {
      const auto of = nbrs.of(v);
      EXPECT_EQ(std::vector<Id>(of.begin(), of.end()), ball_vertices(m, v));
    }
  }
}

TEST(Edges3d, EdgeLongerThanDecidesAsTheExactLength) {
  // Anisotropic vertex metrics and edges whose lengths straddle the limit.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.5, 2.0);
  TetMesh m = cube_tet_mesh(1, 1.0);
  int decided_each_way[2] = {0, 0};
  for (int k = 0; k < 2000; ++k) {
    for (const Id v : {0, 1}) {
      m.set_metric(v, SymMat3{{1.0 / (size(rng) * size(rng)), 0.01 * u(rng),
                               1.0 / (size(rng) * size(rng)), 0.01 * u(rng), 0.01 * u(rng),
                               1.0 / (size(rng) * size(rng))}});
      m.xyz[v] = Vec3{{u(rng), u(rng), u(rng)}};
    }
    const double l = edge_length(m, 0, 1);
    for (const double limit : {l, std::nextafter(l, 0.0), std::nextafter(l, 10.0), 0.9 * l, 1.1 * l}) {
      EXPECT_EQ(edge_longer_than(m, 0, 1, limit), l > limit);
      ++decided_each_way[l > limit];
    }
  }
  EXPECT_GT(decided_each_way[0], 0);
  EXPECT_GT(decided_each_way[1], 0);
}

TEST(Edges3d, CollapseTooLongMeansCollapseEdgeRefuses) {
  // On a 3x3x3 cube with sizes 0.6 (edges 0.55-0.96), for every interior vertex and neighbour: when the table's
  // length test refuses, collapse_edge refuses; when it does not, collapse_edge decides as
  // without a length limit.
  const TetMesh base = cube_tet_mesh(3, 0.6);
  TetMesh probe = base;
  const NeighbourTable nbrs = table_of(probe);
  const CollapseLimits limits{0.0, 1.45};
  int refused = 0, passed = 0;
  for (Id v = 0; v < static_cast<Id>(base.vertex_capacity()); ++v) {
    for (const Id to : nbrs.of(v)) {
      TetMesh a = base, b = base;
      a.vkind.assign(a.vertex_capacity(), VertexKind::kInterior);
      b.vkind = a.vkind;
      const bool too_long = collapse_too_long(a, nbrs.of(v), to, limits);
      const Outcome with = collapse_edge(a, v, to, limits);
      if (too_long) {
        EXPECT_NE(with, Outcome::kApplied);
        ++refused;
      } else {
        EXPECT_EQ(with, collapse_edge(b, v, to, {limits.min_quality, 1e9}));
        ++passed;
      }
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_GT(passed, 0);
}
