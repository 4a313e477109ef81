#pragma once
// Field points for a triangulated planar domain (BOOK.md §4: "field points created along edges at
// unit metric length"): rounds of candidate points placed at unit metric spacing along every
// edge longer than √2 in the metric, each inserted by constrained Bowyer–Watson (the cavity never
// crosses a boundary or interface edge) unless it would come closer than 1/√2 to a vertex, or 1/2
// to a boundary edge, measured in its own metric. The cavity is chosen in the candidate's metric
// (the anisotropic Delaunay kernel, BOOK.md §4: circumcircles measured in that metric), falling
// back to the Euclidean one when the point does not see the whole metric cavity; isotropic
// metrics decide with the exact Euclidean test. The nearest vertex of a Delaunay insertion is on
// its cavity's border, so that check is local. Rounds stop when no point is added.
//
// The result is a Delaunay-like mesh with roughly unit edges, a good start for the optimiser
// (adapt2d), which on the boundary-only triangulation (long needle triangles) can stall.
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "metric/interpolation.hpp"

namespace riemesh {

struct FieldPointStats {
  int rounds = 0;
  std::size_t inserted = 0, rejected = 0;
};

/// Adds field points inside the triangles of `mesh` (dim 2, counter-clockwise triangles; its
/// Edges are kept as they are), appending their metrics — interpolated along the edge that
/// created them with `scheme` — to `metrics` (one per vertex). Deterministic.
FieldPointStats insert_field_points2d(Mesh& mesh, std::vector<SymMat2>& metrics,
                                      InterpScheme scheme, int max_rounds = 60);

}  // namespace riemesh
