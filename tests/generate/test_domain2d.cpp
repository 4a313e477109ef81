// Boundary recovery and region removal (triangulate_domain2d): small hard cases checked by
// properties — every boundary edge is an edge of the result, the area equals the area enclosed by
// the loops (shoelace), triangles are counter-clockwise, non-boundary edges are locally Delaunay
// (constrained Delaunay), holes and subdomains follow the orientation rules or the hole points.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/cdt2d.hpp"
#include "generate/domain2d.hpp"

using namespace riemesh;

namespace {

/// Appends a closed loop through the points (in the given order) with edge ref `ref`.
void add_loop(Mesh& m, const std::vector<std::array<double, 2>>& pts, int ref) {
  const Id first = static_cast<Id>(m.num_vertices());
  const Id n = static_cast<Id>(pts.size());
  for (const auto& p : pts) m.coords.insert(m.coords.end(), {p[0], p[1]});
  for (Id i = 0; i < n; ++i) {
    m.edges.insert(m.edges.end(), {first + i, first + (i + 1) % n});
    m.edge_ref.push_back(ref);
  }
}

Mesh planar() {
  Mesh m;
  m.dim = 2;
  return m;
}

std::vector<std::array<double, 2>> square(double x0, double y0, double s, bool ccw) {
  std::vector<std::array<double, 2>> p = {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
  if (!ccw) std::reverse(p.begin(), p.end());
  return p;
}

double shoelace(const std::vector<std::array<double, 2>>& p) {
  double a = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& u = p[i];
    const auto& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - u[1] * v[0];
  }
  return 0.5 * a;
}

/// Area per triangle ref.
std::map<int, double> areas(const Mesh& m) {
  std::map<int, double> out;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const double* a = &m.coords[2 * m.triangles[3 * t]];
    const double* b = &m.coords[2 * m.triangles[3 * t + 1]];
    const double* c = &m.coords[2 * m.triangles[3 * t + 2]];
    const double o = orient2d(a, b, c);
    EXPECT_GT(o, 0) << "triangle " << t;
    out[m.tri_ref[t]] += 0.5 * o;
  }
  return out;
}

double total(const std::map<int, double>& a) {
  double s = 0;
  for (const auto& [ref, v] : a) s += v;
  return s;
}

/// Every edge of m.edges is a triangle edge; edges that are not boundary edges are locally
/// Delaunay.
void expect_conforming_cdt(const Mesh& m) {
  std::map<std::uint64_t, std::vector<std::pair<std::size_t, int>>> sides;
  for (std::size_t t = 0; t < m.num_triangles(); ++t)
    for (int s = 0; s < 3; ++s)
      sides[edge_key(m.triangles[3 * t + (s + 1) % 3], m.triangles[3 * t + (s + 2) % 3])].push_back(
          {t, s});
  std::set<std::uint64_t> constrained;
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const std::uint64_t k = edge_key(m.edges[2 * e], m.edges[2 * e + 1]);
    EXPECT_TRUE(sides.count(k)) << "boundary edge " << e << " missing";
    constrained.insert(k);
  }
  auto pt = [&](Id v) { return &m.coords[2 * v]; };
  for (const auto& [k, s] : sides) {
    ASSERT_LE(s.size(), 2u);
    if (s.size() == 1) {
      EXPECT_TRUE(constrained.count(k)) << "an edge on the border of the mesh is not a boundary edge";
      continue;
    }
    if (constrained.count(k)) continue;
    const Id* t = &m.triangles[3 * s[0].first];
    const Id q = m.triangles[3 * s[1].first + s[1].second];
    EXPECT_LE(incircle(pt(t[0]), pt(t[1]), pt(t[2]), pt(q)), 0);
  }
}

}  // namespace

TEST(Domain2d, SquareWithClockwiseHole) {
  Mesh m = planar();
  add_loop(m, square(0, 0, 4, true), 1);
  add_loop(m, square(1, 1, 1, false), 2);
  const Domain2d d = triangulate_domain2d(m, {});
  EXPECT_EQ(d.regions, 1);
  EXPECT_EQ(d.holes, 1);
  const auto a = areas(d.mesh);
  ASSERT_EQ(a.size(), 1u);
  EXPECT_DOUBLE_EQ(a.at(1), 15.0);
  EXPECT_EQ(d.mesh.num_edges(), 8u);
  expect_conforming_cdt(d.mesh);
  // No holes: the clockwise loop bounds a subdomain of its own.
  const Domain2d n = triangulate_domain2d(m, {}, InsertionOrder::kBrio, true);
  EXPECT_EQ(n.regions, 2);
  EXPECT_EQ(n.holes, 0);
  const auto b = areas(n.mesh);
  EXPECT_DOUBLE_EQ(b.at(1), 15.0);
  EXPECT_DOUBLE_EQ(b.at(2), 1.0);
}

