// Adjacency of triangle and tetrahedron arrays: symmetry of neighbours, face and edge counts
// against closed formulas, Euler characteristics, vertex balls, shells of edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/fixtures.hpp"

using namespace riemesh;

namespace {

/// If a's neighbour across face i is b, then b has a neighbour a across the face that holds
/// the same vertices (face i of a without the opposite vertex).
void expect_symmetric(const Adjacency& adj, const std::vector<Id>& s) {
  const int k = adj.verts_per_simplex;
  for (std::size_t a = 0; a < adj.num_elements(); ++a)
    for (int i = 0; i < k; ++i) {
      const Id b = adj.elem2elem[k * a + i];
      if (b == kNoId) continue;
      int back = 0;
      for (int j = 0; j < k; ++j)
        if (adj.elem2elem[k * b + j] == static_cast<Id>(a)) {
          ++back;
          // b's vertex opposite the shared face is not in a.
          EXPECT_LT(local_index(&s[k * a], k, s[k * b + j]), 0);
        }
      EXPECT_EQ(back, 1) << "element " << a << " face " << i;
      EXPECT_GE(local_index(&s[k * b], k, s[k * a + (i + 1) % k]), 0);
    }
}

std::size_t count_boundary(const Adjacency& adj) {
  return static_cast<std::size_t>(std::count(adj.elem2elem.begin(), adj.elem2elem.end(), kNoId));
}

}  // namespace

TEST(Adjacency, UnitSquareCounts) {
  for (auto [nx, ny] : {std::pair{1, 1}, {3, 2}, {7, 5}}) {
    const Mesh m = unit_square(nx, ny);
    const Adjacency adj = build_adjacency(m);
    expect_symmetric(adj, m.triangles);
    EXPECT_TRUE(adj.nonmanifold_faces.empty());
    // Edges: nx(ny+1) horizontal + ny(nx+1) vertical + nx ny diagonals = 3 nx ny + nx + ny.
    EXPECT_EQ(adj.num_edges(), static_cast<std::size_t>(3 * nx * ny + nx + ny));
    EXPECT_EQ(count_boundary(adj), static_cast<std::size_t>(2 * (nx + ny)));
    // Euler characteristic of a disk: V - E + F = 1.
    const long chi = static_cast<long>(m.num_vertices()) - static_cast<long>(adj.num_edges()) +
                     static_cast<long>(m.num_triangles());
    EXPECT_EQ(chi, 1);
  }
}

TEST(Adjacency, UnitCubeCounts) {
  for (int n : {1, 2, 4}) {
    const Mesh m = unit_cube(n);
    const Adjacency adj = build_adjacency(m);
    expect_symmetric(adj, m.tets);
    EXPECT_TRUE(adj.nonmanifold_faces.empty());
    // Boundary faces: 6 sides of n² squares, 2 triangles each.
    EXPECT_EQ(count_boundary(adj), static_cast<std::size_t>(12 * n * n));
    // Faces: each interior face counted twice: F = (4T + B) / 2.
    const long v = static_cast<long>(m.num_vertices()), t = static_cast<long>(m.num_tets());
    const long f = (4 * t + 12L * n * n) / 2, e = static_cast<long>(adj.num_edges());
    // Euler characteristic of a ball: V - E + F - T = 1.
    EXPECT_EQ(v - e + f - t, 1);
    // Kuhn edges: 3n(n+1)² axis edges + 3n²(n+1) face diagonals + n³ cube diagonals.
    EXPECT_EQ(e, 3L * n * (n + 1) * (n + 1) + 3L * n * n * (n + 1) + 1L * n * n * n);
  }
}

TEST(Adjacency, EdgesSortedUniqueAndMapped) {
  const Mesh m = unit_cube(3);
  const Adjacency adj = build_adjacency(m);
  for (std::size_t e = 0; e < adj.num_edges(); ++e) {
    EXPECT_LT(adj.edges[2 * e], adj.edges[2 * e + 1]);
    if (e > 0) {
      const auto prev = std::pair{adj.edges[2 * e - 2], adj.edges[2 * e - 1]};
      EXPECT_LT(prev, (std::pair{adj.edges[2 * e], adj.edges[2 * e + 1]}));
    }
  }
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int j = 0; j < 6; ++j) {
      const Id a = m.tets[4 * t + kTetEdge[j][0]], b = m.tets[4 * t + kTetEdge[j][1]];
      const Id g = adj.elem2edge[6 * t + j];
      EXPECT_EQ(std::min(a, b), adj.edges[2 * g]);
      EXPECT_EQ(std::max(a, b), adj.edges[2 * g + 1]);
      EXPECT_EQ(find_edge(adj, b, a), g);
    }
  EXPECT_EQ(find_edge(adj, 0, static_cast<Id>(m.num_vertices() - 1)), kNoId);
}

