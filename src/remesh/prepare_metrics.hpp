#pragma once
// The metric field a remeshing run starts from (2D and 3D drivers alike).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh {

/// Validated (InputError naming the vertex for a NaN or non-SPD tensor, or for a count that does
/// not match the mesh; InputError too when the clipped field asks for more vertices than 32-bit
/// ids hold), clipped to sizes in [o.hmin, o.hmax] and graded (o.hgrad, physical-space
/// growth along adj.edges) copy of the input metrics. Clipping is reported in report.notes (with
/// the place of the first vertex below hmin), gradation in report.gradation_before/after.
/// Checks the input of a remeshing run on its own numbering, before the drivers renumber it (ids in
/// a message would otherwise name another element or vertex of the file): element vertex ids in
/// range, elements positively oriented (triangles counter-clockwise, tets of positive volume),
/// each metric SPD with a finite determinant. InputError naming the 1-based element or vertex.
template <int D>
void require_valid_input(const Mesh& in, std::span<const SymMat<D>> metrics);

/// Throws InputError when the planar triangles of `in` (`adj`: their face adjacency) fold over
/// themselves, as riemesh check finds it (planar_folds), naming the place of the first fold's
/// common edge: each triangle counter-clockwise, such a mesh ran out of memory or came out as
/// the outline of its boundary.
void require_unfolded(const Mesh& in, const Adjacency& adj);

/// Throws InputError("<what>s E0 and E1 join the same vertices with different refs (R0 and R1):
/// an edge has one ref"), E0, E1 1-based: an edge listed twice whose second ref was dropped.
[[noreturn]] void refuse_edge_refs(const char* what, std::size_t e0, std::size_t e1,
                                   std::int32_t r0, std::int32_t r1);

/// Throws InputError if the unit mesh of the metrics m (one per vertex of `in`, whose triangles
/// (D = 2) or tets (D = 3) cover the domain) would need more than max_vertices vertices, or more
/// than 32-bit ids hold, or if the count overflows (a tensor whose determinant is infinite),
/// naming the place of the finest size (by coordinates: the drivers work on a renumbered copy).
/// An upper bound of the complexity, by `bound`: each element in the arithmetic mean of its
/// vertices' sqrt(det M) for log-Euclidean interpolation (the default), or in their geometric
/// mean for isotropic sizes linear in each element (kLinearSizes: the mean of h^-D over a
/// simplex is at most the mean of h^-(D+1) to the power D/(D+1), which is 1 / Π h_i exactly;
/// the arithmetic mean overestimated a tet with one vertex 700 times finer than the others
/// 1e5-fold). Without it such a field ran for hours (complexity 1e12) or crashed on
/// non-finite lengths (a tensor of 1e308).
enum class ComplexityBound { kLogEuclidean, kLinearSizes };

/// The most vertices a 2D run makes (mesh_domain2d, adapt2d: about 2e8 triangles) and a 3D one
/// (mesh_volume, adapt3d: about 2e8 tets): sizes asking for more are refused before any point
/// is added. (adapt allowed 2^31 - 1: --hsiz 1e-4 on the unit square, 1.15e8 vertices, went on
/// until the memory was gone.)
inline constexpr double kMostVertices2d = 1e8;
inline constexpr double kMostVertices3d = 3.5e7;
template <int D>
void require_reachable_complexity(const Mesh& in, std::span<const SymMat<D>> m,
                                  double max_vertices = 2147483647.0,
                                  ComplexityBound bound = ComplexityBound::kLogEuclidean);

template <int D>
std::vector<SymMat<D>> prepare_metrics(const Mesh& in, const Adjacency& adj,
                                       std::span<const SymMat<D>> metrics,
                                       const Adapt2dOptions& o, Adapt2dReport& report);

}  // namespace riemesh
