#pragma once
// Derivative recovery from P1 vertex fields (BOOK.md §2 "Derivative recovery"): gradient and
// Hessian at every vertex of a triangle mesh (D = 2) or tetrahedral mesh (D = 3).
//   kL2Projection: area/volume-weighted average of the element gradients (the L2 projection of the
//                  piecewise-constant gradient onto P1 with a lumped mass matrix), applied twice.
//   kGreen:        weak Hessian by Green's formula, ∫ H φ_i = −∫ ∇u ∇φ_i + boundary term, lumped,
//                  with a boundary correction.
//   kLeastSquares: Taylor fit of u over two rings of vertices (a third where they are too few,
//                  e.g. at boundary corners) in coordinates whitened by the ring's second moments;
//                  cubic in 2D (quadratic where the cubic fit is ill-conditioned), quadratic in
//                  3D. The documented default: exact for quadratics, and robust on stretched
//                  anisotropic meshes (see recovery_lsq.cpp).
// Accuracy (tests/metric/test_recovery.cpp): least squares is exact for quadratics at every vertex
// of any mesh and converges on unstructured meshes (max norm: order 2 in 2D, order > 1 in 3D). L2 and Green are exact
// for quadratics only where the mesh is structured (L2: 2 layers away from the boundary; Green: at
// every vertex of unit_square/unit_cube) and do not converge on unstructured meshes (errors of
// 15-40% of |H| that do not decrease). All three are exact for the gradient of linear fields; the
// gradient of kGreen is the lumped L2 one (Green's formula for ∇u is that projection).
// Cost in 2D (bench_recovery, Hessian): L2 ≈ 100 ns/vertex, Green ≈ 310, least squares ≈ 375.
#include <span>
#include <string_view>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

enum class RecoveryMethod { kL2Projection, kGreen, kLeastSquares };

/// "l2", "green" or "lsq"; throws InputError listing the valid names otherwise.
RecoveryMethod parse_recovery_method(std::string_view name);

/// The gradient of the P1 field u (one value per vertex) at every vertex. D = 2: mesh.dim == 2
/// with triangles; D = 3: a tetrahedral volume. Throws InputError for a size mismatch or another
/// kind of mesh.
template <int D>
std::vector<Vec<D>> recover_gradient(const Mesh& mesh, std::span<const double> u,
                                     RecoveryMethod method = RecoveryMethod::kLeastSquares);

/// The Hessian of the P1 field u at every vertex (symmetric, packed as SymMat<D>).
template <int D>
std::vector<SymMat<D>> recover_hessian(const Mesh& mesh, std::span<const double> u,
                                       RecoveryMethod method = RecoveryMethod::kLeastSquares);

}  // namespace riemesh
