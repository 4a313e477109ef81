// check_mesh: valid fixtures pass, and each single defect is reported as exactly that defect,
// with the right count and first example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "mesh/adjacency.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"

using namespace riemesh;

namespace {

using C = CheckCategory;

std::string describe(const CheckReport& r) {
  std::string s;
  for (const CheckIssue& i : r.issues)
    s += std::string(to_string(i.category)) + " x" + std::to_string(i.count) + " (first " +
         std::to_string(i.example) + "); ";
  return s.empty() ? "valid" : s;
}

/// The report holds exactly one issue: `category`, `count` times.
void expect_only(const CheckReport& r, C category, std::size_t count) {
  ASSERT_EQ(r.issues.size(), 1u) << describe(r);
  EXPECT_EQ(r.issues[0].category, category) << describe(r);
  EXPECT_EQ(r.issues[0].count, count) << describe(r);
  EXPECT_FALSE(r.valid());
}

/// Id of the tet of unit_cube(n) that lies k-th in cell (i, j, l).
Id cube_tet(int n, int i, int j, int l, int k) { return 6 * ((l * n + j) * n + i) + k; }

void erase_tet(Mesh& m, Id t) {
  m.tets.erase(m.tets.begin() + 4 * t, m.tets.begin() + 4 * t + 4);
  m.tet_ref.erase(m.tet_ref.begin() + t);
}

void erase_triangle(Mesh& m, Id f) {
  m.triangles.erase(m.triangles.begin() + 3 * f, m.triangles.begin() + 3 * f + 3);
  m.tri_ref.erase(m.tri_ref.begin() + f);
  m.tri_tag.erase(m.tri_tag.begin() + f);
}

/// Lists every boundary face of the tets as a Triangle (ref 1).
void list_boundary(Mesh& m) {
  const Adjacency adj = build_adjacency(m);
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int i = 0; i < 4; ++i)
      if (adj.elem2elem[4 * t + i] == kNoId) {
        for (int a = 0; a < 3; ++a) m.triangles.push_back(m.tets[4 * t + kTetFace[i][a]]);
        m.tri_ref.push_back(1);
      }
}

Mesh tets_from(std::vector<double> coords, std::vector<Id> tets) {
  Mesh m;
  m.dim = 3;
  m.coords = std::move(coords);
  m.vert_ref.assign(m.num_vertices(), 0);
  m.tets = std::move(tets);
  m.tet_ref.assign(m.num_tets(), 1);
  list_boundary(m);
  return m;
}

}  // namespace

TEST(Check, FixturesAreValid) {
  for (const Mesh& m : {unit_cube(1), unit_cube(3), unit_square(1, 1), unit_square(5, 3),
                        sphere_surface(0), sphere_surface(2)}) {
    const CheckReport r = check_mesh(m);
    EXPECT_TRUE(r.valid()) << describe(r);
  }
  EXPECT_TRUE(check_mesh(Mesh{}).valid());  // empty
}

TEST(Check, InvertedTet) {
  Mesh m = unit_cube(3);
  const Id t = cube_tet(3, 1, 1, 1, 2);
  std::swap(m.tets[4 * t + 2], m.tets[4 * t + 3]);
  const CheckReport r = check_mesh(m);
  expect_only(r, C::kInvertedElement, 1);
  EXPECT_EQ(r.issues[0].entity, EntityKind::kTet);
  EXPECT_EQ(r.issues[0].example, t);
  // Located at its centroid, inside the middle cell [1/3, 2/3]³.
  for (double x : r.issues[0].location) {
    EXPECT_GT(x, 1.0 / 3);
    EXPECT_LT(x, 2.0 / 3);
  }
}

