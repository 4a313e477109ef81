#pragma once
// A first surface remesher (issue #6): local operators on a triangulated surface in 3D driven by
// a metric field — the geometric metric from the curvature and `hausd` (surface_metric.hpp),
// isotropic (its smallest principal size) or anisotropic, capped by `hsiz` — with every new or
// moved point placed on the input's smooth reconstruction (surface_projection.hpp). Lengths and
// qualities below are measured in the metric (the mean of the vertex metrics of a triangle).
//
// Operators, in passes of independent operations (each pass rebuilds the adjacency):
//   split    edges longer than √2 in the metric; the new point on the reconstruction (on the
//            feature curve for a feature edge);
//   collapse edges shorter than 1/√2, a vertex into a neighbour: corners never move, a ridge
//            vertex only along its feature line, link condition (no topology change), no
//            triangle turned by more than 30° nor below quality min(0.3, ½ the old minimum), no
//            new edge longer than √2, and the removed vertex and the new triangles within
//            hausd of the input;
//   swap     non-feature edges when the smallest quality of the pair grows by 5% and the new
//            pair stays within hausd of the old edge and of the input (dihedral check);
//   smooth   vertices to the mean of their neighbours (ridge vertices: of their two line
//            neighbours), placed back on the reconstruction, kept when the smallest quality of
//            the ball grows and the triangles turn by less than 30°.
// Every operation is checked both ways against the input, on (at least) the points that
// `riemesh distance` samples by default (mesh/distance.hpp, lattice of order 4 on every
// triangle; on input triangles long for the sizes, a finer lattice that contains it:
// SurfaceProjection::lattice_orders): the input's lattice points within 0.95 hausd of the old
// triangles stay within 0.95 hausd of the new ones, and the new triangles' lattice points are
// within 0.95 hausd of the input. By induction the sampled two-sided distance of the output
// stays below 0.95 hausd (a denser sampling can find more: the bound holds at those points, not
// everywhere).
// Refs of triangles and feature edges are carried (a patch keeps its ref), corners never move.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "remesh/surface_features.hpp"

namespace riemesh {

/// What one cycle of the surface remesher did (its own counts, not running totals).
struct SurfaceCycle {
  int cycle = 0;  ///< 1-based; 0 for the final touch (splits of bad triangles, swaps, moves)
  std::size_t triangles = 0, vertices = 0;  ///< after the cycle
  std::size_t splits = 0, collapses = 0, swaps = 0, moves = 0;
};

struct SurfaceAdaptOptions {
  double hausd = 0.01;  ///< chordal tolerance (absolute), as mmgs's -hausd
  double hsiz = 0.0;    ///< uniform size cap (0: only the geometric size)
  double hmin = 0.0;    ///< <= 0: hausd (bounds the geometric sizes only); > 0: every size,
                        ///< --hsiz and the user metric's too (clipped, with a note)
  double hmax = 0.0;    ///< <= 0: the bounding-box diagonal
  double hgrad = 1.3;   ///< H-shock gradation of the sizes (<= 0: none)
  /// Anisotropic geometric metric (sizes αρ1 along w1, up to βρ2 along w2; BOOK.md §1), lengths
  /// and qualities measured in it; false: the smallest principal size in every direction.
  bool anisotropic = false;
  double beta_fraction = 1.0;  ///< with anisotropic: 0 isotropic .. 1 the full β
  /// A user metric per input vertex (SPD), intersected with the geometric metric and measured
  /// along the surface (its restriction to the tangent plane): the remesher follows the
  /// smallest size of that (isotropic). Empty: none.
  std::vector<SymMat3> metric;
  FeatureOptions features;
  int max_cycles = 12;  ///< split/collapse/swap/smooth cycles
  bool insert = true, swap = true, move = true;
  /// Called after each cycle and after the final touch (progress lines); may be empty.
  std::function<void(const SurfaceCycle&)> on_cycle;
  void validate() const;  ///< throws InputError for a bad value
};

struct SurfaceAdaptReport {
  std::size_t splits = 0, collapses = 0, swaps = 0, moves = 0;
  int cycles = 0;
  std::size_t input_corners = 0, input_feature_edges = 0;
  double q_min = 0.0, q_mean = 0.0;  ///< Euclidean triangle quality 4√3 A / Σ l² of the output
  /// Sizes clipped to --hmin or --hmax, as Adapt2dReport::notes (one line each, no prefix).
  std::vector<std::string> notes;
};

/// Remeshes a surface mesh (3D triangles, no tetrahedra). The output has Triangles with the
/// input refs, its feature lines as Edges (tagged Ridges where found by angle) and Corners.
/// Throws InputError for a mesh that is not a surface or bad options.
Mesh adapt_surface(const Mesh& input, const SurfaceAdaptOptions& options,
                   SurfaceAdaptReport* report = nullptr);

/// Euclidean quality of a triangle in 3D: 4√3 area / Σ squared edge lengths (1 equilateral).
double triangle_quality(const double* a, const double* b, const double* c);

}  // namespace riemesh
