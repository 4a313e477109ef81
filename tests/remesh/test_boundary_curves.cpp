// Boundary curves: feature edges, corners, chaining, and the smooth reconstruction (analytic
// expectations on squares, circles and ellipses; counts derived from the real data files).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "mesh/fixtures.hpp"
#include "metric/geometric.hpp"
#include "remesh/boundary_curves.hpp"

using namespace riemesh;

namespace {

constexpr double kPi = std::numbers::pi;

void add_vertex(Mesh& m, double x, double y, std::uint8_t tag = kTagNone) {
  m.coords.push_back(x);
  m.coords.push_back(y);
  m.vert_ref.push_back(0);
  m.vert_tag.push_back(tag);
}

void add_triangle(Mesh& m, Id a, Id b, Id c, std::int32_t ref) {
  m.triangles.insert(m.triangles.end(), {a, b, c});
  m.tri_ref.push_back(ref);
  m.tri_tag.push_back(kTagNone);
}

/// Regular N-gon of radius 1 (vertex k at angle 2πk/N, id k) fanned to the centre (id N).
Mesh polygon_fan(int n, double rx = 1.0, double ry = 1.0) {
  Mesh m;
  m.dim = 2;
  for (int k = 0; k < n; ++k)
    add_vertex(m, rx * std::cos(2 * kPi * k / n), ry * std::sin(2 * kPi * k / n));
  add_vertex(m, 0.0, 0.0);
  for (int k = 0; k < n; ++k) add_triangle(m, k, (k + 1) % n, n, 1);
  return m;
}

/// Annulus 0.5 <= r <= 1 with n sectors: outer vertex k = id k, inner = id n + k.
Mesh annulus(int n) {
  Mesh m;
  m.dim = 2;
  for (int ring = 0; ring < 2; ++ring)
    for (int k = 0; k < n; ++k) {
      const double r = ring == 0 ? 1.0 : 0.5, a = 2 * kPi * k / n;
      add_vertex(m, r * std::cos(a), r * std::sin(a));
    }
  for (int k = 0; k < n; ++k) {
    const int k1 = (k + 1) % n;
    add_triangle(m, k, k1, n + k1, 1);
    add_triangle(m, k, n + k1, n + k, 1);
  }
  return m;
}

Vec2 xy(const Mesh& m, Id v) { return {{m.coords[2 * v], m.coords[2 * v + 1]}}; }

int count_open(const BoundaryCurves& bc) {
  return static_cast<int>(std::count_if(bc.curves.begin(), bc.curves.end(),
                                        [](const BoundaryCurve& c) { return !c.closed; }));
}

int count_corners(const BoundaryCurves& bc) {
  return static_cast<int>(std::count(bc.corner.begin(), bc.corner.end(), 1));
}

/// Max radial error |‖γ‖ − 1| of a curve approximating the unit circle, sampled at 16 points a
/// segment (not only at midpoints: the symmetric cubic arc passes through the circle there).
double max_radial_error(const BoundaryCurve& c) {
  double e = 0.0;
  for (int k = 0; k < c.num_edges(); ++k)
    for (int i = 1; i < 16; ++i) e = std::max(e, std::abs(norm(point(c, k + i / 16.0)) - 1.0));
  return e;
}

/// Distance from p to the ellipse (a cos u, b sin u), by Newton on the angle from a dense scan.
double distance_to_ellipse(const Vec2& p, double a, double b) {
  double best = 1e300, ub = 0.0;
  for (int i = 0; i < 720; ++i) {
    const double u = 2 * kPi * i / 720;
    const double d = std::hypot(a * std::cos(u) - p[0], b * std::sin(u) - p[1]);
    if (d < best) best = d, ub = u;
  }
  for (int it = 0; it < 50; ++it) {  // f(u) = (γ(u) − p)·γ'(u)
    const double cu = std::cos(ub), su = std::sin(ub);
    const double qx = a * cu - p[0], qy = b * su - p[1];
    const double f = -qx * a * su + qy * b * cu;
    const double fp = a * a * su * su + b * b * cu * cu - qx * a * cu - qy * b * su;
    ub -= f / fp;
  }
  return std::hypot(a * std::cos(ub) - p[0], b * std::sin(ub) - p[1]);
}

}  // namespace