TEST(Check, ZeroVolumeTet) {
  // A single flat tet (4 coplanar points): its volume is exactly 0.
  const Mesh m = tets_from({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, {0, 1, 2, 3});
  expect_only(check_mesh(m), C::kZeroMeasureElement, 1);
  // Nearly flat but above the tolerance: valid. Height 1e-9 gives |V| / L³ ~ 1e-10.
  const Mesh thin = tets_from({0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1e-9}, {0, 1, 2, 3});
  EXPECT_TRUE(check_mesh(thin).valid()) << describe(check_mesh(thin));
}

TEST(Check, DuplicatedTet) {
  Mesh m = unit_cube(3);
  const Id t = cube_tet(3, 1, 1, 1, 4);
  m.tets.insert(m.tets.end(), m.tets.begin() + 4 * t, m.tets.begin() + 4 * t + 4);
  m.tet_ref.push_back(1);
  const CheckReport r = check_mesh(m);
  expect_only(r, C::kDuplicateElement, 1);
  EXPECT_EQ(r.issues[0].example, static_cast<Id>(m.num_tets() - 1));  // the later copy
}

TEST(Check, MissingBoundaryTriangle) {
  Mesh m = unit_cube(3);
  erase_triangle(m, 17);
  const CheckReport r = check_mesh(m);
  expect_only(r, C::kMissingBoundary, 1);
  EXPECT_GE(r.issues[0].local_face, 0);  // the tet face that should have been listed
}

TEST(Check, HoleInAVolume) {
  // Removing the middle cell's 6 tets opens a cubic cavity: 12 boundary faces nobody listed.
  const int n = 3;
  Mesh m = unit_cube(n);
  for (int k = 5; k >= 0; --k) erase_tet(m, cube_tet(n, 1, 1, 1, k));
  expect_only(check_mesh(m), C::kMissingBoundary, 12);
  // Listing the cavity's faces makes it a valid mesh with an internal boundary.
  Mesh listed = m;
  listed.triangles.clear(), listed.tri_ref.clear(), listed.tri_tag.clear();
  list_boundary(listed);
  EXPECT_TRUE(check_mesh(listed).valid()) << describe(check_mesh(listed));
}

TEST(Check, OrphanAndDuplicateTriangles) {
  Mesh m = unit_cube(2);
  // Vertices 1, 3, 4 are (1/2,0,0), (0,1/2,0), (1/2,1/2,0): the bottom-left square's Kuhn
  // diagonal is 0-4, so its faces are (0,1,4) and (0,4,3); (1,3,4) uses the other diagonal.
  m.triangles.insert(m.triangles.end(), {1, 3, 4});
  m.tri_ref.push_back(7);
  m.tri_tag.push_back(0);
  expect_only(check_mesh(m), C::kOrphanEntity, 1);
  Mesh d = unit_cube(2);
  d.triangles.insert(d.triangles.end(), {d.triangles[5], d.triangles[3], d.triangles[4]});
  d.tri_ref.push_back(1);
  d.tri_tag.push_back(0);
  expect_only(check_mesh(d), C::kDuplicateBoundaryEntity, 1);
}

TEST(Check, InteriorTrianglesMayBeListed) {
  // An internal interface (a face shared by two tets) listed as a Triangle is fine.
  Mesh m = unit_cube(2);
  const Adjacency adj = build_adjacency(m);
  const auto it =
      std::find_if(adj.elem2elem.begin(), adj.elem2elem.end(), [](Id n) { return n != kNoId; });
  const std::size_t f = it - adj.elem2elem.begin();
  for (int a = 0; a < 3; ++a) m.triangles.push_back(m.tets[4 * (f / 4) + kTetFace[f % 4][a]]);
  m.tri_ref.push_back(9);
  m.tri_tag.push_back(0);
  EXPECT_TRUE(check_mesh(m).valid()) << describe(check_mesh(m));
}

TEST(Check, NonManifoldBoundaryEdge) {
  // Two tets sharing only the edge (0, 1): 4 boundary faces around that edge.
  const Mesh m =
      tets_from({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1}, {0, 1, 2, 3, 0, 1, 4, 5});
  expect_only(check_mesh(m), C::kNonManifoldBoundary, 1);
}

TEST(Check, NonManifoldFace) {
  // Three tets on the triangle (0, 1, 2): apexes 3 above, 4 below, 5 further above.
  const Mesh m = tets_from({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0.2, 0.2, 2},
                           {0, 1, 2, 3, 0, 2, 1, 4, 0, 1, 2, 5});
  const CheckReport r = check_mesh(m);
  EXPECT_EQ(r.count(C::kNonManifoldFace), 1u) << describe(r);
  EXPECT_EQ(r.count(C::kInvertedElement), 0u);
}

TEST(Check, BadIdsAndSizes) {
  Mesh m = unit_cube(2);
  m.tets[5] = 1000;
  expect_only(check_mesh(m), C::kIdOutOfRange, 1);
  Mesh s = unit_cube(2);
  s.tet_ref.pop_back();
  expect_only(check_mesh(s), C::kArraySize, 1);
  Mesh c = unit_cube(1);
  c.coords.push_back(0.5);  // not a multiple of 3: nothing else can be checked
  const CheckReport r = check_mesh(c);
  EXPECT_FALSE(r.valid());
  EXPECT_GE(r.count(C::kArraySize), 1u);
}

TEST(Check, UnusedAndRepeatedVertices) {
  Mesh m = unit_cube(1);
  m.coords.insert(m.coords.end(), {2.0, 2.0, 2.0});
  m.vert_ref.push_back(0);
  m.vert_tag.push_back(0);
  const CheckReport r = check_mesh(m);
  expect_only(r, C::kUnusedVertex, 1);
  EXPECT_EQ(r.issues[0].example, 8);
  EXPECT_EQ(r.issues[0].location, (std::array<double, 3>{2.0, 2.0, 2.0}));
  Mesh e = unit_cube(1);
  e.edges.insert(e.edges.end(), {3, 3});
  e.edge_ref.push_back(0);
  e.edge_tag.push_back(0);
  expect_only(check_mesh(e), C::kRepeatedVertex, 1);
}

TEST(Check, ElementsWithARepeatedVertexAreLeftOutOfTheTopology) {
  // A single tet "1 1 2 3": the checker built the adjacency of it and aborted (heap corruption).
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.vert_ref.assign(4, 0);
  m.vert_tag.assign(4, 0);
  m.tets = {0, 0, 1, 2};
  m.tet_ref = {1};
  const CheckReport r = check_mesh(m);
  EXPECT_EQ(r.count(C::kRepeatedVertex), 1u) << describe(r);
  EXPECT_FALSE(r.valid());
  // One in a cube's tets: reported, the others checked as usual.
  Mesh cube = unit_cube(1);
  cube.tets[1] = cube.tets[0];
  const CheckReport c = check_mesh(cube);
  EXPECT_EQ(c.count(C::kRepeatedVertex), 1u) << describe(c);
  // The same for triangles.
  Mesh tri = unit_square(2, 2);
  tri.triangles[2] = tri.triangles[0];
  EXPECT_EQ(check_mesh(tri).count(C::kRepeatedVertex), 1u) << describe(check_mesh(tri));
}

TEST(Check, PlanarDefects) {
  // A hole: an interior triangle of unit_square(3, 3) removed leaves 3 unlisted boundary edges.
  Mesh hole = unit_square(3, 3);
  erase_triangle(hole, 8);  // cell (1, 1), first triangle
  expect_only(check_mesh(hole), C::kMissingBoundary, 3);
  // A missing boundary edge.
  Mesh missing = unit_square(3, 2);
  missing.edges.erase(missing.edges.begin(), missing.edges.begin() + 2);
  missing.edge_ref.erase(missing.edge_ref.begin());
  missing.edge_tag.erase(missing.edge_tag.begin());
  expect_only(check_mesh(missing), C::kMissingBoundary, 1);
  // An edge no triangle has: (1, 4) = (1/3, 0)-(0, 1/2), the anti-diagonal of cell (0, 0)
  // (whose diagonal is 0-5).
  Mesh orphan = unit_square(3, 2);
  orphan.edges.insert(orphan.edges.end(), {1, 4});
  orphan.edge_ref.push_back(5);
  orphan.edge_tag.push_back(0);
  expect_only(check_mesh(orphan), C::kOrphanEntity, 1);
  // An inverted triangle (clockwise).
  Mesh inverted = unit_square(2, 2);
  std::swap(inverted.triangles[0], inverted.triangles[1]);
  expect_only(check_mesh(inverted), C::kInvertedElement, 1);
}

TEST(Check, PlanarBowTieIsValid) {
  // Two triangles touching at vertex 2 only; all 6 boundary edges listed: two boundary loops
  // touching at a vertex (a hole touching the outer boundary, which `riemesh mesh` meshes and
  // `adapt` keeps: their outputs were called invalid).
  Mesh m;
  m.dim = 2;
  m.coords = {0, 0, 1, 0, 1, 1, 2, 1, 2, 2};
  m.vert_ref.assign(5, 0);
  m.triangles = {0, 1, 2, 2, 3, 4};
  m.tri_ref = {1, 1};
  m.edges = {0, 1, 1, 2, 2, 0, 2, 3, 3, 4, 4, 2};
  m.edge_ref.assign(6, 1);
  EXPECT_TRUE(check_mesh(m).valid()) << describe(check_mesh(m));
  // Without one of the loops' edges listed, the vertex is on 3 boundary edges.
  Mesh missing = m;
  missing.edges.resize(10);
  missing.edge_ref.resize(5);
  const CheckReport r = check_mesh(missing);
  EXPECT_EQ(r.count(C::kMissingBoundary), 1u) << describe(r);
}

TEST(Check, EdgeOnlyBoundaryLoops) {
  // The boundary of unit_square(3, 2) alone: a closed loop. Cut one edge: two open ends.
  Mesh m = unit_square(3, 2);
  m.triangles.clear(), m.tri_ref.clear(), m.tri_tag.clear();
  EXPECT_TRUE(check_mesh(m).valid()) << describe(check_mesh(m));
  Mesh open = m;
  open.edges.resize(open.edges.size() - 2);
  open.edge_ref.pop_back();
  open.edge_tag.pop_back();
  expect_only(check_mesh(open), C::kOpenBoundary, 2);
  Mesh twice = m;
  twice.edges.insert(twice.edges.end(), {m.edges[1], m.edges[0]});
  twice.edge_ref.push_back(1);
  twice.edge_tag.push_back(0);
  const CheckReport r = check_mesh(twice);
  EXPECT_EQ(r.count(C::kDuplicateBoundaryEntity), 1u) << describe(r);
  EXPECT_EQ(r.count(C::kNonManifoldBoundary), 2u) << describe(r);
}

TEST(Check, SurfaceOrientation) {
  Mesh m = sphere_surface(1);
  std::swap(m.triangles[3 * 7 + 1], m.triangles[3 * 7 + 2]);  // flip triangle 7
  const CheckReport r = check_mesh(m);
  expect_only(r, C::kInconsistentOrientation, 3);  // its 3 edges
  // A zero-area surface triangle.
  Mesh z = sphere_surface(0);
  for (int c = 0; c < 3; ++c) z.coords[3 * z.triangles[2] + c] = z.coords[3 * z.triangles[1] + c];
  EXPECT_GE(check_mesh(z).count(C::kZeroMeasureElement), 1u);
}

TEST(Check, PlanarFold) {
  // The unit square as (0, 1, 2) and (0, 2, 3), and a third counter-clockwise triangle
  // (0, 1, 3) lying over both: edges 0-1 and 3-0 are traversed the same way by two triangles.
  // Called valid before (total area 1.5; QA hunt 5 F7).
  Mesh m;
  m.dim = 2;
  m.coords = {0, 0, 1, 0, 1, 1, 0, 1};
  m.vert_ref.assign(4, 0);
  m.triangles = {0, 1, 2, 0, 2, 3, 0, 1, 3};
  m.tri_ref = {1, 1, 2};
  m.edges = {0, 1, 1, 2, 2, 3, 3, 0, 1, 3};
  m.edge_ref.assign(5, 1);
  m.edge_tag.assign(5, 0);
  const CheckReport r = check_mesh(m);
  EXPECT_EQ(r.count(C::kOverlappingElements), 2u) << describe(r);
  EXPECT_FALSE(r.valid());
  // Without the third triangle: valid (the listed diagonal is then an orphan, dropped here).
  m.triangles.resize(6), m.tri_ref.resize(2), m.edges.resize(8), m.edge_ref.resize(4),
      m.edge_tag.resize(4);
  EXPECT_TRUE(check_mesh(m).valid()) << describe(check_mesh(m));
}

TEST(Check, SurfaceOfTwoRegions) {
  // Two tets' surfaces sharing the triangle (0, 1, 2), listed once: its 3 edges are on 3
  // triangles each. A surface of two regions: valid, the meeting edges noted.
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.2, 1, 0.2, 0.2, -1};
  m.vert_ref.assign(5, 0);
  // Region above (apex 3) faces out; the interface (0, 2, 1) faces down, out of it; below
  // (apex 4) its other faces face out.
  m.triangles = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3, 0, 4, 1, 1, 4, 2, 2, 4, 0};
  m.tri_ref.assign(7, 1);
  m.tri_tag.assign(7, 0);
  const CheckReport r = check_mesh(m);
  EXPECT_TRUE(r.valid()) << describe(r);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0].category, C::kRegionsMeet);
  EXPECT_EQ(r.count(C::kRegionsMeet), 3u);
  // An outer triangle of the region below turned: its edges to vertex 4 are traversed the same
  // way by both triangles, noted (`riemesh mesh` takes such a surface), still valid.
  Mesh turned = m;
  std::swap(turned.triangles[3 * 4 + 1], turned.triangles[3 * 4 + 2]);
  const CheckReport t = check_mesh(turned);
  EXPECT_TRUE(t.valid()) << describe(t);
  EXPECT_EQ(t.count(C::kInconsistentOrientation), 2u);
  // The same turn on a surface of one region is an issue (SurfaceOrientation); so is an edge
  // on 3 elements of a planar mesh or of a volume (NonManifoldFace).
}

