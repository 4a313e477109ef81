// Metric-field statistics of a mesh: element quality and size, metric edge lengths, unit
// fraction and metric field validation, against hand-derived values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "metric/mesh_quality.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

namespace {
/// The same packed tensor at every vertex.
std::vector<double> constant_field(const Mesh& m, std::vector<double> t) {
  std::vector<double> f;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) f.insert(f.end(), t.begin(), t.end());
  return f;
}
}  // namespace

TEST(MeshQuality, EuclideanRightTriangles) {
  // Right isosceles triangle with legs 1: 4√3 · ½ / (1 + 1 + 2) = √3/2.
  for (double q : element_qualities(unit_square(1, 1))) EXPECT_NEAR(q, std::sqrt(3.0) / 2, 1e-15);
  // Regular size: √3/4 h² = ½ -> h = sqrt(2/√3).
  for (double h : element_sizes(unit_square(1, 1)))
    EXPECT_NEAR(h, std::sqrt(2 / std::sqrt(3.0)), 1e-15);
}

TEST(MeshQuality, ConstantAnisotropicMetric) {
  // M = diag(4, 1): |K|_M = sqrt(det M)·½ = 1; Σ l² = 4 + 1 + 5 = 10 -> q = 4√3/10.
  const Mesh m = unit_square(1, 1);
  const std::vector<double> f = constant_field(m, {4, 0, 1});
  for (double q : element_qualities(m, f)) EXPECT_NEAR(q, 0.4 * std::sqrt(3.0), 1e-14);
  // Size det(M)^(-1/4) = 1/√2.
  for (double h : element_sizes(m, f)) EXPECT_NEAR(h, std::sqrt(0.5), 1e-14);
  // Edges: x-edges 2, y-edges 1, diagonal √5; 2 of 5 in [1/√2, √2].
  const Adjacency adj = build_adjacency(m);
  std::vector<double> l = metric_edge_lengths(m, adj, f);
  std::sort(l.begin(), l.end());
  ASSERT_EQ(l.size(), 5u);
  const double want[5] = {1, 1, 2, 2, std::sqrt(5.0)};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(l[i], want[i], 1e-14);
  EXPECT_DOUBLE_EQ(unit_length_fraction(l), 0.4);
}

TEST(MeshQuality, GeometricEdgeLengthAcrossSizes) {
  // Vertex 0 with M = I, vertex 1 with M = I/4 on the unit edge along x: l_a = 1, l_b = ½,
  // (l_a − l_b)/ln(l_a/l_b) = ½ / ln 2.
  Mesh m = unit_square(1, 1);
  std::vector<double> f = constant_field(m, {1, 0, 1});
  f[3] = f[5] = 0.25;  // vertex 1 = (1, 0)
  const Adjacency adj = build_adjacency(m);
  const std::vector<double> l = metric_edge_lengths(m, adj, f);
  const Id e = find_edge(adj, 0, 1);
  EXPECT_NEAR(l[e], 0.5 / std::log(2.0), 1e-14);
}

TEST(MeshQuality, KuhnTetsAndMeanMetric) {
  // Kuhn tet (0,0,0) (1,0,0) (1,1,0) (1,1,1): Σ l² = 1+2+3+1+2+1 = 10, V = 1/6,
  // q = 12 (3V)^(2/3) / Σ l² = 1.2 · 2^(-2/3). Metric 4I scales every length by 2: same q.
  const Mesh m = unit_cube(1);
  const double want = 1.2 * std::pow(2.0, -2.0 / 3.0);
  for (double q : element_qualities(m)) EXPECT_NEAR(q, want, 1e-14);
  const std::vector<double> f = constant_field(m, {4, 0, 4, 0, 0, 4});
  for (double q : element_qualities(m, f)) EXPECT_NEAR(q, want, 1e-14);
  // Regular tet size: h³/(6√2) = 1/6 -> h = √2^(1/3); metric size det(4I)^(-1/6) = ½.
  for (double h : element_sizes(m)) EXPECT_NEAR(h, std::cbrt(std::sqrt(2.0)), 1e-14);
  for (double h : element_sizes(m, f)) EXPECT_NEAR(h, 0.5, 1e-14);
  // Log-Euclidean mean of two vertices at I and two at 16 I: exp(½ log 16) I = 4I -> size ½
  // (the arithmetic mean 8.5 I would give 0.34).
  std::vector<double> g = constant_field(m, {1, 0, 1, 0, 0, 1});
  const std::span<const Id> t0(m.tets.data(), 4);
  for (int i = 0; i < 2; ++i)
    for (int k : {0, 2, 5}) g[6 * t0[i] + k] = 16.0;
  EXPECT_NEAR(element_sizes(m, g)[0], 0.5, 1e-14);
}

