#pragma once
// 3D anisotropic remeshing to a metric field (issue #7, first core): a tetrahedral volume and one
// metric per vertex in, a unit mesh for that field out, boundary refs kept.
//
// Method (BOOK.md §1, §3, §7), as adapt2d: metrics clipped to [hmin, hmax] and graded; the input
// is the background mesh (new vertices take the log-Euclidean interpolation of the INPUT field);
// passes of edge splits (> √2, at ⌊n/2⌋/n of the metric length), collapses (< 0.9), edge and face
// swaps on bad tets, smoothing and, last, sliver removal (sliver3d.hpp), until the lengths
// settle.
//
// Boundary: a boundary patch (the listed faces of one ref) that is planar is remeshed with the
// volume: its edges are split at points of the plane, its vertices collapse and move in the
// plane, and vertices on the line where two planar patches meet collapse along that line. A
// curved patch is remeshed on the smooth reconstruction of the input surface within hausd
// (boundary3d.hpp). A planar interface between two subdomains (listed faces between two tets) is
// remeshed as a planar patch, its faces listed on both sides; curved interfaces, corners and
// vertices tagged corner or required are kept as given, as is the whole surface with
// keep_surface.
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh {

/// The 2D options (hausd and angle for the curved patches) plus the surface switch.
struct Adapt3dOptions : Adapt2dOptions {
  bool keep_surface = false;  ///< --nosurf: no boundary vertex moves, goes or is added
  /// Staged approach to the target (metric/approach.hpp): the largest size ratio asked of the
  /// mesh from one stage to the next; 0: the target at once. A mesh already near its target
  /// (no input edge longer than this in the target metric) has one stage.
  double approach_growth = 4.0;
  /// The original geometry (not owned; null: the input's): its listed triangles with the refs of
  /// the input's curved patches are the surface those patches are reconstructed from, placed on
  /// and kept within hausd of, instead of the input's own boundary. For adaptation loops: each
  /// run then stays within hausd of the original, not of the previous run's boundary. The input's
  /// boundary should lie within hausd of it (a previous run with the same geometry does).
  const Mesh* geometry = nullptr;
};

struct Adapt3dResult {
  Mesh mesh;                     ///< the adapted mesh (tetrahedra, listed boundary triangles)
  std::vector<SymMat3> metrics;  ///< the metric at each output vertex
  Adapt2dReport report;          ///< PassStats::triangles counts tetrahedra
};

/// Adapts a tetrahedral mesh to the metric field given at its vertices. Throws InputError for a
/// mesh without tetrahedra, a non-positive tet, or a metric that is not SPD or finite (naming
/// the vertex). Deterministic.
Adapt3dResult adapt3d(const Mesh& input, std::span<const SymMat3> metrics,
                      const Adapt3dOptions& options, const PassCallback& on_pass = {});

/// The same, taking over the input mesh (moved from; unspecified afterwards): saves the copy
/// the remesher renumbers, when the caller needs the input no more (memory, issue #7).
Adapt3dResult adapt3d(Mesh&& input, std::span<const SymMat3> metrics,
                      const Adapt3dOptions& options, const PassCallback& on_pass = {});

/// The same, taking over the metrics too (moved from): they are renumbered and prepared in
/// their own storage, which the background mesh then keeps (memory, issue #7).
Adapt3dResult adapt3d(Mesh&& input, std::vector<SymMat3>&& metrics,
                      const Adapt3dOptions& options, const PassCallback& on_pass = {});

}  // namespace riemesh