TEST(BoundaryCurves, UnitSquareGivesFourStraightSides) {
  const Mesh m = unit_square(4, 3);
  const BoundaryCurves bc = build_boundary_curves(m);
  ASSERT_EQ(bc.curves.size(), 4u);
  EXPECT_EQ(count_corners(bc), 4);
  EXPECT_EQ(bc.edges.size(), 14u);  // 2 (4 + 3) boundary edges
  std::vector<int> refs;
  for (const BoundaryCurve& c : bc.curves) {
    EXPECT_FALSE(c.closed);
    EXPECT_TRUE(bc.corner[c.vertices.front()] && bc.corner[c.vertices.back()]);
    EXPECT_EQ(c.left_ref, 1);  // the domain on the left: counter-clockwise
    EXPECT_EQ(c.right_ref, kNoId);
    refs.push_back(c.ref);
    // Each side has a constant coordinate (x or y in {0, 1}): the reconstruction keeps it exactly
    // and is linear in the parameter (up to rounding) between the input vertices.
    const Vec2 a = xy(m, c.vertices.front()), b = xy(m, c.vertices.back());
    const int fixed = a[0] == b[0] ? 0 : 1;
    EXPECT_TRUE(c.straight);  // chord_deviation answers 0 without sampling
    EXPECT_EQ(chord_deviation(c, 0.3, 2.7), 0.0);
    EXPECT_NEAR(c.total_length(), 1.0, 1e-14);
    for (int i = 0; i <= 40 * c.num_edges(); ++i) {
      const double s = i / 40.0;
      const Vec2 p = point(c, s);
      EXPECT_EQ(p[fixed], a[fixed]);
      const int k = std::min(static_cast<int>(s), c.num_edges() - 1);
      const Vec2 lin =
          xy(m, c.vertices[k]) + (s - k) * (xy(m, c.vertices[k + 1]) - xy(m, c.vertices[k]));
      EXPECT_NEAR(p[1 - fixed], lin[1 - fixed], 1e-15);
      EXPECT_EQ(curvature(c, s), 0.0);
      EXPECT_TRUE(std::isinf(hausd_size(c, s, 1e-3)));
    }
    EXPECT_EQ(chord_deviation(c, 0.0, c.param_end()), 0.0);
  }
  std::sort(refs.begin(), refs.end());
  EXPECT_EQ(refs, (std::vector<int>{1, 2, 3, 4}));
  // Maps: every listed edge is a feature edge on its curve at its index.
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const FeatureEdge& f = bc.edges[bc.input_edge2feature[e]];
    EXPECT_EQ(f.ref, m.edge_ref[e]);
    const BoundaryCurve& c = bc.curves[f.curve];
    EXPECT_EQ(c.edges[f.index], bc.input_edge2feature[e]);
    EXPECT_EQ(bc.find_feature_edge(m.edges[2 * e + 1], m.edges[2 * e]), bc.input_edge2feature[e]);
  }
  // Corners sit at two curve ends, other boundary vertices once, interior vertices nowhere.
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const auto at = bc.curves_at(static_cast<Id>(v));
    const double x = m.coords[2 * v], y = m.coords[2 * v + 1];
    const bool on_bnd = x == 0.0 || x == 1.0 || y == 0.0 || y == 1.0;
    EXPECT_EQ(at.size(), bc.corner[v] ? 2u : on_bnd ? 1u : 0u);
    for (const CurveVertex& cv : at)
      EXPECT_EQ(point(bc.curves[cv.curve], cv.param), xy(m, static_cast<Id>(v)));
  }
}

