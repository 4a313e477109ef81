#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "metric/gradation.hpp"
#include "metric/metric.hpp"

using namespace riemesh;

namespace {

struct Graph {
  std::vector<double> xy;
  std::vector<int32_t> edges;
};

// Vertices 0..n-1 on a wiggly line with random spacing, edges (i, i+1).
Graph chain(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> step(0.01, 0.2), wiggle(-0.05, 0.05);
  Graph g;
  double x = 0.0;
  for (int i = 0; i < n; ++i) {
    g.xy.insert(g.xy.end(), {x, wiggle(rng)});
    x += step(rng);
    if (i > 0) g.edges.insert(g.edges.end(), {i - 1, i});
  }
  return g;
}

// (n+1)² vertices of the unit square; the edges of its triangulation (x, y and diagonal).
Graph grid(int n) {
  Graph g;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) g.xy.insert(g.xy.end(), {double(i) / n, double(j) / n});
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int32_t v = j * (n + 1) + i;
      if (i < n) g.edges.insert(g.edges.end(), {v, v + 1});
      if (j < n) g.edges.insert(g.edges.end(), {v, v + n + 1});
      if (i < n && j < n) g.edges.insert(g.edges.end(), {v, v + n + 2});
    }
  return g;
}

// Sizes log-uniform in [1e-2, 1], around the edge lengths (0.01-0.2) so that gradation binds
// (with sizes much below the edge lengths, L is large and H-shock allows huge ratios).
std::vector<SymMat2> random_field(std::size_t n, bool anisotropic, std::mt19937& rng) {
  std::uniform_real_distribution<double> logh(std::log(1e-2), 0.0), angle(0.0, 3.2);
  std::vector<SymMat2> m;
  for (std::size_t v = 0; v < n; ++v) {
    const double h1 = std::exp(logh(rng)), h2 = anisotropic ? std::exp(logh(rng)) : h1;
    const double t = angle(rng), c = std::cos(t), s = std::sin(t);
    m.push_back(metric_from_sizes(Mat2{{{c, -s}, {s, c}}}, Vec2{{h1, h2}}));
  }
  return m;
}

double edge_size(const SymMat2& m, const Vec2& u) { return 1.0 / length(m, u); }

// Sizes never grow: M_new − M_old is positive semidefinite (every length grows or stays).
void expect_no_size_grows(const std::vector<SymMat2>& before, const std::vector<SymMat2>& after) {
  for (std::size_t v = 0; v < before.size(); ++v) {
    const SymMat2 d = after[v] - before[v];
    const double scale = 1e-9 * frobenius(after[v]);
    EXPECT_GE(d.c[0], -scale) << "vertex " << v;
    EXPECT_GE(d.c[0] * d.c[2] - d.c[1] * d.c[1], -scale * frobenius(d)) << "vertex " << v;
  }
}

}  // namespace

TEST(GradationOptions, Validate) {
  GradationOptions o;
  EXPECT_NO_THROW(o.validate());
  o.threshold = 1.0;  // β = 1 forbids any size change: not a gradation
  EXPECT_THROW(o.validate(), InputError);
  o.mode = GradationMode::kHVariation;
  EXPECT_NO_THROW(o.validate());
  o.threshold = 0.0;
  EXPECT_THROW(o.validate(), InputError);
  o.threshold = NAN;
  EXPECT_THROW(o.validate(), InputError);
  o = GradationOptions{};
  o.mode = GradationMode::kGrowth;
  o.threshold = 0.9;
  EXPECT_THROW(o.validate(), InputError);
  o = GradationOptions{};
  o.max_passes = 0;
  EXPECT_THROW(o.validate(), InputError);
}

