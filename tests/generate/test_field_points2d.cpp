// Field points (insert_field_points2d), by properties: on the boundary-only triangulation of a
// domain, uniform size h, the points added keep the triangulation valid (counter-clockwise, same
// area, same boundary edges), are never closer than h/√2 to each other, and leave no edge much
// longer than √2 h; their number is close to area / (√3/2 h²) (vertices of an equilateral
// lattice). An anisotropic metric gives points spaced by its sizes in each direction, and
// triangles close to equilateral in it (the cavities chosen in the metric).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/predicates.hpp"
#include "generate/domain2d.hpp"
#include "generate/field_points2d.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

namespace {

Mesh square_domain(int n) {  // [0, 1]² with n edges per side, triangulated without interior point
  Mesh b;
  b.dim = 2;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < n; ++k) {
      const double t = double(k) / n;
      const double xy[4][2] = {{t, 0}, {1, t}, {1 - t, 1}, {0, 1 - t}};
      b.coords.insert(b.coords.end(), {xy[side][0], xy[side][1]});
    }
  for (Id i = 0; i < 4 * n; ++i) {
    b.edges.insert(b.edges.end(), {i, (i + 1) % (4 * n)});
    b.edge_ref.push_back(1);
  }
  return triangulate_domain2d(b, {}).mesh;
}

double area(const Mesh& m) {
  double a = 0;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const double o = orient2d(&m.coords[2 * m.triangles[3 * t]], &m.coords[2 * m.triangles[3 * t + 1]],
                              &m.coords[2 * m.triangles[3 * t + 2]]);
    EXPECT_GT(o, 0);
    a += 0.5 * o;
  }
  return a;
}

}  // namespace

TEST(FieldPoints2d, UniformSizeSpacing) {
  const double h = 0.05;
  Mesh m = square_domain(20);  // boundary edges of length h
  const std::size_t nv0 = m.num_vertices(), ne0 = m.num_edges();
  std::vector<SymMat2> metrics(nv0, isotropic_metric<2>(h));
  const FieldPointStats s = insert_field_points2d(m, metrics, InterpScheme::kLogEuclidean);
  EXPECT_EQ(metrics.size(), m.num_vertices());
  EXPECT_EQ(m.num_edges(), ne0);
  EXPECT_NEAR(area(m), 1.0, 1e-12);
  EXPECT_EQ(s.inserted, m.num_vertices() - nv0);
  // Interior vertices of an equilateral lattice of side h: 1 / (√3/2 h²) ≈ 462 in all.
  EXPECT_GT(m.num_vertices(), 300u);
  EXPECT_LT(m.num_vertices(), 600u);
  double closest = 1e9, longest = 0;
  for (std::size_t v = nv0; v < m.num_vertices(); ++v)
    for (std::size_t w = 0; w < v; ++w)
      closest = std::min(closest, std::hypot(m.coords[2 * v] - m.coords[2 * w],
                                             m.coords[2 * v + 1] - m.coords[2 * w + 1]));
  for (std::size_t t = 0; t < m.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id a = m.triangles[3 * t + i], b = m.triangles[3 * t + (i + 1) % 3];
      longest = std::max(longest, std::hypot(m.coords[2 * a] - m.coords[2 * b],
                                             m.coords[2 * a + 1] - m.coords[2 * b + 1]));
    }
  EXPECT_GE(closest, h / std::sqrt(2.0) * (1 - 1e-12));
  EXPECT_LT(longest, 2.0 * h);
}

TEST(FieldPoints2d, AnisotropicMetricStretchesTheSpacing) {
  // Sizes 0.2 along x, 0.02 along y: far more points across y than along x.
  Mesh m = square_domain(5);
  std::vector<SymMat2> metrics(m.num_vertices(), SymMat2{{1 / 0.04, 0, 1 / 0.0004}});
  insert_field_points2d(m, metrics, InterpScheme::kLogEuclidean);
  EXPECT_NEAR(area(m), 1.0, 1e-12);
  // Lattice estimate: 1 / (√3/2 · 0.2 · 0.02) ≈ 289 vertices.
  EXPECT_GT(m.num_vertices(), 180u);
  EXPECT_LT(m.num_vertices(), 420u);
}