TEST(BoundaryCurves, DiskIsOneClosedCurveConvergingAtOrderFour) {
  std::vector<double> err;
  for (const int n : {16, 32, 64}) {
    const Mesh m = polygon_fan(n);
    const BoundaryCurves bc = build_boundary_curves(m);
    ASSERT_EQ(bc.curves.size(), 1u);
    const BoundaryCurve& c = bc.curves[0];
    EXPECT_TRUE(c.closed);
    EXPECT_FALSE(c.straight);
    EXPECT_GT(chord_deviation(c, 0.0, 2.0), 0.0);
    EXPECT_EQ(count_corners(bc), 0);
    EXPECT_EQ(c.num_edges(), n);
    EXPECT_EQ(c.vertices.front(), 0);  // the smallest id starts a closed loop
    EXPECT_EQ(c.vertices[1], 1);       // counter-clockwise: the disk on the left
    EXPECT_EQ(c.left_ref, 1);
    EXPECT_EQ(c.right_ref, kNoId);
    EXPECT_EQ(c.ref, 0);  // no Edges listed: unlisted feature edges get ref 0
    err.push_back(max_radial_error(c));
    EXPECT_NEAR(c.total_length(), 2 * kPi, 10 * n * err.back());
    // Curvature ≈ +1 (convex boundary walked counter-clockwise).
    for (int i = 0; i < 4 * n; ++i) EXPECT_NEAR(curvature(c, 0.25 * i), 1.0, 0.05) << n;
  }
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    EXPECT_GE(order, 3.5) << "errors " << err[i - 1] << " -> " << err[i];
  }
  // N = 16: 6.5e-8 (the error of the best cubic for a 22.5° arc; chord gap 0.019). Orders 6.0.
  EXPECT_LT(err[0], 1e-7);
}

TEST(BoundaryCurves, EllipseWithNonUniformSamplingConverges) {
  // Vertices equally spaced in the angle u of (2 cos u, sin u): chords of unequal lengths, so
  // the tangents are estimates, not exact. Error measured as the true distance to the ellipse.
  std::vector<double> err;
  for (const int n : {16, 32, 64, 128}) {
    const BoundaryCurves bc = build_boundary_curves(polygon_fan(n, 2.0, 1.0));
    ASSERT_EQ(bc.curves.size(), 1u);
    const BoundaryCurve& c = bc.curves[0];
    double e = 0.0;
    for (int k = 0; k < n; ++k)
      for (const double t : {0.25, 0.5, 0.75})
        e = std::max(e, distance_to_ellipse(point(c, k + t), 2.0, 1.0));
    err.push_back(e);
  }
  for (std::size_t i = 1; i < err.size(); ++i)
    EXPECT_GE(std::log2(err[i - 1] / err[i]), 3.5) << err[i - 1] << " -> " << err[i];
  // An open arc between two corners, u in [0.3, 2.5] perturbed by 0.1 sin 3u: one-sided stencils
  // at the ends keep the order (measured 3.9, 4.9, 4.7, 4.4).
  err.clear();
  for (const int n : {8, 16, 32, 64, 128}) {
    std::vector<Vec2> p;
    for (int k = 0; k <= n; ++k) {
      const double u0 = 0.3 + 2.2 * k / n, u = u0 + 0.1 * std::sin(3 * u0);
      p.push_back({{2 * std::cos(u), std::sin(u)}});
    }
    BoundaryCurve c;
    build_curve_geometry(c, p);
    double e = 0.0;
    for (int k = 0; k < n; ++k)
      for (int i = 1; i < 16; ++i)
        e = std::max(e, distance_to_ellipse(point(c, k + i / 16.0), 2.0, 1.0));
    err.push_back(e);
  }
  for (std::size_t i = 1; i < err.size(); ++i)
    EXPECT_GE(std::log2(err[i - 1] / err[i]), 3.5) << err[i - 1] << " -> " << err[i];
}

TEST(BoundaryCurves, AnnulusHasTwoLoopsWithTheDomainOnTheLeft) {
  const Mesh m = annulus(24);
  const BoundaryCurves bc = build_boundary_curves(m);
  ASSERT_EQ(bc.curves.size(), 2u);
  // Loops start at their smallest vertex: the outer one (ids 0..23) first.
  EXPECT_EQ(bc.curves[0].vertices.front(), 0);
  EXPECT_EQ(bc.curves[1].vertices.front(), 24);
  EXPECT_EQ(bc.curves[0].vertices[1], 1);   // outer: counter-clockwise
  EXPECT_EQ(bc.curves[1].vertices[1], 47);  // hole: clockwise
  EXPECT_NEAR(curvature(bc.curves[0], 3.3), 1.0, 0.02);
  EXPECT_NEAR(curvature(bc.curves[1], 3.3), -2.0, 0.04);  // the hole turns right
  for (const BoundaryCurve& c : bc.curves) {
    EXPECT_TRUE(c.closed);
    EXPECT_EQ(c.left_ref, 1);
    EXPECT_EQ(c.right_ref, kNoId);
  }
}

