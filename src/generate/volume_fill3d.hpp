#pragma once
// Interior points of a volume meshed from its boundary (issue #8, 3D): the tetrahedra of the
// recovered boundary join surface points only; here they are filled with points at unit spacing
// of an isotropic size field and optimised by the 3D remesher with the boundary kept as it is
// (adapt3d with keep_surface: edge splits create the interior points, then collapses, swaps,
// smoothing and sliver removal).
#include <vector>

#include "mesh/mesh.hpp"
#include "remesh/adapt3d.hpp"

namespace riemesh {

/// The size at each vertex from the boundary: the mean length of the boundary-triangle edges at
/// it (vertices on no boundary triangle: the mean over all boundary edges).
std::vector<double> boundary_sizes(const Mesh& volume);

/// Fills `volume` (tetrahedra and boundary triangles, e.g. recover_volume's) with interior points
/// for the size hsiz (> 0) or, when hsiz == 0, the boundary sizes interpolated inside; the
/// boundary triangles and their vertices are kept. options.keep_surface is forced on; the other
/// options are adapt3d's (gradation, passes). Deterministic.
Adapt3dResult fill_volume(Mesh&& volume, double hsiz, Adapt3dOptions options,
                          const PassCallback& on_pass = {});

}  // namespace riemesh
