// `riemesh mesh SURFACE.mesh -o VOL.mesh`: Delaunay volume of a closed surface (see
// cmd_mesh3d.hpp); boundary recovery is not implemented, so only surfaces whose triangles are all
// Delaunay faces of their vertices can be meshed.
#include "apps/cmd_mesh3d.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "generate/surface_delaunay3d.hpp"
#include "io/mesh_file.hpp"

namespace riemesh::cli {

void mesh_volume_from_surface(const std::string& input, const Mesh& surface,
                              const std::string& output, bool quiet) {
  if (surface.dim != 3 || !surface.tets.empty() || surface.triangles.empty())
    throw InputError(input + ": not a surface (3D triangles without tetrahedra)");
  SurfaceDelaunay d;
  try {
    d = delaunay_of_surface(surface);
  } catch (const InputError& e) {
    std::string msg = input;
    msg += ": ";
    msg += e.what();
    throw InputError(msg);
  }
  if (!d.conforming()) {
    std::string msg = input;
    msg += ": ";
    msg += std::to_string(d.missing_faces);
    msg += " of ";
    msg += std::to_string(d.num_faces);
    msg += " boundary faces (";
    msg += std::to_string(d.missing_edges);
    msg += " of ";
    msg += std::to_string(d.num_edges);
    msg += " edges) are not in the Delaunay mesh; 3D boundary recovery is not implemented yet";
    throw InputError(msg);
  }
  const Mesh volume = volume_inside(surface, d);
  write_mesh(volume, output);
  if (!quiet)
    std::printf("%s: %zu vertices, %zu tetrahedra, %zu boundary triangles (Delaunay of the surface "
                "vertices: %zu tetrahedra, no Steiner point)\n",
                output.c_str(), volume.num_vertices(), volume.num_tets(), volume.num_triangles(),
                d.tz.num_tets());
}

}  // namespace riemesh::cli
