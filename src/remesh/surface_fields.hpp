#pragma once
// Solution fields on triangulated surfaces in 3D (issue #6 with issue #5's tools): the Hessian of
// a P1 field in the tangent plane of the surface, the Lp-optimal metric it gives on the surface
// (the continuous-mesh formula of BOOK.md §2 with the surface's dimension 2), and the P1 transfer
// of vertex fields to a remeshed surface.
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "metric/hessian_metric.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// The Hessian of the P1 field u (one value per vertex) at every vertex of a surface mesh, in the
/// tangent plane: u is fitted by least squares with a quadratic in the coordinates of the
/// vertex's tangent plane (angle-weighted normal) over its two rings of neighbours, and the
/// 2x2 Hessian is returned as a 3D tensor that is zero along the normal. On a smooth surface this
/// is the Riemannian Hessian at the vertex up to O(h²) (e.g. −(a·n) P for u = a·x on the unit
/// sphere, P the tangent projector). Throws InputError for a mesh that is not a surface, a size
/// mismatch or non-finite values.
std::vector<SymMat3> recover_surface_hessian(const Mesh& surface, std::span<const double> u);

/// The Lp-optimal metric for complexity N on the surface (options.complexity > 0, options.norm p
/// finite) or the L∞ metric c|H|/ε (options.tolerance, c = 2/9 as in 2D): in the tangent plane
/// M = D det|H|^{−1/(2p+2)} |H| with D = N / ∫ det|H|^{p/(2p+2)} dA (vertex areas: a third of
/// the adjacent triangles'), sizes clipped to [hmin, hmax] and anisotropy to aniso_max, the
/// normalisation repeated so that Σ_v A_v sqrt(det M_v) = N after clipping. Along the normal the
/// metric takes its smallest tangent eigenvalue (it never asks for a size across the surface).
/// report->complexity is that sum; the predicted counts are those of a 2D unit mesh.
std::vector<SymMat3> surface_hessian_metric(const Mesh& surface, std::span<const SymMat3> hessians,
                                            const HessianMetricOptions& options,
                                            MetricReport* report = nullptr);

/// The vertex fields of surface `from` interpolated linearly at the vertices of surface `to` from
/// the nearest point of `from` (a remeshed surface's vertices lie on or near the input). Throws
/// InputError for fields whose size does not match `from` or meshes that are not surfaces.
std::vector<Field> transfer_surface_p1(const Mesh& from, const std::vector<Field>& fields,
                                       const Mesh& to);

}  // namespace riemesh
