// metric/hessian_metric.hpp: L∞ and Lp metrics from Hessians, clipping, complexity, combination.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/spd.hpp"
#include "mesh/fixtures.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/intersection.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A rotation by angle t in the plane (x, y).
Mat<2> rotation(double t) {
  Mat<2> r{};
  r(0, 0) = std::cos(t);
  r(1, 0) = std::sin(t);
  r(0, 1) = -std::sin(t);
  r(1, 1) = std::cos(t);
  return r;
}

/// The Hessian of u = exp(3x) + sin(4y) + x y² + y²/2 at (x, y): indefinite in places, varying
/// in size and direction, so that the Lp scaling differs from vertex to vertex (and singular at
/// no vertex of the test meshes, so that the expected shape needs no eigenvalue floor).
SymMat2 hessian_2d(double x, double y) {
  return SymMat2{{9.0 * std::exp(3.0 * x), 2.0 * y, -16.0 * std::sin(4.0 * y) + 2.0 * x + 1.0}};
}

/// The Hessian of u = exp(2x) + y² z + y²/2 + cos(3z) in 3D.
SymMat3 hessian_3d(double x, double y, double z) {
  return SymMat3{{4.0 * std::exp(2.0 * x), 0.0, 2.0 * z + 1.0, 0.0, 2.0 * y, -9.0 * std::cos(3.0 * z)}};
}

template <int D>
std::vector<SymMat<D>> hessians_on(const Mesh& mesh) {
  std::vector<SymMat<D>> h(mesh.num_vertices());
  for (std::size_t v = 0; v < h.size(); ++v) {
    const double* p = &mesh.coords[D * v];
    if constexpr (D == 2)
      h[v] = hessian_2d(p[0], p[1]);
    else
      h[v] = hessian_3d(p[0], p[1], p[2]);
  }
  return h;
}

HessianMetricOptions lp(double p, double n) {
  HessianMetricOptions o;
  o.norm = p;
  o.complexity = n;
  return o;
}

}  // namespace

// u = (a x² + b y²)/2 in the frame rotated by 0.3: H = R diag(a, b) Rᵀ, constant. The L∞ metric
// c₂ H / ε has sizes sqrt(ε / (c₂ λ)) along R's columns, c₂ = 2/9.
TEST(HessianMetric, LInfinityOfAQuadraticHasExactSizes) {
  const Mesh mesh = unit_square(4, 4);
  const double a = 50.0, b = 2.0, eps = 1e-3;
  const Mat<2> r = rotation(0.3);
  const std::vector<SymMat2> h(mesh.num_vertices(), compose(r, Vec2{a, b}));
  HessianMetricOptions o;
  o.norm = kInf;
  o.tolerance = eps;
  const std::vector<SymMat2> m = hessian_metric<2>(mesh, h, o);
  for (const SymMat2& mv : m) {
    const MetricSizes<2> s = sizes(mv);
    EXPECT_NEAR(s.sizes[0], std::sqrt(eps / (2.0 / 9.0 * b)), 1e-12);
    EXPECT_NEAR(s.sizes[1], std::sqrt(eps / (2.0 / 9.0 * a)), 1e-12);
    EXPECT_NEAR(length(mv, Vec2{r(0, 0), r(1, 0)}), std::sqrt(2.0 / 9.0 * a / eps), 1e-9);
  }
}

// 3D: c₃ = 9/32, negative eigenvalues enter by their absolute value.
TEST(HessianMetric, LInfinityIn3dUsesAbsoluteEigenvalues) {
  const Mesh mesh = unit_cube(2);
  const std::vector<SymMat3> h(mesh.num_vertices(), SymMat3::diagonal(Vec3{-4.0, 1.0, 9.0}));
  HessianMetricOptions o;
  o.norm = kInf;
  o.tolerance = 0.1;
  for (const SymMat3& mv : hessian_metric<3>(mesh, h, o)) {
    const SymMat3 want = SymMat3::diagonal(Vec3{4.0, 1.0, 9.0});
    EXPECT_TRUE(metrics_equal(mv, (9.0 / 32.0 / 0.1) * want, 1e-12));
  }
}

