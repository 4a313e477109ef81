// 2D adaptation by properties (STYLE.md: no golden meshes): validity, boundary kept, metric edge
// lengths and qualities in range, determinism, and the bad-input paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <string>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/hilbert.hpp"
#include "metric/edge_length.hpp"
#include "metric/metric.hpp"
#include "remesh/adapt2d.hpp"

using namespace riemesh;

namespace {

/// The UGAWG-style linear field of ../shared/PEERS.md with a milder h0: hx = 0.1,
/// hy = h0 + 2(0.1 − h0)|y − 0.5|.
SymMat2 linear_metric(double y, double h0) {
  const double hy = h0 + 2.0 * (0.1 - h0) * std::abs(y - 0.5);
  return SymMat2{{1.0 / 0.01, 0.0, 1.0 / (hy * hy)}};
}

std::vector<SymMat2> linear_field(const Mesh& m, double h0) {
  std::vector<SymMat2> out;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) out.push_back(linear_metric(m.coords[2 * v + 1], h0));
  return out;
}

/// Metric lengths of the unique edges of the output, with the analytic field at the end points
/// (geometric closed form).
std::vector<double> edge_lengths(const Mesh& m, double h0) {
  std::set<std::pair<Id, Id>> edges;
  for (std::size_t t = 0; t < m.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      Id a = m.triangles[3 * t + i], b = m.triangles[3 * t + (i + 1) % 3];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  std::vector<double> out;
  for (const auto& [a, b] : edges) {
    const Vec2 pa{{m.coords[2 * a], m.coords[2 * a + 1]}}, pb{{m.coords[2 * b], m.coords[2 * b + 1]}};
    out.push_back(edge_length_geometric(linear_metric(pa[1], h0), linear_metric(pb[1], h0), pb - pa));
  }
  return out;
}

double area(const Mesh& m) {
  double a = 0;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const Id* v = &m.triangles[3 * t];
    const Vec2 p0{{m.coords[2 * v[0]], m.coords[2 * v[0] + 1]}};
    const Vec2 p1{{m.coords[2 * v[1]], m.coords[2 * v[1] + 1]}};
    const Vec2 p2{{m.coords[2 * v[2]], m.coords[2 * v[2] + 1]}};
    a += 0.5 * cross(p1 - p0, p2 - p0);
  }
  return a;
}

}  // namespace

TEST(Adapt2d, UniformSizeOnTheSquare) {
  const Mesh in = unit_square(10, 10);
  const std::vector<SymMat2> met(in.num_vertices(), isotropic_metric<2>(0.05));
  const Adapt2dResult r = adapt2d(in, met, {});
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  EXPECT_NEAR(area(r.mesh), 1.0, 1e-12);
  // (4/√3) C(M) = (4/√3) / 0.05² ≈ 924 unit triangles.
  EXPECT_GT(r.mesh.num_triangles(), 800u);
  EXPECT_LT(r.mesh.num_triangles(), 1200u);
  int corners = 0;
  for (auto t : r.mesh.vert_tag) corners += (t & kTagCorner) ? 1 : 0;
  EXPECT_EQ(corners, 4);
  std::set<int> refs(r.mesh.edge_ref.begin(), r.mesh.edge_ref.end());
  EXPECT_EQ(refs, (std::set<int>{1, 2, 3, 4}));
}

// Refining a coarse structured mesh to a uniform size lands near the unit-mesh count, not on the
// power of two below it (bisection at midpoints gave 1.11x and 1.42x at these sizes; measured
// now 1.007 and 1.027, and 0.88 to 1.13 over h = 0.003 ... 0.02).
TEST(Adapt2d, UniformRefinementCountNearTheUnitMesh) {
  for (const double h : {0.01, 0.005}) {
    const Mesh in = unit_square(20, 20);
    const std::vector<SymMat2> met(in.num_vertices(), isotropic_metric<2>(h));
    Adapt2dOptions o;
    o.hgrad = 0.0;
    const Adapt2dResult r = adapt2d(in, met, o);
    EXPECT_TRUE(check_mesh(r.mesh).valid());
    const double target = 4.0 / std::sqrt(3.0) / (h * h);
    EXPECT_NEAR(static_cast<double>(r.mesh.num_triangles()) / target, 1.0, 0.05) << h;
  }
}

