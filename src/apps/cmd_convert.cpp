// `riemesh convert IN OUT`: mesh format conversion by extension, written atomically.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
#include "generate/domain2d.hpp"
#include "io/atomic_file.hpp"
#include "io/mesh_file.hpp"
#include "mesh/hilbert.hpp"

namespace riemesh::cli {
namespace {

struct ConvertArgs {
  std::string in, out;
  bool binary = false;
  bool hilbert = false;
  bool boundary = false;
};

void run_convert(const ConvertArgs& a) {
  // An unknown output extension fails before any work; --binary applies to .msh only (.meshb is
  // the binary Medit file; it was accepted and ignored).
  if (mesh_format(a.out) != MeshFormat::kGmsh && a.binary)
    throw InputError("--binary applies to .msh output (for binary Medit, write .meshb)");
  require_writable(a.out);
  Mesh mesh = load_mesh(a.in);
  if (a.boundary) mesh = extract_boundary2d(mesh);
  if (a.hilbert) renumber_hilbert(mesh);
  MeshWriteOptions o;
  o.gmsh_binary = a.binary;
  write_mesh(mesh, a.out, o);
  std::printf("%s: %zu vertices, %zu triangles, %zu tetrahedra, %zu edges\n", a.out.c_str(),
              mesh.num_vertices(), mesh.num_triangles(), mesh.num_tets(), mesh.num_edges());
}

}  // namespace

void register_convert(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "convert",
      "Convert a mesh by extension: reads .mesh .meshb .msh, writes .mesh .meshb .msh .vtu");
  auto a = std::make_shared<ConvertArgs>();
  cmd->add_option("in", a->in, "Input mesh")->required();
  cmd->add_option("out", a->out, "Output mesh (written atomically)")->required();
  cmd->add_flag("--binary", a->binary, "Write .msh files in binary");
  cmd->add_flag("--hilbert", a->hilbert,
                "Renumber vertices and elements along a Hilbert curve (memory locality)");
  cmd->add_flag("--boundary", a->boundary,
                "Keep only the boundary of a planar mesh: its Edges (or its triangles' border), "
                "turned so that the domain is on their left (input for `riemesh mesh`)");
  cmd->callback([a] { run_convert(*a); });
}

}  // namespace riemesh::cli
