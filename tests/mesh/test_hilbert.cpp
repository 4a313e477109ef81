// Hilbert keys (the curve's adjacency property) and renumbering (a permutation that keeps the
// mesh, its measures and validity, and improves locality).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <random>
#include <set>

#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/hilbert.hpp"

using namespace riemesh;

namespace {

/// Visits the 2^(k·dim) cells of a level-k grid in key order and checks that consecutive cells
/// share a face (Manhattan distance 1): the defining property of the Hilbert curve. A cell is
/// represented by its lower corner scaled to the full key resolution; since every aligned block
/// is one contiguous key range, sorting these gives the level-k curve.
void expect_face_adjacent_walk(int dim, int k) {
  const int b = hilbert_bits(dim), n = 1 << k;
  std::vector<std::pair<std::uint64_t, std::array<int, 3>>> cells;
  for (int z = 0; z < (dim == 3 ? n : 1); ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const std::uint32_t p[3] = {std::uint32_t(x) << (b - k), std::uint32_t(y) << (b - k),
                                    std::uint32_t(z) << (b - k)};
        cells.push_back({hilbert_key(p, dim), {x, y, z}});
      }
  std::sort(cells.begin(), cells.end());
  for (std::size_t i = 1; i < cells.size(); ++i) {
    EXPECT_NE(cells[i].first, cells[i - 1].first);
    int dist = 0;
    for (int c = 0; c < 3; ++c) dist += std::abs(cells[i].second[c] - cells[i - 1].second[c]);
    EXPECT_EQ(dist, 1) << "dim " << dim << " step " << i;
  }
  // The curve starts at the origin.
  EXPECT_EQ(cells.front().second, (std::array<int, 3>{0, 0, 0}));
}

double mean_edge_span(const Mesh& m) {
  const Adjacency adj = build_adjacency(m);
  double sum = 0.0;
  for (std::size_t e = 0; e < adj.num_edges(); ++e)
    sum += std::abs(adj.edges[2 * e + 1] - adj.edges[2 * e]);
  return sum / static_cast<double>(adj.num_edges());
}

double total_volume(const Mesh& m) {
  double vol = 0.0;
  auto p = [&m](Id v) { return Vec3{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}}; };
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const Id* v = &m.tets[4 * t];
    vol += dot(p(v[1]) - p(v[0]), cross(p(v[2]) - p(v[0]), p(v[3]) - p(v[0]))) / 6.0;
  }
  return vol;
}

bool is_permutation_of_iota(std::vector<Id> v) {
  std::sort(v.begin(), v.end());
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] != static_cast<Id>(i)) return false;
  return true;
}

/// A random relabelling of the vertices and a shuffle of the elements of m.
Mesh shuffled(Mesh m, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Id> perm(m.num_vertices());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), rng);
  permute_vertices(m, perm);
  return m;
}

}  // namespace

TEST(Hilbert, ConsecutiveCellsShareAFace2D) { expect_face_adjacent_walk(2, 4); }
TEST(Hilbert, ConsecutiveCellsShareAFace3D) { expect_face_adjacent_walk(3, 3); }

TEST(Hilbert, KeysAreDistinctAtFullResolutionAndFitTheBits) {
  // Points near the top corner of the grid: distinct points, distinct keys below 2^(d·b).
  for (int dim : {2, 3}) {
    const std::uint32_t top = (std::uint32_t{1} << hilbert_bits(dim)) - 1;
    std::set<std::uint64_t> keys;
    for (std::uint32_t x = top - 3; x <= top; ++x)
      for (std::uint32_t y = top - 3; y <= top; ++y)
        for (std::uint32_t z = 0; z < 4; ++z) {
          const std::uint32_t p[3] = {x, y, z};
          const std::uint64_t key = hilbert_key(p, dim);
          EXPECT_LT(key, std::uint64_t{1} << (dim * hilbert_bits(dim)));
          keys.insert(key);
        }
    EXPECT_EQ(keys.size(), dim == 3 ? 64u : 16u);
  }
}

TEST(Hilbert, OrderIsAStablePermutation) {
  // Duplicate points keep their input order; a degenerate (single point) box does not crash.
  const std::vector<double> pts = {0.5, 0.5, 0.0, 0.0, 0.5, 0.5, 1.0, 0.0};
  const std::vector<Id> order = hilbert_order(pts, 2);
  EXPECT_TRUE(is_permutation_of_iota(order));
  EXPECT_LT(std::find(order.begin(), order.end(), 0) - order.begin(),
            std::find(order.begin(), order.end(), 2) - order.begin());
  EXPECT_EQ(order.front(), 1);  // (0, 0) is the start of the curve
  EXPECT_EQ(hilbert_order({1.0, 2.0, 3.0, 1.0, 2.0, 3.0}, 3), (std::vector<Id>{0, 1}));
}