TEST(FieldPoints2d, MetricInCircleShapesTrianglesInTheMetric) {
  // A constant metric, sizes 0.1 and 0.01 along directions turned by 30°: the cavities chosen in
  // the candidate's metric (the anisotropic Delaunay kernel) make triangles close to equilateral
  // in it, before any optimisation: mean quality 0.85, 9% below 0.5, 2,186 triangles ((4/√3) C
  // = 2,309). The Euclidean in-circle test made needles across the metric: mean 0.19, 98% below
  // 0.5, 3,432 triangles.
  const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
  const double l1 = 1 / 0.01, l2 = 1 / 0.0001;  // eigenvalues 1/h²
  const SymMat2 m{{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c}};
  Mesh mesh = square_domain(10);
  std::vector<SymMat2> metrics(mesh.num_vertices(), m);
  insert_field_points2d(mesh, metrics, InterpScheme::kLogEuclidean);
  EXPECT_NEAR(area(mesh), 1.0, 1e-12);
  const auto length2 = [&](Id a, Id b) {
    const double dx = mesh.coords[2 * b] - mesh.coords[2 * a],
                 dy = mesh.coords[2 * b + 1] - mesh.coords[2 * a + 1];
    return m.c[0] * dx * dx + 2 * m.c[1] * dx * dy + m.c[2] * dy * dy;
  };
  const double det = std::sqrt(m.c[0] * m.c[2] - m.c[1] * m.c[1]);
  double sum = 0;
  std::size_t poor = 0;
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
    const Id* v = &mesh.triangles[3 * t];
    const double a =
        0.5 * orient2d(&mesh.coords[2 * v[0]], &mesh.coords[2 * v[1]], &mesh.coords[2 * v[2]]);
    const double q = 4 * std::sqrt(3.0) * det * a /
                     (length2(v[0], v[1]) + length2(v[1], v[2]) + length2(v[2], v[0]));
    sum += q;
    poor += q < 0.5;
  }
  const double n = static_cast<double>(mesh.num_triangles());
  EXPECT_GT(sum / n, 0.8);
  EXPECT_LT(poor / n, 0.15);
  EXPECT_NEAR(n, 4 / std::sqrt(3.0) * 1000, 0.15 * 4 / std::sqrt(3.0) * 1000);
}

TEST(FieldPoints2d, NothingToAddWhenEdgesAreShort) {
  Mesh m = square_domain(4);
  std::vector<SymMat2> metrics(m.num_vertices(), isotropic_metric<2>(2.0));
  const FieldPointStats s = insert_field_points2d(m, metrics, InterpScheme::kLogEuclidean);
  EXPECT_EQ(s.inserted, 0u);
  EXPECT_EQ(m.num_vertices(), 16u);
}

