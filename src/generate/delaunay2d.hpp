#pragma once
// Delaunay triangulation of points in the plane (BOOK.md §4, Delaunay kernel): Bowyer–Watson
// insertion inside a super-triangle. For each point: a visibility walk from the last triangle
// created finds the triangle containing it; the cavity is the connected set of triangles whose
// circumcircle contains the point strictly (exact incircle, core/predicates.hpp); it is replaced by
// the fan joining the point to the cavity's boundary. Points are inserted in BRIO order (biased
// randomised rounds, each along the Hilbert curve: Amenta, Choi, Rote 2003) so that walks are short
// and the expected cost stays linear-ish whatever the input order.
//
// With exact predicates the result is a Delaunay triangulation of the points plus the three
// super-triangle vertices; cocircular points are triangulated in one of the valid ways
// (deterministically). Triangles touching the super-triangle are kept (boundary recovery works in
// the whole super-triangle); delaunay_triangles() drops them. Away from the convex hull the
// triangles are those of the Delaunay triangulation of the points alone; near the hull a few hull
// edges may be missing (the super-triangle is finite).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "generate/huge_page_allocator.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

enum class InsertionOrder {
  kBrio,     ///< biased randomised rounds, Hilbert-sorted in each (default)
  kHilbert,  ///< along the Hilbert curve (hilbert_order_coarse), in coarse_first's rounds
  kAsGiven,  ///< the input order
  /// BRIO's rounds over the input order, kept inside each round (brio_rounds): for inputs
  /// already sorted along a space-filling curve, BRIO's work per point without its sort
  kRounds,
  /// Eightfold rounds of samples over the input order (coarse_first): for inputs already
  /// sorted along a space-filling curve
  kCoarseFirst,
};

/// Vertex or half-edge ids of a Triangulation2d: a vector that `resize` does not zero-fill (the
/// kernel writes every triangle it makes; NoFillAllocator).
using TriangleIds = std::vector<Id, NoFillAllocator<Id>>;

/// A triangulation of points in the plane covering a super-triangle.
struct Triangulation2d {
  /// 2 coordinates per vertex: the input points (same ids), then the super-triangle's 3 vertices.
  std::vector<double> xy;
  std::size_t num_points = 0;  ///< input points; super-triangle vertices are num_points + 0..2
  TriangleIds tri;             ///< 3 vertices per triangle, counter-clockwise
  /// 3 per triangle: across the edge opposite vertex i of t, the half-edge 3·t' + j of the
  /// neighbour t' (its edge opposite its vertex j); kNoId on the super-triangle's sides.
  TriangleIds nbr;
  /// For each input point, the vertex that represents it: itself, or an earlier input point at
  /// exactly the same place (duplicates are not inserted).
  std::vector<Id> representative;

  std::size_t num_triangles() const { return tri.size() / 3; }
  bool is_super(Id v) const { return v >= static_cast<Id>(num_points); }
};

/// The Delaunay triangulation of the points xy (2 doubles each, finite). Deterministic.
/// Throws InputError for a non-finite coordinate (naming the point), or for points spread so far
/// (|x| near the largest double) that the enclosing triangle would not be finite.
Triangulation2d delaunay2d(std::span<const double> xy, InsertionOrder order = InsertionOrder::kBrio);

/// The insertion order used by delaunay2d for kBrio: order[k] = the point inserted k-th.
std::vector<Id> brio_order(std::span<const double> xy);

/// BRIO's rounds over a sequence of the point ids 0..n-1 (each once): every point's round from
/// a fixed coin flip of its id — the last round about half the points, the one before a quarter,
/// ... down to a first round of about 1000 — and the sequence's order kept inside each round.
/// Deterministic. brio_order is this over the Hilbert order; the kRounds orders of both kernels
/// over the given order.
std::vector<Id> brio_rounds(const std::vector<Id>& along);

/// Rounds over `along`, each in its order: first the ids at positions divisible by 8^J (J the
/// largest with at least 64 of them), then those divisible by 8^(J−1) and not yet taken, ...,
/// then the rest. Points sorted along a space-filling curve and inserted as given each land on
/// the frontier of the region triangulated so far, whose triangles reach far ahead: their
/// cavities are half as large again as in a finished triangulation (2D: 5.8 triangles instead of
/// about 4, 12.6 in-circle tests per point). Each round's triangulation covers the domain with
/// triangles of a few spacings of the next, so its points meet no long ones (2D: 9.1 tests per
/// point; 3D: 43 insphere tests instead of 59), and the rounds grow eightfold, so the sweeps over
/// memory add up to 1.14 times one (BRIO's halving rounds: twice). Deterministic (no keys, no
/// coin flips). 2D, 1 M points: ratio 8 takes 22% fewer instructions than as given; 2 (every
/// other point) or a single sample of every 16th–64th point fewer still than 1 but more than 8.
std::vector<Id> coarse_first(const std::vector<Id>& along);

/// The triangles not touching the super-triangle (3 vertex ids each, counter-clockwise).
std::vector<Id> delaunay_triangles(const Triangulation2d& t);

}  // namespace riemesh
