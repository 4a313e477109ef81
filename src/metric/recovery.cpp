// Derivative recovery: method names, input checks, simplex gradients and the dispatch to
// recovery_l2.cpp, recovery_green.cpp and recovery_lsq.cpp.
#include "metric/recovery.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "metric/recovery_detail.hpp"

namespace riemesh {

RecoveryMethod parse_recovery_method(std::string_view name) {
  if (name == "l2") return RecoveryMethod::kL2Projection;
  if (name == "green") return RecoveryMethod::kGreen;
  if (name == "lsq") return RecoveryMethod::kLeastSquares;
  std::string msg = "unknown recovery method '";
  msg += name;
  msg += "' (expected l2, green or lsq)";
  throw InputError(msg);
}

namespace detail {

template <int D>
void check_recovery_input(const Mesh& mesh, std::span<const double> u) {
  const bool right_kind = D == 2 ? (mesh.dim == 2 && mesh.kind() == MeshKind::kPlanar)
                                 : (mesh.dim == 3 && mesh.kind() == MeshKind::kVolume);
  if (!right_kind) {
    throw InputError(D == 2 ? "derivative recovery in 2D needs a planar triangle mesh"
                            : "derivative recovery in 3D needs a tetrahedral volume mesh");
  }
  if (u.size() != mesh.num_vertices()) {
    std::string msg = "derivative recovery: the field has ";
    msg += std::to_string(u.size());
    msg += " values for ";
    msg += std::to_string(mesh.num_vertices());
    msg += " vertices";
    throw InputError(msg);
  }
}

template <int D>
SimplexGradients<D> simplex_gradients(const Vec<D> (&x)[D + 1]) {
  SimplexGradients<D> s{};
  if constexpr (D == 2) {
    const Vec2 e1 = x[1] - x[0], e2 = x[2] - x[0];
    const double det = cross(e1, e2);
    if (!(det != 0.0) || !std::isfinite(det)) throw InputError("degenerate triangle in recovery");
    // Rows of J⁻¹ for J = [e1 e2].
    s.grad[1] = Vec2{{e2[1] / det, -e2[0] / det}};
    s.grad[2] = Vec2{{-e1[1] / det, e1[0] / det}};
    s.measure = 0.5 * std::abs(det);
  } else {
    const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0], e3 = x[3] - x[0];
    const double det = dot(e1, cross(e2, e3));
    if (!(det != 0.0) || !std::isfinite(det))
      throw InputError("degenerate tetrahedron in recovery");
    s.grad[1] = cross(e2, e3) / det;
    s.grad[2] = cross(e3, e1) / det;
    s.grad[3] = cross(e1, e2) / det;
    s.measure = std::abs(det) / 6.0;
  }
  s.grad[0] = Vec<D>::zero();
  for (int k = 1; k <= D; ++k) s.grad[0] -= s.grad[k];
  return s;
}

template void check_recovery_input<2>(const Mesh&, std::span<const double>);
template void check_recovery_input<3>(const Mesh&, std::span<const double>);
template SimplexGradients<2> simplex_gradients<2>(const Vec2 (&)[3]);
template SimplexGradients<3> simplex_gradients<3>(const Vec3 (&)[4]);

}  // namespace detail

template <int D>
std::vector<Vec<D>> recover_gradient(const Mesh& mesh, std::span<const double> u,
                                     RecoveryMethod method) {
  detail::check_recovery_input<D>(mesh, u);
  if (method == RecoveryMethod::kLeastSquares) {
    std::vector<Vec<D>> g;
    detail::lsq_recover<D>(mesh, u, &g, nullptr);
    return g;
  }
  // Green's formula for the gradient, ∫ ∇u φ_i lumped, is the lumped L2 projection itself.
  return detail::l2_gradient<D>(mesh, u);
}

namespace {

/// Rounding in u (relative 2.2e-16 of its largest magnitude U) reaches a recovered Hessian as
/// about ε U / h², h the vertex's shortest edge, times the recovery's amplification: Hessians
/// below kRoundoff U / h² are that noise (a linear field's, 1e-13 where the Lp normalisation
/// then made sizes vary 48 times over a square), and are set to zero.
constexpr double kRoundoff = 1e3 * 2.220446049250313e-16;

template <int D>
void drop_roundoff(const Mesh& mesh, std::span<const double> u, std::vector<SymMat<D>>& h) {
  double big = 0.0;
  for (const double x : u) big = std::max(big, std::abs(x));
  const std::vector<Id>& elems = D == 2 ? mesh.triangles : mesh.tets;
  std::vector<double> shortest2(h.size(), std::numeric_limits<double>::infinity());
  for (std::size_t e = 0; e < elems.size(); e += D + 1)
    for (int i = 0; i <= D; ++i)
      for (int j = i + 1; j <= D; ++j) {
        const Id a = elems[e + i], b = elems[e + j];
        double l2 = 0.0;
        for (int k = 0; k < D; ++k) {
          const double d = mesh.coords[D * static_cast<std::size_t>(a) + k] -
                           mesh.coords[D * static_cast<std::size_t>(b) + k];
          l2 += d * d;
        }
        shortest2[a] = std::min(shortest2[a], l2), shortest2[b] = std::min(shortest2[b], l2);
      }
  for (std::size_t v = 0; v < h.size(); ++v) {
    double largest = 0.0;  // the largest coefficient (no squares: a field of 1e-200 has them)
    for (const double c : h[v].c) largest = std::max(largest, std::abs(c));
    if (largest <= kRoundoff * big / shortest2[v]) h[v] = SymMat<D>::zero();
  }
}

}  // namespace

template <int D>
std::vector<SymMat<D>> recover_hessian(const Mesh& mesh, std::span<const double> u,
                                       RecoveryMethod method) {
  detail::check_recovery_input<D>(mesh, u);
  std::vector<SymMat<D>> h;
  switch (method) {
    case RecoveryMethod::kL2Projection:
      h = detail::l2_hessian<D>(mesh, u);
      break;
    case RecoveryMethod::kGreen:
      h = detail::green_hessian<D>(mesh, u);
      break;
    case RecoveryMethod::kLeastSquares:
      detail::lsq_recover<D>(mesh, u, nullptr, &h);
      break;
  }
  drop_roundoff<D>(mesh, u, h);
  return h;
}

template std::vector<Vec2> recover_gradient<2>(const Mesh&, std::span<const double>,
                                               RecoveryMethod);
template std::vector<Vec3> recover_gradient<3>(const Mesh&, std::span<const double>,
                                               RecoveryMethod);
template std::vector<SymMat2> recover_hessian<2>(const Mesh&, std::span<const double>,
                                                 RecoveryMethod);
template std::vector<SymMat3> recover_hessian<3>(const Mesh&, std::span<const double>,
                                                 RecoveryMethod);

}  // namespace riemesh
