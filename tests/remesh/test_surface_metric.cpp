// Geometric metric of a surface mesh: analytic sizes on the sphere and the cylinder, the
// isotropic/anisotropic relation, clipping, feature lines, and gradation on a real surface.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <string>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "metric/gradation.hpp"
#include "metric/intersection.hpp"
#include "metric/metric.hpp"
#include "remesh/surface_metric.hpp"
#include "surface_test_meshes.hpp"

using namespace riemesh;
using namespace riemesh::test;

namespace {

constexpr double kPi = std::numbers::pi;

/// Size of metric m along direction u: 1/‖u‖_M.
double size_along(const SymMat3& m, const Vec3& u) { return 1.0 / length(m, normalize(u)); }

TEST(SurfaceMetric, SphereGivesTheAnalyticSize) {
  // Radius R, gap hausd: the chord 2 sqrt(hausd (2R − hausd)) deviates from the great circle by
  // exactly hausd. R = 2, hausd = 1e-3: h = 0.126487. The curvature error of the icosphere at
  // s = 4 is 0.6% (test_surface_curvature), hence the size within 0.5% (h ∝ sqrt(ρ)).
  const double r = 2.0, hausd = 1e-3;
  const double h = 2.0 * std::sqrt(hausd * (2.0 * r - hausd));
  const Mesh m = sphere_mesh(4, r);
  for (bool aniso : {false, true}) {
    SurfaceMetricOptions o;
    o.hausd = hausd;
    o.anisotropic = aniso;
    SurfaceMetricReport rep;
    const auto metric = geometric_surface_metric(m, o, {}, &rep);
    ASSERT_EQ(metric.size(), m.num_vertices());
    for (std::size_t v = 0; v < m.num_vertices(); ++v) {
      const Vec3 p{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
      Vec3 t1, t2;
      detail::orthonormal_complement(normalize(p), 1.0, t1, t2);
      EXPECT_NEAR(size_along(metric[v], t1), h, 0.005 * h);
      EXPECT_NEAR(size_along(metric[v], t2), h, 0.005 * h);
      EXPECT_NEAR(size_along(metric[v], p), h, 0.005 * h);  // normal size = h1
    }
    EXPECT_NEAR(rep.smallest, h, 0.005 * h);
    EXPECT_NEAR(rep.largest, h, 0.005 * h);
    EXPECT_NEAR(rep.hmax, 4.0 * std::sqrt(3.0), 0.05);  // bounding-box diagonal of [-2,2]³
  }
}

TEST(SurfaceMetric, CylinderAnisotropic) {
  // Radius 0.5: around the axis h = 2 sqrt(hausd (1 − hausd)); along it (ρ2 = inf) hmax.
  const double r = 0.5, hausd = 1e-3, hmax = 0.3;
  const double h = 2.0 * std::sqrt(hausd * (2.0 * r - hausd));
  std::vector<Vec2> uv;
  const Mesh m = param_grid(cylinder_param(r), 96, 32, 0, 2 * kPi, 0, 1, true, false, &uv);
  SurfaceMetricOptions o;
  o.hausd = hausd;
  o.hmax = hmax;
  o.anisotropic = true;
  const auto aniso = geometric_surface_metric(m, o);
  o.anisotropic = false;
  const auto iso = geometric_surface_metric(m, o);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    if (uv[v][1] < 0.25 || uv[v][1] > 0.75) continue;  // away from the open ends
    const Vec3 around{{-std::sin(uv[v][0]), std::cos(uv[v][0]), 0.0}};
    EXPECT_NEAR(size_along(aniso[v], around), h, 0.01 * h);
    // Along the axis: hmax, less the gradation from the one-sided fits at the open ends.
    EXPECT_GT(size_along(aniso[v], Vec3::unit(2)), 0.9 * hmax);
    EXPECT_NEAR(size_along(iso[v], Vec3::unit(2)), h, 0.01 * h);
    EXPECT_TRUE(contained_in(iso[v], aniso[v], 1e-9));  // isotropic is the stricter metric
  }
}

TEST(SurfaceMetric, ClippingAndFlatPlaces) {
  const Mesh sphere = sphere_mesh(3, 1.0);
  SurfaceMetricOptions o;
  o.hausd = 1e-3;  // h ≈ 0.0894
  o.hmin = 0.2;
  o.hmax = 0.5;
  for (const SymMat3& x : geometric_surface_metric(sphere, o))
    EXPECT_NEAR(size_along(x, Vec3::unit(0)), 0.2, 1e-12);
  o.hmin = 0.01;
  o.hmax = 0.05;
  for (const SymMat3& x : geometric_surface_metric(sphere, o))
    EXPECT_NEAR(size_along(x, Vec3::unit(0)), 0.05, 1e-12);
  // A cube: flat faces and straight ridges impose nothing: hmax everywhere.
  const Mesh cube = cube_surface(3);
  o.hmax = 0.25;
  o.anisotropic = true;
  for (const SymMat3& x : geometric_surface_metric(cube, o))
    EXPECT_NEAR(size_along(x, Vec3{{1, 2, 3}}), 0.25, 1e-12);
}

TEST(SurfaceMetric, FeatureLineSize) {
  // Three points on a circle of radius 3: the size is the chord with gap hausd on that circle.
  const double rho = 3.0, hausd = 0.01;
  const Vec3 a{{rho * std::cos(0.1), rho * std::sin(0.1), 0}}, v{{rho, 0, 0}};
  const Vec3 b{{rho * std::cos(-0.2), rho * std::sin(-0.2), 0}};
  EXPECT_NEAR(feature_line_size(a, v, b, hausd), 2.0 * std::sqrt(hausd * (2 * rho - hausd)),
              1e-12);
  EXPECT_TRUE(std::isinf(feature_line_size(Vec3::zero(), Vec3::unit(0), 2.0 * Vec3::unit(0), hausd)));
  EXPECT_NEAR(feature_line_size(a, v, b, 10.0), 2 * rho, 1e-9);  // gap beyond ρ: the diameter
}

TEST(SurfaceMetric, GradationOnTheBunny) {
  const Mesh m = read_medit(RIEMESH_SHARED_DATA "/surf/bunny.mesh");
  const Adjacency adj = build_adjacency(m);
  const SurfaceFeatures f = detect_features(m, adj, {});
  const auto curv = vertex_curvatures(m, adj, f, surface_sectors(m, adj, f));
  SurfaceMetricOptions o;
  o.hausd = 0.002 * 13.0;  // about 0.2% of the bounding-box diagonal (≈ 13.3)
  o.hgrad = 0.0;
  const auto raw = geometric_surface_metric(m, adj, f, curv, o);
  o.hgrad = 1.3;
  SurfaceMetricReport rep;
  const auto graded = geometric_surface_metric(m, adj, f, curv, o, &rep);
  EXPECT_TRUE(rep.gradation.converged);
  EXPECT_GT(rep.gradation.measure_before, 1.3);
  const double after = max_h_shock<3>(std::span<const double>(m.coords),
                                      std::span<const int32_t>(adj.edges),
                                      std::span<const SymMat3>(graded), true);
  EXPECT_LE(after, 1.3 * (1 + 1e-6));
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    EXPECT_TRUE(contained_in(graded[v], raw[v], 1e-9)) << v;  // sizes only shrink
}

TEST(SurfaceMetric, UserMetricIsIntersected) {
  // A user metric with size 0.05 along x and 1 elsewhere on a sphere of radius 1 (geometric
  // size ≈ 0.089 for hausd 1e-3): the result is inside both unit balls (⪰ both metrics).
  const Mesh m = sphere_mesh(3, 1.0);
  const std::vector<SymMat3> user(m.num_vertices(), SymMat3{{400.0, 0.0, 1.0, 0.0, 0.0, 1.0}});
  SurfaceMetricOptions o;
  o.hausd = 1e-3;
  o.hgrad = 0.0;
  const auto geo = geometric_surface_metric(m, o);
  o.user_metric = &user;
  const auto both = geometric_surface_metric(m, o);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    EXPECT_TRUE(contained_in(both[v], geo[v], 1e-9));
    EXPECT_TRUE(contained_in(both[v], user[v], 1e-9));
    EXPECT_NEAR(size_along(both[v], Vec3::unit(0)), 0.05, 1e-9);
  }
  const std::vector<SymMat3> wrong(3, SymMat3::identity());
  o.user_metric = &wrong;
  EXPECT_THROW(geometric_surface_metric(m, o), InputError);
}