TEST(Hilbert, LargeInputsAreSortedStably) {
  // The radix sort path (>= 4096 keys): keys non-decreasing, ties in input order.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> pts(3 * 10000);
  for (double& x : pts) x = u(rng);
  const std::vector<Id> order = hilbert_order(pts, 3);
  ASSERT_TRUE(is_permutation_of_iota(order));
  const std::vector<std::uint64_t> keys = hilbert_keys(pts, 3);
  for (std::size_t i = 1; i < order.size(); ++i) {
    ASSERT_LE(keys[order[i - 1]], keys[order[i]]);
    if (keys[order[i - 1]] == keys[order[i]]) {
      EXPECT_LT(order[i - 1], order[i]);
    }
  }
}

TEST(Hilbert, CoarseOrderIsAStablePermutationAlongTheCurve) {
  // 2^16 cells per side: points closer than a cell keep their input order; on a grid of 256 x 256
  // points (cells far apart) consecutive points are neighbours, as on the full-resolution curve.
  std::vector<double> pts;
  for (int i = 0; i < 256; ++i)
    for (int j = 0; j < 256; ++j) pts.insert(pts.end(), {i / 255.0, j / 255.0});
  pts.insert(pts.end(), {0.5 + 1e-9, 0.5, 0.5, 0.5 + 1e-9});  // one cell, ids 65536 then 65537
  const std::vector<Id> order = hilbert_order_coarse(pts, 2);
  ASSERT_TRUE(is_permutation_of_iota(order));
  EXPECT_LT(std::find(order.begin(), order.end(), 65536) - order.begin(),
            std::find(order.begin(), order.end(), 65537) - order.begin());
  int far = 0;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const double dx = pts[2 * order[k]] - pts[2 * order[k - 1]];
    const double dy = pts[2 * order[k] + 1] - pts[2 * order[k - 1] + 1];
    far += std::hypot(dx, dy) > 1.5 / 255.0;
  }
  EXPECT_LE(far, 4);  // (the two extra points' visit)
  EXPECT_EQ(hilbert_order_coarse(std::vector<double>{1.0, 2.0, 3.0, 1.0, 2.0, 3.0}, 3),
            (std::vector<Id>{0, 1}));
}

TEST(Hilbert, RenumberCubeKeepsTheMeshAndImprovesLocality) {
  const Mesh original = shuffled(unit_cube(6), 1);
  Mesh m = original;
  const Renumbering r = renumber_hilbert(m);
  EXPECT_TRUE(is_permutation_of_iota(r.vertices));
  EXPECT_TRUE(is_permutation_of_iota(r.tets));
  EXPECT_TRUE(is_permutation_of_iota(r.triangles));
  EXPECT_TRUE(is_permutation_of_iota(r.edges));
  EXPECT_NEAR(total_volume(m), 1.0, 1e-12);
  EXPECT_TRUE(check_mesh(m).valid());
  // Everything followed: vertex new i is old r.vertices[i]; tet new t is old r.tets[t].
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    for (int c = 0; c < 3; ++c)
      ASSERT_EQ(m.coords[3 * v + c], original.coords[3 * r.vertices[v] + c]);
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int i = 0; i < 4; ++i)
      ASSERT_EQ(r.vertices[m.tets[4 * t + i]], original.tets[4 * r.tets[t] + i]);
  for (std::size_t f = 0; f < m.num_triangles(); ++f) {
    ASSERT_EQ(m.tri_ref[f], original.tri_ref[r.triangles[f]]);
    for (int i = 0; i < 3; ++i)
      ASSERT_EQ(r.vertices[m.triangles[3 * f + i]], original.triangles[3 * r.triangles[f] + i]);
  }
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    ASSERT_EQ(m.edge_ref[e], original.edge_ref[r.edges[e]]);
    ASSERT_EQ(m.edge_tag[e], original.edge_tag[r.edges[e]]);
  }
  // Locality: the mean id span of the edges falls well below that of the random labelling
  // (about nv/3 = 114 for random labels of 343 vertices; 31 after, about the lexicographic
  // grid order's 33 on such a small grid).
  const double before = mean_edge_span(original), after = mean_edge_span(m);
  EXPECT_LT(after, 0.3 * before) << before << " -> " << after;
  // Deterministic: renumbering again from the same input gives the same mesh.
  Mesh again = original;
  renumber_hilbert(again);
  EXPECT_EQ(again.tets, m.tets);
  EXPECT_EQ(again.coords, m.coords);
}

TEST(Hilbert, RenumberPlanarMeshMovesFieldsAndTags) {
  Mesh m = shuffled(unit_square(9, 7), 3);
  m.fields.push_back({"x", FieldKind::kScalar, {}});
  for (std::size_t v = 0; v < m.num_vertices(); ++v) m.fields[0].values.push_back(m.coords[2 * v]);
  const double before = mean_edge_span(m);
  renumber_hilbert(m);
  EXPECT_TRUE(check_mesh(m).valid());
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    EXPECT_EQ(m.fields[0].values[v], m.coords[2 * v]);
  int corners = 0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    if (m.vert_tag[v] & kTagCorner) {
      ++corners;
      const double x = m.coords[2 * v], y = m.coords[2 * v + 1];
      EXPECT_TRUE((x == 0.0 || x == 1.0) && (y == 0.0 || y == 1.0));
    }
  EXPECT_EQ(corners, 4);
  EXPECT_LT(mean_edge_span(m), 0.5 * before);
}