// Splits append their vertices at the end of the arrays; a mesh refined many times over is
// renumbered along the space between sweeps (cache locality), so its output's numbering is
// coherent: few triangles span more than 4,096 vertex ids (measured: 5.6%; without the
// renumbering 99.9%).
TEST(Adapt2d, RefinedMeshNumberedAlongTheSpace) {
  const Mesh in = unit_square(20, 20);
  const std::vector<SymMat2> met(in.num_vertices(), isotropic_metric<2>(0.005));
  Adapt2dOptions o;
  o.hgrad = 0.0;
  const Adapt2dResult r = adapt2d(in, met, o);
  ASSERT_GT(r.mesh.num_vertices(), 20000u);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  std::size_t far = 0;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t) {
    const Id* v = &r.mesh.triangles[3 * t];
    far += *std::max_element(v, v + 3) - *std::min_element(v, v + 3) > 4096 ? 1 : 0;
  }
  EXPECT_LT(static_cast<double>(far), 0.1 * static_cast<double>(r.mesh.num_triangles()));
}

// The same with renumberings forced on a small case (Adapt2dOptions::renumber_after 200, the
// change stamps following): the same bounds as without, and deterministic.
TEST(Adapt2d, RenumberingTheNewVerticesKeepsTheBounds) {
  const Mesh in = unit_square(10, 10);
  const std::vector<SymMat2> met = linear_field(in, 0.01);
  Adapt2dOptions o;
  o.hgrad = 0.0;
  o.renumber_after = 200;
  const Adapt2dResult a = adapt2d(in, met, o), again = adapt2d(in, met, o);
  o.renumber_after = SIZE_MAX;
  const Adapt2dResult never = adapt2d(in, met, o);
  EXPECT_EQ(a.mesh.coords, again.mesh.coords);
  EXPECT_EQ(a.mesh.triangles, again.mesh.triangles);
  EXPECT_NE(a.mesh.triangles, never.mesh.triangles);  // renumbered: swept in another order
  for (const Adapt2dResult* r : {&a, &never}) {
    EXPECT_TRUE(check_mesh(r->mesh).valid());
    EXPECT_NEAR(area(r->mesh), 1.0, 1e-12);
    const std::vector<double> len = edge_lengths(r->mesh, 0.01);
    const double in_band = std::count_if(len.begin(), len.end(), [](double l) {
                             return l >= std::sqrt(0.5) && l <= std::sqrt(2.0);
                           }) / static_cast<double>(len.size());
    EXPECT_GT(in_band, 0.95);
    EXPECT_GT(*std::min_element(len.begin(), len.end()), 0.4);
    EXPECT_LT(*std::max_element(len.begin(), len.end()), 2.0);
    EXPECT_GT(r->report.passes.back().q_min, 0.5);
  }
}

TEST(Adapt2d, AnisotropicLinearFieldAfterPasses) {
  // The milder linear field (h0 = 0.01), iterated as the UGAWG benchmark does: the metric is
  // re-evaluated on each new mesh. After 4 passes: ≥ 95% of edges in [1/√2, √2], none below 0.4
  // or above 2, minimum quality > 0.4 (in the analytic field at the vertices).
  Mesh m = unit_square(20, 20);
  Adapt2dOptions o;
  o.hgrad = 0.0;
  for (int pass = 0; pass < 4; ++pass) m = adapt2d(m, linear_field(m, 0.01), o).mesh;
  EXPECT_TRUE(check_mesh(m).valid());
  EXPECT_NEAR(area(m), 1.0, 1e-12);
  const std::vector<double> len = edge_lengths(m, 0.01);
  const double in = std::count_if(len.begin(), len.end(), [](double l) {
                      return l >= std::sqrt(0.5) && l <= std::sqrt(2.0);
                    }) / static_cast<double>(len.size());
  EXPECT_GE(in, 0.95);
  EXPECT_GE(*std::min_element(len.begin(), len.end()), 0.4);
  EXPECT_LE(*std::max_element(len.begin(), len.end()), 2.0);
}

