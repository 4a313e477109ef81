// The unit lattice of a constant metric (lattice2d.hpp), by properties: the map to the unit space
// measures lengths in the metric and inverts; the lattice points lie inside the domain (never in
// a hole), at least the clearance away from its boundary, each at exactly unit metric distance
// from its nearest neighbours (six of them inside), as many as the area asks (2/√3 per unit of
// metric area); mesh_domain2d with a constant metric meshes the inside with unit equilateral
// triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/domain2d.hpp"
#include "generate/lattice2d.hpp"
#include "generate/mesh2d.hpp"
#include "generate/square_loop.hpp"
#include "metric/element.hpp"
#include "metric/metric.hpp"

using namespace riemesh;
using test::add_square;

namespace {

Mesh boundary_of_squares(bool hole) {
  Mesh b;
  b.dim = 2;
  add_square(b, 0.0, 1.0, 10, true);
  if (hole) add_square(b, 0.3, 0.4, 4, false);
  return b;
}

/// The metric with sizes h1 along (cos a, sin a) and h2 across.
SymMat2 turned_metric(double h1, double h2, double a) {
  const double c = std::cos(a), s = std::sin(a), l1 = 1 / (h1 * h1), l2 = 1 / (h2 * h2);
  return SymMat2{{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c}};
}

double metric_distance(const SymMat2& m, const double* p, const double* q) {
  const Vec2 d{{q[0] - p[0], q[1] - p[1]}};
  return std::sqrt(quadratic(m, d));
}

/// The metric distance from p to the segment ab (the closest point in the metric).
double distance_to_segment(const SymMat2& m, const double* p, const double* a, const double* b) {
  double best = 1e300;
  for (int k = 0; k <= 2000; ++k) {  // fine enough for a check to 1e-3 of the sizes
    const double t = k / 2000.0, q[2] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    best = std::min(best, metric_distance(m, p, q));
  }
  return best;
}

}  // namespace

TEST(MetricMap2d, MeasuresInTheMetricAndInverts) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 100; ++k) {
    const SymMat2 m = turned_metric(0.5 + u(rng) * 0.4, 0.01 + 0.005 * u(rng), 3 * u(rng));
    const MetricMap2d map(m);
    const double x[2] = {u(rng), u(rng)};
    double v[2], back[2];
    map.to_unit(x, v);
    const Vec2 d{{x[0], x[1]}};
    EXPECT_NEAR(std::hypot(v[0], v[1]), std::sqrt(quadratic(m, d)), 1e-12 * std::hypot(v[0], v[1]));
    map.from_unit(v, back);
    EXPECT_NEAR(back[0], x[0], 1e-12);
    EXPECT_NEAR(back[1], x[1], 1e-12);
  }
  EXPECT_THROW(MetricMap2d(SymMat2{{1, 2, 1}}), InputError);    // indefinite
  EXPECT_THROW(MetricMap2d(SymMat2{{NAN, 0, 1}}), InputError);  // not a number
}

TEST(Lattice2d, IsotropicPointsFillTheSquareAtUnitSpacing) {
  const double h = 0.02, clearance = 0.43;
  const Mesh domain = triangulate_domain2d(boundary_of_squares(false), {}).mesh;
  const SymMat2 m = isotropic_metric<2>(h);
  const std::vector<double> p = lattice_points2d(domain, m, clearance);
  const std::size_t n = p.size() / 2;
  // 2/√3 points per h² of the square, less a strip along the boundary narrower than the widest
  // gap left to the first row kept (clearance + √3/2).
  const double gap = (clearance + std::sqrt(0.75)) * h;
  EXPECT_GT(static_cast<double>(n), 2 / std::sqrt(3.0) * std::pow(1 - 2 * gap, 2) / (h * h));
  EXPECT_LT(static_cast<double>(n), 2 / std::sqrt(3.0) / (h * h));
  std::vector<int> unit_neighbours(n, 0);
  for (std::size_t a = 0; a < n; ++a) {
    EXPECT_GE(std::min({p[2 * a], p[2 * a + 1], 1 - p[2 * a], 1 - p[2 * a + 1]}),
              clearance * h * (1 - 1e-9));
    for (std::size_t b = a + 1; b < n; ++b) {
      const double d = std::hypot(p[2 * a] - p[2 * b], p[2 * a + 1] - p[2 * b + 1]);
      EXPECT_GT(d, h * (1 - 1e-9));  // no point twice, none closer than a lattice step
      if (d < h * (1 + 1e-9)) ++unit_neighbours[a], ++unit_neighbours[b];
    }
  }
  for (std::size_t a = 0; a < n; ++a) EXPECT_GE(unit_neighbours[a], 2);
  EXPECT_GT(std::count(unit_neighbours.begin(), unit_neighbours.end(), 6),
            static_cast<long>(0.9 * n));
}

