// Lumped weak Hessian by Green's formula (BOOK.md §2). For a P1 test function φ_i,
//   ∫ ∂_j∂_k u φ_i = −∫ ∂_k u ∂_j φ_i + ∫_∂Ω φ_i ∂_k u n_j,
// and with the lumped mass ∫ φ_i = |supp φ_i|/(D+1):
//   H_i |supp φ_i|/(D+1) = −Σ_K |K| ∇u_K ⊗ ∇φ_i,K + Σ_F ∫_F φ_i g ⊗ n,   symmetrised,
// where g on a boundary face F is the P1 interpolant of the recovered L2 gradient.
//
// Boundary correction: the boundary term only reaches boundary vertices (φ_i vanishes on ∂Ω
// otherwise), and there it is O(1) wrong even for quadratics, because the L2 gradient is only
// O(h) accurate on the boundary and is divided by a mass of O(h). So each boundary vertex takes
// the average of the Hessians of its interior neighbours (an O(h) extrapolation); boundary vertices
// with no interior neighbour take, in later sweeps, the average of already-corrected neighbours.
// Measured on unit_square(12) / unit_cube(6) with a quadratic: boundary-term values alone are off
// by 150% (relative) at boundary vertices, corrected ones are exact (the interior is exact on these
// structured meshes). The boundary-term value survives only on meshes without interior vertices.
#include <cstddef>

#include "core/mat.hpp"
#include "metric/recovery_detail.hpp"

namespace riemesh::detail {

namespace {

/// Adds ½ s (a ⊗ b + b ⊗ a) to h.
template <int D>
void add_sym_outer(SymMat<D>& h, double s, const Vec<D>& a, const Vec<D>& b) {
  for (int j = 0; j < D; ++j)
    for (int i = 0; i <= j; ++i) h.at(i, j) += 0.5 * s * (a[i] * b[j] + a[j] * b[i]);
}

/// The weak Hessian and lumped mass of every vertex, and which vertices are on the boundary.
template <int D>
void weak_hessian(const Mesh& mesh, std::span<const double> u, const Adjacency& adj,
                  std::vector<SymMat<D>>& w, std::vector<double>& mass,
                  std::vector<char>& on_boundary) {
  const std::vector<Id>& simplices = recovery_simplices<D>(mesh);
  const std::size_t ne = simplices.size() / (D + 1);
  const std::vector<Vec<D>> g = l2_gradient<D>(mesh, u);
  for (std::size_t e = 0; e < ne; ++e) {
    const Id* s = &simplices[e * (D + 1)];
    const SimplexGradients<D> sg = simplex_gradients<D>(mesh, s);
    double val[D + 1];
    for (int k = 0; k <= D; ++k) val[k] = u[static_cast<std::size_t>(s[k])];
    const Vec<D> gk = p1_gradient<D>(sg, val);
    for (int k = 0; k <= D; ++k) {
      const auto v = static_cast<std::size_t>(s[k]);
      add_sym_outer<D>(w[v], -sg.measure, gk, sg.grad[k]);
      mass[v] += sg.measure / (D + 1);
    }
    for (int f = 0; f <= D; ++f) {
      if (adj.elem2elem[e * (D + 1) + f] != kNoId) continue;
      // Face f (opposite vertex f): |F| n = −D |K| ∇φ_f, outward whatever the orientation.
      const Vec<D> area_normal = (-D * sg.measure) * sg.grad[f];
      // ∫_F φ_k φ_l = |F| (1 + δ_kl) / (D (D+1)) on the (D−1)-simplex F.
      Vec<D> g_sum = Vec<D>::zero();
      for (int k = 0; k <= D; ++k)
        if (k != f) g_sum += g[static_cast<std::size_t>(s[k])];
      for (int k = 0; k <= D; ++k) {
        if (k == f) continue;
        const auto v = static_cast<std::size_t>(s[k]);
        add_sym_outer<D>(w[v], 1.0 / (D * (D + 1)), g_sum + g[v], area_normal);
        on_boundary[v] = 1;
      }
    }
  }
}

/// Replaces the Hessian of each boundary vertex by the average over its neighbours that are
/// interior (sweep 0) or already corrected (later sweeps, Jacobi style: deterministic).
template <int D>
void correct_boundary(const Adjacency& adj, std::vector<char> done, std::vector<SymMat<D>>& h) {
  const std::size_t nv = h.size();
  for (;;) {
    std::vector<SymMat<D>> sum(nv, SymMat<D>::zero());
    std::vector<int> count(nv, 0);
    for (std::size_t k = 0; k < adj.num_edges(); ++k) {
      const auto a = static_cast<std::size_t>(adj.edges[2 * k]);
      const auto b = static_cast<std::size_t>(adj.edges[2 * k + 1]);
      if (!done[a] && done[b]) sum[a] += h[b], ++count[a];
      if (!done[b] && done[a]) sum[b] += h[a], ++count[b];
    }
    bool progress = false, pending = false;
    for (std::size_t v = 0; v < nv; ++v) {
      if (done[v]) continue;
      if (count[v] > 0) {
        h[v] = (1.0 / count[v]) * sum[v];
        done[v] = 1;
        progress = true;
      } else {
        pending = true;
      }
    }
    if (!pending || !progress) return;  // all done, or the rest has no interior vertex at all
  }
}

}  // namespace

template <int D>
std::vector<SymMat<D>> green_hessian(const Mesh& mesh, std::span<const double> u) {
  const std::size_t nv = mesh.num_vertices();
  const Adjacency adj = build_adjacency(recovery_simplices<D>(mesh), D + 1, nv);
  std::vector<SymMat<D>> h(nv, SymMat<D>::zero());
  std::vector<double> mass(nv, 0.0);
  std::vector<char> on_boundary(nv, 0);
  weak_hessian<D>(mesh, u, adj, h, mass, on_boundary);
  for (std::size_t v = 0; v < nv; ++v)
    if (mass[v] > 0.0) h[v] = (1.0 / mass[v]) * h[v];
  std::vector<char> interior(nv);
  for (std::size_t v = 0; v < nv; ++v) interior[v] = on_boundary[v] ? 0 : 1;
  correct_boundary<D>(adj, std::move(interior), h);
  return h;
}

template std::vector<SymMat2> green_hessian<2>(const Mesh&, std::span<const double>);
template std::vector<SymMat3> green_hessian<3>(const Mesh&, std::span<const double>);

}  // namespace riemesh::detail