/// The UGAWG-style polar field of ../shared/PEERS.md (polar2d) with a milder h0: radial size
/// h0 + 2(0.1 − h0)|r − 0.5|, tangential 0.1, r = |(x, y)|.
SymMat2 polar_metric(const Vec2& p, double h0) {
  const double r = norm(p), hr = h0 + 2.0 * (0.1 - h0) * std::abs(r - 0.5);
  const double c = r > 1e-300 ? p[0] / r : 1.0, s = r > 1e-300 ? p[1] / r : 0.0;
  const double a = 1.0 / (hr * hr), b = 100.0;
  return SymMat2{{a * c * c + b * s * s, (a - b) * c * s, a * s * s + b * c * c}};
}

/// A polar layer of radial size h0 adapted from unit_square(20, 20) over `runs` runs, the metric
/// re-evaluated at the vertices before each, measured as the harness measures (../shared/bench):
/// lengths integrated along each edge in the analytic field, quality in the analytic metric at
/// the centroid.
struct PolarFigures {
  double in_band = 0, q_min = 1, q_mean = 0;
};
PolarFigures polar_run(double h0, int runs) {
  Mesh m = unit_square(20, 20);
  Adapt2dOptions o;
  o.hgrad = 0.0;
  const auto field = [h0](const Mesh& mesh) {
    std::vector<SymMat2> out;
    for (std::size_t v = 0; v < mesh.num_vertices(); ++v)
      out.push_back(polar_metric(Vec2{{mesh.coords[2 * v], mesh.coords[2 * v + 1]}}, h0));
    return out;
  };
  for (int run = 0; run < runs; ++run) m = adapt2d(m, field(m), o).mesh;
  EXPECT_TRUE(check_mesh(m).valid());
  const auto point = [&](Id v) { return Vec2{{m.coords[2 * v], m.coords[2 * v + 1]}}; };
  std::set<std::pair<Id, Id>> edges;
  PolarFigures f;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const Id* v = &m.triangles[3 * t];
    for (int i = 0; i < 3; ++i) edges.insert({std::min(v[i], v[(i + 1) % 3]), std::max(v[i], v[(i + 1) % 3])});
    const Vec2 pa = point(v[0]), pb = point(v[1]), pc = point(v[2]);
    const SymMat2 mc = polar_metric((1.0 / 3.0) * (pa + pb + pc), h0);
    const double l2 = quadratic(mc, pb - pa) + quadratic(mc, pc - pb) + quadratic(mc, pa - pc);
    const double q = 4.0 * std::sqrt(3.0) * std::sqrt(det(mc)) * 0.5 * cross(pb - pa, pc - pa) / l2;
    f.q_min = std::min(f.q_min, q);
    f.q_mean += q / static_cast<double>(m.num_triangles());
  }
  int in = 0;
  for (const auto& [a, b] : edges) {
    const Vec2 pa = point(a), ab = point(b) - pa;
    double l = 0.0;  // composite midpoint rule, 200 pieces
    for (int k = 0; k < 200; ++k) l += length(polar_metric(pa + ((k + 0.5) / 200) * ab, h0), ab) / 200;
    in += l >= std::sqrt(0.5) && l <= std::sqrt(2.0);
  }
  f.in_band = in / static_cast<double>(edges.size());
  return f;
}

TEST(Adapt2d, PolarLayerLengthsAlongTheEdges) {
  // A thin layer along the circle r = 0.5 (radial size 0.002, tangential 0.1: 50:1), iterated
  // as the UGAWG benchmark does. Across the curved layer the metric turns along a tangential
  // edge: measured from its end metrics alone the edge looks twice as long, and the remesher
  // made those edges too short (90.5% in band, q min 0.395 with the closed form and the plain
  // mean; 98.8%, 0.483 with the measures where the metric turns).
  const PolarFigures f = polar_run(0.002, 4);
  EXPECT_GE(f.in_band, 0.97);
  EXPECT_GE(f.q_min, 0.45);
}

TEST(Adapt2d, PolarLayerRelocatedAfterThePasses) {
  // polar2d itself (radial size 0.001: 100:1), 5 runs. The tangential edges of the layer cannot
  // be unit (a chord of 0.1 has a sagitta of 2.5 radial sizes), and splits, collapses and the
  // length-driven smoothing left poor balls and edges out of band there (96.9% in band, q min
  // 0.358). After the passes: the quality-driven relocation of the poor balls alone gives
  // 97.2%, q min 0.419; the length-driven one of the ends of the edges out of band alone 97.6%,
  // 0.369; both 98.2%, 0.410 (q mean 0.837-0.838 throughout); 97.8%, 0.418 by the code of
  // 2026-12-04. With the band measured by the 3-point Gauss rule, poor balls below 0.55 and two
  // rounds of both: 97.7%, 0.445 (q mean 0.835).
  const PolarFigures f = polar_run(0.001, 5);
  EXPECT_GE(f.in_band, 0.975);
  EXPECT_GE(f.q_min, 0.43);
  EXPECT_GE(f.q_mean, 0.80);
}