TEST(Adjacency, SphereIsClosedWithEulerTwo) {
  const Mesh m = sphere_surface(3);
  const Adjacency adj = build_adjacency(m);
  expect_symmetric(adj, m.triangles);
  EXPECT_EQ(count_boundary(adj), 0u);
  // V - E + F = 2, and E = 3F/2 on a closed triangulated surface.
  EXPECT_EQ(2 * adj.num_edges(), 3 * m.num_triangles());
  EXPECT_EQ(static_cast<long>(m.num_vertices()) - static_cast<long>(adj.num_edges()) +
                static_cast<long>(m.num_triangles()),
            2);
}

TEST(Adjacency, BallListsExactlyTheIncidentElements) {
  const Mesh m = unit_cube(2);
  const Adjacency adj = build_adjacency(m);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    std::vector<Id> expected;
    for (std::size_t t = 0; t < m.num_tets(); ++t)
      if (local_index(&m.tets[4 * t], 4, static_cast<Id>(v)) >= 0)
        expected.push_back(static_cast<Id>(t));
    const auto b = ball(adj, static_cast<Id>(v));
    EXPECT_EQ(std::vector<Id>(b.begin(), b.end()), expected);
  }
  // The centre vertex of unit_cube(2) (id 13): the 2 cubes having it at an end of their main
  // diagonal give all 6 tets, the other 6 cubes give the 2 Kuhn tets through that corner: 24.
  EXPECT_EQ(ball(adj, 13).size(), 24u);
}

TEST(Adjacency, NonManifoldFacesAreListed) {
  // Three triangles sharing the edge (0, 1).
  const std::vector<Id> tris = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  const Adjacency adj = build_adjacency(tris, 3, 5);
  ASSERT_EQ(adj.nonmanifold_faces.size(), 3u);
  // Edge (0,1) is face 2 of triangles 0 and 2, face 2 of triangle 1.
  EXPECT_EQ(adj.nonmanifold_faces, (std::vector<Id>{2, 5, 8}));
  for (Id f : adj.nonmanifold_faces) EXPECT_EQ(adj.elem2elem[f], kNoId);
}

TEST(Adjacency, FaceAdjacencyIsTheFullOneWithoutEdges) {
  const Mesh m = unit_cube(3);
  const Adjacency full = build_adjacency(m.tets, 4, m.num_vertices());
  const Adjacency faces = build_face_adjacency(m.tets, 4, m.num_vertices());
  EXPECT_EQ(faces.elem2elem, full.elem2elem);
  EXPECT_EQ(faces.vert2elem, full.vert2elem);
  EXPECT_EQ(faces.vert2elem_offsets, full.vert2elem_offsets);
  EXPECT_TRUE(faces.edges.empty());
  EXPECT_TRUE(faces.elem2edge.empty());
  const std::vector<Id> tris = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  EXPECT_EQ(build_face_adjacency(tris, 3, 5).nonmanifold_faces, (std::vector<Id>{2, 5, 8}));
  EXPECT_THROW(build_face_adjacency({0, 1, 5}, 3, 4), InputError);
}

TEST(Adjacency, TriangleNeighboursWithScrambledIdsAndOrientations) {
  // unit_square(6, 6) with vertex v renamed 17 v + 5 mod 49 (17 is prime to 49) and every third
  // triangle turned clockwise: neighbours are found whatever the numbering and orientation.
  const Mesh m = unit_square(6, 6);
  const std::size_t nv = m.num_vertices();
  std::vector<Id> s = m.triangles;
  for (Id& v : s) v = static_cast<Id>((17 * static_cast<std::size_t>(v) + 5) % nv);
  for (std::size_t t = 0; t < s.size() / 3; t += 3) std::swap(s[3 * t + 1], s[3 * t + 2]);
  const Adjacency adj = build_adjacency(s, 3, nv);
  expect_symmetric(adj, s);
  EXPECT_TRUE(adj.nonmanifold_faces.empty());
  EXPECT_EQ(count_boundary(adj), 24u);
  // add_edges on the face adjacency gives build_adjacency's edges.
  Adjacency faces = build_face_adjacency(s, 3, nv);
  EXPECT_EQ(faces.elem2elem, adj.elem2elem);
  add_edges(faces, s);
  EXPECT_EQ(faces.edges, adj.edges);
  EXPECT_EQ(faces.elem2edge, adj.elem2edge);
  // A fourth triangle on a side of the fan of NonManifoldFacesAreListed, and one with a
  // repeated vertex: the generic matching takes over and gives the same neighbours elsewhere.
  const std::vector<Id> tris = {0, 1, 2, 1, 0, 3, 0, 1, 4, 2, 1, 5, 5, 5, 6};
  const Adjacency odd = build_adjacency(tris, 3, 7);
  EXPECT_EQ(odd.nonmanifold_faces, (std::vector<Id>{2, 5, 8}));
  EXPECT_EQ(odd.elem2elem[0], 3);  // triangle 0's side (1, 2) faces triangle 3
  EXPECT_EQ(odd.elem2elem[9 + 2], 0);
}