TEST(Gradation, TwoVerticesHVariation) {
  // h = 1 and 0.01 at distance 1: v = 0.99 > α, so the larger size becomes 0.01 + α·1.
  for (const bool aniso : {false, true}) {
    const std::vector<double> xy = {0, 0, 1, 0};
    const std::vector<int32_t> e = {0, 1};
    std::vector<SymMat2> m = {isotropic_metric<2>(1.0), isotropic_metric<2>(0.01)};
    GradationOptions o;
    o.mode = GradationMode::kHVariation;
    o.threshold = 0.25;
    o.anisotropic = aniso;
    const GradationReport r = gradate<2>(xy, e, m, o);
    EXPECT_NEAR(sizes(m[0]).sizes[0], 0.26, 1e-12);
    EXPECT_NEAR(sizes(m[0]).sizes[1], 0.26, 1e-12);
    EXPECT_EQ(m[1], isotropic_metric<2>(0.01));
    EXPECT_TRUE(r.converged);
    EXPECT_EQ(r.passes, 2);  // one pass corrects, the second finds nothing to do
    EXPECT_EQ(r.modified_vertices, 1u);
    EXPECT_NEAR(r.measure_before, 0.99, 1e-12);
    EXPECT_NEAR(r.measure_after, 0.25, 1e-12);
  }
}

TEST(Gradation, TwoVerticesHShock) {
  // hs = 0.01, hl = 1, |AB| = 0.1: L = |AB|(hl − hs)/(hs hl ln(hl/hs)) = 0.099/(0.01 ln 100)
  // ≈ 2.1497, c = 100^{1/L} ≈ 8.50 > β = 1.3, so hl ← η hl = hs β^L ≈ 0.01758.
  const double len = 0.1, hs = 0.01, hl = 1.0, beta = 1.3;
  const double l = len * (hl - hs) / (hs * hl * std::log(hl / hs));
  const std::vector<double> xy = {0, 0, 0, len};
  const std::vector<int32_t> e = {1, 0};
  for (const bool aniso : {false, true}) {
    std::vector<SymMat2> m = {isotropic_metric<2>(hl), isotropic_metric<2>(hs)};
    GradationOptions o;
    o.threshold = beta;
    o.anisotropic = aniso;
    const GradationReport r = gradate<2>(xy, e, m, o);
    EXPECT_NEAR(sizes(m[0]).sizes[1], hs * std::pow(beta, l), 1e-12);
    EXPECT_NEAR(r.measure_before, std::pow(hl / hs, 1.0 / l), 1e-9);
    // L grew as hl shrank, so c = β^{L_old/L_new} < β: one pass suffices.
    EXPECT_LT(r.measure_after, beta);
    EXPECT_EQ(r.passes, 2);
  }
}

TEST(Gradation, AnisotropicFloorKeepsSmallSizes) {
  // A: isotropic h = 0.01; B at distance 1 along x: size 1 along x, 0.02 along y; Hv α = 0.1.
  // Along the edge h_s = 0.01, h_l = 1: target 0.01 + 0.1 = 0.11, η = 0.11. The isotropic
  // correction of the smallest sizes (0.01 at A, 0.02 at B) changes nothing, h*_iso = 0.02; so
  // B gets max(0.11·1, 0.02) = 0.11 along x and keeps min(0.02, max(0.11·0.02, 0.02)) = 0.02.
  const std::vector<double> xy = {0, 0, 1, 0};
  const std::vector<int32_t> e = {0, 1};
  std::vector<SymMat2> m = {isotropic_metric<2>(0.01), SymMat2{{1.0, 0.0, 1.0 / (0.02 * 0.02)}}};
  GradationOptions o;
  o.mode = GradationMode::kHVariation;
  o.threshold = 0.1;
  const GradationReport r = gradate<2>(xy, e, m, o);
  EXPECT_NEAR(m[1].c[0], 1.0 / (0.11 * 0.11), 1e-9);
  EXPECT_NEAR(m[1].c[1], 0.0, 1e-9);
  EXPECT_NEAR(m[1].c[2], 1.0 / (0.02 * 0.02), 1e-6);
  EXPECT_EQ(r.passes, 2);
}

