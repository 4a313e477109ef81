#pragma once
// What the surface adapter refuses in its input, before any work: a surface `riemesh check`
// calls invalid would come out invalid too (a flipped triangle spread to six edges, a seam not
// merged crossed the surface twenty times).
#include "mesh/mesh.hpp"

namespace riemesh {

/// Throws InputError naming the first defect: vertices at the same place (a seam not merged),
/// neighbours traversing their common edge the same way on a surface of one region (inconsistent
/// orientation; where regions meet, an interface may face either way), triangles that cross or
/// overlap (find_self_intersections, coplanar overlaps included).
void require_adaptable_surface(const Mesh& surface);

}  // namespace riemesh
