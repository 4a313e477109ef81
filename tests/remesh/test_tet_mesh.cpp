// TetMesh: built from the unit cube and written back, balls and shells, and replace_cavity's
// face matching refusing fills that are not the cavity.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>

#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/hilbert.hpp"
#include "metric/metric.hpp"
#include "remesh/background.hpp"
#include "remesh/ops3d.hpp"
#include "remesh/prepare_metrics.hpp"
#include "remesh/simplex_geometry.hpp"
#include "tet_test_util.hpp"

using namespace riemesh;
using riemesh::test::volume;
using riemesh::test::worst_quality;

namespace {

TetMesh cube_tet_mesh(int n) {
  const Mesh cube = unit_cube(n);
  return build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()));
}

/// Splits each edge (a, b) still in m at its midpoint (identity metric); the count applied.
int split_at_midpoints(TetMesh& m, const std::vector<std::pair<Id, Id>>& edges) {
  int splits = 0;
  for (const auto& [a, b] : edges) {
    if (find_edge_tet(m, a, b) == kNoId) continue;
    NewVertex3 nv;
    nv.p = 0.5 * (m.xyz[a] + m.xyz[b]);
    nv.metric = SymMat3::identity();
    Id x = kNoId;
    splits += split_edge(m, a, b, nv, 0.0, &x) == Outcome::kApplied;
  }
  return splits;
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
  const Mesh back = to_mesh(m);
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
  EXPECT_EQ(refs_of(to_mesh(m)), refs_of(cube));
  // Splitting every boundary edge of the mesh moves the refs (overflow ones too) to the halves.
  std::vector<std::pair<Id, Id>> edges;
  for (std::size_t f = 0; f < cube.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(cube.triangles[3 * f + k], cube.triangles[3 * f + (k + 1) % 3]);
  EXPECT_GT(split_at_midpoints(m, edges), 300);
  EXPECT_EQ(check_tet_mesh(m), "");
  const Mesh back = to_mesh(m);
  EXPECT_EQ(back.num_triangles(), 4 * cube.num_triangles());
  std::map<int, int> count;
  for (const int r : back.tri_ref) ++count[r];
  ASSERT_EQ(count.size(), 300u);
  for (const auto& [r, c] : count) EXPECT_EQ(c, 4) << r;
}

// Renumbering the vertices created by splits (and the tets) keeps the mesh: the same tets by
// their corners, the face refs (overflow ones too), the quality cache and the clocks by vertex;
// the head's ids in place, the dead slots dropped, the tail in Hilbert order, the tets by their
// smallest vertex.
// Two cubes sharing one edge (or one corner): the tets at the edge's vertices are not joined
// through faces, and adapt stopped on an internal check (an edge's shell came up empty). An
// input error now, naming the place.
TEST(TetMesh, SolidsTouchingAlongAnEdgeAreRefused) {
  for (const Vec3 shift : {Vec3{{1, 1, 0}}, Vec3{{1, 1, 1}}}) {
    const Mesh a = unit_cube(1);
    Mesh m = a;
    m.triangles.clear(), m.tri_ref.clear(), m.tri_tag.clear();
    m.edges.clear(), m.edge_ref.clear(), m.edge_tag.clear();
    std::map<std::array<double, 3>, Id> ids;
    for (std::size_t v = 0; v < a.num_vertices(); ++v)
      ids[{a.coords[3 * v], a.coords[3 * v + 1], a.coords[3 * v + 2]}] = static_cast<Id>(v);
    std::vector<Id> map(a.num_vertices());
    for (std::size_t v = 0; v < a.num_vertices(); ++v) {
      const std::array<double, 3> p = {a.coords[3 * v] + shift[0], a.coords[3 * v + 1] + shift[1],
                                       a.coords[3 * v + 2] + shift[2]};
      const auto it = ids.find(p);
      if (it != ids.end()) {
        map[v] = it->second;
        continue;
      }
      map[v] = static_cast<Id>(m.num_vertices());
      m.coords.insert(m.coords.end(), p.begin(), p.end());
      m.vert_ref.push_back(0);
      m.vert_tag.push_back(kTagNone);
    }
    for (std::size_t t = 0; t < a.num_tets(); ++t) {
      for (int k = 0; k < 4; ++k) m.tets.push_back(map[a.tets[4 * t + k]]);
      m.tet_ref.push_back(1);
    }
    try {
      build_tet_mesh(m, std::vector<SymMat3>(m.num_vertices(), SymMat3::identity()));
      ADD_FAILURE() << "a volume pinched at an edge or a corner was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("the volume is not a manifold at"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(build_tet_mesh(unit_cube(2), std::vector<SymMat3>(27, SymMat3::identity())));
}

TEST(TetMesh, RenumberTailKeepsTheMesh) {
  Mesh cube = unit_cube(5);  // 300 boundary triangles, each its own ref: 46 in the overflow map
  for (std::size_t f = 0; f < cube.num_triangles(); ++f) cube.tri_ref[f] = 1000 + static_cast<int>(f);
  TetMesh m = build_tet_mesh(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()));
  ASSERT_FALSE(m.ref_overflow.empty());
  const Id head = static_cast<Id>(m.vertex_capacity());
  // Split every edge once (boundary ones carry their refs to the halves), then collapse a new
  // interior vertex: new vertices at the end, a dead slot in the tail.
  std::vector<std::pair<Id, Id>> edges;
  for (std::size_t t = 0; t < cube.num_tets(); ++t)
    for (const auto& [i, j] : kTetEdge) edges.emplace_back(cube.tets[4 * t + i], cube.tets[4 * t + j]);
  split_at_midpoints(m, edges);
  Id gone = kNoId;
  std::vector<Id> ball, around;
  for (Id v = static_cast<Id>(m.vertex_capacity()) - 1; v >= head && gone == kNoId; --v) {
    if (m.vkind[v] != VertexKind::kInterior) continue;
    collect_ball(m, v, ball);
    ball_neighbours(m, v, ball, around);
    for (const Id to : around)
      if (collapse_edge(m, v, to, CollapseLimits{0.0, 10.0}) == Outcome::kApplied) {
        gone = v;
        break;
      }
  }
  ASSERT_NE(gone, kNoId);
  ASSERT_EQ(check_tet_mesh(m), "");
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t))) cached_quality(m, static_cast<Id>(t));
  m.vtouch.resize(m.vertex_capacity(), 0);
  for (std::size_t v = 0; v < m.vtouch.size(); ++v) m.vtouch[v] = static_cast<std::uint32_t>(v);
  const TetMesh before = m;

  std::vector<Id> tet_old2new;
  const std::vector<Id> old2new = renumber_tail(m, head, &tet_old2new);
  EXPECT_EQ(check_tet_mesh(m), "");
  // The tets and the listed faces by their corners' coordinates, with their refs.
  auto corners = [](const Mesh& x, const std::vector<Id>& conn, int k, const std::vector<int>& refs) {
    std::map<std::vector<double>, int> out;
    for (std::size_t e = 0; e < conn.size() / k; ++e) {
      std::vector<std::array<double, 3>> c;
      for (int i = 0; i < k; ++i) {
        const Id v = conn[k * e + i];
        c.push_back({x.coords[3 * v], x.coords[3 * v + 1], x.coords[3 * v + 2]});
      }
      std::sort(c.begin(), c.end());
      std::vector<double> key;
      for (const auto& p : c) key.insert(key.end(), p.begin(), p.end());
      out[key] = refs.empty() ? 0 : refs[e];
    }
    return out;
  };
  const Mesh a = to_mesh(before), b = to_mesh(m);
  EXPECT_EQ(corners(b, b.tets, 4, {}), corners(a, a.tets, 4, {}));
  EXPECT_EQ(corners(b, b.triangles, 3, b.tri_ref), corners(a, a.triangles, 3, a.tri_ref));
  EXPECT_EQ(m.vertex_capacity(), before.num_live_vertices());
  EXPECT_EQ(m.tet_capacity(), before.num_live_tets());
  EXPECT_TRUE(m.free_tets.empty());
  EXPECT_EQ(old2new[gone], kNoId);
  for (Id v = 0; v < head; ++v) EXPECT_EQ(old2new[v], v);
  for (std::size_t v = 0; v < old2new.size(); ++v) {
    if (old2new[v] == kNoId) continue;
    EXPECT_EQ(m.xyz[old2new[v]], before.xyz[v]);
    EXPECT_EQ(m.vkind[old2new[v]], before.vkind[v]);
    EXPECT_EQ(m.vtouch[old2new[v]], before.vtouch[v]);
  }
  for (std::size_t t = 0; t < tet_old2new.size(); ++t) {
    if (tet_old2new[t] != kNoId) {
      EXPECT_EQ(m.quality[tet_old2new[t]], before.quality[t]);
    }
  }
  std::vector<double> tail;
  for (std::size_t v = static_cast<std::size_t>(head); v < m.vertex_capacity(); ++v)
    tail.insert(tail.end(), {m.xyz[v][0], m.xyz[v][1], m.xyz[v][2]});
  const std::vector<Id> order = hilbert_order(tail, 3);
  for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], static_cast<Id>(i));
  for (std::size_t t = 1; t < m.tet_capacity(); ++t) {
    const Id* p = &m.tv[4 * (t - 1)];
    const Id* q = &m.tv[4 * t];
    EXPECT_LE(*std::min_element(p, p + 4), *std::min_element(q, q + 4));
  }
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

