#pragma once
// Solution transfer between meshes of the same domain (BOOK.md §8): P1 interpolation of vertex
// fields, each new vertex located in the old mesh by walking.
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

/// The vertex fields of `from` (one value set per vertex of `from`) interpolated linearly at the
/// vertices of `to`; vertices outside `from` (a curved boundary) take the values at their
/// projection. 2D triangle meshes and tetrahedral volumes. Throws InputError for fields whose size
/// does not match `from` or meshes of different kinds.
std::vector<Field> transfer_p1(const Mesh& from, const std::vector<Field>& fields, const Mesh& to);

}  // namespace riemesh
