// Principal curvatures by local quadric fits, against the exact values on analytic surfaces
// (icosphere, cylinder, torus, saddle z = x² − y²) meshed coarsely and finely: stated error
// bounds, and errors that fall with refinement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "mesh/adjacency.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_features.hpp"
#include "surface_test_meshes.hpp"

using namespace riemesh;
using namespace riemesh::test;

namespace {

constexpr double kPi = std::numbers::pi;

std::vector<VertexCurvature> curvatures(const Mesh& m) {
  const Adjacency adj = build_adjacency(m);
  const SurfaceFeatures f = detect_features(m, adj, {});
  return vertex_curvatures(m, adj, f, surface_sectors(m, adj, f));
}

/// Errors of the estimated principal curvatures, relative to the largest exact |k1| of the
/// surface (so that zero curvatures are measured on the same scale).
struct Errors {
  double max = 0.0, mean = 0.0;
  std::size_t count = 0;
  void add(double e) {
    max = std::max(max, e);
    mean += e;
    ++count;
  }
  void finish() { mean /= static_cast<double>(count); }
};

/// Compares |k1|, |k2| (unsigned: the orientation of the fitted normal is the sector's) at the
/// vertices accepted by `keep`.
template <class Keep>
Errors grid_errors(const Param& s, int nu, int nv, double u0, double u1, double v0, double v1,
                   bool pu, bool pv, double kscale, Keep keep) {
  std::vector<Vec2> uv;
  const Mesh m = param_grid(s, nu, nv, u0, u1, v0, v1, pu, pv, &uv);
  const auto c = curvatures(m);
  Errors e;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (!keep(uv[v])) continue;
    const SurfaceGeometry g = exact_geometry(s, uv[v][0], uv[v][1]);
    EXPECT_TRUE(c[v].fitted);
    const double e1 = std::abs(std::abs(c[v].geometry.k1) - std::abs(g.k1));
    const double e2 = std::abs(std::abs(c[v].geometry.k2) - std::abs(g.k2));
    e.add(std::max(e1, e2) / kscale);
  }
  e.finish();
  return e;
}

void report(const char* what, int n, const Errors& e) {
  std::printf("%-10s n=%-4d max %.3e mean %.3e (%zu vertices)\n", what, n, e.max, e.mean, e.count);
}

TEST(SurfaceCurvature, QuadricFitIsExactOnAQuadric) {
  // Points on z = 0.3x² − 0.2xy + 0.5y² around the origin: the fit recovers the surface, so
  // the curvatures are those of the graph at the origin: eigenvalues of [[0.6, −0.2], [−0.2, 1]].
  std::vector<Vec3> q;
  for (int k = 0; k < 8; ++k) {
    const double x = 0.1 * std::cos(0.8 * k), y = 0.07 * std::sin(1.3 * k + 0.2);
    q.push_back({{x, y, 0.3 * x * x - 0.2 * x * y + 0.5 * y * y}});
  }
  const VertexCurvature c = fit_quadric(Vec3::zero(), Vec3::unit(2), q);
  ASSERT_TRUE(c.fitted);
  const double mid = 0.8, rad = std::sqrt(0.04 + 0.04);  // eigenvalues 0.8 ± √(0.2² + 0.2²)
  EXPECT_NEAR(c.geometry.k1, mid + rad, 1e-10);
  EXPECT_NEAR(c.geometry.k2, mid - rad, 1e-10);
  EXPECT_NEAR(c.geometry.normal[2], 1.0, 1e-12);
  // Too few points: not fitted, zero curvature.
  q.resize(4);
  const VertexCurvature d = fit_quadric(Vec3::zero(), Vec3::unit(2), q);
  EXPECT_FALSE(d.fitted);
  EXPECT_EQ(d.geometry.k1, 0.0);
}

TEST(SurfaceCurvature, Sphere) {
  const double r = 2.0;
  double previous = 1.0;
  for (int s : {2, 3, 4}) {
    const Mesh m = sphere_mesh(s, r);
    const auto c = curvatures(m);
    Errors e;
    for (const auto& x : c) {
      e.add(std::abs(std::abs(x.geometry.k1) - 1 / r) * r);
      e.add(std::abs(std::abs(x.geometry.k2) - 1 / r) * r);
    }
    e.finish();
    report("sphere", s, e);
    // Measured 9.8e-2, 2.3e-2, 5.9e-3: a factor 4 per subdivision (O(h²)).
    EXPECT_LT(e.max, previous / 3.5);
    previous = e.max;
  }
  EXPECT_LT(previous, 0.01);
}

