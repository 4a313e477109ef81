// remesh/background.hpp: point location in the background mesh (walk, grid fallback, projection
// outside the domain) checked against brute-force containment, and the interpolated metric and
// fields against analytic values (BOOK.md §1 interpolation, §8 P1 transfer).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "core/random_metrics.hpp"
#include "core/spd.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/hilbert.hpp"
#include "metric/interpolation.hpp"
#include "remesh/background.hpp"
#include "remesh/simplex_geometry.hpp"

using namespace riemesh;

namespace {

template <int D>
Vec<D> vertex_of(const Mesh& m, Id v) {
  Vec<D> x{};
  for (int a = 0; a < D; ++a) x[a] = m.coords[D * static_cast<std::size_t>(v) + a];
  return x;
}

template <int D>
const std::vector<Id>& simplices_of(const Mesh& m) {
  return D == 2 ? m.triangles : m.tets;
}

/// The fixture with interior vertices moved by up to `jitter` cell sizes per axis (the mesh is
/// no longer a regular, Delaunay-like grid; elements stay positive: checked by the caller).
template <int D>
Mesh jittered(Mesh m, int n, double jitter, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-jitter / n, jitter / n);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    bool interior = true;
    for (int a = 0; a < D; ++a) {
      const double x = m.coords[D * v + a];
      interior = interior && x > 0.0 && x < 1.0;
    }
    if (interior)
      for (int a = 0; a < D; ++a) m.coords[D * v + a] += u(rng);
  }
  return m;
}

/// Metric field M(x) = exp(L(x)) with L linear in x (anisotropic, rotating): log-Euclidean
/// interpolation of such a field at a point of a simplex is exp of the interpolated logs.
template <int D>
SymMat<D> field_metric(const Vec<D>& x) {
  SymMat<D> l = SymMat<D>::zero();
  for (int i = 0; i < D; ++i) l.at(i, i) = 2.0 + 3.0 * x[i] - (i == 1 ? 2.0 * x[0] : 0.0);
  l.at(0, 1) = 0.8 * x[D - 1] - 0.3;
  return exp_sym(l);
}

/// A metric linear in x, SPD on [0,1]^D (diagonally dominant): the kLinear scheme reproduces it.
template <int D>
SymMat<D> linear_metric(const Vec<D>& x) {
  SymMat<D> m = SymMat<D>::zero();
  for (int i = 0; i < D; ++i) m.at(i, i) = 4.0 + 2.0 * x[i] + x[(i + 1) % D];
  m.at(0, 1) = 0.5 + x[0] - 0.7 * x[D - 1];
  return m;
}

template <int D, class F>
std::vector<double> metric_field(const Mesh& m, F f) {
  std::vector<double> out;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const SymMat<D> s = f(vertex_of<D>(m, static_cast<Id>(v)));
    out.insert(out.end(), s.c, s.c + SymMat<D>::kSize);
  }
  return out;
}

/// Barycentric coordinates of p in simplex s by sub-volumes (independent of the class).
template <int D>
void bary_of(const Mesh& m, Id s, const Vec<D>& p, double b[D + 1]) {
  Vec<D> x[D + 1];
  for (int i = 0; i <= D; ++i) x[i] = vertex_of<D>(m, simplices_of<D>(m)[(D + 1) * s + i]);
  simplex::sub_volumes(x, p, b);
  const double vol = simplex::signed_volume(x);
  for (int i = 0; i <= D; ++i) b[i] /= vol;
}

template <int D>
bool contains(const Mesh& m, Id s, const Vec<D>& p, double tol = 1e-10) {
  double b[D + 1];
  bary_of<D>(m, s, p, b);
  return *std::min_element(b, b + D + 1) >= -tol;
}

template <int D>
Vec<D> point_of(const Mesh& m, const Location<D>& loc) {
  Vec<D> q = Vec<D>::zero();
  for (int i = 0; i <= D; ++i)
    q += loc.bary[i] * vertex_of<D>(m, simplices_of<D>(m)[(D + 1) * loc.simplex + i]);
  return q;
}

template <int D>
double rel_err(const SymMat<D>& x, const SymMat<D>& ref) {
  return frobenius(x - ref) / frobenius(ref);
}