TEST(Gradation, ObliqueEdgeReachesTheTargetInOneStep) {
  // B has sizes 1 (x) and 0.02 (y); the edge from A (h = 0.01) leaves at a small angle φ
  // (sin φ = 0.035), length 1: h_AB(B) = (cos²φ + sin²φ/0.02²)^{-1/2} ≈ 0.50. Hv α = 0.1: the
  // size along the edge must become 0.11. h*_iso = 0.02 (the smallest sizes 0.01, 0.02 need no
  // isotropic correction), so the y size stays (floor) and only x shrinks: solve
  // cos²φ/(η·1)² + sin²φ/0.02² = 1/0.11², η ≈ 0.112, not 0.11/0.50 = 0.22 (which leaves
  // h_AB ≈ 0.2 and, repeated, converges only linearly).
  const double s = 0.035, c = std::sqrt(1 - s * s);
  const std::vector<double> xy = {-c, -s, 0, 0};
  const std::vector<int32_t> e = {0, 1};
  std::vector<SymMat2> m = {isotropic_metric<2>(0.01), SymMat2{{1.0, 0.0, 1.0 / (0.02 * 0.02)}}};
  GradationOptions o;
  o.mode = GradationMode::kHVariation;
  o.threshold = 0.1;
  const GradationReport r = gradate<2>(xy, e, m, o);
  const double eta = c / std::sqrt(1 / (0.11 * 0.11) - s * s / (0.02 * 0.02));
  EXPECT_NEAR(edge_size(m[1], Vec2{{c, s}}), 0.11, 1e-12);
  EXPECT_NEAR(m[1].c[0], 1 / (eta * eta), 1e-9 / (eta * eta));
  EXPECT_NEAR(m[1].c[1], 0.0, 1e-9);                  // directions kept
  EXPECT_NEAR(m[1].c[2], 1.0 / (0.02 * 0.02), 1e-6);  // y size at the floor
  EXPECT_NEAR(r.measure_after, 0.1, 1e-12);
  EXPECT_EQ(r.passes, 2);
}

TEST(Gradation, IsotropicVariantRescalesUniformly) {
  // anisotropic = false works on h = det^{-1/(2D)} and rescales the whole metric: the
  // anisotropy ratio and directions of every vertex are kept.
  std::mt19937 rng(8);
  const Graph g = grid(8);
  std::vector<SymMat2> m = random_field(g.xy.size() / 2, true, rng);
  const std::vector<SymMat2> before = m;
  GradationOptions o;
  o.anisotropic = false;
  const GradationReport r = gradate<2>(g.xy, g.edges, m, o);
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.modified_vertices, 0u);
  EXPECT_LE(max_h_shock<2>(g.xy, g.edges, m, false), 1.3 * (1 + 1e-8));
  for (std::size_t v = 0; v < m.size(); ++v) {
    const double scale = m[v].c[0] / before[v].c[0];
    EXPECT_GE(scale, 1.0 - 1e-12);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(m[v].c[k], scale * before[v].c[k], 1e-9 * m[v].c[2] + 1e-9 * std::abs(m[v].c[k]));
  }
}

TEST(Gradation, HShockBoundHoldsOnRandomIsotropicFields) {
  std::mt19937 rng(11);
  const Graph graphs[2] = {chain(200, rng), grid(12)};
  for (const GradationMode mode : {GradationMode::kHShock, GradationMode::kGrowth})
    for (int gi = 0; gi < 2; ++gi)
      for (const bool aniso : {false, true}) {
        const Graph& g = graphs[gi];
        std::vector<SymMat2> m = random_field(g.xy.size() / 2, false, rng);
        const std::vector<SymMat2> before = m;
        GradationOptions o;
        o.mode = mode;
        o.threshold = 1.3;
        o.anisotropic = aniso;
        const GradationReport r = gradate<2>(g.xy, g.edges, m, o);
        EXPECT_TRUE(r.converged);
        EXPECT_LE(r.measure_after, 1.3 * (1 + 1e-8));
        EXPECT_LE(max_h_shock<2>(g.xy, g.edges, m, aniso), 1.3 * (1 + 1e-8));
        EXPECT_GT(r.measure_before, 1.3);
        EXPECT_GT(r.modified_vertices, 0u);
        expect_no_size_grows(before, m);
        const std::string key =
            std::string(mode == GradationMode::kHShock ? "hshock_" : "growth_") +
            (gi == 0 ? "chain_" : "grid_") + (aniso ? "aniso" : "iso");
        RecordProperty(key + "_passes", r.passes);
      }
}

