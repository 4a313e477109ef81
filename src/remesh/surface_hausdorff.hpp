#pragma once
// The Hausdorff checks of the surface operators (issue #6), shared by the surface remesher
// (surface_ops.cpp) and the curved boundaries of the 3D remesher (boundary3d.cpp): an operation
// replacing some triangles of a remeshed surface by others is accepted only when the new ones
// stay within hausd of the input surface, and the input stays within hausd of them.
#include <array>
#include <vector>

#include "core/vec.hpp"
#include "remesh/surface_projection.hpp"

namespace riemesh {

using Tri3 = std::array<Vec3, 3>;

/// The A -> B half: the input's check points (SurfaceProjection::check_points) that were within
/// hausd of the old triangles stay within hausd of the new ones (the new triangles cover the
/// same footprint, so a point the old ones covered is the new ones' business). Without it,
/// errors accumulate: each operation would be checked against the current mesh only.
/// Faster when old_t[i] and new_t[i] are the same triangle before and after (they share a box).
bool keeps_input_close(const SurfaceProjection& geo, double hausd, const std::vector<Tri3>& old_t,
                       const std::vector<Tri3>& new_t);

/// The B -> A half: the points of the order-4 lattice of each new triangle (corners excluded)
/// within hausd of the input polyhedron (`hint`: a nearby input triangle, or kNoId). `old_t`
/// (optional): the triangles replaced, when the caller knows that their lattice points passed
/// this check (or lie on the input): the points of an edge of theirs are not checked again.
bool new_triangles_close(const SurfaceProjection& geo, double hausd, const std::vector<Tri3>& new_t,
                         Id hint, const std::vector<Tri3>* old_t = nullptr);

}  // namespace riemesh