TEST(BoundaryCurves, InterfaceBetweenTwoRefsIsACurve) {
  // unit_square(4, 2) with the upper half (y > 0.5) of ref 2: the line y = 0.5 is an interface
  // from (0, 0.5) to (1, 0.5); its ends are T-points (degree 3), and the sides x=0, x=1 split.
  Mesh m = unit_square(4, 2);
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    double yc = 0.0;
    for (int i = 0; i < 3; ++i) yc += m.coords[2 * m.triangles[3 * t + i] + 1] / 3.0;
    m.tri_ref[t] = yc > 0.5 ? 2 : 1;
  }
  const BoundaryCurves bc = build_boundary_curves(m);
  EXPECT_EQ(bc.curves.size(), 7u);  // 4 sides, x=0 and x=1 split in two, plus the interface
  EXPECT_EQ(count_corners(bc), 6);
  int interfaces = 0;
  for (const BoundaryCurve& c : bc.curves) {
    if (c.right_ref == kNoId) continue;
    ++interfaces;
    EXPECT_EQ(c.left_ref, 1);  // left_ref < right_ref: walked from x = 1 to x = 0
    EXPECT_EQ(c.right_ref, 2);
    EXPECT_EQ(c.ref, 0);
    EXPECT_EQ(c.num_edges(), 4);
    EXPECT_EQ(xy(m, c.vertices.front())[0], 1.0);
    EXPECT_EQ(point(c, 2.5)[1], 0.5);
  }
  EXPECT_EQ(interfaces, 1);
}

TEST(BoundaryCurves, AngleThresholdSplitsAtSharpCornersOnly) {
  // A fan over a 24-gon (15° turns) with vertex 0 pulled out to (1.6, 0): turns of about 136°
  // at vertex 0 and 45° at its neighbours 1 and 23 (computed below), 15° elsewhere.
  Mesh m = polygon_fan(24);
  m.coords[0] = 1.6;
  const auto turn = [&](Id v) {
    const Id a = (v + 23) % 24, b = (v + 1) % 24;
    const Vec2 u = xy(m, v) - xy(m, a), w = xy(m, b) - xy(m, v);
    return std::acos(dot(u, w) / (norm(u) * norm(w))) * 180.0 / kPi;
  };
  const double t0 = turn(0), t1 = turn(1);
  ASSERT_GT(t0, t1);
  ASSERT_GT(t1, 15.5);
  for (Id v = 2; v < 23; ++v) ASSERT_NEAR(turn(v), 15.0, 1e-9);
  {  // threshold between t1 and t0: one corner, a single-corner loop (open, both ends = 0)
    CurveOptions o;
    o.angle_deg = 0.5 * (t0 + t1);
    const BoundaryCurves bc = build_boundary_curves(m, o);
    ASSERT_EQ(bc.curves.size(), 1u);
    EXPECT_FALSE(bc.curves[0].closed);
    EXPECT_EQ(bc.curves[0].vertices.front(), 0);
    EXPECT_EQ(bc.curves[0].vertices.back(), 0);
    EXPECT_EQ(bc.curves[0].vertices[1], 1);
    EXPECT_EQ(bc.curves_at(0).size(), 2u);
  }
  {  // between 15° and t1: vertices 0, 1 and 23 are corners
    CurveOptions o;
    o.angle_deg = 0.5 * (15.0 + t1);
    const BoundaryCurves bc = build_boundary_curves(m, o);
    EXPECT_EQ(bc.curves.size(), 3u);
    EXPECT_EQ(count_corners(bc), 3);
    EXPECT_TRUE(bc.corner[0] && bc.corner[1] && bc.corner[23]);
  }
  {  // below 15°: every vertex is a corner, every curve a single straight edge
    CurveOptions o;
    o.angle_deg = 14.0;
    const BoundaryCurves bc = build_boundary_curves(m, o);
    EXPECT_EQ(bc.curves.size(), 24u);
    for (const BoundaryCurve& c : bc.curves) EXPECT_LT(chord_deviation(c, 0.0, 1.0), 1e-15);
  }
  {  // -nr: no angle corners below 90 degrees, whatever --angle: vertex 0 (136) only
    CurveOptions o;
    o.detect_angles = false;
    o.angle_deg = 1.0;
    const BoundaryCurves bc = build_boundary_curves(m, o);
    ASSERT_EQ(bc.curves.size(), 1u);
    EXPECT_FALSE(bc.curves[0].closed);
    EXPECT_EQ(count_corners(bc), 1);
    EXPECT_TRUE(bc.corner[0]);
  }
}

