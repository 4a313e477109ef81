#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "metric/element.hpp"

using namespace riemesh;

namespace {

const double kSqrt3 = std::sqrt(3.0);

template <int D>
void expect_near(const SymMat<D>& a, const SymMat<D>& b, double tol) {
  for (int k = 0; k < SymMat<D>::kSize; ++k)
    EXPECT_NEAR(a.c[k], b.c[k], tol) << "coefficient " << k;
}

// Unit-edge regular simplices.
const Vec2 kTri[3] = {{{0.0, 0.0}}, {{1.0, 0.0}}, {{0.5, kSqrt3 / 2}}};
const Vec3 kTet[4] = {{{0.0, 0.0, 0.0}},
                      {{1.0, 0.0, 0.0}},
                      {{0.5, kSqrt3 / 2, 0.0}},
                      {{0.5, kSqrt3 / 6, std::sqrt(2.0 / 3.0)}}};

}  // namespace

TEST(ElementMetric, EquilateralTriangleIsIdentity) {
  // Three unit vectors 60° apart: Σ v vᵀ = (3/2) I, so M = (3/2)(2/3) I = I.
  expect_near(element_metric<2>(kTri), SymMat2::identity(), 1e-14);
}

TEST(ElementMetric, RegularTetIsIdentity) {
  // Six unit edges of a regular tet: Σ v vᵀ = (6/3) I = 2I (isotropic by symmetry, trace 6);
  // M = (4/2)(1/2) I = I.
  expect_near(element_metric<3>(kTet), SymMat3::identity(), 1e-14);
}

TEST(ElementMetric, RightTriangleByHand) {
  // (0,0),(1,0),(0,1): edges (1,0),(0,1),(-1,1). N = [[2,-1],[-1,2]], det 3,
  // N⁻¹ = [[2,1],[1,2]]/3, M = (3/2) N⁻¹ = [[1, 1/2],[1/2, 1]].
  // Check: |(1,0)|² = 1, |(0,1)|² = 1, |(-1,1)|² = 1 - 1 + 1 = 1.
  const Vec2 p[3] = {{{0.0, 0.0}}, {{1.0, 0.0}}, {{0.0, 1.0}}};
  expect_near(element_metric<2>(p), SymMat2{{1.0, 0.5, 1.0}}, 1e-15);
}

TEST(ElementMetric, RandomSimplicesBecomeUnitAndRegular) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    Vec3 p[4];
    for (auto& v : p) v = {{u(rng), u(rng), u(rng)}};
    if (std::abs(simplex_measure(p)) < 1e-3) continue;
    const SymMat3 m = element_metric<3>(p);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) EXPECT_NEAR(length(m, p[j] - p[i]), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(quality(m, p)), 1.0, 1e-9);
    Vec2 q[3];
    for (int i = 0; i < 3; ++i) q[i] = {{p[i][0], p[i][1]}};
    if (std::abs(simplex_measure(q)) < 1e-3) continue;
    const SymMat2 m2 = element_metric<2>(q);
    EXPECT_NEAR(std::abs(quality(m2, q)), 1.0, 1e-10);
  }
}

TEST(ElementMetric, DegenerateSimplexThrows) {
  const Vec2 line[3] = {{{0.0, 0.0}}, {{1.0, 1.0}}, {{2.0, 2.0}}};
  EXPECT_THROW(element_metric<2>(line), InputError);
  const Vec3 flat[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{1, 1, 0}}};
  EXPECT_THROW(element_metric<3>(flat), InputError);
  const Vec2 nan[3] = {{{0.0, 0.0}}, {{NAN, 0.0}}, {{0.0, 1.0}}};
  EXPECT_THROW(element_metric<2>(nan), InputError);
  // The test is relative: a tiny but well-shaped simplex is fine (M = I/s²).
  const double s = 1e-9;
  const Vec2 tiny[3] = {s * kTri[0], s * kTri[1], s * kTri[2]};
  expect_near(element_metric<2>(tiny), (1.0 / (s * s)) * SymMat2::identity(), 1e-14 / (s * s));
}

TEST(Quality, RegularIsOneInvertedIsMinusOne) {
  EXPECT_NEAR(quality(SymMat2::identity(), kTri), 1.0, 1e-15);
  EXPECT_NEAR(quality(SymMat3::identity(), kTet), 1.0, 1e-15);
  const Vec2 tri_inv[3] = {kTri[0], kTri[2], kTri[1]};
  const Vec3 tet_inv[4] = {kTet[1], kTet[0], kTet[2], kTet[3]};
  EXPECT_NEAR(quality(SymMat2::identity(), tri_inv), -1.0, 1e-15);
  EXPECT_NEAR(quality(SymMat3::identity(), tet_inv), -1.0, 1e-15);
}

