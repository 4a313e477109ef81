// Least-squares Taylor fit (BOOK.md §2): at each vertex i, the polynomial
//   u(x) ≈ u_i + g·(x−x_i) + ½ (x−x_i)ᵀ H (x−x_i) [+ cubic terms in 2D]
// (D + D(D+1)/2 unknowns: 5 in 2D, 9 in 3D, plus 4 cubic ones in 2D; u_i is kept, so a quadratic
// is reproduced exactly) is fitted to the values at the vertices of the ball. Ring 1 is used alone
// only when it has at least twice as many points as unknowns and the fit is well conditioned;
// otherwise ring 2 (and at most ring 3, for tiny meshes) is added. In practice interior vertices
// of 2D meshes (valence ≈ 6) and of tetrahedral meshes (valence ≈ 14) use two rings, which also
// makes the fit robust on the boundary, where the ball is one-sided. (Measured: accepting ring 1
// at 1.5x the unknowns makes 3D interior fits use ring 1 alone, twice as fast, but the max error
// on perturbed meshes then stops converging: observed order 0.2 instead of 1.2.)
//
// Why cubic terms in 2D: on meshes adapted to a front (anisotropy 1:100 and more), the Hessian
// across the front is large and along it nearly zero; a quadratic fit folds the third derivative
// across the front into the small along-front curvature, and the metric built from it asks for
// sizes that swing by 10x between neighbours (the adaptation loop on the tanh front then stalled
// at N = 64000 with edges of metric length 0.001; with the cubic terms it converges, see README).
// Where the cubic fit is ill-conditioned (pivot below kCubicPivotTol) the quadratic block of the
// same normal equations is solved instead. (In 3D the cubic fit needs 19 unknowns: not done yet.)
//
// Coordinates are whitened by the ring-1 second-moment tensor C (x' = C^{-1/2} (x − x_i)), so the
// stencil is round in the fit's frame whatever the mesh's anisotropy and the normal equations
// stay O(1) conditioned; weights 1/|x'_j − x'_i|² (the Taylor remainder grows with distance, so
// farther ring-2 points count less). They are solved by Cholesky after symmetric diagonal
// equilibration, a pivot below kPivotTol (relative) marking the fit as ill-conditioned. If no
// ring up to 3 determines a quadratic, the gradient comes from the linear fit and the Hessian is
// zero. Gradient and Hessian map back as g = A g', H = A H' A with A = C^{-1/2}.
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/error.hpp"
#include "core/spd.hpp"
#include "metric/recovery_detail.hpp"

namespace riemesh::detail {

namespace {

constexpr int kMaxRings = 3;
constexpr double kPivotTol = 1e-10;
/// A cubic fit whose equilibrated pivots fall below this is replaced by the quadratic one: the
/// normal equations square the condition number, so a cubic fit on a thin stencil (a boundary
/// corner) would lose more digits than the third-order terms gain.
constexpr double kCubicPivotTol = 1e-6;

/// Normal equations of the weighted polynomial fit at one vertex (fixed size: no allocation):
/// Order 2 fits the quadratic Taylor polynomial, Order 3 adds the cubic terms (their
/// coefficients are discarded; they keep the third derivatives out of the Hessian).
template <int D, int Order = 2>
struct QuadraticFit {
  static constexpr int kCubic = Order == 3 ? D * (D + 1) * (D + 2) / 6 : 0;
  static constexpr int kUnknowns = D + D * (D + 1) / 2 + kCubic;
  double a[kUnknowns][kUnknowns];  // upper triangle used
  double b[kUnknowns];
  int count;

