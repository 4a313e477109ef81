// TetMesh: built from the unit cube and written back, balls and shells, and replace_cavity's
// face matching refusing fills that are not the cavity.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/ops3d.hpp"
#include "tet_test_util.hpp"

using namespace riemesh;
using riemesh::test::volume;
using riemesh::test::worst_quality;

namespace {

TetMesh cube_tet_mesh(int n) {
  const Mesh cube = unit_cube(n);
  return build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()));
}

}  // namespace

TEST(TetMesh, RoundTripsTheUnitCube) {
  const Mesh cube = unit_cube(3);
  const TetMesh m =
      build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()));
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 162u);
  EXPECT_EQ(m.num_live_vertices(), 64u);
  EXPECT_NEAR(volume(m), 1.0, 1e-14);
  const Mesh back = to_mesh(m, {});
  EXPECT_TRUE(check_mesh(back).valid());
  EXPECT_EQ(back.coords, cube.coords);
  EXPECT_EQ(back.tets, cube.tets);
  ASSERT_EQ(back.num_triangles(), cube.num_triangles());
  std::map<int, int> in, out;
  for (int r : cube.tri_ref) ++in[r];
  for (int r : back.tri_ref) ++out[r];
  EXPECT_EQ(in, out);
  // The 12 cube edges (faces of different refs meet) come back as ridge edges.
  EXPECT_EQ(back.num_edges(), 36u);
}

TEST(TetMesh, KeepsMoreDistinctFaceRefsThanItsOneByteTable) {
  // 300 boundary triangles, each its own ref: 254 in the table, the rest in the overflow map.
  Mesh cube = unit_cube(5);
  for (std::size_t f = 0; f < cube.num_triangles(); ++f) cube.tri_ref[f] = 1000 + static_cast<int>(f);
  TetMesh m = build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()));
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.ref_table.size(), 254u);
  EXPECT_EQ(m.ref_overflow.size(), 300u - 254u);
  auto refs_of = [](const Mesh& mesh) {
    std::map<std::array<Id, 3>, int> out;
    for (std::size_t f = 0; f < mesh.num_triangles(); ++f) {
      std::array<Id, 3> k{mesh.triangles[3 * f], mesh.triangles[3 * f + 1], mesh.triangles[3 * f + 2]};
      std::sort(k.begin(), k.end());
      out[k] = mesh.tri_ref[f];
    }
    return out;
  };
  EXPECT_EQ(refs_of(to_mesh(m, {})), refs_of(cube));
  // Splitting every boundary edge of the mesh moves the refs (overflow ones too) to the halves.
  std::vector<std::pair<Id, Id>> edges;
  for (std::size_t f = 0; f < cube.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(cube.triangles[3 * f + k], cube.triangles[3 * f + (k + 1) % 3]);
  int splits = 0;
  for (const auto& [a, b] : edges) {
    if (find_edge_tet(m, a, b) == kNoId) continue;
    NewVertex3 nv;
    nv.p = 0.5 * (m.xyz[a] + m.xyz[b]);
    nv.metric = SymMat3::identity();
    Id x = kNoId;
    splits += split_edge(m, a, b, nv, 0.0, &x) == Outcome::kApplied;
  }
  EXPECT_GT(splits, 300);
  EXPECT_EQ(check_tet_mesh(m), "");
  const Mesh back = to_mesh(m, {});
  EXPECT_EQ(back.num_triangles(), 4 * cube.num_triangles());
  std::map<int, int> count;
  for (const int r : back.tri_ref) ++count[r];
  ASSERT_EQ(count.size(), 300u);
  for (const auto& [r, c] : count) EXPECT_EQ(c, 4) << r;
}

TEST(TetMesh, BallsAndShells) {
  const TetMesh m = cube_tet_mesh(2);
  std::vector<Id> ball, shell;
  collect_ball(m, 13, ball);  // the centre of the 2x2x2 Kuhn cube: in all 48 tets... of 8 cubes
  EXPECT_EQ(ball.size(), 24u);
  collect_ball(m, 0, ball);  // corner (0,0,0): on the Kuhn diagonal, in 6 tets of its cube
  EXPECT_EQ(ball.size(), 6u);
  collect_shell(m, 13, 0, shell);  // the diagonal from the centre to the corner
  EXPECT_EQ(shell.size(), 6u);
  collect_shell(m, 13, 26, shell);
  EXPECT_EQ(shell.size(), 6u);
  collect_shell(m, 0, 26, shell);  // not joined
  EXPECT_TRUE(shell.empty());
}

TEST(TetMesh, ReplaceCavityRefusesWrongFills) {
  TetMesh m = cube_tet_mesh(2);
  const Id t = 0;
  const Id* v = &m.tv[0];
  // The same tet reversed: every face has the wrong orientation.
  const NewTet reversed[1] = {{{v[1], v[0], v[2], v[3]}, 1}};
  const Id cavity[1] = {t};
  EXPECT_FALSE(replace_cavity(m, cavity, reversed, {}));
  // Two tets replaced by one of them: the other's faces stay uncovered.
  const Id two[2] = {0, m.tadj[0] / 4};
  const NewTet one[1] = {{{v[0], v[1], v[2], v[3]}, 1}};
  ASSERT_NE(m.tadj[0], kNoId);
  EXPECT_FALSE(replace_cavity(m, two, one, {}));
  // A degenerate tet (repeated vertex) is refused.
  const NewTet flat[1] = {{{v[0], v[0], v[2], v[3]}, 1}};
  EXPECT_FALSE(replace_cavity(m, cavity, flat, {}));
  EXPECT_EQ(check_tet_mesh(m), "");
  // The tet itself is a valid fill.
  const NewTet same[1] = {{{v[0], v[1], v[2], v[3]}, 1}};
  EXPECT_TRUE(replace_cavity(m, cavity, same, {}));
  EXPECT_EQ(check_tet_mesh(m), "");
  EXPECT_EQ(m.num_live_tets(), 48u);
}