TEST(Check, CategoryNames) {
  for (int c = 0; c <= static_cast<int>(C::kRegionsMeet); ++c)
    EXPECT_STRNE(to_string(static_cast<C>(c)), "unknown");
}

TEST(Check, CoincidentVerticesOfTheElementsAreFound) {
  Mesh m = unit_square(2, 2);  // 9 vertices, none at the same place
  EXPECT_EQ(find_coincident_vertices(m).pairs, 0u);
  EXPECT_EQ(find_coincident_vertices(m).first_a, kNoId);
  // Copies of vertices 5 and 2 (9 at 5's place, 10 and 11 at 2's place) and a NaN (12), used by
  // nothing at first.
  for (const Id v : {5, 2, 2})
    m.coords.insert(m.coords.end(), {m.coords[2 * v], m.coords[2 * v + 1]});
  m.coords.insert(m.coords.end(), {std::nan(""), 0.5});
  m.vert_ref.resize(13, 0);
  m.vert_tag.resize(13, 0);
  EXPECT_EQ(find_coincident_vertices(m).pairs, 0u);
  // 10, 11 and the NaN on edges; 9 stays unused.
  m.edges.insert(m.edges.end(), {10, 11, 12, 4});
  m.edge_ref.insert(m.edge_ref.end(), {1, 1});
  m.edge_tag.insert(m.edge_tag.end(), {0, 0});
  const CoincidentVertices c = find_coincident_vertices(m);
  EXPECT_EQ(c.pairs, 2u);  // 2, 10 and 11 at one place: two pairs
  EXPECT_EQ(c.first_a, 2);
  EXPECT_EQ(c.first_b, 10);
}
