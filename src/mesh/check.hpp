#pragma once
// Validity checks of a mesh: array sizes, ids, orientation, conformity, boundary closure and
// manifoldness, consistency of the listed boundary entities with the elements. The result is a
// report (no printing, no exceptions for an invalid mesh): one issue per category found, with a
// count and the first example in id order.
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

enum class CheckCategory {
  kArraySize,     // an array's size does not match its entity count (refs missing, ...)
  kIdOutOfRange,  // a vertex id outside [0, num_vertices)
  kNonFiniteCoordinate,
  kRepeatedVertex,           // an element, triangle or edge using the same vertex twice
  kUnusedVertex,             // a vertex of no element
  kInvertedElement,          // negative signed area (2D) or volume (3D) beyond the tolerance
  kZeroMeasureElement,       // |measure| <= kMeasureTolerance · (longest edge)^d
  kDuplicateElement,         // an element with the same vertex set as an earlier one
  kNonManifoldFace,          // a face (edge in 2D / on surfaces) shared by more than two elements
  kInconsistentOrientation,  // surface: two neighbours traverse their common edge the same way
  kOverlappingElements,      // planar: two positive neighbours traverse their common edge the
                             // same way (the mesh folds over itself there)
  kOpenBoundary,             // volume: a boundary edge on one boundary face only; edges-only
                             // mesh: a vertex on one edge
  kNonManifoldBoundary,      // volume: boundary edge on > 2 boundary faces; 2D: a boundary
                             // vertex on an odd number of boundary edges (an even number above
                             // 2 is loops touching at a vertex: valid); edges-only meshes: a
                             // vertex on more than 2 edges
  kMissingBoundary,          // a boundary face (edge in 2D) of the elements not listed
  kOrphanEntity,             // a listed triangle (edge) that is no face (edge) of any element
  kDuplicateBoundaryEntity,  // a triangle or edge listed twice
  kRegionsMeet,  // surface: an edge on 3 or more triangles, where the regions of a surface of
                 // several regions meet (a note, not an issue: `riemesh mesh` takes it)
};

/// Relative tolerance of the measure test: an element is degenerate when its signed measure is
/// at most this times its longest edge to the power d (a regular tet has 0.118 L³), i.e. about
/// a thousand times the rounding error of the determinant.
inline constexpr double kMeasureTolerance = 1e-12;

enum class EntityKind { kNone, kVertex, kEdge, kTriangle, kTet };

/// One category of problem: how many entities have it and the first of them.
struct CheckIssue {
  CheckCategory category{};
  std::size_t count = 0;
  EntityKind entity = EntityKind::kNone;  // what `example` numbers
  Id example = kNoId;                     // kNoId when no single entity is to blame
  int local_face = -1;               // when the issue is about face local_face of element `example`
  std::array<double, 3> location{};  // centroid of the example (z = 0 in 2D)
};

struct CheckReport {
  std::vector<CheckIssue> issues;  // in CheckCategory order, one per category present
  /// Found but valid: edges where regions meet on a surface (kRegionsMeet) and, on such a
  /// surface, kInconsistentOrientation (an interface may face either way).
  std::vector<CheckIssue> notes;
  bool valid() const { return issues.empty(); }
  /// The number of entities with that problem, among the issues or the notes (0 when absent).
  std::size_t count(CheckCategory category) const;
  const CheckIssue* find(CheckCategory category) const;
};

/// A short name of a category ("inverted element", ...).
const char* to_string(CheckCategory category);

/// Checks a planar, surface or volume mesh (see CheckCategory for what is checked).
CheckReport check_mesh(const Mesh& mesh);

/// Vertices of the elements (tets, triangles, edges) at exactly the same coordinates: a seam
/// not merged. `first_a` < `first_b` is the pair with the smallest ids (kNoId when none).
struct CoincidentVertices {
  std::size_t pairs = 0;  ///< vertices at the place of an earlier one (a triple counts 2)
  Id first_a = kNoId, first_b = kNoId;
};
CoincidentVertices find_coincident_vertices(const Mesh& mesh);

/// Two counter-clockwise neighbours of a planar mesh that traverse their common edge the same
/// way: one lies over the other (kOverlappingElements). Triangle ids as in the array given.
struct PlanarFold {
  std::size_t triangle = 0, neighbour = 0;  ///< triangle < neighbour
  int edge = 0;  ///< the common edge, local edge of `triangle` (kTriEdge)
};

/// The first `most` folds of the planar triangles (3 ids each, counter-clockwise or not; `adj`
/// their face adjacency, build_face_adjacency), in triangle order: the test of check_mesh,
/// for the remeshers to refuse a folded input with.
std::vector<PlanarFold> planar_folds(std::span<const double> coords, std::span<const Id> triangles,
                                     const Adjacency& adj,
                                     std::size_t most = static_cast<std::size_t>(-1));

}  // namespace riemesh
