// `riemesh mesh3d SURFACE.mesh -o VOL.mesh`: Delaunay volume of a closed surface (see
// cmd_mesh3d.hpp); boundary recovery is not implemented, so only surfaces whose triangles are all
// Delaunay faces of their vertices can be meshed.
#include "apps/cmd_mesh3d.hpp"

#include <cstdio>
#include <memory>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
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

namespace {
struct Mesh3dArgs {
  std::string input, output;
  bool quiet = false;
};
}  // namespace

void register_mesh3d(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "mesh3d",
      "Tetrahedralise the volume bounded by a closed surface (Delaunay of its vertices; no "
      "boundary recovery yet: fails when a surface triangle is not a Delaunay face)");
  auto a = std::make_shared<Mesh3dArgs>();
  cmd->add_option("surface", a->input, "Closed, manifold, oriented surface (.mesh, .meshb, .msh)")
      ->required();
  cmd->add_option("-o,--output", a->output, "Volume mesh to write")->required();
  cmd->add_flag("-q,--quiet", a->quiet, "No summary line");
  cmd->callback([a] {
    mesh_volume_from_surface(a->input, load_mesh(a->input), a->output, a->quiet);
  });
}

}  // namespace riemesh::cli