// A constant Hessian on the unit square: M = K H with sqrt(det M) · 1 = N, so M = N H / sqrt(det H)
// for every p.
TEST(HessianMetric, LpOfAConstantHessianIsUniformWithComplexityN) {
  const Mesh mesh = unit_square(5, 5);
  const SymMat2 h = compose(rotation(1.1), Vec2{8.0, 0.5});
  const std::vector<SymMat2> hs(mesh.num_vertices(), h);
  for (double p : {1.0, 2.0, kInf}) {
    MetricReport rep;
    const std::vector<SymMat2> m = hessian_metric<2>(mesh, hs, lp(p, 400.0), &rep);
    for (const SymMat2& mv : m) EXPECT_TRUE(metrics_equal(mv, (400.0 / 2.0) * h, 1e-10));
    EXPECT_NEAR(rep.complexity, 400.0, 400.0 * 1e-12);
    EXPECT_NEAR(rep.predicted_elements, 4.0 / std::sqrt(3.0) * 400.0, 1e-9);
  }
}

// Without clipping the Lp metric is K det|H|^{-1/(2p+D)} |H| with one K for the whole mesh, and
// its complexity is N (to 1e-9) for p = 1, 2, ∞, in 2D and 3D.
template <int D>
void check_lp_complexity(const Mesh& mesh, double n) {
  const std::vector<SymMat<D>> h = hessians_on<D>(mesh);
  for (double p : {1.0, 2.0, kInf}) {
    MetricReport rep;
    const std::vector<SymMat<D>> m = hessian_metric<D>(mesh, h, lp(p, n), &rep);
    EXPECT_NEAR(field_complexity<D>(mesh, m), n, n * 1e-9) << "p = " << p;
    EXPECT_NEAR(rep.complexity, n, n * 1e-9);
    const double e = std::isfinite(p) ? -1.0 / (2.0 * p + D) : 0.0;
    double k0 = 0.0;
    for (std::size_t v = 0; v < m.size(); ++v) {
      const SymMat<D> habs = map_eigenvalues(h[v], [](double l) { return std::abs(l); });
      const SymMat<D> shape = std::pow(det(habs), e) * habs;
      const double k = std::pow(det(m[v]) / det(shape), 1.0 / D);
      if (v == 0) k0 = k;
      EXPECT_TRUE(metrics_equal(m[v], k0 * shape, 1e-9)) << "vertex " << v;
    }
  }
}

TEST(HessianMetric, LpComplexityIsNOnUnitSquare) { check_lp_complexity<2>(unit_square(24, 24), 1000.0); }
TEST(HessianMetric, LpComplexityIsNOnUnitCube) { check_lp_complexity<3>(unit_cube(6), 2000.0); }

// With hmin, hmax and aniso_max active the normalisation is iterated: complexity within 5% of N
// (in fact much closer), and every size and ratio within its bounds.
template <int D>
void check_clipped(const Mesh& mesh, double n, double hmin, double hmax, double aniso) {
  const std::vector<SymMat<D>> h = hessians_on<D>(mesh);
  HessianMetricOptions o = lp(2.0, n);
  o.hmin = hmin;
  o.hmax = hmax;
  o.aniso_max = aniso;
  const std::vector<SymMat<D>> m = hessian_metric<D>(mesh, h, o);
  EXPECT_NEAR(field_complexity<D>(mesh, m), n, 0.05 * n);
  int at_hmin = 0, at_hmax = 0;
  for (const SymMat<D>& mv : m) {
    const MetricSizes<D> s = sizes(mv);
    EXPECT_LE(s.sizes[0], hmax * (1 + 1e-9));
    EXPECT_GE(s.sizes[D - 1], hmin * (1 - 1e-9));
    EXPECT_LE(s.sizes[0] / s.sizes[D - 1], aniso * (1 + 1e-9));
    at_hmin += s.sizes[D - 1] <= hmin * (1 + 1e-9);
    at_hmax += s.sizes[0] >= hmax * (1 - 1e-9);
  }
  EXPECT_GT(at_hmin + at_hmax, 0) << "the test must exercise clipping";
}