TEST(Adjacency, RejectsBadInput) {
  EXPECT_THROW(build_adjacency({0, 1, 2, 3}, 3, 4), InputError);
  EXPECT_THROW(build_adjacency({0, 1, 5}, 3, 4), InputError);
  EXPECT_THROW(build_adjacency({0, 1, 2}, 2, 4), InputError);
  const Adjacency empty = build_adjacency(std::vector<Id>{}, 4, 0);
  EXPECT_EQ(empty.num_elements(), 0u);
  EXPECT_EQ(empty.num_edges(), 0u);
}

TEST(Shell, InteriorEdgeClosesAndIsWalkedInOrder) {
  const int n = 4;
  const Mesh m = unit_cube(n);
  const Adjacency adj = build_adjacency(m);
  std::size_t interior = 0;
  for (std::size_t g = 0; g < adj.num_edges(); ++g) {
    const Id a = adj.edges[2 * g], b = adj.edges[2 * g + 1];
    const Shell sh = shell(adj, m.tets, a, b);
    ASSERT_TRUE(sh.ordered);
    ASSERT_FALSE(sh.elements.empty());
    // Every element holds the edge, and consecutive ones share a face (a neighbour link).
    for (std::size_t i = 0; i < sh.elements.size(); ++i) {
      const Id t = sh.elements[i];
      EXPECT_GE(local_index(&m.tets[4 * t], 4, a), 0);
      EXPECT_GE(local_index(&m.tets[4 * t], 4, b), 0);
      if (i + 1 < sh.elements.size() || sh.closed) {
        const Id next = sh.elements[(i + 1) % sh.elements.size()];
        const auto* nb = &adj.elem2elem[4 * t];
        EXPECT_TRUE(std::find(nb, nb + 4, next) != nb + 4);
      }
    }
    // Interior edges (both ends strictly inside the cube) have closed shells.
    auto inside = [&](Id v) {
      for (int c = 0; c < 3; ++c) {
        const double x = m.coords[3 * v + c];
        if (x <= 0.0 || x >= 1.0) return false;
      }
      return true;
    };
    if (inside(a) || inside(b)) {
      EXPECT_TRUE(sh.closed) << a << "-" << b;
      ++interior;
    }
    // Open shells start and end with a boundary face on the edge.
    if (!sh.closed) {
      EXPECT_FALSE(inside(a) || inside(b));
    }
  }
  EXPECT_GT(interior, 0u);
}

TEST(Shell, CountsMatchTheBallIntersection) {
  const Mesh m = unit_cube(3);
  const Adjacency adj = build_adjacency(m);
  for (std::size_t g = 0; g < adj.num_edges(); g += 7) {
    const Id a = adj.edges[2 * g], b = adj.edges[2 * g + 1];
    std::set<Id> expected;
    for (Id t : ball(adj, a))
      if (local_index(&m.tets[4 * t], 4, b) >= 0) expected.insert(t);
    const Shell sh = shell(adj, m.tets, a, b);
    EXPECT_EQ(std::set<Id>(sh.elements.begin(), sh.elements.end()), expected);
    EXPECT_EQ(sh.elements.size(), expected.size());
  }
}

TEST(Shell, TrianglesAroundAnEdge) {
  const Mesh m = unit_square(2, 2);
  const Adjacency adj = build_adjacency(m);
  EXPECT_EQ(shell(adj, m.triangles, 0, 4).elements.size(), 2u);  // interior diagonal
  EXPECT_EQ(shell(adj, m.triangles, 0, 1).elements.size(), 1u);  // boundary edge
}