TEST(SurfaceMetric, RejectsBadOptions) {
  const Mesh m = sphere_mesh(1, 1.0);
  SurfaceMetricOptions o;
  o.hausd = 0.0;
  EXPECT_THROW(geometric_surface_metric(m, o), InputError);
  o.hausd = 0.01;
  o.hmin = 1.0;
  o.hmax = 0.5;
  EXPECT_THROW(geometric_surface_metric(m, o), InputError);
  o.hmin = 0.0;
  o.hgrad = 1.0;
  EXPECT_THROW(geometric_surface_metric(m, o), InputError);
}

// The restriction to a plane of M = diag(1, 4, 100): normal to z it is diag(1, 4) (largest 4,
// whatever n's length); normal to (1, 0, 1) the plane holds y (4) and (1, 0, −1)/√2 ((1 + 100)/2
// = 50.5, no cross term), so 50.5. tangent_metric keeps the block and puts its largest across.
TEST(SurfaceMetric, RestrictionToAPlane) {
  const SymMat3 m = SymMat3::diagonal(Vec3{{1.0, 4.0, 100.0}});
  EXPECT_NEAR(largest_in_plane(m, Vec3{{0.0, 0.0, 2.0}}), 4.0, 1e-12);
  EXPECT_NEAR(largest_in_plane(m, Vec3{{1.0, 0.0, 1.0}}), 50.5, 1e-12);
  const SymMat3 t = tangent_metric(m, Vec3{{0.0, 0.0, 3.0}});
  const SymMat3 want = SymMat3::diagonal(Vec3{{1.0, 4.0, 4.0}});
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(t.c[k], want.c[k], 1e-12) << k;
  const Vec3 n = normalize(Vec3{{1.0, 0.0, 1.0}}),
             u{{1.0 / std::sqrt(2.0), 0.0, -1.0 / std::sqrt(2.0)}};
  const SymMat3 tt = tangent_metric(m, n);
  EXPECT_NEAR(quadratic(tt, u), 50.5, 1e-12);  // in the plane: m's
  EXPECT_NEAR(quadratic(tt, Vec3{{0.0, 1.0, 0.0}}), 4.0, 1e-12);
  EXPECT_NEAR(quadratic(tt, n), 50.5, 1e-12);  // across: the finest along it
  EXPECT_NEAR(bilinear(tt, n, u), 0.0, 1e-12);
}

}  // namespace