TEST(BoundaryCurves, NoAngleDetectionKeepsTurnsOf90DegreesAndMore) {
  // -nr: square corners (90 degrees) and a spike's tip (170 degrees) stay corners; a smooth
  // curve through them bulged by a fifth of the edges and more, and the passes left flat
  // triangles there (QA hunt 5 F12). The turns below 90 degrees (47 and 59 at vertices 5 and
  // 6, 85 at vertex 2) are smoothed.
  Mesh m;
  m.dim = 2;
  // (0,0) (1,0) (1,1), a spike out to (3, 1.09) and back (10 degrees wide), a bend, home.
  const double sp = std::tan(10.0 * std::numbers::pi / 180.0);
  m.coords = {0, 0, 1, 0, 1, 1, 3, 1 + 2 * sp * 0.5, 1, 1 + 2 * sp, 0.5, 1.5, 0, 1.2};
  for (Id k = 0; k < 7; ++k) m.edges.insert(m.edges.end(), {k, (k + 1) % 7});
  m.edge_ref.assign(7, 1);
  m.edge_tag.assign(7, kTagNone);
  m.vert_tag.assign(7, kTagNone);
  CurveOptions o;
  o.detect_angles = false;
  const BoundaryCurves bc = build_boundary_curves(m, o);
  EXPECT_TRUE(bc.corner[0] && bc.corner[1]);  // 90 degrees
  EXPECT_TRUE(bc.corner[3]);                  // the spike's tip
  EXPECT_FALSE(bc.corner[2] || bc.corner[4] || bc.corner[5] || bc.corner[6]);
}

TEST(BoundaryCurves, RefChangesAndTagsMakeCorners) {
  // A 16-gon whose boundary is listed in two halves of refs 7 and 8, plus vertex 5 required.
  Mesh m = polygon_fan(16);
  for (int k = 0; k < 16; ++k) {
    m.edges.insert(m.edges.end(), {k, (k + 1) % 16});
    m.edge_ref.push_back(k < 8 ? 7 : 8);
    m.edge_tag.push_back(kTagNone);
  }
  m.vert_tag[5] = kTagRequired;
  const BoundaryCurves bc = build_boundary_curves(m);
  EXPECT_EQ(count_corners(bc), 3);  // 0 and 8 (ref changes), 5 (required)
  EXPECT_TRUE(bc.corner[0] && bc.corner[8] && bc.corner[5]);
  ASSERT_EQ(bc.curves.size(), 3u);
  std::vector<std::pair<int, int>> got;
  for (const BoundaryCurve& c : bc.curves) got.push_back({c.vertices.front(), c.num_edges()});
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, (std::vector<std::pair<int, int>>{{0, 5}, {5, 3}, {8, 8}}));
  for (const BoundaryCurve& c : bc.curves) EXPECT_EQ(c.ref, c.vertices.front() < 8 ? 7 : 8);
  // Open arcs of the circle: the one-sided tangent stencils at the corners are exact on a
  // uniformly sampled circle, so only the cubic arc error remains (6.5e-8 for 22.5° arcs, against
  // the chord gap 1 − cos(π/16) = 0.019).
  for (const BoundaryCurve& c : bc.curves)
    for (int i = 0; i <= 8 * c.num_edges(); ++i) EXPECT_NEAR(norm(point(c, i / 8.0)), 1.0, 1e-7);
}

