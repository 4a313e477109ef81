#pragma once
// 2D anisotropic remeshing to a metric field (issue #4): a planar triangle mesh and one metric per
// vertex in, a unit mesh for that field out, the domain's boundary curves, refs and corners kept.
//
// Method (BOOK.md §1, §3, §7): metrics are clipped to [hmin, hmax] and graded on the input edges;
// the input mesh becomes the background mesh (new vertices take the log-Euclidean interpolation of
// the INPUT field); boundary and interface curves are reconstructed (cubic, see
// boundary_curves.hpp) and boundary vertices are always placed on that reconstruction, with the
// metric tightened along the curve so that chords stay within hausd. Passes then alternate edge
// splits (metric length > √2), collapses (< 1/√2), swaps and smoothing until the lengths settle.
#include <cstddef>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "metric/interpolation.hpp"

namespace riemesh {

/// The smallest --hausd, relative to the domain's bounding-box diagonal: below it adapt2d
/// refuses the run (chords that close ask for millions of boundary vertices).
inline constexpr double kSmallestHausd = 1e-9;

/// The hausd to use when none is given: the default 0.01 (MMG's, absolute), raised to the
/// smallest allowed, kSmallestHausd times the bounding-box diagonal, on domains over 1e7
/// across (the default was refused there, about an option never given: QA hunt 5 F9).
double default_hausd(const Mesh& domain);

struct Adapt2dOptions {
  double hmin = 0.0;                                         ///< smallest size (0: none)
  double hmax = std::numeric_limits<double>::infinity();     ///< largest size (inf: none)
  double hgrad = 1.3;       ///< metric growth bound between neighbours (MMG's -hgrad); 0: off
  double hausd = 0.01;      ///< largest distance between boundary chords and the curve
  double angle_deg = 45.0;  ///< corner when the boundary turns by more than this (MMG's -ar)
  bool detect_angles = true;  ///< false: corners only from tags and refs (MMG's -nr)
  bool insert = true;         ///< split and collapse (false: MMG's -noinsert)
  bool swap = true;           ///< edge swaps (false: -noswap)
  bool move = true;           ///< vertex smoothing (false: -nomove)
  InterpScheme interp = InterpScheme::kLogEuclidean;  ///< metric interpolation for new vertices
  int max_passes = 15;        ///< bound on the passes (each pass is itself bounded)
  /// Splits append their vertices at the end of the arrays, far in memory from their
  /// neighbours: when a split sweep leaves more than this many vertices (and a quarter of the
  /// mesh) created since the numbering last followed the space, they are renumbered along the
  /// Hilbert curve (cache locality; the sweeps' order, hence the result's details, follow the
  /// numbering). 0: the default, 16,384 vertices in 2D and 65,536 in 3D; SIZE_MAX: never.
  std::size_t renumber_after = 0;

  /// Throws InputError naming the option when a value is out of range or options contradict.
  void validate() const;
};

/// What one pass did and the state of the mesh after it.
struct PassStats {
  int pass = 0;
  int stage = 0, stages = 0;  ///< stage k of n of a staged approach (3D; n: the target); 0, 0: none
  long splits = 0, collapses = 0, swaps = 0, moves = 0;
  long rejected = 0;  ///< operations refused by their checks (not errors)
  std::size_t vertices = 0, triangles = 0;
  double len_min = 0, len_max = 0, len_mean = 0, len_in = 0;  ///< metric edge lengths
  double q_min = 0, q_mean = 0;                               ///< metric quality (1 = regular)
  double seconds = 0;
};

struct Adapt2dReport {
  std::vector<PassStats> passes;
  bool converged = false;
  /// Why the passes stopped without converging, with a place ("... near (x, y)"); empty if
  /// they converged.
  std::string stall_reason;
  double gradation_before = 0, gradation_after = 0;  ///< max growth factor over input edges
  /// Things the caller should tell the user, one line each (e.g. sizes clipped by hmin).
  std::vector<std::string> notes;
};

struct Adapt2dResult {
  Mesh mesh;                     ///< the adapted mesh (dim 2)
  std::vector<SymMat2> metrics;  ///< the metric at each output vertex
  Adapt2dReport report;
};

/// Called after each pass (for progress lines and -v statistics).
using PassCallback = std::function<void(const PassStats&)>;

/// Adapts a planar triangle mesh to the metric field given at its vertices. Throws InputError for
/// a mesh that is not planar, has no triangles, has a clockwise or degenerate triangle, or for a
/// metric that is not SPD or finite (naming the vertex). Deterministic.
Adapt2dResult adapt2d(const Mesh& input, std::span<const SymMat2> metrics,
                      const Adapt2dOptions& options, const PassCallback& on_pass = {});

/// The same, taking the mesh and metrics over: they are released (left empty) as soon as the
/// remesher has built its own structures, before the passes (peak memory of large runs).
Adapt2dResult adapt2d(Mesh&& input, std::vector<SymMat2>&& metrics, const Adapt2dOptions& options,
                      const PassCallback& on_pass = {});

}  // namespace riemesh