TEST(MeshQuality, SurfaceTriangles) {
  // A unit equilateral triangle tilted in 3D has quality 1 in I and in any c·I; a metric that
  // stretches x tenfold flattens it.
  Mesh m;
  m.dim = 3;
  const double s = std::sqrt(0.5);
  m.coords = {0, 0, 0, s, s, 0, 0, s, s};  // pairwise distances 1
  m.vert_ref = {0, 0, 0};
  m.triangles = {0, 1, 2};
  m.tri_ref = {1};
  EXPECT_NEAR(element_qualities(m)[0], 1.0, 1e-14);
  EXPECT_NEAR(element_qualities(m, constant_field(m, {9, 0, 9, 0, 0, 9}))[0], 1.0, 1e-14);
  EXPECT_LT(element_qualities(m, constant_field(m, {100, 0, 1, 0, 0, 1}))[0], 0.9);
}

TEST(MeshQuality, InvertedTriangleIsNegative) {
  Mesh m = unit_square(1, 1);
  std::swap(m.triangles[1], m.triangles[2]);
  EXPECT_NEAR(element_qualities(m)[0], -std::sqrt(3.0) / 2, 1e-15);
}

TEST(MeshQuality, ValidateMetricField) {
  const Mesh m = unit_square(1, 1);
  std::vector<double> f = constant_field(m, {1, 0, 1});
  EXPECT_NO_THROW(validate_metric_field(m, f));
  f[3 * 2 + 1] = 2.0;  // vertex 2 (1-based 3): [[1,2],[2,1]] is indefinite
  try {
    validate_metric_field(m, f);
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 3"), std::string::npos) << e.what();
  }
  f.pop_back();
  EXPECT_THROW(validate_metric_field(m, f), InputError);
}

TEST(MeshQuality, HistogramEdges) {
  const std::vector<double> e = length_histogram_edges();
  ASSERT_EQ(e.size(), 11u);
  EXPECT_EQ(e[0], 0.0);
  EXPECT_DOUBLE_EQ(e[1], 0.25);
  EXPECT_DOUBLE_EQ(e[5], 1.0);
  EXPECT_DOUBLE_EQ(e[4] * e[6], 1.0);
  EXPECT_EQ(quality_histogram_edges().size(), 11u);
}

TEST(MeshQuality, EdgeLengthsWhereTheMetricTurns) {
  // The ends of the x-edge (0,0)-(1,0) carry a stiff axis turned by ±0.4 rad: their metrics do
  // not commute, and the edge is measured as the remeshers do, by Simpson's rule on the
  // log-Euclidean field (its middle sees the stiff axis across the edge: shorter than its ends).
  Mesh m = unit_square(1, 1);
  const auto turned = [](double a) {
    const double c = std::cos(a), s = std::sin(a);
    return SymMat2{{c * c * 1.0 + s * s * 100.0, c * s * (1.0 - 100.0), s * s * 1.0 + c * c * 100.0}};
  };
  std::vector<double> f = constant_field(m, {1, 0, 1});
  const SymMat2 m0 = turned(0.4), m1 = turned(-0.4);
  for (int k = 0; k < 3; ++k) f[k] = m0.c[k], f[3 + k] = m1.c[k];  // vertices 0 and 1
  const Adjacency adj = build_adjacency(m);
  const std::vector<double> l = metric_edge_lengths(m, adj, f);
  const Vec2 ab{{1.0, 0.0}};
  const double ends = std::sqrt(quadratic(m0, ab));  // both ends alike, by symmetry
  EXPECT_NEAR(ends, std::sqrt(std::cos(0.4) * std::cos(0.4) + 100 * std::sin(0.4) * std::sin(0.4)), 1e-12);
  // Log-Euclidean middle: the logs R(±a) diag(0, ln 100) R(±a)ᵀ average to
  // diag(sin²a ln 100, cos²a ln 100), so the x-edge is 10^(sin²a) long there.
  const double mid = std::pow(10.0, std::sin(0.4) * std::sin(0.4));
  EXPECT_NEAR(l[find_edge(adj, 0, 1)], (2 * ends + 4 * mid) / 6, 1e-9);
  EXPECT_LT(l[find_edge(adj, 0, 1)], 0.8 * ends);
}