template <int D>
Vec<D> random_point(std::mt19937_64& rng, double lo = 0.0, double hi = 1.0) {
  std::uniform_real_distribution<double> u(lo, hi);
  Vec<D> p{};
  for (int a = 0; a < D; ++a) p[a] = u(rng);
  return p;
}

/// Removes the elements whose centroid satisfies `drop`, then the vertices no element uses
/// (renumbering the rest in order). Edges and boundary triangles are dropped: not needed here.
template <int D, class Pred>
Mesh remove_elements(const Mesh& in, Pred drop) {
  Mesh out;
  out.dim = D;
  const std::vector<Id>& s = simplices_of<D>(in);
  std::vector<Id> kept;
  for (std::size_t e = 0; e < s.size() / (D + 1); ++e) {
    Vec<D> c = Vec<D>::zero();
    for (int i = 0; i <= D; ++i) c += vertex_of<D>(in, s[(D + 1) * e + i]) / (D + 1.0);
    if (!drop(c)) kept.insert(kept.end(), s.begin() + (D + 1) * e, s.begin() + (D + 1) * (e + 1));
  }
  std::vector<Id> old2new(in.num_vertices(), kNoId);
  for (Id v : kept) old2new[v] = 0;
  Id next = 0;
  for (std::size_t v = 0; v < in.num_vertices(); ++v) {
    if (old2new[v] == kNoId) continue;
    old2new[v] = next++;
    for (int a = 0; a < D; ++a) out.coords.push_back(in.coords[D * v + a]);
  }
  for (Id& v : kept) v = old2new[v];
  (D == 2 ? out.triangles : out.tets) = std::move(kept);
  return out;
}

template <int D>
Mesh fixture(int n) {
  if constexpr (D == 2) {
    return unit_square(n, n);
  } else {
    return unit_cube(n);
  }
}

template <class T>
class BackgroundTest : public ::testing::Test {};
using Dims = ::testing::Types<std::integral_constant<int, 2>, std::integral_constant<int, 3>>;
TYPED_TEST_SUITE(BackgroundTest, Dims);

}  // namespace

