#pragma once
// Self-intersections of a triangle surface: pairs of triangles that meet other than along what
// they share (issue #6: a remeshed surface must not intersect itself).
#include <cstddef>

#include "mesh/mesh.hpp"

namespace riemesh {

struct SelfIntersections {
  std::size_t pairs = 0;             ///< intersecting pairs found (up to the cap)
  Id first_a = kNoId, first_b = kNoId;  ///< the first pair, in triangle order
};

/// Pairs of triangles of a 3D mesh that intersect: triangles with no common vertex that touch
/// or cross (an edge of one meets the other), and triangles with one common vertex that meet
/// elsewhere than at it. Decided exactly (robust orient3d signs, no tolerance: nearly coplanar
/// neighbours, as remeshed surfaces have many, are neither missed nor reported by rounding).
/// Triangles sharing an edge are not tested, nor are coplanar overlaps (an edge lying in the
/// other triangle's plane never counts): the test finds crossings and folds through the
/// surface, which is what remeshing can introduce. With `coplanar`, triangles in one plane whose
/// interiors overlap count too (whatever they share: two triangulations of one face, a
/// triangle folded onto its neighbour), as meshing a volume from the surface needs. Candidate
/// pairs come from an AABB tree; stops after `max_pairs`. Throws InputError for a mesh that is
/// not 3D.
SelfIntersections find_self_intersections(const Mesh& mesh, std::size_t max_pairs = 1000,
                                          bool coplanar = false);

}  // namespace riemesh
