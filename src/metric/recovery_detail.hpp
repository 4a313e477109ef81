#pragma once
// Shared pieces of the derivative recovery (recovery*.cpp): input checks, P1 basis gradients of a
// simplex, and the per-method drivers. Not part of the public API.
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::detail {

/// Throws InputError unless the mesh is a planar triangle mesh (D = 2) or a tetrahedral volume
/// (D = 3) and u has one value per vertex.
template <int D>
void check_recovery_input(const Mesh& mesh, std::span<const double> u);

/// The simplex array of the mesh kind recovered in dimension D (triangles or tetrahedra).
template <int D>
const std::vector<Id>& recovery_simplices(const Mesh& mesh) {
  if constexpr (D == 2) {
    return mesh.triangles;
  } else {
    return mesh.tets;
  }
}

template <int D>
Vec<D> vertex_position(const Mesh& mesh, Id v) {
  Vec<D> x{};
  for (int i = 0; i < D; ++i) x[i] = mesh.coords[static_cast<std::size_t>(v) * D + i];
  return x;
}

/// Measure |K| and the gradients of the D+1 P1 basis functions of a simplex.
template <int D>
struct SimplexGradients {
  double measure;
  Vec<D> grad[D + 1];
};

/// ∇φ_k for k >= 1 are the rows of J⁻¹, J = [x1-x0 ... xD-x0]; ∇φ_0 = -Σ ∇φ_k. Valid for either
/// orientation (the sign of det J cancels). Throws InputError for a zero-measure simplex.
template <int D>
SimplexGradients<D> simplex_gradients(const Vec<D> (&x)[D + 1]);

/// The gradient on a simplex of the P1 field with vertex values `val`.
template <int D>
Vec<D> p1_gradient(const SimplexGradients<D>& s, const double (&val)[D + 1]) {
  Vec<D> g = Vec<D>::zero();
  for (int k = 0; k <= D; ++k) g += val[k] * s.grad[k];
  return g;
}

/// Gathers the simplex e's vertex positions and returns its basis gradients.
template <int D>
SimplexGradients<D> simplex_gradients(const Mesh& mesh, const Id* simplex) {
  Vec<D> x[D + 1];
  for (int k = 0; k <= D; ++k) x[k] = vertex_position<D>(mesh, simplex[k]);
  return simplex_gradients<D>(x);
}

/// Lumped L2 projection of the element gradients (also the Green-formula gradient).
template <int D>
std::vector<Vec<D>> l2_gradient(const Mesh& mesh, std::span<const double> u);
/// The L2 projection applied to each component of the L2 gradient, symmetrised.
template <int D>
std::vector<SymMat<D>> l2_hessian(const Mesh& mesh, std::span<const double> u);
/// Lumped weak Hessian by Green's formula with the boundary correction of recovery_green.cpp.
template <int D>
std::vector<SymMat<D>> green_hessian(const Mesh& mesh, std::span<const double> u);
/// Quadratic least-squares fit on the vertex rings; either output may be null.
template <int D>
void lsq_recover(const Mesh& mesh, std::span<const double> u, std::vector<Vec<D>>* gradient,
                 std::vector<SymMat<D>>* hessian);

}  // namespace riemesh::detail
