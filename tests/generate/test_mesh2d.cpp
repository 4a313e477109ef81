// Meshing a domain from its boundary (mesh_domain2d), tested by properties: valid counter-
// clockwise triangles, area and boundary kept, region refs, element count in a range for a
// uniform size (equilateral triangles of side h have area √3/4 h²), quality bounded below,
// determinism. Also the real 2D domains of ../shared/data/2d.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <string>

#include "core/predicates.hpp"
#include "generate/domain2d.hpp"
#include "generate/mesh2d.hpp"
#include "generate/square_loop.hpp"
#include "io/mesh_file.hpp"
#include "mesh/check.hpp"

using namespace riemesh;
using test::add_square;

namespace {

std::map<int, double> region_areas(const Mesh& m) {
  std::map<int, double> out;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const double o = orient2d(&m.coords[2 * m.triangles[3 * t]], &m.coords[2 * m.triangles[3 * t + 1]],
                              &m.coords[2 * m.triangles[3 * t + 2]]);
    EXPECT_GT(o, 0);
    out[m.tri_ref[t]] += 0.5 * o;
  }
  return out;
}

double q_min(const Mesh2dResult& r) { return r.report.passes.back().q_min; }

}  // namespace

TEST(Mesh2d, SquareKeepsItsBoundary) {
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 1, 10, true, 1);
  Mesh2dOptions o;
  o.adapt.hgrad = 0;
  const Mesh2dResult r = mesh_domain2d(b, o);
  const auto a = region_areas(r.mesh);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_NEAR(a.at(1), 1.0, 1e-12);
  EXPECT_EQ(r.mesh.num_edges(), 40u);  // the 40 given edges, not split
  std::set<std::pair<double, double>> given, on_edges;
  for (std::size_t v = 0; v < b.num_vertices(); ++v) given.insert({b.coords[2 * v], b.coords[2 * v + 1]});
  for (const Id v : r.mesh.edges) on_edges.insert({r.mesh.coords[2 * v], r.mesh.coords[2 * v + 1]});
  EXPECT_EQ(given, on_edges);
  // Boundary edges of length 0.1: ~ 1 / (√3/4 · 0.01) ≈ 231 triangles; interior vertices exist.
  EXPECT_GT(r.mesh.num_triangles(), 150u);
  EXPECT_LT(r.mesh.num_triangles(), 350u);
  EXPECT_GT(q_min(r), 0.5);
}

TEST(Mesh2d, KeptBoundaryWritesOnlyItsRealCorners) {
  // A square (4 corners by angle) with a 40-gon circle hole (one ref, no corner), one of whose
  // vertices is a given Corner: the kept boundary was made of corners only (every vertex
  // required for the remesher), and a later adapt kept every new boundary point on the chords.
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 1, 4, true, 1);
  const auto first = static_cast<Id>(b.num_vertices());
  b.vert_ref.assign(b.num_vertices(), 0), b.vert_tag.assign(b.num_vertices(), kTagNone);
  b.edge_tag.assign(b.num_edges(), kTagNone);
  for (int k = 0; k < 40; ++k) {
    const double t = -2.0 * std::numbers::pi * k / 40;  // clockwise: a hole
    b.coords.insert(b.coords.end(), {0.5 + 0.25 * std::cos(t), 0.5 + 0.25 * std::sin(t)});
    b.vert_ref.push_back(0);
    b.vert_tag.push_back(k == 7 ? kTagCorner : kTagNone);
    b.edges.insert(b.edges.end(), {first + k, first + (k + 1) % 40});
    b.edge_ref.push_back(2);
    b.edge_tag.push_back(kTagNone);
  }
  const Mesh2dResult r = mesh_domain2d(b, {});
  std::set<std::pair<double, double>> corners;
  for (std::size_t v = 0; v < r.mesh.num_vertices(); ++v)
    if (r.mesh.vert_tag[v] & kTagCorner)
      corners.insert({r.mesh.coords[2 * v], r.mesh.coords[2 * v + 1]});
  std::set<std::pair<double, double>> expected = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  expected.insert({b.coords[2 * (first + 7)], b.coords[2 * (first + 7) + 1]});
  EXPECT_EQ(corners, expected);
}