TEST(Adapt2d, Deterministic) {
  const Mesh in = unit_square(12, 12);
  const std::vector<SymMat2> met = linear_field(in, 0.02);
  const Adapt2dResult a = adapt2d(in, met, {});
  const Adapt2dResult b = adapt2d(in, met, {});
  EXPECT_EQ(a.mesh.coords, b.mesh.coords);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.edges, b.mesh.edges);
}

TEST(Adapt2d, TakingTheInputOverGivesTheSameMeshAndReleasesIt) {
  Mesh in = unit_square(12, 12);
  std::vector<SymMat2> met = linear_field(in, 0.02);
  const Adapt2dResult a = adapt2d(in, met, {});
  const Adapt2dResult b = adapt2d(std::move(in), std::move(met), {});
  EXPECT_EQ(a.mesh.coords, b.mesh.coords);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.edges, b.mesh.edges);
  EXPECT_EQ(in.num_triangles(), 0u);  // NOLINT(bugprone-use-after-move): released, as documented
  EXPECT_TRUE(met.empty());           // NOLINT(bugprone-use-after-move)
}

// adapt2d renumbers the input along a Hilbert curve only when its numbering is not already
// coherent (a scrambled numbering is renumbered, a structured grid is used as it is): both paths
// must give valid unit meshes of the same quality, each deterministic.
TEST(Adapt2d, ScrambledAndCoherentNumberingsGiveTheSameQuality) {
  const Mesh grid = unit_square(130, 130);  // 17,161 vertices: above the always-renumber size
  Mesh scrambled = grid;
  const std::size_t nv = grid.num_vertices();
  std::vector<Id> new2old(nv);
  for (std::size_t v = 0; v < nv; ++v) new2old[v] = static_cast<Id>((v * 2654435761u) % nv);
  ASSERT_EQ(std::set<Id>(new2old.begin(), new2old.end()).size(), nv);  // a permutation
  permute_vertices(scrambled, new2old);
  Adapt2dOptions o;
  o.hgrad = 0.0;
  std::vector<double> in_band;
  std::vector<std::size_t> counts;
  for (const Mesh* m : {&grid, static_cast<const Mesh*>(&scrambled)}) {
    const std::vector<SymMat2> met = linear_field(*m, 0.01);
    const Adapt2dResult a = adapt2d(*m, met, o), b = adapt2d(*m, met, o);
    EXPECT_EQ(a.mesh.coords, b.mesh.coords);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_TRUE(check_mesh(a.mesh).valid());
    EXPECT_NEAR(area(a.mesh), 1.0, 1e-12);
    const std::vector<double> len = edge_lengths(a.mesh, 0.01);
    in_band.push_back(std::count_if(len.begin(), len.end(), [](double l) {
                        return l >= std::sqrt(0.5) && l <= std::sqrt(2.0);
                      }) / static_cast<double>(len.size()));
    counts.push_back(a.mesh.num_triangles());
  }
  EXPECT_GE(std::min(in_band[0], in_band[1]), 0.9);
  EXPECT_NEAR(static_cast<double>(counts[1]) / static_cast<double>(counts[0]), 1.0, 0.05);
}

TEST(Adapt2d, BoundaryStaysOnTheSquare) {
  const Mesh in = unit_square(8, 8);
  const Adapt2dResult r = adapt2d(in, linear_field(in, 0.02), {});
  for (std::size_t e = 0; e < r.mesh.num_edges(); ++e)
    for (int k = 0; k < 2; ++k) {
      const Id v = r.mesh.edges[2 * e + k];
      const double x = r.mesh.coords[2 * v], y = r.mesh.coords[2 * v + 1];
      const double d = std::min({x, y, 1.0 - x, 1.0 - y});
      EXPECT_LT(std::abs(d), 1e-14) << "boundary vertex off the square at " << x << ", " << y;
    }
}

