// adapt3d keeps the input's Edges as lines with their refs (QA hunt 6 G2): several lines between
// the same two patches each keep their own ref, lines drawn inside one patch are kept (refined,
// moved and collapsed along themselves), and --nosurf gives the input's edges back exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/adapt3d.hpp"

using namespace riemesh;

namespace {

Vec3 point(const Mesh& m, Id v) {
  const std::size_t i = 3 * static_cast<std::size_t>(v);
  return Vec3{{m.coords[i], m.coords[i + 1], m.coords[i + 2]}};
}

/// The id of the vertex at p (exactly), or kNoId.
Id vertex_at(const Mesh& m, const Vec3& p) {
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    if (point(m, static_cast<Id>(v)) == p) return static_cast<Id>(v);
  return kNoId;
}

/// unit_cube(4) with the bottom face (z = 0) of ref 5 and the five others of ref 2, so that the
/// four bottom sides (Edges refs 1..4 of unit_cube: between ref 5 and ref 2 all four) are lines
/// between the same two patches, and the other eight cube edges lines inside patch 2. Added:
/// the top face's diagonal (0,0,1)-(1,1,1) (ref 20, straight, 4 edges inside the face), and an
/// L in the face y = 0 (ref 31: (¼,0,¼) up to (¼,0,¾), then across to (¾,0,¾)).
Mesh cube_with_lines() {
  Mesh in = unit_cube(4);
  for (std::size_t t = 0; t < in.num_triangles(); ++t)
    if (in.tri_ref[t] != 5) in.tri_ref[t] = 2;
  const auto add = [&in](const Vec3& a, const Vec3& b, int ref) {
    const Id va = vertex_at(in, a), vb = vertex_at(in, b);
    ASSERT_NE(va, kNoId);
    ASSERT_NE(vb, kNoId);
    in.edges.insert(in.edges.end(), {va, vb});
    in.edge_ref.push_back(ref);
    in.edge_tag.push_back(kTagNone);
  };
  for (int i = 0; i < 4; ++i)
    add(Vec3{{0.25 * i, 0.25 * i, 1.0}}, Vec3{{0.25 * (i + 1), 0.25 * (i + 1), 1.0}}, 20);
  for (int i = 1; i < 3; ++i) {
    add(Vec3{{0.25, 0.0, 0.25 * i}}, Vec3{{0.25, 0.0, 0.25 * (i + 1)}}, 31);
    add(Vec3{{0.25 * i, 0.0, 0.75}}, Vec3{{0.25 * (i + 1), 0.0, 0.75}}, 31);
  }
  return in;
}

double distance_to_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
  return norm(a + t * d - p);
}

/// Whether p lies on an input edge of ref `ref` (within 1e-12).
bool on_input_line(const Mesh& in, const Vec3& p, int ref) {
  for (std::size_t f = 0; f < in.num_edges(); ++f)
    if (in.edge_ref[f] == ref &&
        distance_to_segment(p, point(in, in.edges[2 * f]), point(in, in.edges[2 * f + 1])) < 1e-12)
      return true;
  return false;
}

/// Checks that every output edge lies on the input's line of its ref (its ends and three inner
/// points: on straight pieces, the edge then lies on them; inner vertices slide along the line,
/// so an output edge may straddle two input edges), and returns the total length of the output
/// edges per ref.
std::map<int, double> lengths_on_input_lines(const Mesh& in, const Mesh& out) {
  std::map<int, double> len;
  for (std::size_t e = 0; e < out.num_edges(); ++e) {
    const Vec3 p = point(out, out.edges[2 * e]), q = point(out, out.edges[2 * e + 1]);
    const int ref = out.edge_ref[e];
    bool on = true;
    for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0})
      on = on && on_input_line(in, p + t * (q - p), ref);
    EXPECT_TRUE(on) << "output edge " << e << " (ref " << ref << ") off the input's line";
    len[ref] += norm(q - p);
  }
  return len;
}

std::map<int, double> input_lengths(const Mesh& in) {
  std::map<int, double> len;
  for (std::size_t e = 0; e < in.num_edges(); ++e)
    len[in.edge_ref[e]] += norm(point(in, in.edges[2 * e + 1]) - point(in, in.edges[2 * e]));
  return len;
}

Adapt3dResult adapt_at(const Mesh& in, double h, bool keep_surface) {
  Adapt3dOptions o;
  o.hgrad = 0.0;
  o.keep_surface = keep_surface;
  return adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(h)), o);
}

}  // namespace

// Refined (h = 0.08, lines of 0.25-edges split) and coarsened (h = 0.6): every output edge lies
// on an input edge of its ref and the edges of each ref cover its input line exactly. Before:
// the four bottom sides came back with one ref (that of the last input edge between patches 5
// and 2), and the eight cube edges inside patch 2, the diagonal and the L were dropped.
TEST(Adapt3dLines, EveryLineKeepsItsRef) {
  const Mesh in = cube_with_lines();
  const std::map<int, double> expected = input_lengths(in);
  ASSERT_EQ(expected.size(), 14u);  // 12 cube edges, the diagonal, the L
  for (const double h : {0.08, 0.6}) {
    SCOPED_TRACE(h);
    const Adapt3dResult r = adapt_at(in, h, false);
    EXPECT_TRUE(check_mesh(r.mesh).valid());
    const std::map<int, double> len = lengths_on_input_lines(in, r.mesh);
    ASSERT_EQ(len.size(), expected.size());
    for (const auto& [ref, l] : expected) EXPECT_NEAR(len.at(ref), l, 1e-12) << "ref " << ref;
    if (h < 0.25) {  // the lines were split, and their inner vertices moved only along them
      EXPECT_GT(r.mesh.num_edges(), 2 * in.num_edges());
    }
  }
}

// The line inside a patch stays a line of the boundary triangles: no boundary triangle crosses
// the top face's diagonal (its vertices are on one side of it or on it).
TEST(Adapt3dLines, NoBoundaryTriangleCrossesALineInsideAPatch) {
  const Adapt3dResult r = adapt_at(cube_with_lines(), 0.08, false);
  int crossing = 0;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t) {
    bool above = false, below = false, top = true;
    for (int k = 0; k < 3; ++k) {
      const Vec3 p = point(r.mesh, r.mesh.triangles[3 * t + k]);
      top = top && p[2] == 1.0;
      above = above || p[1] - p[0] > 1e-12;
      below = below || p[1] - p[0] < -1e-12;
    }
    crossing += top && above && below;
  }
  EXPECT_EQ(crossing, 0);
}

// --nosurf: the boundary is kept, and so are the edges: exactly the input's, with their refs.
TEST(Adapt3dLines, KeptSurfaceGivesTheInputEdgesBack) {
  const Mesh in = cube_with_lines();
  const Adapt3dResult r = adapt_at(in, 0.15, true);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  using Edge = std::tuple<std::array<double, 3>, std::array<double, 3>, int>;
  const auto edges = [](const Mesh& m) {
    std::set<Edge> out;
    for (std::size_t e = 0; e < m.num_edges(); ++e) {
      std::array<double, 3> a{}, b{};
      for (int k = 0; k < 3; ++k)
        a[k] = point(m, m.edges[2 * e])[k], b[k] = point(m, m.edges[2 * e + 1])[k];
      out.insert({std::min(a, b), std::max(a, b), m.edge_ref[e]});
    }
    return out;
  };
  EXPECT_EQ(edges(r.mesh), edges(in));
  EXPECT_EQ(r.mesh.num_edges(), in.num_edges());
}
