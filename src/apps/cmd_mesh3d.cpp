// `riemesh mesh SURFACE.mesh -o VOL.mesh`: the volume inside a closed surface, its boundary
// recovered with Steiner points on the surface (see cmd_mesh3d.hpp and
// generate/boundary_recovery3d.hpp).
#include "apps/cmd_mesh3d.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "generate/boundary_recovery3d.hpp"
#include "io/mesh_file.hpp"

namespace riemesh::cli {

void mesh_volume_from_surface(const std::string& input, const Mesh& surface,
                              const std::string& output, bool quiet) {
  if (surface.dim != 3 || !surface.tets.empty() || surface.triangles.empty())
    throw InputError(input + ": not a surface (3D triangles without tetrahedra)");
  RecoveredVolume r;
  try {
    r = recover_volume(surface);
  } catch (const InputError& e) {
    std::string msg = input;
    msg += ": ";
    msg += e.what();
    throw InputError(msg);
  }
  write_mesh(r.volume, output);
  if (!quiet) {
    const BoundaryRecoveryStats& s = r.stats;
    std::printf("%s: %zu vertices, %zu tetrahedra, %zu boundary triangles; %zu Steiner points "
                "(%zu on edges, %zu in faces, %zu inside); Delaunay of the %zu surface vertices: "
                "%zu tetrahedra, %zu faces and %zu edges missing, recovered in %zu rounds\n",
                output.c_str(), r.volume.num_vertices(), r.volume.num_tets(),
                r.volume.num_triangles(), s.steiner(), s.steiner_on_edges, s.steiner_in_faces,
                s.steiner_inside, s.surface_vertices, s.delaunay_tets, s.missing_faces,
                s.missing_edges, s.rounds);
  }
}

}  // namespace riemesh::cli