// A metric whose unit mesh cannot be built: one tensor of 1e308 (sizes 1e-154) made adapt2d
// crash (boundary curve parameter NaN), a complexity of 1e12 ran for hours. The count of vertices
// asked for, (2/√3) C, over the 2^31 - 1 ids is an InputError naming the finest place.
TEST(Adapt2d, MetricAskingTooManyVertices) {
  const Mesh in = unit_square(4, 4);
  std::vector<SymMat2> met(in.num_vertices(), SymMat2::identity());
  met[6] = SymMat2{{1e308, 0.0, 1e308}};  // determinant overflows: refused as a tensor
  try {
    adapt2d(in, met, {});
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("vertex 7: ", 0), 0u) << e.what();
  }
  met[6] = SymMat2{{1e150, 0.0, 1e150}};  // finite, but sizes 1e-75: ~1e148 vertices
  try {
    adapt2d(in, met, {});
    ADD_FAILURE();
  } catch (const InputError& e) {
    // unit_square(4, 4) numbers vertices row by row: vertex 6 is (0.25, 0.25).
    EXPECT_NE(std::string(e.what()).find("near (0.25, 0.25)"), std::string::npos) << e.what();
  }
  // Complexity 1e12 on the unit square: sizes 1e-6.
  met.assign(in.num_vertices(), isotropic_metric<2>(1e-6));
  EXPECT_THROW(adapt2d(in, met, {}), InputError);
}

// The remesher works on a Hilbert-renumbered copy: errors about the input name its own ids (a
// clockwise triangle was reported under its renumbered id, another triangle of the file).
TEST(Adapt2d, ClockwiseTriangleNamedByItsInputId) {
  Mesh in = unit_square(4, 4);
  for (const std::size_t t : {std::size_t{5}, std::size_t{30}}) {
    Mesh flipped = in;
    std::swap(flipped.triangles[3 * t], flipped.triangles[3 * t + 1]);
    try {
      adapt2d(flipped, std::vector<SymMat2>(in.num_vertices(), SymMat2::identity()), {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), "triangle " + std::to_string(t + 1) +
                                           " is clockwise or degenerate");
    }
  }
}