TEST(Gradation, HVariationBoundHoldsOnRandomFields) {
  std::mt19937 rng(5);
  const Graph g = grid(10);
  for (const bool aniso_field : {false, true}) {
    std::vector<SymMat2> m = random_field(g.xy.size() / 2, aniso_field, rng);
    const std::vector<SymMat2> before = m;
    GradationOptions o;
    o.mode = GradationMode::kHVariation;
    o.threshold = 0.2;
    const GradationReport r = gradate<2>(g.xy, g.edges, m, o);
    EXPECT_TRUE(r.converged);
    // Hv: h*_iso = h_min(A) + α|AB| <= h_AB(A) + α|AB|, so the floor never blocks the bound.
    EXPECT_LE(r.measure_after, 0.2 * (1 + 1e-6));
    expect_no_size_grows(before, m);
    RecordProperty(std::string("hv_grid_") + (aniso_field ? "anisofield" : "isofield") + "_passes",
                   r.passes);
  }
}

TEST(Gradation, AnisotropicKeepsDirectionsAndNeverGrows) {
  std::mt19937 rng(9);
  const Graph g = grid(10);
  for (const GradationMode mode : {GradationMode::kHShock, GradationMode::kHVariation}) {
    std::vector<SymMat2> m = random_field(g.xy.size() / 2, true, rng);
    const std::vector<SymMat2> before = m;
    GradationOptions o;
    o.mode = mode;
    o.threshold = mode == GradationMode::kHShock ? 1.5 : 0.3;
    const GradationReport r = gradate<2>(g.xy, g.edges, m, o);
    EXPECT_TRUE(r.converged);
    EXPECT_LE(r.measure_after, r.measure_before);
    for (std::size_t v = 0; v < m.size(); ++v) {
      // Same eigenvectors: each old principal direction r_i is still an eigenvector.
      const MetricSizes<2> old = sizes(before[v]);
      for (int i = 0; i < 2; ++i) {
        const Vec2 ri = old.directions.column(i), mr = m[v] * ri;
        EXPECT_NEAR(std::abs(cross(ri, mr)) / norm(mr), 0.0, 1e-9) << "vertex " << v;
        EXPECT_LE(edge_size(m[v], ri), old.sizes[i] * (1 + 1e-12)) << "vertex " << v;
      }
    }
    expect_no_size_grows(before, m);
    RecordProperty(
        std::string(mode == GradationMode::kHShock ? "hshock" : "hv") + "_grid_anisofield_passes",
        r.passes);
    RecordProperty(std::string(mode == GradationMode::kHShock ? "hshock" : "hv") +
                       "_grid_anisofield_measure_after_x1000",
                   static_cast<int>(1000 * r.measure_after));
  }
}

TEST(Gradation, GrowthOnAnisotropicFieldBoundsEdgeShock) {
  // Along AB the grown metric has size h_B(1 + ℓ ln β), ℓ = |AB|/h_B, which implies
  // c <= β ((1+x) ln²(1+x) <= x² for x >= 0), so at the fixed point every edge has c <= β.
  std::mt19937 rng(21);
  const Graph g = grid(10);
  std::vector<SymMat2> m = random_field(g.xy.size() / 2, true, rng);
  const std::vector<SymMat2> before = m;
  GradationOptions o;
  o.mode = GradationMode::kGrowth;
  o.threshold = 1.4;
  const GradationReport r = gradate<2>(g.xy, g.edges, m, o);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.measure_after, 1.4 * (1 + 1e-6));
  expect_no_size_grows(before, m);
  RecordProperty("growth_grid_anisofield_passes", r.passes);
}