  void clear() {
    for (int r = 0; r < kUnknowns; ++r) {
      b[r] = 0.0;
      for (int s = 0; s < kUnknowns; ++s) a[r][s] = 0.0;
    }
    count = 0;
  }
  /// Adds the point at scaled offset dx (non-zero) with value difference du.
  void add(const Vec<D>& dx, double du) {
    double p[kUnknowns];
    for (int i = 0; i < D; ++i) p[i] = dx[i];
    for (int j = 0; j < D; ++j)
      for (int i = 0; i <= j; ++i) p[D + sym_index(i, j)] = (i == j ? 0.5 : 1.0) * dx[i] * dx[j];
    if constexpr (Order == 3) {
      int k = D + D * (D + 1) / 2;
      for (int i = 0; i < D; ++i)
        for (int j = i; j < D; ++j)
          for (int l = j; l < D; ++l) p[k++] = dx[i] * dx[j] * dx[l];
    }
    const double dist2 = dot(dx, dx);
    if (!(dist2 > 0.0)) throw InputError("coincident vertices in least-squares recovery");
    const double w = 1.0 / dist2;
    for (int r = 0; r < kUnknowns; ++r) {
      const double wp = w * p[r];
      b[r] += wp * du;
      for (int s = r; s < kUnknowns; ++s) a[r][s] += wp * p[s];
    }
    ++count;
  }
  /// Solves the leading n x n system (n = kUnknowns: quadratic, n = D: linear fit) into c.
  /// False when a pivot of the equilibrated matrix falls below kPivotTol.
  bool solve(int n, double* c, double pivot_tol = kPivotTol) const {
    double l[kUnknowns][kUnknowns], inv_diag[kUnknowns], scale[kUnknowns], y[kUnknowns];
    for (int r = 0; r < n; ++r) {
      if (!(a[r][r] > 0.0)) return false;
      scale[r] = 1.0 / std::sqrt(a[r][r]);
    }
    for (int j = 0; j < n; ++j) {  // Cholesky L Lᵀ of S A S, column by column
      double d = a[j][j] * scale[j] * scale[j];
      for (int k = 0; k < j; ++k) d -= l[j][k] * l[j][k];
      if (!(d > pivot_tol)) return false;
      l[j][j] = std::sqrt(d);
      inv_diag[j] = 1.0 / l[j][j];
      for (int i = j + 1; i < n; ++i) {
        double s = a[j][i] * scale[i] * scale[j];
        for (int k = 0; k < j; ++k) s -= l[i][k] * l[j][k];
        l[i][j] = s * inv_diag[j];
      }
    }
    for (int i = 0; i < n; ++i) {  // L y = S b
      double s = b[i] * scale[i];
      for (int k = 0; k < i; ++k) s -= l[i][k] * y[k];
      y[i] = s * inv_diag[i];
    }
    for (int i = n - 1; i >= 0; --i) {  // Lᵀ z = y, c = S z
      double s = y[i];
      for (int k = i + 1; k < n; ++k) s -= l[k][i] * c[k];
      c[i] = s * inv_diag[i];
    }
    for (int i = 0; i < n; ++i) c[i] *= scale[i];
    return true;
  }
};

/// Vertex neighbours (CSR, each list in order of first appearance around the vertex), built from
/// the simplices alone. build_adjacency would also give vert2elem, but its face neighbours and edge
/// list cost about 150 ns per vertex in 2D (measured: a quarter of the whole recovery), and rings
/// walked over vertices touch 3x fewer entries than rings walked over elements.
struct VertexGraph {
  std::vector<Id> offsets;  // num_vertices + 1
  std::vector<Id> neighbours;
  std::span<const Id> of(Id v) const {
    const auto b = static_cast<std::size_t>(offsets[static_cast<std::size_t>(v)]);
    const auto e = static_cast<std::size_t>(offsets[static_cast<std::size_t>(v) + 1]);
    return std::span<const Id>(neighbours).subspan(b, e - b);
  }
};

VertexGraph vertex_graph(const std::vector<Id>& simplices, int k, std::size_t nv,
                         std::vector<Id>& stamp) {
  // vert2elem by a counting sort, then the unique vertices of each ball (stamped).
  std::vector<Id> v2e_offsets(nv + 1, 0);
  for (const Id v : simplices) ++v2e_offsets[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < nv; ++v) v2e_offsets[v + 1] += v2e_offsets[v];
  std::vector<Id> v2e(simplices.size());
  std::vector<Id> fill(v2e_offsets.begin(), v2e_offsets.end() - 1);
  const std::size_t ne = simplices.size() / static_cast<std::size_t>(k);
  for (std::size_t e = 0; e < ne; ++e)
    for (int i = 0; i < k; ++i)
      v2e[static_cast<std::size_t>(fill[static_cast<std::size_t>(simplices[e * k + i])]++)] =
          static_cast<Id>(e);
  VertexGraph g;
  g.offsets.assign(nv + 1, 0);
  g.neighbours.reserve(simplices.size() * (k == 3 ? 1 : 2));  // ~6 per vertex 2D, ~14 in 3D
  for (std::size_t v = 0; v < nv; ++v) {
    stamp[v] = static_cast<Id>(v);
    for (Id j = v2e_offsets[v]; j < v2e_offsets[v + 1]; ++j) {
      const Id* s = &simplices[static_cast<std::size_t>(v2e[static_cast<std::size_t>(j)]) * k];
      for (int i = 0; i < k; ++i) {
        if (stamp[static_cast<std::size_t>(s[i])] == static_cast<Id>(v)) continue;
        stamp[static_cast<std::size_t>(s[i])] = static_cast<Id>(v);
        g.neighbours.push_back(s[i]);
      }
    }
    g.offsets[v + 1] = static_cast<Id>(g.neighbours.size());
  }
  return g;
}

/// Scratch reused across vertices: a stamp per vertex (the last vertex that collected it) and the
/// list of collected neighbours, ring after ring.
struct RingScratch {
  std::vector<Id> stamp;
  std::vector<Id> ring;
};

/// The whitening map of the ring-1 offsets: A = C^{-1/2}, C = their second-moment tensor, so the
/// fit runs in coordinates x' = A (x − x_v) where the stencil is as round as the mesh is in its
/// own metric. On stretched meshes (anisotropy 1:1000 along a front at 45°) fitting in plain
/// coordinates makes the x and y columns nearly equal and the normal equations lose 6 to 12 digits;
/// whitened, they stay O(1) conditioned. Eigenvalues of C are floored at 1e-12 of the largest
/// (a ring along one line).
template <int D>
SymMat<D> whitening(const Mesh& mesh, std::span<const Id> ring1, const Vec<D>& xv) {
  SymMat<D> c = SymMat<D>::zero();
  for (const Id w : ring1) c = c + outer(vertex_position<D>(mesh, w) - xv);
  c = (1.0 / static_cast<double>(ring1.size())) * c;
  double trace = 0.0;
  for (int i = 0; i < D; ++i) trace += c(i, i);
  return map_eigenvalues(c, [floor = 1e-12 * trace](double l) {
    return 1.0 / std::sqrt(std::max(l, floor));
  });
}

/// The fit at vertex v: coefficients in c for the whitened coordinates x' = A (x − x_v); returns
/// the number of coefficients solved for (kUnknowns, D for the linear fallback, 0 for an isolated
/// vertex).
template <int D, int Order>
int fit_vertex(const Mesh& mesh, std::span<const double> u, const VertexGraph& graph, Id v,
               RingScratch& scratch, QuadraticFit<D, Order>& fit, double* c, SymMat<D>& a) {
  constexpr int kN = QuadraticFit<D, Order>::kUnknowns;
  constexpr int kQ = QuadraticFit<D, 2>::kUnknowns;
  const std::span<const Id> ring1 = graph.of(v);
  if (ring1.empty()) return 0;
  const Vec<D> xv = vertex_position<D>(mesh, v);
  const double uv = u[static_cast<std::size_t>(v)];
  a = whitening<D>(mesh, ring1, xv);
  fit.clear();
  scratch.ring.clear();
  scratch.stamp[static_cast<std::size_t>(v)] = v;
  auto take = [&](Id w) {
    scratch.stamp[static_cast<std::size_t>(w)] = v;
    scratch.ring.push_back(w);
    fit.add(a * (vertex_position<D>(mesh, w) - xv), u[static_cast<std::size_t>(w)] - uv);
  };
  for (const Id w : ring1) take(w);
  std::size_t begin = 0;
  for (int rings = 1;; ++rings) {
    if (Order == 3 && 2 * fit.count >= 3 * kN && fit.solve(kN, c, kCubicPivotTol)) return kN;
    // The quadratic fit is the leading block of the same normal equations; with the cubic
    // terms available it is taken from ring 2 on (ring 1 alone cannot hold a cubic).
    const bool quadratic_ok = (Order == 2 || rings >= 2) && fit.count >= (rings == 1 ? 2 * kQ : kQ);
    if (quadratic_ok && fit.solve(kQ, c)) return kQ;
    const std::size_t end = scratch.ring.size();
    if (rings == kMaxRings || begin == end) break;
    for (std::size_t k = begin; k < end; ++k)
      for (const Id w : graph.of(scratch.ring[k]))
        if (scratch.stamp[static_cast<std::size_t>(w)] != v) take(w);
    begin = end;
  }
  return fit.solve(D, c) ? D : 0;
}

}  // namespace

template <int D>
void lsq_recover(const Mesh& mesh, std::span<const double> u, std::vector<Vec<D>>* gradient,
                 std::vector<SymMat<D>>* hessian) {
  const std::size_t nv = mesh.num_vertices();
  const std::vector<Id>& simplices = recovery_simplices<D>(mesh);
  if (gradient) gradient->assign(nv, Vec<D>::zero());
  if (hessian) hessian->assign(nv, SymMat<D>::zero());
  RingScratch scratch;
  scratch.stamp.assign(nv, kNoId);
  const VertexGraph graph = vertex_graph(simplices, D + 1, nv, scratch.stamp);
  scratch.stamp.assign(nv, kNoId);  // fit_vertex's stamps mean "collected for this vertex"
  scratch.ring.reserve(256);
  constexpr int kOrder = D == 2 ? 3 : 2;
  QuadraticFit<D, kOrder> fit;
  double c[QuadraticFit<D, kOrder>::kUnknowns];
  for (std::size_t v = 0; v < nv; ++v) {
    SymMat<D> a;
    const int solved = fit_vertex<D, kOrder>(mesh, u, graph, static_cast<Id>(v), scratch, fit, c, a);
    if (solved == 0) continue;
    // u ≈ g'·x' + ½ x'ᵀ H' x' with x' = A dx: g = A g', H = A H' A.
    if (gradient) {
      Vec<D> g;
      for (int i = 0; i < D; ++i) g[i] = c[i];
      (*gradient)[v] = a * g;
    }
    if (hessian && solved > D) {
      SymMat<D> hw;
      for (int k = 0; k < SymMat<D>::kSize; ++k) hw.c[k] = c[D + k];
      (*hessian)[v] = congruence(a.to_mat(), hw);
    }
  }
}

template void lsq_recover<2>(const Mesh&, std::span<const double>, std::vector<Vec2>*,
                             std::vector<SymMat2>*);
template void lsq_recover<3>(const Mesh&, std::span<const double>, std::vector<Vec3>*,
                             std::vector<SymMat3>*);

}  // namespace riemesh::detail
