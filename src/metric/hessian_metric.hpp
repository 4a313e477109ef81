#pragma once
// Metrics from Hessians (BOOK.md §2, §8.2): the L∞ metric for a tolerance and the Lp-optimal metric
// of the continuous-mesh framework (Loseille–Alauzet) for a target complexity, with clipping, and
// the combination of several fields' metrics.
#include <limits>
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

struct HessianMetricOptions {
  /// Norm p of the Lp-optimal metric (1, 2, ...); +inf selects the L∞ metric c_d |H| / ε.
  double norm = 2.0;
  /// Target complexity N (Lp metric); 0 for the L∞ metric with `tolerance`.
  double complexity = 0.0;
  /// ε of the L∞ metric (used when complexity == 0).
  double tolerance = 0.0;
  double hmin = 0.0;
  double hmax = std::numeric_limits<double>::infinity();
  double aniso_max = std::numeric_limits<double>::infinity();  ///< largest h_max/h_min
  /// Throws InputError naming the option for out-of-range or contradicting values.
  void validate() const;
};

struct MetricReport {
  double complexity = 0.0;          ///< C(M) = ∫ sqrt(det M) over the mesh
  double predicted_vertices = 0.0;  ///< (2/√3) C(M) in 2D, √2 C(M) in 3D (a unit mesh's vertices)
  double predicted_elements = 0.0;  ///< (4/√3) C(M) triangles in 2D; 6√2 C(M) tetrahedra in 3D
};

/// The metric at every vertex from the vertex Hessians of a field: |H| (absolute eigenvalues) made
/// SPD (absolute eigenvalues floored at 1e-12 of the largest over the mesh; a Hessian zero
/// everywhere gives a uniform Lp metric, and an L∞ metric of size hmax), scaled as the options
/// say, clipped to sizes in [hmin, hmax] and then to anisotropy <= aniso_max (smallest sizes
/// shrunk). The Lp normalisation starts from the BOOK formula with ∫ det|H|^{p/(2p+D)} by P1
/// quadrature per element, then is refined so that field_complexity of the clipped result is N
/// (to 1e-12 relative when the bounds allow it). Throws InputError for bad options, a size
/// mismatch, non-finite Hessians or another kind of mesh.
template <int D>
std::vector<SymMat<D>> hessian_metric(const Mesh& mesh, std::span<const SymMat<D>> hessians,
                                      const HessianMetricOptions& options,
                                      MetricReport* report = nullptr);

/// ∫ sqrt(det M) over the mesh of a vertex metric field (interpolated log-Euclidean per element).
template <int D>
double field_complexity(const Mesh& mesh, std::span<const SymMat<D>> metrics);

/// The complexity of a vertex metric field and the counts it predicts (see MetricReport).
template <int D>
MetricReport metric_report(const Mesh& mesh, std::span<const SymMat<D>> metrics);

/// Relative normalisation of a field before its metric is combined with others: divides the
/// Hessians by max |u| over the vertices, so that the tolerance of an L∞ metric is an error
/// relative to the field's magnitude and fields of different units weigh alike in an
/// intersection. Absolute normalisation is to leave the Hessians as they are. A field that is
/// zero everywhere is left unchanged. (The Lp metric for a complexity is invariant under scaling
/// of u, so this matters for --tolerance and for combining.)
template <int D>
void normalize_hessians_relative(std::span<SymMat<D>> hessians, std::span<const double> u);

/// Several metric fields on the same vertices combined by intersection at every vertex: the
/// metric that asks, in every direction, for the smallest size of any input (BOOK.md §2 "Several
/// fields"). Two fields: intersect() (simultaneous reduction); more: intersect_max_volume()
/// (order-independent). Throws InputError for an empty list, fields of different sizes or a
/// tensor that is not SPD.
template <int D>
std::vector<SymMat<D>> combine_metrics(std::span<const std::vector<SymMat<D>>> fields);

}  // namespace riemesh
