// Lumped L2 projection (BOOK.md §2): the vertex gradient is the measure-weighted average of the
// element gradients over the vertex ball, g_i = Σ_K |K| ∇u_K / Σ_K |K| — the L2 projection of the
// piecewise-constant ∇u onto P1 with a lumped mass matrix (the |K|/(D+1) factors cancel).
// The Hessian applies the same projection to each component of g and symmetrises. Both are exact
// where the ball is centrally symmetric (structured meshes away from the boundary; see the tests).
#include <cstddef>

#include "core/mat.hpp"
#include "metric/recovery_detail.hpp"

namespace riemesh::detail {

template <int D>
std::vector<Vec<D>> l2_gradient(const Mesh& mesh, std::span<const double> u) {
  const std::size_t nv = mesh.num_vertices();
  const std::vector<Id>& simplices = recovery_simplices<D>(mesh);
  std::vector<Vec<D>> g(nv, Vec<D>::zero());
  std::vector<double> weight(nv, 0.0);
  const std::size_t ne = simplices.size() / (D + 1);
  for (std::size_t e = 0; e < ne; ++e) {
    const Id* s = &simplices[e * (D + 1)];
    const SimplexGradients<D> sg = simplex_gradients<D>(mesh, s);
    double val[D + 1];
    for (int k = 0; k <= D; ++k) val[k] = u[static_cast<std::size_t>(s[k])];
    const Vec<D> gk = sg.measure * p1_gradient<D>(sg, val);
    for (int k = 0; k <= D; ++k) {
      g[static_cast<std::size_t>(s[k])] += gk;
      weight[static_cast<std::size_t>(s[k])] += sg.measure;
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (weight[v] > 0.0) g[v] = g[v] / weight[v];  // isolated vertices keep a zero gradient
  return g;
}

template <int D>
std::vector<SymMat<D>> l2_hessian(const Mesh& mesh, std::span<const double> u) {
  const std::vector<Vec<D>> g = l2_gradient<D>(mesh, u);
  const std::size_t nv = mesh.num_vertices();
  const std::vector<Id>& simplices = recovery_simplices<D>(mesh);
  std::vector<Mat<D>> sum(nv, Mat<D>{});
  std::vector<double> weight(nv, 0.0);
  const std::size_t ne = simplices.size() / (D + 1);
  for (std::size_t e = 0; e < ne; ++e) {
    const Id* s = &simplices[e * (D + 1)];
    const SimplexGradients<D> sg = simplex_gradients<D>(mesh, s);
    // Row c of the element Hessian: the gradient of the P1 field g_c.
    Mat<D> hk{};
    for (int k = 0; k <= D; ++k) {
      const Vec<D>& gv = g[static_cast<std::size_t>(s[k])];
      for (int c = 0; c < D; ++c)
        for (int j = 0; j < D; ++j) hk(c, j) += gv[c] * sg.grad[k][j];
    }
    for (int k = 0; k <= D; ++k) {
      Mat<D>& acc = sum[static_cast<std::size_t>(s[k])];
      for (int c = 0; c < D; ++c)
        for (int j = 0; j < D; ++j) acc(c, j) += sg.measure * hk(c, j);
      weight[static_cast<std::size_t>(s[k])] += sg.measure;
    }
  }
  std::vector<SymMat<D>> h(nv, SymMat<D>::zero());
  for (std::size_t v = 0; v < nv; ++v)
    if (weight[v] > 0.0) h[v] = (1.0 / weight[v]) * SymMat<D>::from_mat(sum[v]);
  return h;
}

template std::vector<Vec2> l2_gradient<2>(const Mesh&, std::span<const double>);
template std::vector<Vec3> l2_gradient<3>(const Mesh&, std::span<const double>);
template std::vector<SymMat2> l2_hessian<2>(const Mesh&, std::span<const double>);
template std::vector<SymMat3> l2_hessian<3>(const Mesh&, std::span<const double>);

}  // namespace riemesh::detail