TEST(Domain2d, CounterClockwiseInnerLoopIsASubdomain) {
  Mesh m = planar();
  add_loop(m, square(0, 0, 4, true), 1);
  add_loop(m, square(1, 1, 1, true), 2);
  const Domain2d d = triangulate_domain2d(m, {});
  EXPECT_EQ(d.regions, 2);
  EXPECT_EQ(d.holes, 0);
  const auto a = areas(d.mesh);
  EXPECT_DOUBLE_EQ(a.at(1), 15.0);  // region of the outer loop's first edge
  EXPECT_DOUBLE_EQ(a.at(2), 1.0);
  expect_conforming_cdt(d.mesh);
  // A hole point overrides the orientation rule.
  const double hole[] = {1.5, 1.5};
  const Domain2d h = triangulate_domain2d(m, hole);
  EXPECT_EQ(h.regions, 1);
  EXPECT_DOUBLE_EQ(total(areas(h.mesh)), 15.0);
  // Hole points alone decide: a point in the ring removes the ring, the clockwise rule is off.
  const double ring[] = {3.5, 3.5};
  EXPECT_DOUBLE_EQ(total(areas(triangulate_domain2d(m, ring).mesh)), 1.0);
}

TEST(Domain2d, InterfaceSplitsASquareIntoTwoRefs) {
  // Outer loop (0,0)-(2,0)-(2,1)-(0,1) with midpoints (1,0), (1,1) and an interface (1,0)→(1,1).
  Mesh m = planar();
  add_loop(m, {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}}, 1);
  m.edges.insert(m.edges.end(), {1, 4});
  m.edge_ref.push_back(7);
  const Domain2d d = triangulate_domain2d(m, {});
  EXPECT_EQ(d.regions, 2);
  const auto a = areas(d.mesh);
  EXPECT_DOUBLE_EQ(a.at(1), 1.0);
  EXPECT_DOUBLE_EQ(a.at(2), 1.0);
  EXPECT_EQ(d.mesh.num_edges(), 7u);
  expect_conforming_cdt(d.mesh);
}

TEST(Domain2d, SpikyStarPolygonsNeedManyFlips) {
  // Star-shaped polygons with random radii in [0.05, 1]: many boundary edges are not Delaunay
  // edges of the vertices, and each crosses several. Also the same with the loop reversed
  // (nothing to mesh) and inside a bigger square as a hole.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> r(0.05, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<std::array<double, 2>> p;
    const int n = 50 + 10 * trial;
    for (int k = 0; k < n; ++k) {
      const double th = 2 * M_PI * k / n, rad = (k % 2) ? r(rng) : 1.0 - 0.9 * r(rng) * r(rng);
      p.push_back({rad * std::cos(th), rad * std::sin(th)});
    }
    Mesh m = planar();
    add_loop(m, p, 1);
    const Domain2d d = triangulate_domain2d(m, {});
    EXPECT_NEAR(total(areas(d.mesh)), shoelace(p), 1e-12);
    EXPECT_EQ(d.mesh.num_triangles(), std::size_t(n - 2));
    expect_conforming_cdt(d.mesh);

    std::reverse(p.begin(), p.end());
    Mesh holed = planar();
    add_loop(holed, square(-2, -2, 4, true), 1);
    add_loop(holed, p, 2);
    const Domain2d h = triangulate_domain2d(holed, {});
    EXPECT_NEAR(total(areas(h.mesh)), 16.0 + shoelace(p), 1e-12);
    expect_conforming_cdt(h.mesh);
  }
}