TEST(BoundaryCurves, ListedEdgeInsideASubdomainIsACurve) {
  // The diagonal (0,0)-(1,1) of unit_square(2, 2) listed as edges (ref 9) inside ref-1
  // triangles: a curve with ref 1 on both sides, from corner 0 through vertex 4 to corner 8.
  Mesh m = unit_square(2, 2);
  m.edges.insert(m.edges.end(), {0, 4, 4, 8});
  m.edge_ref.insert(m.edge_ref.end(), {9, 9});
  m.edge_tag.insert(m.edge_tag.end(), {kTagNone, kTagNone});
  const BoundaryCurves bc = build_boundary_curves(m);
  int found = 0;
  for (const BoundaryCurve& c : bc.curves)
    if (c.ref == 9) {
      ++found;
      EXPECT_EQ(c.left_ref, 1);
      EXPECT_EQ(c.right_ref, 1);
      EXPECT_EQ(c.vertices, (std::vector<Id>{0, 4, 8}));  // tie: from the smaller end
      EXPECT_FALSE(bc.corner[4]);
    }
  EXPECT_EQ(found, 1);
}

TEST(BoundaryCurves, MidpointLengthProjectAreConsistent) {
  const BoundaryCurves bc = build_boundary_curves(polygon_fan(20, 2.0, 1.0));
  const BoundaryCurve& c = bc.curves[0];
  // Length is additive and matches the cumulative table.
  EXPECT_NEAR(length(c, 0.0, 20.0), c.total_length(), 1e-13);
  EXPECT_NEAR(length(c, 1.3, 7.9), length(c, 1.3, 4.2) + length(c, 4.2, 7.9), 1e-13);
  EXPECT_NEAR(length(c, 7.9, 1.3), length(c, 1.3, 7.9), 0.0);
  // Closed curve, unwrapped parameters: the arc 18.5 -> 21.5 goes through the start.
  EXPECT_NEAR(length(c, 18.5, 21.5), length(c, 18.5, 20.0) + length(c, 0.0, 1.5), 1e-13);
  EXPECT_NEAR(unwrap_near(c, 19.0, 1.5), 21.5, 0.0);
  EXPECT_NEAR(unwrap_near(c, 1.5, 19.0), -1.0, 0.0);
  EXPECT_NEAR(wrap_param(c, 21.5), 1.5, 1e-15);
  EXPECT_NEAR(wrap_param(c, -1.0), 19.0, 1e-15);
  EXPECT_EQ(point(c, 21.5), point(c, 1.5));
  for (const auto& [s0, s1] : std::vector<std::pair<double, double>>{
           {0.2, 0.9}, {0.2, 5.7}, {5.7, 0.2}, {18.5, 21.5}, {3.0, 4.0}, {-2.5, 1.25}}) {
    const double mid = midpoint(c, s0, s1);
    EXPECT_GT(mid, std::min(s0, s1));
    EXPECT_LT(mid, std::max(s0, s1));
    EXPECT_NEAR(length(c, s0, mid), length(c, mid, s1), 1e-12 * length(c, s0, s1));
    const double q = param_at_fraction(c, s0, s1, 0.25);
    EXPECT_NEAR(length(c, s0, q), 0.25 * length(c, s0, s1), 1e-12 * length(c, s0, s1));
    // Projection of a curve point returns its parameter (from a hint one segment off).
    EXPECT_NEAR(project(c, point(c, mid), mid + 0.9), mid, 1e-9);
  }
  // Projection of an off-curve point: the residual is normal to the curve.
  const Vec2 p = point(c, 6.4) + 0.05 * Vec2{{0.3, 1.0}};
  const double s = project(c, p, 6.0);
  EXPECT_NEAR(dot(p - point(c, s), tangent(c, s)), 0.0, 1e-12);
  // Tangent is the derivative: central differences.
  const double h = 1e-6;
  const Vec2 fd = (point(c, 3.3 + h) - point(c, 3.3 - h)) / (2 * h);
  EXPECT_NEAR(norm(fd - tangent(c, 3.3)), 0.0, 1e-7);
  // Open curve: parameters clamp to [0, n].
  const BoundaryCurves sq = build_boundary_curves(unit_square(3, 3));
  const BoundaryCurve& side = sq.curves[0];
  EXPECT_EQ(wrap_param(side, 4.0), 3.0);
  EXPECT_NEAR(length(side, 0.0, 3.0), 1.0, 1e-15);
  EXPECT_NEAR(length(side, 0.5, 2.0), 0.5, 1e-15);
  EXPECT_NEAR(midpoint(side, 0.0, 3.0), 1.5, 1e-14);
  EXPECT_NEAR(midpoint(side, 3.0, 1.0), 2.0, 1e-14);
  // The search is local: from a hint in segment 0 it covers segments 0 and 1 only.
  EXPECT_NEAR(project(side, point(side, 2.7), 0.5), 2.0, 1e-15);
  EXPECT_NEAR(project(side, point(side, 2.7), 2.2), 2.7, 1e-12);
}

