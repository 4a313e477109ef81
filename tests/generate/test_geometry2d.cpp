// Parametric curves and their meshing (curve2d.hpp), and a planar geometry's boundary meshed for
// mesh_domain2d (geometry2d.hpp): nodes on the exact curves, chords within hausd, counts from the
// metric length, orientation, refs, shared curves as interfaces, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/curve2d.hpp"
#include "generate/geometry2d.hpp"
#include "generate/mesh2d.hpp"
#include "mesh/check.hpp"

using namespace riemesh;

namespace {

CurveSizing uniform(double h, double hausd = 0.0) {
  CurveSizing s;
  s.size = [h](double) { return h; };
  s.hausd = hausd;
  return s;
}

/// Unit square (Physical Curve 20, Physical Surface 7) with a circular hole of radius r at
/// (0.5, 0.5) made of four arcs (curves 5-8, loop 2).
Geometry2d square_with_hole(double r) {
  Geometry2d g;
  const double xy[9][2] = {{0, 0},         {1, 0},         {1, 1},
                           {0, 1},         {0.5, 0.5},     {0.5 + r, 0.5},
                           {0.5, 0.5 + r}, {0.5 - r, 0.5}, {0.5, 0.5 - r}};
  for (int i = 0; i < 9; ++i)
    g.points.push_back({i + 1, xy[i][0], xy[i][1], 0.0, std::size_t(i + 1)});
  for (int i = 0; i < 4; ++i)
    g.curves.push_back({i + 1, GeoCurveKind::kLine, {i + 1, (i + 1) % 4 + 1}, 10});
  for (int i = 0; i < 4; ++i)
    g.curves.push_back({i + 5, GeoCurveKind::kCircle, {i + 6, 5, (i + 1) % 4 + 6}, 11});
  g.loops.push_back({1, {1, 2, 3, 4}, 13});
  g.loops.push_back({2, {5, 6, 7, 8}, 14});
  g.surfaces.push_back({1, {1, 2}, 15});
  g.physical_curves.push_back({20, "outer", {1, 2, 3, 4}, 16});
  g.physical_surfaces.push_back({7, "", {1}, 17});
  return g;
}

double twice_area(const Mesh& m, Id a, Id b, Id c) {
  return orient2d(&m.coords[2 * a], &m.coords[2 * b], &m.coords[2 * c]);
}

}  // namespace