TEST(Gradation, DeterministicIdempotentAndCapped) {
  std::mt19937 rng(2);
  const Graph g = chain(300, rng);
  const std::vector<SymMat2> start = random_field(300, true, rng);
  std::vector<SymMat2> a = start, b = start;
  GradationOptions o;
  EXPECT_TRUE(gradate<2>(g.xy, g.edges, a, o).converged);
  gradate<2>(g.xy, g.edges, b, o);
  EXPECT_EQ(a, b);  // bitwise
  const GradationReport again = gradate<2>(g.xy, g.edges, a, o);
  EXPECT_EQ(again.passes, 1);
  EXPECT_EQ(again.modified_vertices, 0u);
  EXPECT_EQ(a, b);
  // A chain fed from its far end needs one pass per vertex in the given edge order: cap it.
  std::vector<SymMat2> c(300, isotropic_metric<2>(1.0));
  c.back() = isotropic_metric<2>(1e-4);
  o.mode = GradationMode::kHVariation;
  o.threshold = 0.1;
  o.max_passes = 3;
  const GradationReport capped = gradate<2>(g.xy, g.edges, c, o);
  EXPECT_EQ(capped.passes, 3);
  EXPECT_FALSE(capped.converged);
  // Uncapped, each pass fixes exactly one more vertex towards the start of the chain.
  std::vector<SymMat2> d(300, isotropic_metric<2>(1.0));
  d.back() = isotropic_metric<2>(1e-4);
  o.max_passes = 1000;
  const GradationReport slow = gradate<2>(g.xy, g.edges, d, o);
  EXPECT_TRUE(slow.converged);
  EXPECT_EQ(static_cast<std::size_t>(slow.passes), slow.modified_vertices + 1);
  RecordProperty("hv_chain_backward_passes", slow.passes);
  // With the edges listed from the small end, one pass propagates everything.
  std::vector<int32_t> reversed(g.edges.rbegin(), g.edges.rend());
  std::vector<SymMat2> f(300, isotropic_metric<2>(1.0));
  f.back() = isotropic_metric<2>(1e-4);
  const GradationReport fast = gradate<2>(g.xy, reversed, f, o);
  EXPECT_EQ(fast.passes, 2);
  EXPECT_EQ(fast.modified_vertices, slow.modified_vertices);
  for (std::size_t v = 0; v < d.size(); ++v) EXPECT_NEAR(d[v].c[0], f[v].c[0], 1e-9 * d[v].c[0]);
}

TEST(Gradation, UniformFieldIsUntouched) {
  const Graph g = grid(4);
  std::vector<SymMat2> m(g.xy.size() / 2, SymMat2{{100.0, 10.0, 400.0}});
  const GradationReport r = gradate<2>(g.xy, g.edges, m, GradationOptions{});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.passes, 1);
  EXPECT_EQ(r.modified_vertices, 0u);
  EXPECT_DOUBLE_EQ(r.measure_before, 1.0);
  EXPECT_EQ(max_h_variation<2>(g.xy, g.edges, m, true), 0.0);
}

TEST(Gradation, ThreeDimensionalLattice) {
  // 4x4x4 lattice with axis edges, random anisotropic 3D metrics, H-shock: converges and never
  // grows a size.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> logh(std::log(1e-2), 0.0), u(-1, 1);
  const int n = 4;
  std::vector<double> xyz;
  std::vector<int32_t> e;
  std::vector<SymMat3> m;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int32_t v = (k * n + j) * n + i;
        xyz.insert(xyz.end(), {i / 3.0, j / 3.0, k / 3.0});
        if (i + 1 < n) e.insert(e.end(), {v, v + 1});
        if (j + 1 < n) e.insert(e.end(), {v, v + n});
        if (k + 1 < n) e.insert(e.end(), {v, v + n * n});
        const Mat3 r = eigen(SymMat3{{u(rng), u(rng), u(rng), u(rng), u(rng), u(rng)}}).vectors;
        m.push_back(metric_from_sizes(
            r, Vec3{{std::exp(logh(rng)), std::exp(logh(rng)), std::exp(logh(rng))}}));
      }
  const std::vector<SymMat3> before = m;
  for (const GradationMode mode : {GradationMode::kHShock, GradationMode::kGrowth}) {
    GradationOptions o;
    o.mode = mode;
    const GradationReport r = gradate<3>(xyz, e, m, o);
    EXPECT_TRUE(r.converged);
    EXPECT_LE(r.measure_after, r.measure_before);
    for (std::size_t v = 0; v < m.size(); ++v) {
      const SymEigen<3> d = eigen(m[v] - before[v]);
      EXPECT_GE(d.values[0], -1e-9 * frobenius(m[v]));
    }
    RecordProperty(
        std::string(mode == GradationMode::kHShock ? "hshock" : "growth") + "_lattice3d_passes",
        r.passes);
  }
}