TEST(BoundaryCurves, HausdSize) {
  // Sagitta of a chord h on a circle of radius ρ: ρ − sqrt(ρ² − h²/4) = hausd.
  for (const double rho : {0.1, 1.0, 37.0})
    for (const double hd : {1e-4, 1e-2, 0.05}) {
      const double h = hausd_chord_length(rho, hd);
      if (hd < rho) {
        EXPECT_NEAR(rho - std::sqrt(rho * rho - 0.25 * h * h), hd, 1e-12 * rho);
        EXPECT_NEAR(h, rho * alpha_from_gap(hd / rho), 1e-12 * h);
      }
    }
  EXPECT_EQ(hausd_chord_length(0.1, 0.5), 0.2);
  EXPECT_TRUE(std::isinf(hausd_chord_length(std::numeric_limits<double>::infinity(), 0.1)));
  EXPECT_THROW(hausd_chord_length(1.0, 0.0), InputError);
  // On the reconstructed unit circle (ρ ≈ 1): the chord of the predicted size deviates by about
  // hausd from the curve.
  const BoundaryCurve c = build_boundary_curves(polygon_fan(64)).curves[0];
  const double hd = 1e-3, h = hausd_size(c, 10.3, hd);
  EXPECT_NEAR(h, std::sqrt(8 * hd) * std::sqrt(1 - hd / 2), 1e-2 * h);
  const double s1 = param_at_fraction(c, 10.3, 30.0, 2 * std::asin(h / 2) / length(c, 10.3, 30.0));
  EXPECT_NEAR(norm(point(c, s1) - point(c, 10.3)), h, 1e-3 * h);
  EXPECT_NEAR(chord_deviation(c, 10.3, s1, 200), hd, 2e-2 * hd);
}