TEST(Curve2d, ArcStaysOnItsCircleAndDerivativesAgree) {
  const Vec2 c{{0.3, -0.2}}, a{{1.3, -0.2}}, b{{0.3, 0.8}};
  const Curve2d arc = Curve2d::arc(a, c, b);
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    const CurveSample s = arc.at(t);
    EXPECT_NEAR(norm(s.p - c), 1.0, 1e-15);
    const double e = 1e-6;
    const Vec2 fd = (arc.at(t + e).p - arc.at(t - e).p) / (2 * e);
    EXPECT_NEAR(norm(fd - s.d1), 0.0, 1e-8);
    const Vec2 fd2 = (arc.at(t + e).d1 - arc.at(t - e).d1) / (2 * e);
    EXPECT_NEAR(norm(fd2 - s.d2), 0.0, 1e-7);
  }
  EXPECT_NEAR(norm(arc.at(1.0).p - b), 0.0, 1e-15);
  // The shorter way: from (1, 0) to (0, 1) counter-clockwise, through 45 degrees.
  EXPECT_NEAR(arc.at(0.5).p[0] - c[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(norm(Curve2d::arc(b, c, a).at(0.5).p - arc.at(0.5).p), 0.0, 1e-15);
}

TEST(Curve2d, HalfCircleTurnsCounterClockwiseAsGmsh) {
  const Vec2 c{{0.5, 0.5}}, a{{0.7, 0.5}}, b{{0.3, 0.5}};
  EXPECT_NEAR(norm(Curve2d::arc(a, c, b).at(0.5).p - Vec2{{0.5, 0.7}}), 0.0, 1e-15);
  EXPECT_NEAR(norm(Curve2d::arc(b, c, a).at(0.5).p - Vec2{{0.5, 0.3}}), 0.0, 1e-15);
}

TEST(Curve2d, SplineThroughItsPointsClosedOneSmooth) {
  const std::vector<Vec2> pts = {{{0, 0}}, {{1, 0.5}}, {{2, -0.3}}, {{3, 1}}};
  const Curve2d open = Curve2d::spline(pts, false);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(norm(open.at(i / 3.0).p - pts[i]), 0.0, 1e-15);
  const std::vector<Vec2> ring = {{{1, 0}}, {{0, 1}}, {{-1, 0}}, {{0, -1}}, {{1, 0}}};
  const Curve2d closed = Curve2d::spline(ring, true);
  // C1 across the join: the tangent at t = 0 and at t = 1 agree.
  EXPECT_NEAR(norm(closed.at(0.0).d1 - closed.at(1.0).d1), 0.0, 1e-12);
  EXPECT_NEAR(norm(closed.at(1.0).p - ring[0]), 0.0, 1e-15);
  // Finite differences agree with the derivatives inside a piece.
  const double t = 0.37, e = 1e-6;
  EXPECT_NEAR(norm((closed.at(t + e).p - closed.at(t - e).p) / (2 * e) - closed.at(t).d1), 0, 1e-7);
}

TEST(MeshCurve, SegmentCountsFollowTheMetricLength) {
  const Curve2d seg = Curve2d::segment(Vec2{{0, 0}}, Vec2{{1, 0}});
  std::vector<double> t = mesh_curve(seg, uniform(0.1));
  ASSERT_EQ(t.size(), 11u);
  for (std::size_t k = 0; k < t.size(); ++k) EXPECT_NEAR(t[k], k / 10.0, 1e-12);
  // Sizes from 0.01 to 0.1 linearly: metric length ∫ dx / h = ln(10) / 0.09 = 25.58 -> 26.
  CurveSizing graded;
  graded.size = [](double s) { return 0.01 + 0.09 * s; };
  t = mesh_curve(seg, graded);
  EXPECT_EQ(t.size(), 27u);
  EXPECT_LT(t[1], t.back() - t[t.size() - 2]);  // short edges at the fine end
  EXPECT_THROW(mesh_curve(seg, uniform(0.0)), InputError);
  EXPECT_THROW(mesh_curve(seg, uniform(1e-8)), InputError);  // over 10^7 segments: refused
}

TEST(MeshCurve, ArcChordsWithinHausd) {
  const Curve2d arc = Curve2d::arc(Vec2{{2, 0}}, Vec2{{0, 0}}, Vec2{{0, 2}});  // r = 2, 90°
  for (const double hausd : {1e-2, 1e-3, 1e-4}) {
    const std::vector<double> t = mesh_curve(arc, uniform(10.0, hausd));
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      EXPECT_LE(chord_distance(arc, t[k], t[k + 1]), hausd);
    // Sagitta h² / (8 r) = hausd: segments of sqrt(8 r hausd) = 4 sqrt(hausd) at most, over a
    // length of pi: about pi / (4 sqrt(hausd)) of them.
    const double best = std::numbers::pi / (4.0 * std::sqrt(hausd));
    EXPECT_GE(static_cast<double>(t.size() - 1), best - 0.5) << hausd;
    EXPECT_LE(static_cast<double>(t.size() - 1), 1.05 * best + 2) << hausd;
  }
}

TEST(GeometryBoundary, SquareWithACircularHole) {
  GeometryMeshOptions o;
  o.hsiz = 0.05;
  const GeometryBoundary b = mesh_geometry_boundary(square_with_hole(0.2), o);
  const Mesh& d = b.domain;
  EXPECT_EQ(b.curves, 8);
  std::size_t on_circle = 0;
  for (std::size_t v = 0; v < d.num_vertices(); ++v) {
    const double r = std::hypot(d.coords[2 * v] - 0.5, d.coords[2 * v + 1] - 0.5);
    if (std::abs(r - 0.2) < 1e-3) {
      EXPECT_NEAR(r, 0.2, 1e-15);
      ++on_circle;
    }
  }
  // Circumference 1.257 at size 0.05: 24 to 28 segments (four arcs rounded apart).
  EXPECT_GE(on_circle, 24u);
  EXPECT_LE(on_circle, 28u);
  std::map<int, int> refs;
  for (const int r : d.edge_ref) ++refs[r];
  EXPECT_EQ(refs[20], 80);  // 4 sides of 20 edges, Physical Curve 20
  EXPECT_EQ(refs[5] + refs[6] + refs[7] + refs[8], static_cast<int>(on_circle));  // curve ids
  // Outer loop counter-clockwise, hole clockwise: the edges' signed areas add up to the domain's.
  double area = 0.0;
  for (std::size_t e = 0; e < d.num_edges(); ++e)
    area +=
        0.5 * cross(Vec2{{d.coords[2 * d.edges[2 * e]], d.coords[2 * d.edges[2 * e] + 1]}},
                    Vec2{{d.coords[2 * d.edges[2 * e + 1]], d.coords[2 * d.edges[2 * e + 1] + 1]}});
  EXPECT_NEAR(area, 1.0 - std::numbers::pi * 0.04, 2e-3);

  Mesh2dOptions mo;
  mo.adapt.hgrad = 0.0;
  Mesh2dResult r = mesh_domain2d(d, mo);
  assign_surface_refs(b, r.mesh);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  double tri_area = 0.0;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t) {
    EXPECT_EQ(r.mesh.tri_ref[t], 7);  // Physical Surface 7
    tri_area += 0.5 * twice_area(r.mesh, r.mesh.triangles[3 * t], r.mesh.triangles[3 * t + 1],
                                 r.mesh.triangles[3 * t + 2]);
  }
  EXPECT_NEAR(tri_area, area, 1e-12);
  EXPECT_EQ(r.holes, 1);
  // Corners: the 8 points of the geometry (square corners, arc ends) only.
  keep_point_corners(b, r.mesh);
  int corners = 0;
  for (const std::uint8_t tag : r.mesh.vert_tag) corners += (tag & kTagCorner) != 0;
  EXPECT_EQ(corners, 8);
}