TEST(HessianMetric, ClippedLpComplexityWithinFivePercentOnUnitSquare) {
  check_clipped<2>(unit_square(24, 24), 1000.0, 0.01, 0.1, 5.0);
}
TEST(HessianMetric, ClippedLpComplexityWithinFivePercentOnUnitCube) {
  check_clipped<3>(unit_cube(6), 2000.0, 0.03, 0.2, 4.0);
}

// The Lp metric for a complexity does not depend on the scale of u (H → s H).
TEST(HessianMetric, LpMetricIsInvariantUnderScalingOfU) {
  const Mesh mesh = unit_square(12, 12);
  std::vector<SymMat2> h = hessians_on<2>(mesh);
  HessianMetricOptions o = lp(2.0, 500.0);
  o.hmax = 0.3;
  o.aniso_max = 20.0;
  const std::vector<SymMat2> m = hessian_metric<2>(mesh, h, o);
  for (SymMat2& hv : h) hv = 1e4 * hv;
  const std::vector<SymMat2> ms = hessian_metric<2>(mesh, h, o);
  for (std::size_t v = 0; v < m.size(); ++v) EXPECT_TRUE(metrics_equal(m[v], ms[v], 1e-9));
  // Down to scales where det|H| underflows and up to where the eigen solver's discriminant
  // overflowed (both gave NaN metrics and an internal error before 2026-12-06).
  for (const double scale : {1e-204, 1e196}) {
    std::vector<SymMat2> hs = hessians_on<2>(mesh);
    for (SymMat2& hv : hs) hv = scale * hv;
    const std::vector<SymMat2> mx = hessian_metric<2>(mesh, hs, o);
    for (std::size_t v = 0; v < m.size(); ++v)
      EXPECT_TRUE(metrics_equal(m[v], mx[v], 1e-9)) << scale;
  }
}

// H = diag(100, 1e-4), L∞ with ε = 2/9: M = diag(100, 1e-4), anisotropy 1000; aniso_max 10
// raises the small eigenvalue to 100/10² = 1 and keeps the large one.
TEST(HessianMetric, AnisotropyIsClippedByRaisingSmallEigenvalues) {
  const Mesh mesh = unit_square(2, 2);
  const std::vector<SymMat2> h(mesh.num_vertices(), SymMat2::diagonal(Vec2{100.0, 1e-4}));
  HessianMetricOptions o;
  o.norm = kInf;
  o.tolerance = 2.0 / 9.0;
  o.aniso_max = 10.0;
  for (const SymMat2& mv : hessian_metric<2>(mesh, h, o)) {
    EXPECT_NEAR(mv(0, 0), 100.0, 1e-12);
    EXPECT_NEAR(mv(1, 1), 1.0, 1e-12);
    EXPECT_NEAR(anisotropy(mv), 10.0, 1e-12);
  }
}

// A zero Hessian (linear u): the L∞ metric is hmax everywhere; the Lp metric is uniform.
TEST(HessianMetric, ZeroHessianGivesTheCoarsestOrAUniformMetric) {
  const Mesh mesh = unit_square(3, 3);
  const std::vector<SymMat2> h(mesh.num_vertices(), SymMat2::zero());
  HessianMetricOptions o;
  o.norm = kInf;
  o.tolerance = 0.01;
  EXPECT_THROW(hessian_metric<2>(mesh, h, o), InputError);
  o.hmax = 0.5;
  for (const SymMat2& mv : hessian_metric<2>(mesh, h, o))
    EXPECT_TRUE(metrics_equal(mv, isotropic_metric<2>(0.5)));
  for (const SymMat2& mv : hessian_metric<2>(mesh, h, lp(2.0, 100.0)))
    EXPECT_TRUE(metrics_equal(mv, SymMat2::diagonal(100.0), 1e-12));
}