TEST(Gradation, InputErrors) {
  const std::vector<double> xy = {0, 0, 1, 0, 1, 0};
  std::vector<SymMat2> m(3, SymMat2::identity());
  const GradationOptions o;
  EXPECT_THROW(gradate<2>(xy, std::vector<int32_t>{1, 2}, m, o), InputError);  // zero length
  EXPECT_THROW(gradate<2>(xy, std::vector<int32_t>{0, 3}, m, o), InputError);  // out of range
  EXPECT_THROW(gradate<2>(xy, std::vector<int32_t>{0}, m, o), InputError);     // odd count
  std::vector<SymMat2> two(2, SymMat2::identity());
  EXPECT_THROW(gradate<2>(xy, std::vector<int32_t>{0, 1}, two, o), InputError);
  m[0] = SymMat2{{1.0, 2.0, 1.0}};  // indefinite
  EXPECT_THROW(gradate<2>(xy, std::vector<int32_t>{0, 1}, m, o), InputError);
}

TEST(Gradation, PhysicalGrowthKeepsATurningAnisotropicField) {
  // A polar-like field on a ring of radius 0.5: radial size 0.001, tangential 0.1, vertices
  // 0.02 apart. The field is smooth, but neighbouring metrics are rotated by 0.04 rad. The
  // metric-space growth shrinks the tangential size to a few times the radial one (the
  // intersection of two thin rotated ellipses); the physical-space growth, where the radial
  // size grows additively to 0.001 + 0.02 ln 1.3 ≈ 0.0062, keeps it above half its value.
  const int n = 157;  // 2π·0.5 / 0.02
  std::vector<double> coords;
  std::vector<int32_t> edges;
  std::vector<SymMat2> metrics;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    coords.insert(coords.end(), {0.5 * std::cos(a), 0.5 * std::sin(a)});
    const Mat2 r{{{std::cos(a), -std::sin(a)}, {std::sin(a), std::cos(a)}}};
    metrics.push_back(metric_from_sizes(r, Vec2{{0.001, 0.1}}));  // radial first
    edges.insert(edges.end(), {i, (i + 1) % n});
  }
  auto tangential_size = [](const SymMat2& m) { return sizes(m).sizes[0]; };
  GradationOptions o;
  o.threshold = 1.3;
  o.mode = GradationMode::kGrowthPhysical;
  std::vector<SymMat2> physical = metrics;
  const GradationReport r = gradate<2>(coords, edges, std::span<SymMat2>(physical), o);
  EXPECT_TRUE(r.converged);
  o.mode = GradationMode::kGrowth;
  std::vector<SymMat2> metric_space = metrics;
  gradate<2>(coords, edges, std::span<SymMat2>(metric_space), o);
  for (int i = 0; i < n; ++i) {
    EXPECT_GT(tangential_size(physical[i]), 0.05) << i;
    EXPECT_LT(tangential_size(metric_space[i]), 0.05) << i;
  }
}

TEST(Gradation, PhysicalGrowthBoundsSizesAndIsAFixedPoint) {
  // Sizes 0.01 and 1 at distance 1 along x: the large end may keep at most 0.01 + ln 1.3 in
  // every direction (additive growth of each principal size); a second run changes nothing.
  std::vector<double> coords = {0, 0, 1, 0};
  std::vector<int32_t> edges = {0, 1};
  std::vector<SymMat2> m = {isotropic_metric<2>(0.01), isotropic_metric<2>(1.0)};
  GradationOptions o;
  o.mode = GradationMode::kGrowthPhysical;
  o.threshold = 1.3;
  gradate<2>(coords, edges, std::span<SymMat2>(m), o);
  const MetricSizes<2> s = sizes(m[1]);
  EXPECT_NEAR(s.sizes[0], 0.01 + std::log(1.3), 1e-12);
  EXPECT_NEAR(s.sizes[1], 0.01 + std::log(1.3), 1e-12);
  const GradationReport again = gradate<2>(coords, edges, std::span<SymMat2>(m), o);
  EXPECT_EQ(again.modified_vertices, 0u);
  EXPECT_EQ(again.passes, 1);
}