TEST(FieldPoints2d, FewLongEdgesAreRefinedInTheirNeighbourhoodOnly) {
  // A 40 × 40 grid about its metric's size, except a patch around (0.5, 0.5) asking for a quarter
  // of it: the few triangles with long edges take field points (the rounds around them only),
  // the rest of the mesh is kept (its vertices first, in place), the result conforming and valid.
  Mesh m = unit_square(40, 40);
  const std::size_t nv = m.num_vertices(), nt = m.num_triangles();
  std::vector<SymMat2> metrics(nv, isotropic_metric<2>(1.0 / 36));  // diagonals 1.27
  for (std::size_t v = 0; v < nv; ++v)
    if (std::hypot(m.coords[2 * v] - 0.5, m.coords[2 * v + 1] - 0.5) < 0.03)
      metrics[v] = isotropic_metric<2>(1.0 / 144);
  const Mesh before = m;
  const FieldPointStats s = insert_field_points2d(m, metrics, InterpScheme::kLogEuclidean);
  EXPECT_GT(s.inserted, 10u);
  ASSERT_EQ(m.num_vertices(), nv + s.inserted);
  ASSERT_EQ(metrics.size(), m.num_vertices());
  EXPECT_EQ(m.num_triangles(), nt + 2 * s.inserted);  // each point inside adds two triangles
  EXPECT_TRUE(std::equal(before.coords.begin(), before.coords.end(), m.coords.begin()));
  EXPECT_EQ(m.edges, before.edges);
  EXPECT_TRUE(check_mesh(m).valid());
  double area = 0.0;
  std::size_t kept = 0;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const Id* v = &m.triangles[3 * t];
    const double o = orient2d(&m.coords[2 * v[0]], &m.coords[2 * v[1]], &m.coords[2 * v[2]]);
    EXPECT_GT(o, 0.0);
    area += 0.5 * o;
    kept += t < nt && std::equal(v, v + 3, &before.triangles[3 * t]);
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_GT(kept, nt - 200);  // far from the patch, the triangles as they were
  for (std::size_t v = nv; v < m.num_vertices(); ++v)  // the new points in the patch's reach
    EXPECT_LT(std::hypot(m.coords[2 * v] - 0.5, m.coords[2 * v + 1] - 0.5), 0.2);
}

TEST(FieldPoints2d, FineHoleInACoarseSquareGivesFewCandidates) {
  // The unit square as 4 edges around a circle of radius 0.2 in 800 edges (hunt 5, F3), sizes the
  // mean length of the boundary edges at each vertex, interpolated linearly as `riemesh mesh`
  // does: the ~800 edges of the fan from the circle to the square's corners are about d / 2h =
  // 95 long by the mean of their ends' lengths, d / h · log(ratio)-like = 2 to 3 in the sizes
  // interpolated along them. At equal steps of the former, 136 k candidates, every one too close
  // to the circle or a corner (1.1 s here, 26 s for 3000 edges); along the latter, a few per edge.
  const int n = 800;
  Mesh b;
  b.dim = 2;
  b.coords = {0, 0, 1, 0, 1, 1, 0, 1};
  for (Id i = 0; i < 4; ++i) b.edges.insert(b.edges.end(), {i, (i + 1) % 4});
  for (int k = 0; k < n; ++k) {
    const double a = -2 * std::numbers::pi * k / n;  // clockwise: a hole
    b.coords.insert(b.coords.end(), {0.5 + 0.2 * std::cos(a), 0.5 + 0.2 * std::sin(a)});
    b.edges.insert(b.edges.end(), {4 + k, 4 + (k + 1) % n});
  }
  b.edge_ref.assign(b.num_edges(), 1);
  Mesh m = triangulate_domain2d(b, {}).mesh;
  ASSERT_EQ(m.num_vertices(), std::size_t(n + 4));
  std::vector<double> sum(m.num_vertices(), 0.0);
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const Id p = m.edges[2 * e], q = m.edges[2 * e + 1];
    const double l = std::hypot(m.coords[2 * q] - m.coords[2 * p], m.coords[2 * q + 1] - m.coords[2 * p + 1]);
    sum[p] += 0.5 * l, sum[q] += 0.5 * l;  // every vertex is on two edges
  }
  std::vector<SymMat2> metrics;
  for (const double h : sum) metrics.push_back(isotropic_metric<2>(h));
  const std::size_t nt0 = m.num_triangles();
  const FieldPointStats s = insert_field_points2d(m, metrics, InterpScheme::kIsoLinear);
  EXPECT_LT(s.inserted + s.rejected, 4 * nt0);
  EXPECT_EQ(m.num_vertices(), std::size_t(n + 4) + s.inserted);
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_NEAR(area(m), 1.0 - std::numbers::pi * 0.04 * std::sin(2 * std::numbers::pi / n) /
                                 (2 * std::numbers::pi / n),
              1e-9);
}
