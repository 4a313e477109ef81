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
  double predicted_vertices = 0.0;  ///< ≈ C(M) in 2D (a unit mesh's vertex count)
  double predicted_elements = 0.0;  ///< (4/√3) C(M) triangles in 2D; 6√2 C(M) tetrahedra in 3D
};

/// The metric at every vertex from the vertex Hessians of a field: |H| (absolute eigenvalues) made
/// SPD, scaled as the options say, clipped to [hmin, hmax] and aniso_max. The Lp normalisation
/// integrates det|H|^{p/(2p+D)} over the mesh (P1 quadrature per element).
template <int D>
std::vector<SymMat<D>> hessian_metric(const Mesh& mesh, std::span<const SymMat<D>> hessians,
                                      const HessianMetricOptions& options,
                                      MetricReport* report = nullptr);

/// ∫ sqrt(det M) over the mesh of a vertex metric field (interpolated log-Euclidean per element).
template <int D>
double field_complexity(const Mesh& mesh, std::span<const SymMat<D>> metrics);

}  // namespace riemesh
