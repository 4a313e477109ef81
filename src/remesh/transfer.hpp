#pragma once
// Solution transfer between meshes of the same domain (BOOK.md §8): P1 interpolation of vertex
// fields, each new vertex located in the old mesh by walking, and the conservative transfer of
// P0 (per-element) fields by intersection of old and new elements.
#include <cstddef>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

/// The vertex fields of `from` (one value set per vertex of `from`) interpolated linearly at the
/// vertices of `to`; vertices outside `from` (a curved boundary) take the values at their
/// projection. 2D triangle meshes and tetrahedral volumes. Throws InputError for fields whose size
/// does not match `from` or meshes of different kinds.
/// What a P1 transfer met: the new vertices outside the old mesh and their largest distance to
/// it (a curved boundary remeshed: small; another domain: as large as the gap).
struct P1TransferReport {
  std::size_t outside = 0;
  double farthest = 0.0;
};

std::vector<Field> transfer_p1(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                               P1TransferReport* report = nullptr);

/// What a conservative transfer measured (measures are areas in 2D, volumes in 3D). Integrals are
/// Σ value × measure per field component (fields in order, components in order).
struct P0TransferReport {
  double old_measure = 0.0;      ///< Σ |old element|
  double new_measure = 0.0;      ///< Σ |new element|
  double overlap_measure = 0.0;  ///< Σ |old ∩ new| over all pairs
  /// Parts of new elements outside the old mesh (new_measure − overlap, >= 0 up to round-off).
  double uncovered_new = 0.0;
  /// Parts of old elements outside the new mesh (old_measure − overlap): their mass is lost.
  double uncovered_old = 0.0;
  /// New elements that overlap no old element; they take the value of the nearest old element.
  std::size_t unmatched_elements = 0;
  std::size_t pairs = 0;  ///< (old, new) pairs with a positive overlap
  std::vector<double> old_integral, new_integral;
};

/// Conservative transfer of per-element (P0) fields of `from` (one value set per triangle of a
/// planar mesh, or per tetrahedron of a volume) to the elements of `to`: each new element gets
///   v_new = Σ_old v_old |old ∩ new| / Σ_old |old ∩ new|,
/// the intersections computed exactly by convex clipping (remesh/polygon_clip.hpp,
/// remesh/polyhedron_clip.hpp: exact up to round-off), candidates
/// found by locating the new element's centroid in the old mesh (walk) and then crossing to
/// neighbours while they overlap, so the cost is linear in the number of overlapping pairs. When
/// both meshes cover the same domain, Σ v_new |new| = Σ v_old |old| to round-off and constants are
/// kept; otherwise the mean is over the covered part of each new element (constants still kept)
/// and the report says how much area, hence mass, was not matched. Throws InputError for fields
/// whose size does not match `from`, or meshes of different kinds or of another kind (surfaces).
std::vector<Field> transfer_p0(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                               P0TransferReport* report = nullptr);

}  // namespace riemesh
