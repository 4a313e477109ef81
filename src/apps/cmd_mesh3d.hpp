#pragma once
// Meshing a volume from its closed boundary surface, for `riemesh mesh SURFACE.mesh -o VOL.mesh`
// (`riemesh mesh` calls this when its input is a surface in 3D).
#include <string>

#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// Tetrahedralises the closed surface `surface` read from `input` and writes the volume inside it
/// to `output`; prints one summary line unless quiet. Throws InputError naming `input` for a
/// surface with a defect (hole, non-manifold edge, inconsistent orientation, coincident
/// vertices) and when boundary recovery gives up (Steiner cap, e.g. a self-intersecting
/// surface); nothing is written then. The summary line reports the Steiner points.
void mesh_volume_from_surface(const std::string& input, const Mesh& surface,
                              const std::string& output, bool quiet);

}  // namespace riemesh::cli