// Random points from random hints on a jittered mesh: the simplex found contains the point
// (brute-force containment test), the coordinates rebuild the point, and agree with the
// independent sub-volume computation.
TYPED_TEST(BackgroundTest, LocateMatchesBruteForce) {
  constexpr int D = TypeParam::value;
  const int n = D == 2 ? 24 : 7;
  const Mesh m = jittered<D>(fixture<D>(n), n, D == 2 ? 0.15 : 0.1, 3);
  const std::size_t ns = simplices_of<D>(m).size() / (D + 1);
  for (std::size_t s = 0; s < ns; ++s) {  // jitter kept every element positive
    Vec<D> x[D + 1];
    for (int i = 0; i <= D; ++i) x[i] = vertex_of<D>(m, simplices_of<D>(m)[(D + 1) * s + i]);
    ASSERT_GT(simplex::signed_volume(x), 0.0);
  }
  const BackgroundMesh<D> bg(m, metric_field<D>(m, field_metric<D>));
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<Id> any(0, static_cast<Id>(ns) - 1);
  LocateStats stats;
  for (int q = 0; q < 2000; ++q) {
    const Vec<D> p = random_point<D>(rng);
    const Id hint = q % 10 == 0 ? kNoId : any(rng);
    const Location<D> loc = bg.locate(p, hint, &stats);
    ASSERT_TRUE(loc.inside);
    ASSERT_TRUE(contains<D>(m, loc.simplex, p)) << "query " << q;
    int containing = 0;
    for (std::size_t s = 0; s < ns; ++s) containing += contains<D>(m, static_cast<Id>(s), p);
    EXPECT_GE(containing, 1);
    double sum = 0.0, b[D + 1];
    bary_of<D>(m, loc.simplex, p, b);
    for (int i = 0; i <= D; ++i) {
      EXPECT_GE(loc.bary[i], 0.0);
      EXPECT_NEAR(loc.bary[i], b[i], 1e-12);
      sum += loc.bary[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_LT(norm(point_of<D>(m, loc) - p), 1e-14);
  }
  EXPECT_EQ(stats.queries, 2000);
  EXPECT_EQ(stats.outside, 0);
  EXPECT_EQ(stats.fallbacks, 0);  // a convex domain: every walk arrives
}

// Queries along a Hilbert-ordered point set, each hinted by the previous answer: the walk is
// short (consecutive points are close). Hint-free queries start from the grid: short too.
TYPED_TEST(BackgroundTest, WalkIsShortAlongHilbertOrder) {
  constexpr int D = TypeParam::value;
  const int n = D == 2 ? 60 : 14;
  const Mesh m = fixture<D>(n);
  const BackgroundMesh<D> bg(m, metric_field<D>(m, field_metric<D>));
  std::mt19937_64 rng(5);
  const int count = 20000;
  std::vector<double> pts;
  for (int q = 0; q < count; ++q) {
    const Vec<D> p = random_point<D>(rng);
    pts.insert(pts.end(), p.x, p.x + D);
  }
  const std::vector<Id> order = hilbert_order(pts, D);
  LocateStats hilbert, gridded;
  Id hint = kNoId;
  for (Id k : order) {
    Vec<D> p{};
    for (int a = 0; a < D; ++a) p[a] = pts[D * k + a];
    hint = bg.locate(p, hint, &hilbert).simplex;
    bg.locate(p, kNoId, &gridded);
  }
  // Mean steps: ~1 along the curve (about one simplex per query), ~1-2 from the grid cell in
  // 2D, ~4 in 3D (cells of ~64 tetrahedra, memory).
  EXPECT_LT(static_cast<double>(hilbert.walk_steps) / count, 2.0);
  EXPECT_LT(static_cast<double>(gridded.walk_steps) / count, D == 2 ? 3.0 : 4.5);
  EXPECT_EQ(hilbert.fallbacks + gridded.fallbacks, 0);
  // Random order hinted by the previous answer: hints beyond hint_reach() are replaced by the
  // grid start, so no walk crosses the mesh.
  LocateStats scattered;
  hint = 0;
  for (int q = 0; q < count; ++q) {
    Vec<D> p{};
    for (int a = 0; a < D; ++a) p[a] = pts[D * q + a];
    hint = bg.locate(p, hint, &scattered).simplex;
  }
  EXPECT_LT(static_cast<double>(scattered.walk_steps) / count, D == 2 ? 3.5 : 4.5);
  EXPECT_EQ(scattered.fallbacks, 0);
}

// At a vertex the metric is the input metric bit for bit, in every scheme and from any of the
// simplices around it.
TYPED_TEST(BackgroundTest, ExactAtVertices) {
  constexpr int D = TypeParam::value;
  const Mesh m = jittered<D>(fixture<D>(D == 2 ? 6 : 3), D == 2 ? 6 : 3, 0.1, 2);
  std::mt19937_64 rng(1);
  std::vector<double> metrics;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const SymMat<D> s = test_support::random_spd<D>(rng, 1e4);
    metrics.insert(metrics.end(), s.c, s.c + SymMat<D>::kSize);
  }
  for (InterpScheme scheme : {InterpScheme::kLogEuclidean, InterpScheme::kLinear,
                              InterpScheme::kSimredGeometric, InterpScheme::kCholesky}) {
    const BackgroundMesh<D> bg(m, metrics, scheme);
    const std::vector<Id>& s = simplices_of<D>(m);
    for (std::size_t e = 0; e < s.size() / (D + 1); ++e)
      for (int i = 0; i <= D; ++i) {
        const Id v = s[(D + 1) * e + i];
        Id found = kNoId;
        const SymMat<D> got = bg.metric_at(vertex_of<D>(m, v), static_cast<Id>(e), &found);
        EXPECT_EQ(found, static_cast<Id>(e));  // a vertex of the hint: no step
        for (int k = 0; k < SymMat<D>::kSize; ++k)
          EXPECT_EQ(got.c[k], metrics[SymMat<D>::kSize * v + k]) << "vertex " << v;
      }
  }
}

// A constant field is reproduced (log-Euclidean: exp(log M) = M to rounding; linear: exactly
// up to the rounding of Σ wᵢ = 1).
TYPED_TEST(BackgroundTest, ConstantField) {
  constexpr int D = TypeParam::value;
  const Mesh m = fixture<D>(D == 2 ? 10 : 4);
  std::mt19937_64 rng(9);
  const SymMat<D> c = test_support::random_spd<D>(rng, 1e3);
  const std::vector<double> metrics = metric_field<D>(m, [&](const Vec<D>&) { return c; });
  for (InterpScheme scheme : {InterpScheme::kLogEuclidean, InterpScheme::kLinear}) {
    const BackgroundMesh<D> bg(m, metrics, scheme);
    for (int q = 0; q < 200; ++q)
      EXPECT_LT(rel_err(bg.metric_at(random_point<D>(rng), kNoId), c), 1e-12);
  }
}

// Log-Euclidean: metric_at equals interpolate() over the containing simplex with the located
// coordinates, and since log M is linear in x for field_metric, equals M(p) itself.
TYPED_TEST(BackgroundTest, MatchesLogEuclideanInterpolation) {
  constexpr int D = TypeParam::value;
  const Mesh m = jittered<D>(fixture<D>(D == 2 ? 12 : 5), D == 2 ? 12 : 5, 0.1, 4);
  const std::vector<double> metrics = metric_field<D>(m, field_metric<D>);
  const BackgroundMesh<D> bg(m, metrics);
  EXPECT_EQ(bg.scheme(), InterpScheme::kLogEuclidean);
  std::mt19937_64 rng(21);
  Id hint = kNoId;
  for (int q = 0; q < 500; ++q) {
    const Vec<D> p = random_point<D>(rng);
    const Location<D> loc = bg.locate(p, hint);
    hint = loc.simplex;
    SymMat<D> mv[D + 1];
    for (int i = 0; i <= D; ++i) {
      const Id v = simplices_of<D>(m)[(D + 1) * loc.simplex + i];
      std::copy_n(&metrics[SymMat<D>::kSize * v], SymMat<D>::kSize, mv[i].c);
    }
    const SymMat<D> ref =
        interpolate<D>(InterpScheme::kLogEuclidean, std::span<const SymMat<D>>(mv),
                       std::span<const double>(loc.bary));
    const SymMat<D> got = bg.metric_at(loc);
    EXPECT_LT(rel_err(got, ref), 1e-12);
    EXPECT_LT(rel_err(got, field_metric<D>(p)), 1e-11);
  }
}

// The linear scheme reproduces a field linear in x: Σ wᵢ M(xᵢ) = M(Σ wᵢ xᵢ). Also the P1 field
// transfer of linear scalar and vector fields.
TYPED_TEST(BackgroundTest, LinearFieldsAreExact) {
  constexpr int D = TypeParam::value;
  const Mesh m = jittered<D>(fixture<D>(D == 2 ? 12 : 5), D == 2 ? 12 : 5, 0.1, 8);
  const BackgroundMesh<D> bg(m, metric_field<D>(m, linear_metric<D>), InterpScheme::kLinear);
  std::vector<double> values;  // 2 components: 1 + 2x - 3y(+z), and x·y-free 0.5x
  auto f = [](const Vec<D>& x, int c) {
    return c == 0 ? 1.0 + 2.0 * x[0] - 3.0 * x[1] + (D == 3 ? x[2] : 0.0) : 0.5 * x[D - 1];
  };
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    for (int c = 0; c < 2; ++c) values.push_back(f(vertex_of<D>(m, static_cast<Id>(v)), c));
  std::mt19937_64 rng(17);
  Id hint = kNoId;
  for (int q = 0; q < 500; ++q) {
    const Vec<D> p = random_point<D>(rng);
    const Location<D> loc = bg.locate(p, hint);
    hint = loc.simplex;
    EXPECT_LT(rel_err(bg.metric_at(loc), linear_metric<D>(p)), 1e-14);
    double out[2];
    bg.interpolate_fields(loc, values, 2, out);
    EXPECT_NEAR(out[0], f(p, 0), 1e-13);
    EXPECT_NEAR(out[1], f(p, 1), 1e-14);
  }
  double out[2];
  const Location<D> loc = bg.locate(random_point<D>(rng));
  EXPECT_THROW(bg.interpolate_fields(loc, values, 3, out), InputError);
  EXPECT_THROW(bg.interpolate_fields(loc, values, 2, std::span<double>(out, 1)), InputError);
}

// Points outside the domain: inside = false, the closest simplex, coordinates of the projection,
// and the metric there (= the metric at the projected boundary point).
TYPED_TEST(BackgroundTest, OutsidePointsProject) {
  constexpr int D = TypeParam::value;
  const Mesh m = fixture<D>(D == 2 ? 10 : 4);
  const BackgroundMesh<D> bg(m, metric_field<D>(m, field_metric<D>));
  std::mt19937_64 rng(2);
  for (int q = 0; q < 300; ++q) {
    Vec<D> p = random_point<D>(rng, 0.02, 0.98);
    Vec<D> proj = p;
    const int axis = q % D;
    // Just outside (as boundary points on a curved reconstruction) and far outside.
    const double out = q % 3 == 0 ? 3.0 : 1.01;
    p[axis] = q % 2 ? out : 1.0 - out, proj[axis] = q % 2 ? 1.0 : 0.0;
    LocateStats stats;
    const Location<D> loc = bg.locate(p, q % 4 ? kNoId : 0, &stats);
    EXPECT_FALSE(loc.inside);
    EXPECT_EQ(stats.outside, 1);
    EXPECT_LT(norm(point_of<D>(m, loc) - proj), 1e-14);
    Id found = kNoId;
    const SymMat<D> at_proj = bg.metric_at(proj, kNoId, &found);
    EXPECT_LT(rel_err(bg.metric_at(loc), at_proj), 1e-12);
  }
  // The brief's example: (1.01, 0.5[, 0.5]) takes the metric of the boundary point (1, 0.5[, 0.5]).
  Vec<D> p{}, b{};
  for (int a = 0; a < D; ++a) p[a] = b[a] = 0.5;
  p[0] = 1.01, b[0] = 1.0;
  const Location<D> loc = bg.locate(p);
  EXPECT_FALSE(loc.inside);
  EXPECT_LT(rel_err(bg.metric_at(loc), field_metric<D>(b)), 1e-11);
}

// Determinism: two backgrounds built from the same input answer the same queries identically,
// bit for bit, including ties (points on edges and vertices, outside points).
TYPED_TEST(BackgroundTest, Deterministic) {
  constexpr int D = TypeParam::value;
  const int n = D == 2 ? 8 : 4;
  const Mesh m = fixture<D>(n);
  const std::vector<double> metrics = metric_field<D>(m, field_metric<D>);
  const BackgroundMesh<D> a(m, metrics), b(m, metrics);
  std::mt19937_64 rng(31);
  std::uniform_int_distribution<int> grid(-2, 2 * n + 2);
  for (int q = 0; q < 1000; ++q) {
    Vec<D> p{};  // on the half-grid: vertices, edge midpoints, faces, a bit outside
    for (int a2 = 0; a2 < D; ++a2) p[a2] = grid(rng) / (2.0 * n);
    const Id hint = q % 2 ? kNoId : static_cast<Id>(q % 37);
    const Location<D> la = a.locate(p, hint), lb = b.locate(p, hint), la2 = a.locate(p, hint);
    EXPECT_EQ(la.simplex, lb.simplex);
    EXPECT_EQ(la.simplex, la2.simplex);
    EXPECT_EQ(la.inside, lb.inside);
    for (int i = 0; i <= D; ++i) EXPECT_EQ(la.bary[i], lb.bary[i]);
    const SymMat<D> ma = a.metric_at(la), mb = b.metric_at(lb);
    for (int k = 0; k < SymMat<D>::kSize; ++k) EXPECT_EQ(ma.c[k], mb.c[k]);
  }
}

// Non-convex domains: an L shape (the quadrant x, y > 1/2 removed) and a square with a square
// hole. Walks blocked by the re-entrant corner or the hole fall back to the grid, which finds
// the containing simplex; points in the hole project onto its boundary.
TEST(BackgroundNonConvex, LShapeAcrossTheReentrantCorner) {
  const int n = 40;
  const Mesh m =
      remove_elements<2>(unit_square(n, n), [](const Vec2& c) { return c[0] > 0.5 && c[1] > 0.5; });
  ASSERT_EQ(m.num_triangles(), static_cast<std::size_t>(2 * n * n * 3 / 4));
  const BackgroundMesh<2> bg(m, metric_field<2>(m, field_metric<2>));
  // The hint in the upper arm next to the corner, p in the right arm: the walk heads straight
  // for p, through the removed quadrant, and leaves the domain at x = 0.5 (in the triangle
  // (0.475, 0.5) (0.5, 0.5) (0.5, 0.525), p's coordinate for (0.475, 0.5) is the most negative).
  const Id hint = bg.locate({{0.49, 0.52}}).simplex;
  const Vec2 p{{0.52, 0.49}};
  ASSERT_LT(norm(p - vertex_of<2>(m, m.triangles[3 * hint])), bg.hint_reach());  // hint used
  LocateStats stats;
  const Location<2> loc = bg.locate(p, hint, &stats);
  EXPECT_EQ(stats.fallbacks, 1);
  EXPECT_TRUE(loc.inside);
  EXPECT_TRUE(contains<2>(m, loc.simplex, p));
  EXPECT_LT(rel_err(bg.metric_at(loc), field_metric<2>(p)), 1e-11);
  // Random points in the L, hinted by the previous answer: every answer contains its point;
  // points in the removed quadrant project onto the nearer side of the corner.
  std::mt19937_64 rng(7);
  Id h = hint;
  for (int q = 0; q < 3000; ++q) {
    const Vec2 x = random_point<2>(rng);
    const Location<2> got = bg.locate(x, h);
    if (x[0] > 0.5 && x[1] > 0.5) {
      EXPECT_FALSE(got.inside);
      EXPECT_NEAR(std::min(x[0] - 0.5, x[1] - 0.5), norm(point_of<2>(m, got) - x), 1e-14);
      continue;
    }
    ASSERT_TRUE(got.inside);
    ASSERT_TRUE(contains<2>(m, got.simplex, x));
    h = got.simplex;
  }
}

TEST(BackgroundNonConvex, SquareWithAHole) {
  // A slit-shaped hole [0.475, 0.525] x [0.3, 0.7] on grid lines (h = 0.025), narrower than
  // the hint reach, so that a hint on one side walks towards a point on the other side.
  const int n = 40;
  auto in_hole = [](const Vec2& c) {
    return c[0] > 0.475 && c[0] < 0.525 && c[1] > 0.3 && c[1] < 0.7;
  };
  const Mesh m = remove_elements<2>(unit_square(n, n), in_hole);
  ASSERT_EQ(m.num_triangles(), static_cast<std::size_t>(2 * (n * n - 2 * 16)));
  const BackgroundMesh<2> bg(m, metric_field<2>(m, field_metric<2>));
  const Id left = bg.locate({{0.465, 0.51}}).simplex;
  const Vec2 p{{0.535, 0.51}};
  ASSERT_LT(norm(p - vertex_of<2>(m, m.triangles[3 * left])), bg.hint_reach());
  LocateStats stats;
  const Location<2> loc = bg.locate(p, left, &stats);
  EXPECT_EQ(stats.fallbacks, 1);
  EXPECT_TRUE(loc.inside);
  EXPECT_TRUE(contains<2>(m, loc.simplex, p));
  EXPECT_LT(rel_err(bg.metric_at(loc), field_metric<2>(p)), 1e-11);
  // A point in the hole, nearest to its left side x = 0.475: projected there.
  const Location<2> h = bg.locate({{0.485, 0.52}}, left);
  EXPECT_FALSE(h.inside);
  const Vec2 q = point_of<2>(m, h);
  EXPECT_NEAR(q[0], 0.475, 1e-15);
  EXPECT_NEAR(q[1], 0.52, 1e-15);
  EXPECT_LT(rel_err(bg.metric_at(h), field_metric<2>(q)), 1e-11);
  // Hilbert-ordered points around the hole, hinted by the previous answer.
  std::mt19937_64 rng(13);
  std::vector<double> pts;
  for (int k = 0; k < 4000; ++k) {
    const Vec2 x = random_point<2>(rng, 0.3, 0.7);
    pts.insert(pts.end(), x.x, x.x + 2);
  }
  Id hint = kNoId;
  LocateStats sweep;
  for (Id k : hilbert_order(pts, 2)) {
    const Vec2 x{{pts[2 * k], pts[2 * k + 1]}};
    const Location<2> got = bg.locate(x, hint, &sweep);
    ASSERT_EQ(got.inside, !in_hole(x));
    if (got.inside) {
      ASSERT_TRUE(contains<2>(m, got.simplex, x));
    }
    hint = got.simplex;
  }
  EXPECT_GT(sweep.fallbacks, 0);
}

// A 3D non-convex domain: the cube without the octant x, y, z > 1/2.
TEST(BackgroundNonConvex, CubeWithoutAnOctant) {
  const int n = 6;
  const Mesh m = remove_elements<3>(
      unit_cube(n), [](const Vec3& c) { return c[0] > 0.5 && c[1] > 0.5 && c[2] > 0.5; });
  const BackgroundMesh<3> bg(m, metric_field<3>(m, field_metric<3>));
  std::mt19937_64 rng(3);
  Id h = kNoId;
  for (int q = 0; q < 2000; ++q) {
    const Vec3 x = random_point<3>(rng);
    const Location<3> loc = bg.locate(x, h);
    const bool in_octant = x[0] > 0.5 && x[1] > 0.5 && x[2] > 0.5;
    ASSERT_EQ(loc.inside, !in_octant);
    if (in_octant) {
      const double d = std::min({x[0], x[1], x[2]}) - 0.5;
      EXPECT_NEAR(norm(point_of<3>(m, loc) - x), d, 1e-14);
    } else {
      ASSERT_TRUE(contains<3>(m, loc.simplex, x));
      h = loc.simplex;
    }
  }
}

TYPED_TEST(BackgroundTest, BadInput) {
  constexpr int D = TypeParam::value;
  const Mesh m = fixture<D>(2);
  std::vector<double> metrics = metric_field<D>(m, field_metric<D>);
  std::vector<double> short_metrics(metrics.begin(), metrics.end() - 1);
  EXPECT_THROW(BackgroundMesh<D>(m, short_metrics), InputError);
  std::vector<double> bad = metrics;
  bad[SymMat<D>::kSize * 3] = -1.0;  // vertex 4 not SPD
  EXPECT_THROW(BackgroundMesh<D>(m, bad), InputError);
  bad = metrics;
  bad[1] = std::nan("");
  EXPECT_THROW(BackgroundMesh<D>(m, bad), InputError);
  std::vector<Id> s = simplices_of<D>(m);
  s[1] = static_cast<Id>(m.num_vertices());  // id out of range
  EXPECT_THROW(BackgroundMesh<D>(m.coords, s, metrics), InputError);
  s = simplices_of<D>(m);
  s[1] = s[0];  // a flat simplex
  EXPECT_THROW(BackgroundMesh<D>(m.coords, s, metrics), InputError);
  EXPECT_THROW(BackgroundMesh<D>(m.coords, std::span<const Id>(s).first(D), metrics), InputError);
  Mesh wrong = m;
  wrong.dim = 5 - D;
  EXPECT_THROW(BackgroundMesh<D>(wrong, metrics), InputError);
  const BackgroundMesh<D> bg(m, metrics);
  Vec<D> p{};
  p[0] = std::nan("");
  EXPECT_THROW(bg.locate(p), InputError);
  p[0] = 0.5;
  EXPECT_THROW(bg.locate(p, static_cast<Id>(bg.num_simplices())), InputError);
  EXPECT_THROW(bg.locate(p, -2), InputError);
}

TEST(BackgroundMetrics, SetMetricsReplacesTheField) {
  // The staged approach (adapt3d) swaps the field: queries then interpolate the new one; a
  // wrong size or a non-SPD metric is refused and leaves the field as it was.
  const Mesh m = unit_cube(2);
  const std::size_t nv = m.num_vertices();
  BackgroundMesh<3> bg(m, metric_field<3>(m, field_metric<3>));
  const Vec3 p{{0.3, 0.6, 0.2}};
  const SymMat3 before = bg.metric_at(p, kNoId);
  bg.set_metrics(std::vector<SymMat3>(nv, SymMat3::diagonal(4.0)));
  EXPECT_LT(rel_err(bg.metric_at(p, kNoId), SymMat3::diagonal(4.0)), 1e-14);
  EXPECT_THROW(bg.set_metrics(std::vector<SymMat3>(nv - 1, SymMat3::identity())), InputError);
  std::vector<SymMat3> bad(nv, SymMat3::identity());
  bad[3].at(1, 1) = -1.0;
  EXPECT_THROW(bg.set_metrics(std::move(bad)), InputError);
  EXPECT_LT(rel_err(bg.metric_at(p, kNoId), SymMat3::diagonal(4.0)), 1e-14);
  std::vector<SymMat3> field;
  for (std::size_t v = 0; v < nv; ++v) field.push_back(field_metric<3>(vertex_of<3>(m, static_cast<Id>(v))));
  bg.set_metrics(std::move(field));
  EXPECT_LT(rel_err(bg.metric_at(p, kNoId), before), 1e-14);
}