TEST(Domain2d, CocircularBoundary) {
  // A regular 64-gon (all vertices cocircular) with a regular 16-gon hole of the same centre.
  std::vector<std::array<double, 2>> outer, inner;
  for (int k = 0; k < 64; ++k) outer.push_back({std::cos(2 * M_PI * k / 64), std::sin(2 * M_PI * k / 64)});
  for (int k = 16; k > 0; --k)
    inner.push_back({0.5 * std::cos(2 * M_PI * k / 16), 0.5 * std::sin(2 * M_PI * k / 16)});
  Mesh m = planar();
  add_loop(m, outer, 1);
  add_loop(m, inner, 2);
  const Domain2d d = triangulate_domain2d(m, {});
  EXPECT_EQ(d.holes, 1);
  EXPECT_NEAR(total(areas(d.mesh)), shoelace(outer) + shoelace(inner), 1e-12);
  expect_conforming_cdt(d.mesh);
}

TEST(Domain2d, ErrorsNameTheDefect) {
  auto message = [](const Mesh& m) {
    try {
      triangulate_domain2d(m, {});
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  Mesh open = planar();
  add_loop(open, square(0, 0, 1, true), 1);
  open.edges.resize(6), open.edge_ref.resize(3);  // drop the last edge
  EXPECT_NE(message(open).find("open boundary: vertex 1 (0, 0) ends boundary edge 1"), std::string::npos) << message(open);

  Mesh bowtie = planar();
  add_loop(bowtie, {{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 1);
  const std::string cross = message(bowtie);
  EXPECT_NE(cross.find("cross near (0.5, 0.5)"), std::string::npos) << cross;

  Mesh on_edge = planar();
  add_loop(on_edge, square(0, 0, 2, true), 1);
  add_loop(on_edge, {{1, 0}, {1, -1}, {1.5, -1}}, 2);  // (1, 0) lies on the first edge
  EXPECT_NE(message(on_edge).find("lies on boundary edge 1"), std::string::npos) << message(on_edge);

  Mesh clockwise = planar();
  add_loop(clockwise, square(0, 0, 1, false), 1);
  EXPECT_NE(message(clockwise).find("nothing to mesh"), std::string::npos);

  Mesh m = planar();
  add_loop(m, square(0, 0, 1, true), 1);
  const double far[] = {5, 5};
  EXPECT_THROW(triangulate_domain2d(m, far), InputError);
}

TEST(Domain2d, ExtractBoundaryOrientsEdgesWithTheDomainOnTheLeft) {
  // Two triangles of the unit square; Edges given clockwise: extraction turns them.
  Mesh m = planar();
  m.coords = {0, 0, 1, 0, 1, 1, 0, 1};
  m.triangles = {0, 1, 2, 0, 2, 3};
  m.tri_ref = {1, 1};
  m.edges = {1, 0, 2, 1, 3, 2, 0, 3};
  m.edge_ref = {1, 2, 3, 4};
  const Mesh b = extract_boundary2d(m);
  EXPECT_EQ(b.edges, (std::vector<Id>{0, 1, 1, 2, 2, 3, 3, 0}));
  EXPECT_EQ(b.edge_ref, (std::vector<std::int32_t>{1, 2, 3, 4}));
  const Domain2d d = triangulate_domain2d(b, {});
  EXPECT_DOUBLE_EQ(total(areas(d.mesh)), 1.0);
  m.edges.clear(), m.edge_ref.clear();  // no Edges: the triangles' border
  EXPECT_EQ(extract_boundary2d(m).num_edges(), 4u);
}

TEST(Domain2d, EdgeGivenBothWaysIsAnInterface) {
  // Two unit squares side by side, each a counter-clockwise loop: the shared side appears as
  // (1,0)→(1,1) in the left loop and (1,1)→(1,0) in the right one. Two regions, the shared side
  // kept once.
  Mesh m = planar();
  m.coords = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};
  m.edges = {0, 1, 1, 2, 2, 3, 3, 0, 1, 4, 4, 5, 5, 2, 2, 1};
  m.edge_ref = {1, 2, 1, 1, 1, 1, 1, 2};
  const Domain2d d = triangulate_domain2d(m, {});
  EXPECT_EQ(d.regions, 2);
  EXPECT_EQ(d.holes, 0);
  const auto a = areas(d.mesh);
  EXPECT_DOUBLE_EQ(a.at(1), 1.0);
  EXPECT_DOUBLE_EQ(a.at(2), 1.0);
  EXPECT_EQ(d.mesh.num_edges(), 7u);
  expect_conforming_cdt(d.mesh);
}