TEST(Quality, RightIsoscelesTriangle) {
  // Area 1/2, Σl² = 1 + 1 + 2 = 4: Q = 4√3 (1/2) / 4 = √3/2.
  const Vec2 p[3] = {{{0.0, 0.0}}, {{1.0, 0.0}}, {{0.0, 1.0}}};
  EXPECT_NEAR(quality(SymMat2::identity(), p), kSqrt3 / 2, 1e-15);
  // Trirectangular tet (0, e1, e2, e3): V = 1/6, Σl² = 3 + 3·2 = 9,
  // Q = 12 (1/2)^{2/3} / 9 = (4/3) 2^{-2/3} ≈ 0.840.
  const Vec3 t[4] = {{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}};
  EXPECT_NEAR(quality(SymMat3::identity(), t), 4.0 / 3.0 * std::pow(2.0, -2.0 / 3.0), 1e-15);
}

TEST(Quality, InvariantUnderMetricMapsAndScaling) {
  // Q(M, p) = Q(I, φ p) with φ = M^{1/2} (BOOK.md §1: φ_M maps metric space to Euclidean), and
  // Q(sM, p) = Q(M, p): Σl² scales by s, and so do |K|_M (2D, sqrt(det sM) = s sqrt(det M))
  // and |K|_M^{2/3} (3D, (s^{3/2})^{2/3} = s).
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const SymMat3 m{{4.0, 0.5, 1.0, 0.2, -0.3, 9.0}};
  const Mat3 phi = sqrt_spd(m).to_mat();
  for (int trial = 0; trial < 50; ++trial) {
    Vec3 p[4], q[4];
    for (int i = 0; i < 4; ++i) {
      p[i] = {{u(rng), u(rng), u(rng)}};
      q[i] = phi * p[i];
    }
    const double qm = quality(m, p);
    EXPECT_NEAR(qm, quality(SymMat3::identity(), q), 1e-12);
    EXPECT_NEAR(qm, quality(37.0 * m, p), 1e-12);
  }
  // A rotation of the points with the metric rotated alike changes nothing.
  const double c = std::cos(0.7), s = std::sin(0.7);
  const Mat2 r{{{c, -s}, {s, c}}};
  const SymMat2 m2{{1.0, 0.3, 25.0}};
  const Vec2 p[3] = {{{0.1, 0.2}}, {{0.9, 0.1}}, {{0.3, 0.05}}};
  const Vec2 rp[3] = {r * p[0], r * p[1], r * p[2]};
  EXPECT_NEAR(quality(m2, p), quality(congruence(r, m2), rp), 1e-13);
}

TEST(LogEuclideanMean, KnownValues) {
  // log diag(1,4) = diag(0, ln4), log diag(4,1) = diag(ln4, 0); mean diag(ln2, ln2) -> 2I.
  const SymMat2 a[2] = {SymMat2{{1.0, 0.0, 4.0}}, SymMat2{{4.0, 0.0, 1.0}}};
  expect_near(log_euclidean_mean(a, 2), SymMat2::diagonal(2.0), 1e-14);
  const double w[2] = {1.0, 0.0};
  expect_near(log_euclidean_mean<2>(a, w), a[0], 1e-14);
  const double w3[2] = {3.0, 1.0};  // diag(4^{1/4}, 4^{3/4})
  expect_near(log_euclidean_mean<2>(a, w3), SymMat2{{std::sqrt(2.0), 0.0, std::pow(2.0, 1.5)}},
              1e-13);
  EXPECT_THROW(log_euclidean_mean(a, 0), InputError);
  const double wneg[2] = {1.0, -1.0};
  EXPECT_THROW(log_euclidean_mean<2>(a, wneg), InputError);
}

TEST(Quality, VertexMetricsAtTheElement) {
  // All vertex metrics equal to the element metric: their mean is M_K, so Q = 1.
  const Vec2 p[3] = {{{0.0, 0.0}}, {{3.0, 0.0}}, {{0.0, 0.02}}};
  const SymMat2 mk = element_metric<2>(p);
  const SymMat2 m[3] = {mk, mk, mk};
  EXPECT_NEAR(quality(p, m), 1.0, 1e-9);
}