TEST(SurfaceCurvature, Cylinder) {
  const double r = 0.5;
  // Interior rows only (v in [0.25, 0.75] of the height): the open ends are fitted one-sided.
  auto interior = [](const Vec2& p) { return p[1] > 0.24 && p[1] < 0.76; };
  const Errors coarse = grid_errors(cylinder_param(r), 24, 8, 0, 2 * kPi, 0, 1, true, false,
                                    1 / r, interior);
  const Errors fine = grid_errors(cylinder_param(r), 96, 32, 0, 2 * kPi, 0, 1, true, false,
                                  1 / r, interior);
  report("cylinder", 24, coarse);
  report("cylinder", 96, fine);
  EXPECT_LT(fine.max, coarse.max / 8);  // measured 7.2e-2 -> 4.3e-3: O(h²)
  EXPECT_LT(fine.max, 0.01);
}

TEST(SurfaceCurvature, Torus) {
  const double big = 1.0, r = 0.4;
  auto all = [](const Vec2&) { return true; };
  const Errors coarse = grid_errors(torus_param(big, r), 32, 16, 0, 2 * kPi, 0, 2 * kPi, true,
                                    true, 1 / r, all);
  const Errors fine = grid_errors(torus_param(big, r), 128, 64, 0, 2 * kPi, 0, 2 * kPi, true, true,
                                  1 / r, all);
  report("torus", 32, coarse);
  report("torus", 128, fine);
  EXPECT_LT(fine.max, coarse.max / 8);  // measured 0.200 -> 0.0114: O(h²)
  EXPECT_LT(fine.max, 0.015);
}

TEST(SurfaceCurvature, Saddle) {
  // Exact curvature at the origin: ±2; relative to 2. Interior vertices (|x|, |y| <= 0.75).
  auto interior = [](const Vec2& p) { return std::abs(p[0]) < 0.76 && std::abs(p[1]) < 0.76; };
  const Errors coarse = grid_errors(saddle_param(), 16, 16, -1, 1, -1, 1, false, false, 2.0,
                                    interior);
  const Errors fine = grid_errors(saddle_param(), 64, 64, -1, 1, -1, 1, false, false, 2.0,
                                  interior);
  report("saddle", 16, coarse);
  report("saddle", 64, fine);
  EXPECT_LT(fine.max, coarse.max / 8);  // measured 1.08e-2 -> 7.2e-4: O(h²)
  EXPECT_LT(fine.max, 2e-3);
}

TEST(SurfaceCurvature, StretchedRingsSpreadAcross) {
  // Rows far thinner than the facets are wide: the 2-ring of a vertex is a strip along the axis
  // (cells 1:60 on the 10-sided prism, 1:25 on the finer tube). Fitted on the strip alone, the
  // quadric's term along the axis took up the residual around it: |k1| 570 on the prism (exact
  // 1 for the circle through its edges, 0.55-1.5 for a quadric on its facets).
  for (const int sides : {10, 64}) {
    std::vector<Vec2> uv;
    const Mesh m = param_grid(cylinder_param(1.0), sides, 200, 0, 2 * kPi, 0, 2, true, false, &uv);
    const auto c = curvatures(m);
    const double tol = sides == 10 ? 0.5 : 0.02;  // the 64-gon is close to its circle
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      if (uv[v][1] < 0.5 || uv[v][1] > 1.5) continue;
      EXPECT_NEAR(std::abs(c[v].geometry.k1), 1.0, tol) << sides << " sides, vertex " << v;
      EXPECT_LT(std::abs(c[v].geometry.k2), 0.05) << sides << " sides, vertex " << v;
      EXPECT_LT(std::abs(c[v].geometry.w1[2]), 0.05) << sides << " sides, vertex " << v;
    }
  }
}

TEST(SurfaceCurvature, CylinderDirections) {
  // w1 (largest |k|) goes around the axis, w2 along it.
  std::vector<Vec2> uv;
  const Mesh m = param_grid(cylinder_param(1.0), 64, 16, 0, 2 * kPi, 0, 1, true, false, &uv);
  const auto c = curvatures(m);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (uv[v][1] < 0.2 || uv[v][1] > 0.8) continue;
    EXPECT_LT(std::abs(c[v].geometry.w1[2]), 0.02) << v;
    EXPECT_GT(std::abs(c[v].geometry.w2[2]), 0.999) << v;
  }
}

TEST(SurfaceCurvature, CubeFacesAreFlat) {
  // Each side of a ridge is fitted on its own face: zero curvature everywhere, corners included.
  const Mesh m = cube_surface(4);
  const auto c = curvatures(m);
  const Adjacency adj = build_adjacency(m);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (ball(adj, static_cast<Id>(v)).empty()) continue;
    EXPECT_NEAR(c[v].geometry.k1, 0.0, 1e-9) << v;
  }
}

}  // namespace