TEST(Mesh2d, UniformSizeRemeshesTheBoundaryAndHolesStayEmpty) {
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 1, 3, true, 1);
  add_square(b, 0.25, 0.25, 2, false, 2);  // clockwise: a hole
  Mesh2dOptions o;
  o.hsiz = 0.04;
  o.keep_boundary = false;
  const Mesh2dResult r = mesh_domain2d(b, o);
  EXPECT_EQ(r.regions, 1);
  EXPECT_EQ(r.holes, 1);
  const auto a = region_areas(r.mesh);
  EXPECT_NEAR(a.at(1), 1.0 - 0.0625, 1e-9);  // straight sides: reconstruction is exact
  // (1 − 0.0625) / (√3/4 · 0.04²) ≈ 1353 triangles.
  EXPECT_GT(r.mesh.num_triangles(), 1000u);
  EXPECT_LT(r.mesh.num_triangles(), 1900u);
  EXPECT_GT(q_min(r), 0.5);
  EXPECT_GT(r.report.passes.back().len_in, 0.8);  // unit edges in the metric
  EXPECT_EQ(mesh_domain2d(b, o).mesh.coords, r.mesh.coords);  // deterministic
}

TEST(Mesh2d, AnisotropicMetricCutsTheCoarseBoundaryFirst) {
  // A constant metric, sizes 0.1 and 0.001 turned by 30°, on the unit square given by 4 edges
  // per side (each about 125 units long in the metric): the boundary is cut to the sizes before
  // the field points, its corners kept; the edges come out near unit length (99.2%; 72.8% when
  // the field points kept away from the long edges and adapt2d cut them afterwards, leaving
  // needles along them), the count near (4/√3) C, C = 1e4 (23,560; 34,854 before).
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 1, 4, true, 1);
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const double l1 = 1 / (0.1 * 0.1), l2 = 1 / (0.001 * 0.001);
  const SymMat2 m{{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c}};
  Mesh2dOptions o;
  o.metric.assign(b.num_vertices(), m);
  o.keep_boundary = false;
  o.adapt.hgrad = 0.0;
  const Mesh2dResult r = mesh_domain2d(b, o);
  EXPECT_NEAR(region_areas(r.mesh).at(1), 1.0, 1e-9);
  std::size_t in = 0, edges = 0;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id u = r.mesh.triangles[3 * t + i], v = r.mesh.triangles[3 * t + (i + 1) % 3];
      const Vec2 d{{r.mesh.coords[2 * v] - r.mesh.coords[2 * u],
                    r.mesh.coords[2 * v + 1] - r.mesh.coords[2 * u + 1]}};
      const double l = std::sqrt(quadratic(m, d));
      ++edges, in += l > std::sqrt(0.5) && l < std::sqrt(2.0);
    }
  EXPECT_GT(static_cast<double>(in) / static_cast<double>(edges), 0.97);
  const double best = 4 / std::sqrt(3.0) * 1e4;
  EXPECT_NEAR(static_cast<double>(r.mesh.num_triangles()), best, 0.1 * best);
  for (const double x : {0.0, 1.0})
    for (const double y : {0.0, 1.0}) {  // the square's corners are still vertices
      bool found = false;
      for (std::size_t v = 0; v < r.mesh.num_vertices(); ++v)
        found |= r.mesh.coords[2 * v] == x && r.mesh.coords[2 * v + 1] == y;
      EXPECT_TRUE(found) << x << " " << y;
    }
}

TEST(Mesh2d, SubdomainsKeepDistinctRefs) {
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 1, 4, true, 1);
  add_square(b, 0.25, 0.5, 2, true, 2);  // counter-clockwise inside: a subdomain
  Mesh2dOptions o;
  o.hsiz = 0.05;
  const Mesh2dResult r = mesh_domain2d(b, o);
  EXPECT_EQ(r.regions, 2);
  const auto a = region_areas(r.mesh);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_NEAR(a.at(1), 0.75, 1e-9);
  EXPECT_NEAR(a.at(2), 0.25, 1e-9);
}