namespace {

// Structured mesh of [0,1]x[0,sy] with n x n squares split along their (0,0)-(1,1) diagonal.
void grid(int n, double sy, std::vector<double>& xy, std::vector<int32_t>& tri) {
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      xy.push_back(static_cast<double>(i) / n);
      xy.push_back(sy * j / n);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t v = j * (n + 1) + i;
      tri.insert(tri.end(), {v, v + 1, v + n + 2, v, v + n + 2, v + n + 1});
    }
}

}  // namespace

TEST(ImpliedMetric, AnisotropicGridRecoversDirectionalSizes) {
  // Every triangle has edges (hx,0), (0,hy), (hx,hy) up to sign with hx = 1/n, hy = 0.01/n, so
  // every M_K = [[1/hx², -1/(2hx hy)], [·, 1/hy²]] (the right-triangle result scaled) and the
  // vertex means equal it: the sizes along x and y are hx and hy, a ratio of 100.
  const int n = 8;
  std::vector<double> xy;
  std::vector<int32_t> tri;
  grid(n, 0.01, xy, tri);
  const std::vector<SymMat2> m = implied_metric<2>(xy, tri);
  const double hx = 1.0 / n, hy = 0.01 / n;
  for (const SymMat2& mv : m) {
    EXPECT_NEAR(length(mv, Vec2{{hx, 0.0}}), 1.0, 1e-9);
    EXPECT_NEAR(length(mv, Vec2{{0.0, hy}}), 1.0, 1e-9);
    EXPECT_NEAR(length(mv, Vec2{{hx, hy}}), 1.0, 1e-9);
  }
}

TEST(ImpliedMetric, StretchedEquilateralLatticeHasExactAnisotropy) {
  // A lattice of equilateral triangles (side h) has M_K = I/h²; scaling y by 0.01 maps it to
  // diag(1/h², 1/(0.01h)²): anisotropy exactly 100 at every vertex.
  const int n = 6;
  const double h = 1.0 / n, row = h * kSqrt3 / 2, sy = 0.01;
  std::vector<double> xy;
  std::vector<int32_t> tri;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      xy.push_back(i * h + (j % 2) * h / 2);
      xy.push_back(sy * j * row);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      if (j % 2 == 0)
        tri.insert(tri.end(), {a, b, c, b, d, c});
      else
        tri.insert(tri.end(), {a, d, c, a, b, d});
    }
  const std::vector<SymMat2> m = implied_metric<2>(xy, tri);
  for (const SymMat2& mv : m) {
    EXPECT_NEAR(anisotropy(mv), 100.0, 1e-8);
    expect_near(mv, SymMat2{{1.0 / (h * h), 0.0, 1.0 / (sy * sy * h * h)}},
                1e-6 / (sy * sy * h * h));
  }
}

TEST(ImpliedMetric, ScatterFormMatchesVertexKernel) {
  // Vertex 0 of a fan of three triangles of different shapes.
  const std::vector<double> xy = {0, 0, 1, 0, 0.2, 1, -1, 0.3, -0.2, -2};
  const std::vector<int32_t> tri = {0, 1, 2, 0, 2, 3, 0, 3, 4};
  const std::vector<SymMat2> m = implied_metric<2>(xy, tri);
  std::vector<SymMat2> ball;
  std::vector<double> w;
  for (int t = 0; t < 3; ++t) {
    Vec2 p[3];
    for (int i = 0; i < 3; ++i) p[i] = {{xy[2 * tri[3 * t + i]], xy[2 * tri[3 * t + i] + 1]}};
    ball.push_back(element_metric<2>(p));
    w.push_back(std::abs(simplex_measure(p)));
  }
  expect_near(m[0], implied_vertex_metric<2>(ball, w), 1e-12);
  expect_near(m[1], ball[0], 1e-12);  // vertex 1 is in one triangle only
}

TEST(ImpliedMetric, SingleTetAndErrors) {
  const std::vector<double> xyz = {0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 0.5};
  const std::vector<int32_t> tet = {0, 1, 2, 3};
  Vec3 p[4];
  for (int i = 0; i < 4; ++i) p[i] = {{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}};
  for (const SymMat3& mv : implied_metric<3>(xyz, tet))
    expect_near(mv, element_metric<3>(p), 1e-12);

  std::vector<double> extra = xyz;
  extra.insert(extra.end(), {5, 5, 5});  // a vertex in no simplex
  EXPECT_THROW(implied_metric<3>(extra, tet), InputError);
  const std::vector<int32_t> bad = {0, 1, 2, 4};
  EXPECT_THROW(implied_metric<3>(xyz, bad), InputError);
  const std::vector<int32_t> flat = {0, 1, 2, 2};
  EXPECT_THROW(implied_metric<3>(xyz, flat), InputError);
}