TEST(Adapt2d, BadMetricNamedByItsInputVertex) {
  const Mesh in = unit_square(4, 4);
  for (const std::size_t v : {std::size_t{6}, std::size_t{17}}) {
    std::vector<SymMat2> met(in.num_vertices(), SymMat2::identity());
    met[v] = SymMat2{{1.0, 2.0, 1.0}};  // not positive definite
    try {
      adapt2d(in, met, {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("vertex " + std::to_string(v + 1) + ":", 0), 0u)
          << e.what();
    }
  }
}

TEST(Adapt2d, BadInput) {
  const Mesh in = unit_square(2, 2);
  std::vector<SymMat2> met(in.num_vertices(), SymMat2::identity());
  Adapt2dOptions o;
  met[3] = SymMat2{{1.0, 2.0, 1.0}};  // not positive definite
  EXPECT_THROW(adapt2d(in, met, o), InputError);
  met[3] = SymMat2{{std::nan(""), 0.0, 1.0}};
  EXPECT_THROW(adapt2d(in, met, o), InputError);
  met.pop_back();
  EXPECT_THROW(adapt2d(in, met, o), InputError);  // count mismatch
  met.assign(in.num_vertices(), SymMat2::identity());
  o.hmin = 2.0, o.hmax = 1.0;
  EXPECT_THROW(adapt2d(in, met, o), InputError);  // contradicting sizes
  o = {};
  o.hgrad = 0.5;
  EXPECT_THROW(adapt2d(in, met, o), InputError);
  Mesh flipped = in;
  std::swap(flipped.triangles[0], flipped.triangles[1]);
  EXPECT_THROW(adapt2d(flipped, met, {}), InputError);
}

// Sizes hn·(1 + x) across a direction 30 degrees from x, 0.1 along it (an_var.py of the QA
// reports): (4/√3) C(M) = (4/√3) ln 2 / (hn · 0.1) triangles on the unit square.
namespace {
std::vector<SymMat2> tilted_field(const Mesh& in, double hn0) {
  std::vector<SymMat2> metrics;
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  for (std::size_t v = 0; v < in.num_vertices(); ++v) {
    const double hn = hn0 * (1.0 + in.coords[2 * v]), ht = 0.1;
    const double l1 = 1.0 / (ht * ht), l2 = 1.0 / (hn * hn);
    metrics.push_back(
        SymMat2{{l1 * c * c + l2 * s * s, (l1 - l2) * c * s, l1 * s * s + l2 * c * c}});
  }
  return metrics;
}
}  // namespace

// The stop rules "no new low of splits + collapses for 3 passes" and "no change in band or
// quality" now need a pass of fewer than 5% of the vertices inserted or removed: the first
// pass's few operations were the low, and a 1:300 field stopped after its fourth pass with
// 4,921 collapses left (15% of the vertices, 98.7% in band); --hsiz 1e-4 on a square stopped
// after its second pass with every edge still 4-12 long (the band at 0% both times).
TEST(Adapt2d, PassesGoOnWhileMuchChanges) {
  // gmsh's unit square at lc 0.05 (tests/data/square_gmsh.geo): unstructured.
  const Mesh in = read_medit(RIEMESH_TEST_DATA "/square_gmsh.mesh");
  Adapt2dOptions o;
  o.hgrad = 0.0;
  const Adapt2dResult r = adapt2d(in, tilted_field(in, 3e-4), o);
  const PassStats& last = r.report.passes.back();
  std::printf("1:300 field: %zu passes, %.4f in band, last pass %ld splits %ld collapses\n",
              r.report.passes.size(), last.len_in, last.splits, last.collapses);
  EXPECT_LE(last.splits + last.collapses, static_cast<long>(last.vertices / 20));
  EXPECT_GT(last.len_in, 0.98);
}

TEST(Adapt2d, SizesBeyondTheVertexLimitAreRefused) {
  const Mesh in = unit_square(4, 4);
  // 1.15e8 vertices for h = 1e-4 (more than kMostVertices2d): it ran until the memory was gone.
  EXPECT_THROW(adapt2d(in, std::vector<SymMat2>(in.num_vertices(), isotropic_metric<2>(1e-4)), {}),
               InputError);
}

TEST(Adapt2d, HausdBelowRoundoffIsRefused) {
  // 1e-12 on a domain of size ~1 ran away (hundreds of thousands of boundary vertices, growing);
  // 0 means no bound.
  const Mesh in = unit_square(4, 4);
  const std::vector<SymMat2> metrics(in.num_vertices(), isotropic_metric<2>(0.3));
  Adapt2dOptions o;
  o.hausd = 1e-12;
  EXPECT_THROW(adapt2d(in, metrics, o), InputError);
  o.hausd = 0.0;
  EXPECT_NO_THROW(adapt2d(in, metrics, o));
}

// From a coarse isotropic mesh in a strongly anisotropic field, the splits refine toward the
// target count without overshooting it: each split's new vertex is reconnected by flips where
// its triangles are needles in the metric (swap_around), instead of joining far apexes by long
// edges that the next sweep splits again in every direction. 1:300 field, target 53.4 k
// triangles: before, passes at 0.89, 3.15, 1.22, 1.05 ... 1.04 of it (7 passes); now 0.23, 1.07,
// 1.02, 1.01 ... 1.01 (6 passes).
TEST(Adapt2d, CoarseStartInAnAnisotropicFieldDoesNotOvershoot) {
  const Mesh in = read_medit(RIEMESH_TEST_DATA "/square_gmsh.mesh");
  const double target = 4.0 / std::sqrt(3.0) * std::log(2.0) / (3e-4 * 0.1);
  Adapt2dOptions o;
  o.hgrad = 0.0;
  std::vector<std::size_t> counts;
  const Adapt2dResult r = adapt2d(in, tilted_field(in, 3e-4), o,
                                  [&](const PassStats& st) { counts.push_back(st.triangles); });
  for (std::size_t k = 0; k < counts.size(); ++k)
    std::printf("pass %zu: %.3f of the target\n", k + 1, static_cast<double>(counts[k]) / target);
  for (const std::size_t n : counts) EXPECT_LT(static_cast<double>(n), 1.5 * target);
  EXPECT_NEAR(static_cast<double>(r.mesh.num_triangles()) / target, 1.0, 0.1);
  EXPECT_GT(r.report.passes.back().len_in, 0.98);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
}