namespace {

/// A flat sliver from `riemesh mesh` on a cube's faces remeshed to 1/20 (two vertices on face
/// x = 0, two on face z = 0, at y = 0.75 and 0.775 each up to one unit in the last place): its
/// volume rounds to exactly 0 but it is positive (1.6e-19 in exact arithmetic). `flat`: the
/// x of the second vertex one unit lower, which makes the four points exactly coplanar.
Mesh sliver(bool flat) {
  Mesh m;
  m.dim = 3;
  m.coords = {0.0,
              0x1.8cccccccccccdp-1,
              0x1.cccccccccccccp-3,
              flat ? 0x1.cccccccccccccp-3 : 0x1.ccccccccccccdp-3,
              0x1.8p-1,
              0.0,
              0.0,
              0x1.8p-1,
              0x1.cccccccccccccp-3,
              0x1.cccccccccccccp-3,
              0x1.8cccccccccccdp-1,
              0.0};
  m.vert_ref.assign(4, 0);
  m.vert_tag.assign(4, 0);
  m.tets = {0, 1, 2, 3};
  m.tet_ref = {1};
  return m;
}

}  // namespace

TEST(TetMesh, FlatSliversArePositiveByTheExactOrientation) {
  const std::vector<SymMat3> identity(4, SymMat3::identity());
  std::vector<double> metrics(4 * SymMat3::kSize);  // packed, for the background
  for (std::size_t v = 0; v < 4; ++v)
    std::copy_n(SymMat3::identity().c, SymMat3::kSize, &metrics[SymMat3::kSize * v]);
  const Mesh positive = sliver(false);
  const Vec3 p[4] = {{{positive.coords[0], positive.coords[1], positive.coords[2]}},
                     {{positive.coords[3], positive.coords[4], positive.coords[5]}},
                     {{positive.coords[6], positive.coords[7], positive.coords[8]}},
                     {{positive.coords[9], positive.coords[10], positive.coords[11]}}};
  EXPECT_EQ(simplex::signed_volume(p), 0.0);  // rounded
  EXPECT_GT(simplex::exact_orientation(p), 0.0);
  EXPECT_NO_THROW(require_valid_input<3>(positive, identity));
  EXPECT_NO_THROW(build_tet_mesh(positive, identity));
  EXPECT_NO_THROW(BackgroundMesh<3>(positive, metrics));
  const Mesh flat = sliver(true);
  EXPECT_THROW(require_valid_input<3>(flat, identity), InputError);
  EXPECT_THROW(build_tet_mesh(flat, identity), InputError);
  EXPECT_THROW(BackgroundMesh<3>(flat, metrics), InputError);
}
