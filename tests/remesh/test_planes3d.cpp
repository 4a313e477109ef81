#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include "curved_test_meshes.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/planar_pieces3d.hpp"
#include "remesh/plane_fit.hpp"

namespace riemesh {
namespace {

TetMesh tet_mesh(const Mesh& m) {
  return build_tet_mesh(m, std::vector<SymMat3>(m.num_vertices(), SymMat3::identity()));
}

/// Per face ref of m: the planes (rounded normal and offset) its faces lie on.
std::map<std::int32_t, std::set<std::array<long, 4>>> planes_by_ref(const TetMesh& m) {
  std::map<std::int32_t, std::set<std::array<long, 4>>> out;
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    if (!m.fbdy[s] || !m.tet_alive(static_cast<Id>(s / 4))) continue;
    const Id* v = &m.tv[4 * (s / 4)];
    const int i = static_cast<int>(s % 4);
    const Vec3 &a = m.xyz[v[kTetFace[i][0]]], &b = m.xyz[v[kTetFace[i][1]]],
               &c = m.xyz[v[kTetFace[i][2]]];
    Vec3 n = normalize(cross(b - a, c - a));
    if (m.tadj[s] != kNoId && (n[0] < 0 || (n[0] == 0 && (n[1] < 0 || (n[1] == 0 && n[2] < 0)))))
      n = -1.0 * n;  // an interface face: either side
    out[m.face_ref(s)].insert({std::lround(1e6 * n[0]), std::lround(1e6 * n[1]),
                               std::lround(1e6 * n[2]), std::lround(1e6 * dot(n, a))});
  }
  return out;
}

}  // namespace

// A cube whose six faces have one ref (a "wall" group): six planar pieces meeting at right
// angles, the first keeping ref 1, the others fresh refs 2..6 (above every face ref); each
// piece on one plane; restored, every face has ref 1 again.
TEST(PlanarPieces3d, OneRefOnSixPlanesIsSplit) {
  Mesh cube = unit_cube(3);
  std::fill(cube.tri_ref.begin(), cube.tri_ref.end(), 1);
  TetMesh m = tet_mesh(cube);
  const std::map<std::int32_t, std::int32_t> pieces = split_planar_pieces(m, 45.0, std::sqrt(3.0));
  ASSERT_EQ(pieces.size(), 5u);
  for (const auto& [piece, given] : pieces) {
    EXPECT_EQ(given, 1);
    EXPECT_GE(piece, 2);
    EXPECT_LE(piece, 6);
  }
  const auto planes = planes_by_ref(m);
  ASSERT_EQ(planes.size(), 6u);
  for (const auto& [ref, p] : planes) EXPECT_EQ(p.size(), 1u) << "ref " << ref;
  restore_piece_refs(m, pieces);
  const auto restored = planes_by_ref(m);
  ASSERT_EQ(restored.size(), 1u);
  EXPECT_EQ(restored.begin()->first, 1);
  EXPECT_EQ(restored.begin()->second.size(), 6u);
  // A ref at INT32_MAX: the fresh refs are taken below every ref (there were none above it, and
  // the ref was left whole).
  constexpr std::int32_t kTop = std::numeric_limits<std::int32_t>::max();
  std::fill(cube.tri_ref.begin(), cube.tri_ref.end(), kTop);
  TetMesh top = tet_mesh(cube);
  const auto top_pieces = split_planar_pieces(top, 45.0, std::sqrt(3.0));
  ASSERT_EQ(top_pieces.size(), 5u);
  for (const auto& [piece, given] : top_pieces) {
    EXPECT_EQ(given, kTop);
    EXPECT_LT(piece, kTop);
  }
  EXPECT_EQ(planes_by_ref(top).size(), 6u);
}

// The same cube with a shallow roof (its top rises to 0.1 at x = 0.5, turning by 11.4 degrees
// there): the ref is a curved patch for the default 45 degrees (a faceted curved surface turns
// by a few degrees from facet to facet) and left alone; for 5 degrees the roof's ridge is sharp
// and the ref splits into seven planes.
TEST(PlanarPieces3d, SmoothEdgesKeepARefWhole) {
  Mesh cube = unit_cube(4);
  std::fill(cube.tri_ref.begin(), cube.tri_ref.end(), 1);
  for (std::size_t v = 0; v < cube.num_vertices(); ++v)
    if (cube.coords[3 * v + 2] == 1.0)
      cube.coords[3 * v + 2] += 0.2 * std::min(cube.coords[3 * v], 1.0 - cube.coords[3 * v]);
  TetMesh m = tet_mesh(cube);
  EXPECT_TRUE(split_planar_pieces(m, 45.0, std::sqrt(3.0)).empty());
  EXPECT_EQ(planes_by_ref(m).size(), 1u);
  EXPECT_EQ(split_planar_pieces(m, 5.0, std::sqrt(3.0)).size(), 6u);
  EXPECT_EQ(planes_by_ref(m).size(), 7u);
}

// An L-shaped interface (the faces between the tets with x < 0.5 and y < 0.5 and the others,
// one ref): two planes at right angles, two pieces; the face seen from both sides gets the
// piece's ref on both.
TEST(PlanarPieces3d, LShapedInterfaceIsSplit) {
  const Mesh cube = test::with_regions(
      unit_cube(4), [](const Vec3& c) { return c[0] < 0.5 && c[1] < 0.5 ? 2 : 1; });
  TetMesh m = tet_mesh(cube);
  const auto pieces = split_planar_pieces(m, 45.0, std::sqrt(3.0));
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces.begin()->second, 12);
  const auto planes = planes_by_ref(m);
  EXPECT_EQ(planes.at(12).size(), 1u);
  EXPECT_EQ(planes.at(pieces.begin()->first).size(), 1u);
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    if (m.fbdy[s] && m.tadj[s] != kNoId) {
      EXPECT_EQ(m.face_ref(s), m.face_ref(static_cast<std::size_t>(m.tadj[s])));
    }
  }
}

// The plane fitted to faces of either orientation: exact on a plane, a vertex off it measured,
// faces turning by 1 degree not aligned.
TEST(PlaneFit, FitsFacesOfEitherOrientation) {
  const Vec3 a{{0, 0, 0.3}}, b{{1, 0, 0.3}}, c{{1, 1, 0.3}}, d{{0, 1, 0.3}};
  const std::vector<Tri3> square = {Tri3{a, b, c}, Tri3{a, d, c}};  // the second turned
  PlaneFit f = fit_plane(square);
  EXPECT_TRUE(f.aligned);
  EXPECT_DOUBLE_EQ(std::abs(f.n[2]), 1.0);
  EXPECT_DOUBLE_EQ(f.d * f.n[2], 0.3);
  EXPECT_LT(f.deviation, 1e-15);
  EXPECT_TRUE(is_planar(f, 1.0));
  const Vec3 up{{0, 1, 0.3 + 4e-6}};  // d lifted: off the fitted plane by about 2e-6
  f = fit_plane(std::vector<Tri3>{Tri3{a, b, c}, Tri3{a, c, up}});
  EXPECT_TRUE(f.aligned);
  EXPECT_GT(f.deviation, 1e-6);
  EXPECT_LT(f.deviation, 4e-6);
  EXPECT_FALSE(is_planar(f, 1.0));
  EXPECT_TRUE(is_planar(f, 10.0));
  const Vec3 bent{{0, 1, 0.3 + std::tan(M_PI / 180)}};
  EXPECT_FALSE(fit_plane(std::vector<Tri3>{Tri3{a, b, c}, Tri3{a, c, bent}}).aligned);
}

}  // namespace riemesh