TEST(BoundaryCurves, DeterministicAndIndependentOfTriangleOrder) {
  Mesh m = annulus(12);
  for (std::size_t t = 0; t < m.num_triangles(); ++t) m.tri_ref[t] = t % 5 == 0 ? 2 : 1;
  const BoundaryCurves a = build_boundary_curves(m);
  // Shuffle the triangles and rotate their vertices (orientation kept).
  Mesh s = m;
  std::vector<std::size_t> perm(m.num_triangles());
  for (std::size_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::mt19937 rng(4);
  std::shuffle(perm.begin(), perm.end(), rng);
  for (std::size_t i = 0; i < perm.size(); ++i) {
    const std::size_t t = perm[i];
    const int r = static_cast<int>(i % 3);
    for (int j = 0; j < 3; ++j) s.triangles[3 * i + j] = m.triangles[3 * t + (j + r) % 3];
    s.tri_ref[i] = m.tri_ref[t];
  }
  const BoundaryCurves b = build_boundary_curves(s);
  ASSERT_EQ(a.curves.size(), b.curves.size());
  EXPECT_GT(a.curves.size(), 2u);
  for (std::size_t i = 0; i < a.curves.size(); ++i) {
    EXPECT_EQ(a.curves[i].vertices, b.curves[i].vertices);
    EXPECT_EQ(a.curves[i].left_ref, b.curves[i].left_ref);
    EXPECT_EQ(a.curves[i].right_ref, b.curves[i].right_ref);
    EXPECT_EQ(a.curves[i].bezier, b.curves[i].bezier);
  }
  EXPECT_EQ(a.corner, b.corner);
}

TEST(BoundaryCurves, BadInput) {
  Mesh m = unit_square(2, 2);
  CurveOptions o;
  o.angle_deg = 200.0;
  EXPECT_THROW(build_boundary_curves(m, o), InputError);
  o.angle_deg = std::nan("");
  EXPECT_THROW(build_boundary_curves(m, o), InputError);
  Mesh bad = m;
  bad.edges[0] = 99;
  EXPECT_THROW(build_boundary_curves(bad), InputError);
  bad = m;
  bad.coords[2] = 0.0;  // vertex 1 onto vertex 0
  EXPECT_THROW(build_boundary_curves(bad), InputError);
  bad = m;
  bad.dim = 3;
  EXPECT_THROW(build_boundary_curves(bad), InputError);
}

TEST(BoundaryCurves, RealData) {
  const std::string dir = RIEMESH_SHARED_DATA "/2d/";
  {  // NACA 0012: outer circle of radius 3 (50 edges of ref 1, 7.2° turns: one loop) and the
     // airfoil (140 edges of ref 99) with corners at the trailing edge (1, 0) (164° turn) and
     // the leading edge (0, 0) (69° turn, coarse there); the next largest turn is 25°.
    const Mesh m = read_medit(dir + "naca0012.mesh");
    const BoundaryCurves bc = build_boundary_curves(m);
    EXPECT_EQ(bc.edges.size(), 190u);
    ASSERT_EQ(bc.curves.size(), 3u);
    EXPECT_EQ(count_corners(bc), 2);
    int airfoil_edges = 0;
    for (const BoundaryCurve& c : bc.curves) {
      EXPECT_EQ(c.left_ref, 0);
      EXPECT_EQ(c.right_ref, kNoId);
      if (c.ref == 1) {
        EXPECT_TRUE(c.closed);
        EXPECT_EQ(c.num_edges(), 50);
        EXPECT_NEAR(norm(point(c, 0.5)), 3.0, 1e-3);  // within 3e-4 relative of the circle
      } else {
        EXPECT_EQ(c.ref, 99);
        EXPECT_FALSE(c.closed);
        airfoil_edges += c.num_edges();
        const Vec2 a = point(c, 0.0), b = point(c, c.param_end());
        EXPECT_NEAR(std::min(a[0], b[0]), 0.0, 1e-12);  // leading edge
        EXPECT_NEAR(std::max(a[0], b[0]), 1.0, 1e-12);  // trailing edge
      }
    }
    EXPECT_EQ(airfoil_edges, 140);
    // The trailing edge vertex (1, −7e-6) is a corner; with -ar 90 only it remains a corner and
    // the airfoil is a single-corner loop.
    CurveOptions o;
    o.angle_deg = 90.0;
    const BoundaryCurves bc90 = build_boundary_curves(m, o);
    EXPECT_EQ(count_corners(bc90), 1);
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      if (bc90.corner[v]) {
        EXPECT_NEAR(m.coords[2 * v], 1.0, 1e-12);
      }
    }
  }
  {  // Wing: a profile of 30 edges with turns of 172.5°, 116.3°, 55° and 47.4° (4 corners, the
     // next is 36°) inside a regular decagon (10 edges, 36° turns: one loop). All refs 1.
    const BoundaryCurves bc = build_boundary_curves(read_medit(dir + "aile.mesh"));
    EXPECT_EQ(count_corners(bc), 4);
    EXPECT_EQ(bc.curves.size(), 5u);
    EXPECT_EQ(count_open(bc), 4);
    int profile = 0;
    for (const BoundaryCurve& c : bc.curves) {
      EXPECT_EQ(c.ref, 1);
      if (c.closed)
        EXPECT_EQ(c.num_edges(), 10);
      else
        profile += c.num_edges();
    }
    EXPECT_EQ(profile, 30);
  }
  {  // Lake Geneva: one loop of 163 edges with 12 ref changes and, among the remaining vertices,
     // 4 turns above 45° (78°, 50.5°, 46.7° at non-ref-change vertices, 113.5° at a ref change).
    const Mesh m = read_medit(dir + "lac-leman.mesh");
    const BoundaryCurves bc = build_boundary_curves(m);
    int total = 0;
    for (const BoundaryCurve& c : bc.curves) {
      total += c.num_edges();
      EXPECT_EQ(c.left_ref, 0);
      EXPECT_FALSE(c.closed);
      for (int k = 0; k <= c.num_edges(); ++k)
        EXPECT_EQ(point(c, k), xy(m, c.vertices[k]));  // interpolates the input vertices
    }
    EXPECT_EQ(total, 163);
    EXPECT_EQ(count_corners(bc), 12 + 3);
    EXPECT_EQ(bc.curves.size(), 15u);
  }
}
