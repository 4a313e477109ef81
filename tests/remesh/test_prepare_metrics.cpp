// require_reachable_complexity: its two upper bounds of the vertex count of a unit mesh, checked
// against the complexity integrated numerically.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/prepare_metrics.hpp"

using namespace riemesh;

namespace {

/// One tetrahedron (0,0,0), (1,0,0), (0,1,0), (0,0,1) with isotropic sizes h at its vertices.
struct OneTet {
  Mesh mesh;
  std::vector<SymMat3> metrics;
};

OneTet one_tet(const double (&h)[4]) {
  OneTet t;
  t.mesh.dim = 3;
  t.mesh.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  t.mesh.tets = {0, 1, 2, 3};
  t.mesh.tet_ref = {1};
  for (double x : h) t.metrics.push_back(isotropic_metric<3>(x));
  return t;
}

/// The mean of h^-3 over a tetrahedron for h linear between distinct vertex sizes, in closed
/// form (Hermite–Genocchi: 3! times the divided difference of ln(x) / 2 over the four sizes).
double mean_inverse_cube(const double (&h)[4]) {
  double dd = 0.0;
  for (int i = 0; i < 4; ++i) {
    double denominator = 1.0;
    for (int j = 0; j < 4; ++j)
      if (j != i) denominator *= h[i] - h[j];
    dd += std::log(h[i]) / denominator;
  }
  return 3.0 * dd;
}

/// The vertex count of a unit mesh of linear sizes over the unit corner tet (volume 1/6).
double linear_vertices(const double (&h)[4]) { return std::sqrt(2.0) / 6.0 * mean_inverse_cube(h); }

bool refused(const OneTet& t, double max_vertices, ComplexityBound bound) {
  try {
    require_reachable_complexity<3>(t.mesh, t.metrics, max_vertices, bound);
  } catch (const InputError&) {
    return true;
  }
  return false;
}

}  // namespace

// A tet with one vertex 700 times finer than the others (a small dent in a cube's face, meshed
// with sizes from the surface): linear sizes need ~30 vertices (√2 ∫ h^-3); the log-Euclidean
// bound (the mean of the vertices' h^-3) said 1.7e8 and `riemesh mesh` refused the surface.
TEST(PrepareMetrics, LinearSizesAreBoundedByTheGeometricMean) {
  const double h[4] = {7e-4, 0.3, 0.5, 0.8};
  const OneTet t = one_tet(h);
  const double exact = linear_vertices(h);
  EXPECT_NEAR(exact, 29.6, 0.1);  // Monte Carlo on 8 M points: 28.1 (a heavy tail at the vertex)
  EXPECT_FALSE(refused(t, 20.0 * exact, ComplexityBound::kLinearSizes));
  EXPECT_TRUE(refused(t, 1e6 * exact, ComplexityBound::kLogEuclidean));
  // Still an upper bound: refused below the true count.
  EXPECT_TRUE(refused(t, 0.9 * exact, ComplexityBound::kLinearSizes));
}

// The geometric mean bounds the mean of h^-3 from above for any linear sizes (Jensen: the mean
// of h^-4 over a tetrahedron is exactly 1 / Π h_i); checked on random sizes, one per decade
// range so that the closed form is well conditioned.
TEST(PrepareMetrics, GeometricMeanIsAnUpperBoundOfLinearSizes) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    const double h[4] = {std::pow(10.0, -3.0 + u(rng)), std::pow(10.0, -2.0 + u(rng)),
                         0.1 + 0.4 * u(rng), 0.5 + 0.5 * u(rng)};
    const double exact = linear_vertices(h);
    const double bound = std::sqrt(2.0) / 6.0 / std::pow(h[0] * h[1] * h[2] * h[3], 0.75);
    EXPECT_LE(exact, bound) << h[0] << " " << h[1] << " " << h[2] << " " << h[3];
    EXPECT_FALSE(refused(one_tet(h), 1.001 * bound, ComplexityBound::kLinearSizes));
    EXPECT_TRUE(refused(one_tet(h), 0.999 * bound, ComplexityBound::kLinearSizes));
  }
}

TEST(PrepareMetrics, HminHoldsAfterGradation) {
  // Anisotropic sizes 0.001 x 0.2 clipped to --hmin 0.01, turned 60° from vertex to vertex:
  // gradation intersects neighbouring ellipses, whose intersection is finer than either in
  // directions between theirs, after the clip (0.00991 seen for --hmin 0.01).
  const Mesh m = unit_square(8, 8);
  std::vector<SymMat2> metrics(m.num_vertices());
  for (std::size_t v = 0; v < metrics.size(); ++v) {
    const double a = 1.0471975511965976 * static_cast<double>(v % 3);
    const double c = std::cos(a), s = std::sin(a), l1 = 1.0 / (0.001 * 0.001), l2 = 1.0 / 0.04;
    metrics[v] = SymMat2{{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c}};
  }
  Adapt2dOptions o;
  o.hmin = 0.01;
  o.hgrad = 1.3;
  Adapt2dReport report;
  const std::vector<SymMat2> out =
      prepare_metrics<2>(m, build_adjacency(m.triangles, 3, m.num_vertices()),
                         std::span<const SymMat2>(metrics), o, report);
  double largest = 0.0;
  for (const SymMat2& x : out) largest = std::max(largest, eigen(x).values[1]);
  EXPECT_LE(largest, (1.0 + 1e-9) / (0.01 * 0.01));
}