TEST(Mesh2d, SharedDataDomains) {
  for (const char* name : {"aile", "lac-leman", "naca0012"}) {
    const Mesh full = read_mesh(std::string(RIEMESH_SHARED_DATA) + "/2d/" + name + ".mesh");
    const Mesh b = extract_boundary2d(full);
    Mesh2dOptions o;
    o.adapt.hgrad = 0;
    const Mesh2dResult r = mesh_domain2d(b, o);
    double area = 0, expected = 0;
    for (const auto& [ref, v] : region_areas(r.mesh)) area += v;
    for (const auto& [ref, v] : region_areas(full)) expected += v;
    EXPECT_NEAR(area, expected, 1e-9 * expected) << name;  // the same boundary, kept exactly
    EXPECT_EQ(r.mesh.num_edges(), b.num_edges()) << name;
    EXPECT_GT(q_min(r), 0.5) << name;
  }
}

TEST(Mesh2d, SizesFarBeyondTheDomainGiveItsCoarsestMesh) {
  // --hsiz 1e100 on the lake of Geneva (40 across): its metric 1e-200 has a determinant that
  // underflows, and the unit lattice refused it as "not positive definite", blaming the domain.
  // The size is clamped to 1e10 times the domain: the coarsest mesh, as from --hsiz 1e12.
  const Mesh full = read_mesh(RIEMESH_SHARED_DATA "/2d/lac-leman.mesh");
  const Mesh b = extract_boundary2d(full);
  std::size_t coarsest = 0;
  for (const double h : {1e12, 1e100, 1e150}) {
    Mesh2dOptions o;
    o.hsiz = h;
    const Mesh2dResult r = mesh_domain2d(b, o);
    EXPECT_TRUE(check_mesh(r.mesh).valid()) << h;
    if (coarsest == 0) coarsest = r.mesh.num_triangles();
    EXPECT_EQ(r.mesh.num_triangles(), coarsest) << h;
    EXPECT_LT(r.mesh.num_triangles(), full.num_triangles() / 5) << h;
  }
}

TEST(Mesh2d, TwelveCircularHoles) {
  // The unit square with 12 disjoint clockwise circles (radius 0.02-0.08, edges ~0.01): one
  // region, 12 holes, a valid mesh whose area is that of the polygons (boundary remeshed on its
  // smooth reconstruction: equal to within the chord error).
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 1, 1, true, 1);
  std::vector<std::array<double, 3>> circles;
  double expected = 1.0;
  while (circles.size() < 12) {
    const double x = 0.1 + 0.8 * u(rng), y = 0.1 + 0.8 * u(rng), r = 0.02 + 0.06 * u(rng);
    bool fits = std::min({x - r, y - r, 1 - x - r, 1 - y - r}) > 0.01;
    for (const auto& c : circles) fits = fits && std::hypot(x - c[0], y - c[1]) > r + c[2] + 0.01;
    if (!fits) continue;
    circles.push_back({x, y, r});
    const int n = std::max(8, static_cast<int>(2 * M_PI * r / 0.01));
    const Id first = static_cast<Id>(b.num_vertices());
    for (int k = 0; k < n; ++k) {
      const double th = -2 * M_PI * k / n;  // clockwise: a hole
      b.coords.push_back(x + r * std::cos(th));  // (push_back: GCC 12 warns falsely on insert)
      b.coords.push_back(y + r * std::sin(th));
      b.edges.push_back(first + k);
      b.edges.push_back(first + (k + 1) % n);
      b.edge_ref.push_back(2);
    }
    expected -= 0.5 * n * r * r * std::sin(2 * M_PI / n);  // the polygon's area
  }
  Mesh2dOptions o;
  o.hsiz = 0.02;
  o.keep_boundary = false;
  const Mesh2dResult r = mesh_domain2d(b, o);
  EXPECT_EQ(r.regions, 1);
  EXPECT_EQ(r.holes, 12);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  double area = 0;
  for (const auto& [ref, v] : region_areas(r.mesh)) area += v;
  EXPECT_NEAR(area, expected, 2e-3);
  EXPECT_GT(q_min(r), 0.5);
}