TEST(HessianMetric, ValidateNamesTheBadOption) {
  auto message = [](HessianMetricOptions o) {
    try {
      o.validate();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(lp(2.0, 100.0)), "no error");
  EXPECT_NE(message(lp(0.0, 100.0)).find("--norm"), std::string::npos);
  EXPECT_NE(message(lp(std::nan(""), 100.0)).find("--norm"), std::string::npos);
  EXPECT_NE(message(lp(2.0, -1.0)).find("--complexity"), std::string::npos);
  EXPECT_NE(message(lp(2.0, 0.0)).find("no target"), std::string::npos);
  HessianMetricOptions both = lp(kInf, 100.0);
  both.tolerance = 0.1;
  EXPECT_NE(message(both).find("contradict"), std::string::npos);
  HessianMetricOptions tol_lp = lp(2.0, 0.0);
  tol_lp.tolerance = 0.1;
  EXPECT_NE(message(tol_lp).find("--norm inf"), std::string::npos);
  HessianMetricOptions sizes = lp(2.0, 100.0);
  sizes.hmin = 0.5;
  sizes.hmax = 0.1;
  EXPECT_NE(message(sizes).find("--hmin"), std::string::npos);
  sizes.hmin = 0.0;
  sizes.hmax = 0.0;
  EXPECT_NE(message(sizes).find("--hmax"), std::string::npos);
  // Out of range: metrics that cannot be stored (1/h² under- or overflows).
  EXPECT_NE(message(lp(2.0, 1e-300)).find("--complexity"), std::string::npos);
  EXPECT_NE(message(lp(2.0, 1e300)).find("--complexity"), std::string::npos);
  sizes.hmax = 1e-320;
  EXPECT_NE(message(sizes).find("--hmax"), std::string::npos);
  sizes.hmax = kInf;
  sizes.hmin = 1e300;
  EXPECT_NE(message(sizes).find("--hmin"), std::string::npos);
  HessianMetricOptions aniso = lp(2.0, 100.0);
  aniso.aniso_max = 0.5;
  EXPECT_NE(message(aniso).find("--aniso-max"), std::string::npos);
}

TEST(HessianMetric, RejectsMismatchedInputs) {
  const Mesh mesh = unit_square(2, 2);
  const std::vector<SymMat2> few(3, SymMat2::identity());
  EXPECT_THROW(hessian_metric<2>(mesh, few, lp(2.0, 10.0)), InputError);
  const std::vector<SymMat3> h3(mesh.num_vertices(), SymMat3::identity());
  EXPECT_THROW(hessian_metric<3>(mesh, h3, lp(2.0, 10.0)), InputError);
  std::vector<SymMat2> nan(mesh.num_vertices(), SymMat2::identity());
  nan[2].c[1] = std::nan("");
  EXPECT_THROW(hessian_metric<2>(mesh, nan, lp(2.0, 10.0)), InputError);
}

// Intersection per vertex: diag(1,4) ∩ diag(4,1) = diag(4,4); with a third field, the
// maximal-volume intersection contains (⪰) every input.
TEST(CombineMetrics, IntersectsAtEveryVertex) {
  const std::vector<std::vector<SymMat2>> two = {
      std::vector<SymMat2>(3, SymMat2::diagonal(Vec2{1.0, 4.0})),
      std::vector<SymMat2>(3, SymMat2::diagonal(Vec2{4.0, 1.0}))};
  for (const SymMat2& m : combine_metrics<2>(two))
    EXPECT_TRUE(metrics_equal(m, SymMat2::diagonal(4.0), 1e-12));
  std::vector<std::vector<SymMat2>> three = two;
  three.push_back(std::vector<SymMat2>(3, compose(rotation(0.5), Vec2{9.0, 0.5})));
  for (const SymMat2& m : combine_metrics<2>(three))
    for (const auto& f : three) EXPECT_TRUE(contained_in(m, f[0], 1e-9));
  const std::vector<std::vector<SymMat2>> mismatched = {std::vector<SymMat2>(3, SymMat2::identity()),
                                                        std::vector<SymMat2>(2, SymMat2::identity())};
  EXPECT_THROW(combine_metrics<2>(mismatched), InputError);
  EXPECT_THROW(combine_metrics<2>(std::span<const std::vector<SymMat2>>{}), InputError);
}

// Relative normalisation divides by max |u| = 4.
TEST(CombineMetrics, RelativeNormalisationDividesByMaxAbsU) {
  std::vector<SymMat2> h(3, SymMat2::diagonal(8.0));
  const std::vector<double> u = {1.0, -4.0, 2.0};
  normalize_hessians_relative<2>(h, u);
  for (const SymMat2& m : h) EXPECT_EQ(m, SymMat2::diagonal(2.0));
}
