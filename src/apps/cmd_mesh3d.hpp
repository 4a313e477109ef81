#pragma once
// Meshing a volume from its closed boundary surface, for `riemesh mesh SURFACE.mesh -o VOL.mesh`
// (`riemesh mesh` calls this when its input is a surface in 3D).
#include <string>

#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// Tetrahedralises the closed surface `surface` read from `input` and writes the volume inside it
/// to `output`; prints one summary line unless quiet. Throws InputError naming `input` for a
/// surface with a defect (hole, non-manifold edge, inconsistent orientation, coincident
/// vertices) and for surface triangles missing from the Delaunay tetrahedralisation of its
/// vertices, since boundary recovery is not implemented yet; nothing is written then.
void mesh_volume_from_surface(const std::string& input, const Mesh& surface,
                              const std::string& output, bool quiet);

}  // namespace riemesh::cli