TEST(GeometryBoundary, FilledHoleIsASecondSurfaceWithItsRef) {
  Geometry2d g = square_with_hole(0.2);
  g.surfaces.push_back({2, {2}, 18});  // the disk
  g.physical_surfaces.clear();
  GeometryMeshOptions o;
  o.hsiz = 0.1;
  const GeometryBoundary b = mesh_geometry_boundary(g, o);
  Mesh2dOptions mo;
  mo.adapt.hgrad = 0.0;
  Mesh2dResult r = mesh_domain2d(b.domain, mo);
  assign_surface_refs(b, r.mesh);
  std::map<int, double> area;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t)
    area[r.mesh.tri_ref[t]] +=
        0.5 * twice_area(r.mesh, r.mesh.triangles[3 * t], r.mesh.triangles[3 * t + 1],
                         r.mesh.triangles[3 * t + 2]);
  ASSERT_EQ(area.size(), 2u);
  EXPECT_NEAR(area[1] + area[2], 1.0, 1e-12);
  EXPECT_NEAR(area[2], std::numbers::pi * 0.04, 2e-3);
  EXPECT_EQ(r.holes, 0);
}

TEST(GeometryBoundary, PointSizesAndCurvature) {
  Geometry2d g = square_with_hole(0.02);  // a small hole: the curvature decides there
  for (GeoPoint& p : g.points) p.lc = 0.1;
  GeometryMeshOptions o;
  o.hausd = 1e-4;
  const GeometryBoundary b = mesh_geometry_boundary(g, o);
  std::map<int, int> refs;
  for (const int r : b.domain.edge_ref) ++refs[r];
  EXPECT_EQ(refs[20], 40);  // sides at lc = 0.1
  // Circle r = 0.02 within 1e-4: sagitta h²/(8r) <= 1e-4 -> h <= 0.004, ~32 or more segments
  // (the lc 0.1 would give 2).
  EXPECT_GE(refs[5] + refs[6] + refs[7] + refs[8], 30);
  EXPECT_NEAR(b.hausd, 1e-4, 0.0);
}

TEST(GeometryBoundary, SizesFarTooSmallAreRefusedBeforeTheCurvesAreMeshed) {
  // The square with a hole, area about 0.87: at 1e-5 at least ~2e9 vertices (refused at once,
  // not after meshing 4e5 boundary nodes); at 1e-4 the lower bound, ~2e7, lets it through (the
  // domain's own complexity check then decides, with the boundary meshed).
  GeometryMeshOptions o;
  o.hsiz = 1e-5;
  try {
    mesh_geometry_boundary(square_with_hole(0.2), o);
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("line ", 0), 0u) << what;
    EXPECT_NE(what.find("Plane Surface 1: its sizes (at most 1e-05) ask for more than 1e+08 "
                        "vertices over its area (about 0.87"),
              std::string::npos)
        << what;
  }
  Geometry2d g = square_with_hole(0.2);
  for (GeoPoint& p : g.points) p.lc = 1e-6;  // the points' lc, clamped by hmin
  o = GeometryMeshOptions{};
  EXPECT_THROW(mesh_geometry_boundary(g, o), InputError);
  o.hsiz = 1e-4;
  EXPECT_NO_THROW(mesh_geometry_boundary(square_with_hole(0.2), o));
}

TEST(GeometryBoundary, Errors) {
  GeometryMeshOptions o;
  Geometry2d g = square_with_hole(0.2);
  g.loops[0].curves = {1, 3, 2, 4};
  try {
    mesh_geometry_boundary(g, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "line 13: Curve Loop 1: curve 3 starts at point 3, not at point 2 where the curve "
              "before it ends");
  }
  g = square_with_hole(0.2);
  g.loops[0].curves = {1, 2, 3};
  EXPECT_THROW(mesh_geometry_boundary(g, o), InputError);  // not closed
  g = square_with_hole(0.2);
  g.surfaces.clear();
  EXPECT_THROW(mesh_geometry_boundary(g, o), InputError);
  g = square_with_hole(0.2);
  for (int i = 4; i < 9; ++i) g.points[i].x += 2.5;  // the hole outside
  EXPECT_THROW(mesh_geometry_boundary(g, o), InputError);
  g = square_with_hole(0.2);
  o.hmin = 0.2, o.hmax = 0.1;
  EXPECT_THROW(mesh_geometry_boundary(g, o), InputError);
  g = square_with_hole(0.2);
  g.surfaces.push_back({2, {1}, 19});  // on the square again: overlaps surface 1
  try {
    mesh_geometry_boundary(g, GeometryMeshOptions{});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "line 19: Plane Surface 2 overlaps Plane Surface 1: both lie on the same side of "
              "curve 1");
  }
  // A reversed curve in a loop is fine: the same loop, its last side walked backwards.
  g = square_with_hole(0.2);
  g.curves[3].points = {1, 4};
  g.loops[0].curves = {1, 2, 3, -4};
  EXPECT_NO_THROW(mesh_geometry_boundary(g, GeometryMeshOptions{}));
}
