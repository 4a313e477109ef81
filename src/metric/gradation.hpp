#pragma once
// Gradation: bound the variation of a metric field along the edges of a mesh, a priori, by only
// ever shrinking sizes (BOOK.md §1 "Gradation"; Borouchaki, Hecht, Frey 1998; Alauzet 2010).
//
// The mesh enters as flat arrays: coords with D numbers per vertex, edges as vertex-id pairs
// (0-based); metrics (one per vertex) are modified in place. Edges are processed in the given
// order, so the result is deterministic.
#include <cstddef>
#include <cstdint>
#include <span>

#include "core/symmat.hpp"

namespace riemesh {

enum class GradationMode {
  kHVariation,  ///< size gradient v = (h_B − h_A)/|AB| <= threshold (α > 0)
  kHShock,      ///< H-shock c = (h_B/h_A)^{1/L} <= threshold (β > 1)
  kGrowth,  ///< metric-space growth M_B → η² M_B, η = (1 + ℓ_{M_B}(AB) ln β)⁻¹, intersected
  /// Physical-space growth: each principal size of M_B grows by |AB| ln β along its own
  /// direction (Alauzet 2010's mixed space), then intersected. Unlike kGrowth it does not
  /// shrink the long sizes of a smooth field whose directions turn (polar fields), because the
  /// small sizes grow additively instead of by a common factor.
  kGrowthPhysical,
};

struct GradationOptions {
  GradationMode mode = GradationMode::kHShock;
  /// α for kHVariation, β for kHShock and kGrowth (MMG's hgrad 1.3 is a typical β).
  double threshold = 1.3;
  /// Sizes along each edge with directions kept (true), or the mean size det^{-1/(2D)} with a
  /// uniform rescaling of the metric (false).
  bool anisotropic = true;
  /// Cap on the sweeps over all edges.
  int max_passes = 200;
  /// Fill GradationReport's measures (a sweep over the edges before and one after; off where
  /// nobody reads them).
  bool measure = true;
  /// Throws InputError when a value is out of range.
  void validate() const;
};

struct GradationReport {
  int passes = 0;          ///< sweeps over the edges, including the final one that changed nothing
  bool converged = false;  ///< the last sweep changed no size (by more than 1e-9 relative)
  std::size_t modified_vertices = 0;  ///< vertices whose metric changed
  /// Max H-variation (kHVariation) or max H-shock (other modes) over the edges, before and after
  /// (0 when GradationOptions::measure is off).
  double measure_before = 0.0, measure_after = 0.0;
};

/// Gradates `metrics` in place along `edges` (BOOK.md §1 "Gradation"). Sizes only shrink. Throws
/// InputError for malformed arrays, zero-length edges, non-SPD metrics or bad options.
template <int D>
GradationReport gradate(std::span<const double> coords, std::span<const int32_t> edges,
                        std::span<SymMat<D>> metrics, const GradationOptions& options);

/// Max over edges of the H-variation |h_B − h_A| / |AB|; sizes are the sizes along the edge
/// 1/‖u‖_M (anisotropic) or det(M)^{-1/(2D)} (isotropic). 0 for a uniform field.
template <int D>
double max_h_variation(std::span<const double> coords, std::span<const int32_t> edges,
                       std::span<const SymMat<D>> metrics, bool anisotropic);

/// Max over edges of the H-shock c = (h_max/h_min)^{1/L}, L the edge length under geometric size
/// interpolation; sizes as in max_h_variation. 1 for a uniform field.
template <int D>
double max_h_shock(std::span<const double> coords, std::span<const int32_t> edges,
                   std::span<const SymMat<D>> metrics, bool anisotropic);

}  // namespace riemesh
