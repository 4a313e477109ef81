#pragma once
// Constrained boundary recovery in 2D (BOOK.md §4: boundary recovery, then exterior removal):
// each given edge is made an edge of a Delaunay triangulation by edge flips only — no Steiner
// point — and the triangulation is then made constrained Delaunay by Lawson flips of the edges
// that are not constraints.
//
// Edge recovery follows Sloan ("A fast algorithm for generating constrained Delaunay
// triangulations", Computers & Structures 47, 1993): list the edges crossed by the segment, then
// flip them in turn, each only when its quadrilateral is strictly convex, putting back in the list
// the new edges that still cross. All orientation and in-circle tests use the exact predicates.
#include <cstdint>
#include <span>
#include <vector>

#include "generate/delaunay2d.hpp"

namespace riemesh {

/// Recovers the edges (2 vertex ids of t each; input points, not super-triangle vertices; no
/// repeated edge) in t, then flips the other edges until t is constrained Delaunay. Returns, per
/// half-edge 3·tri + slot of t, the index of the constraint it lies on, or kNoId.
/// Throws InputError when two edges cross or a vertex lies inside an edge, naming the edges
/// (1-based) and the place.
std::vector<Id> recover_edges(Triangulation2d& t, std::span<const Id> edges);

/// The key of an undirected edge {a, b} (both ≥ 0).
inline std::uint64_t edge_key(Id a, Id b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b);
  const auto hi = static_cast<std::uint64_t>(a < b ? b : a);
  return hi << 32 | lo;
}

}  // namespace riemesh