TEST(Lattice2d, TurnedMetricAndAHole) {
  // Sizes 0.1 × 0.01 turned by 30°: neighbours at unit metric distance; nothing in the hole
  // [0.3, 0.7]², nothing closer than the clearance to an edge of either loop.
  const double clearance = 0.5;
  const Mesh boundary = boundary_of_squares(true);
  const Mesh domain = triangulate_domain2d(boundary, {}).mesh;
  const SymMat2 m = turned_metric(0.1, 0.01, std::numbers::pi / 6);
  const std::vector<double> p = lattice_points2d(domain, m, clearance);
  const std::size_t n = p.size() / 2;
  // C = ∫ √det M = 1000 · (1 − 0.16): about 2/√3 · 840 points, less the strips.
  EXPECT_GT(n, 700u);
  EXPECT_LT(n, 970u);
  for (std::size_t a = 0; a < n; ++a) {
    const double* q = &p[2 * a];
    EXPECT_FALSE(q[0] > 0.3 && q[0] < 0.7 && q[1] > 0.3 && q[1] < 0.7) << q[0] << " " << q[1];
    double nearest = 1e300;
    for (std::size_t b = 0; b < n; ++b)
      if (b != a) nearest = std::min(nearest, metric_distance(m, q, &p[2 * b]));
    EXPECT_NEAR(nearest, 1.0, 1e-9);
  }
  for (std::size_t e = 0; e < boundary.num_edges(); ++e) {
    const double* a = &boundary.coords[2 * boundary.edges[2 * e]];
    const double* b = &boundary.coords[2 * boundary.edges[2 * e + 1]];
    for (std::size_t k = 0; k < n; ++k)
      if (metric_distance(m, &p[2 * k], a) < 4 || metric_distance(m, &p[2 * k], b) < 4) {
        EXPECT_GE(distance_to_segment(m, &p[2 * k], a, b), clearance * (1 - 1e-3));
      }
  }
}

TEST(Mesh2d, ConstantMetricMeshesTheInsideWithUnitEquilateralTriangles) {
  // The square with a square hole, sizes 0.05 × 0.005 turned by 30° (the boundary remeshed):
  // mean quality in the metric above 0.98 (0.984; the field points along edges gave 0.94 on such
  // cases, bench/mesh2d_aniso.sh), the count within 3% of (4/√3) C (+1.3%).
  const SymMat2 m = turned_metric(0.05, 0.005, std::numbers::pi / 6);
  const Mesh boundary = boundary_of_squares(true);
  Mesh2dOptions o;
  o.metric.assign(boundary.num_vertices(), m);
  o.keep_boundary = false;
  o.adapt.hgrad = 0.0;
  const Mesh2dResult r = mesh_domain2d(boundary, o);
  double sum = 0, worst = 1;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t) {
    const Id* v = &r.mesh.triangles[3 * t];
    const Vec2 p[3] = {{{r.mesh.coords[2 * v[0]], r.mesh.coords[2 * v[0] + 1]}},
                       {{r.mesh.coords[2 * v[1]], r.mesh.coords[2 * v[1] + 1]}},
                       {{r.mesh.coords[2 * v[2]], r.mesh.coords[2 * v[2] + 1]}}};
    const double q = quality<2>(m, p);
    sum += q, worst = std::min(worst, q);
  }
  EXPECT_GT(sum / static_cast<double>(r.mesh.num_triangles()), 0.98);
  EXPECT_GT(worst, 0.3);  // at the corners, acute in the metric
  const double best = 4 / std::sqrt(3.0) * 4000 * 0.84;
  EXPECT_NEAR(static_cast<double>(r.mesh.num_triangles()), best, 0.03 * best);
}
