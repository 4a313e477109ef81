// `riemesh transfer OLD.mesh OLD.sol NEW.mesh -o NEW.sol`: vertex fields carried to another mesh
// of the same domain by P1 interpolation (BOOK.md §8).
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
#include "core/error.hpp"
#include "io/sol.hpp"
#include "remesh/transfer.hpp"

namespace riemesh::cli {
namespace {

struct TransferArgs {
  std::string old_mesh, old_sol, new_mesh, output;
};

void run(const TransferArgs& a) {
  if (a.output.empty()) throw InputError("no output file: give -o NEW.sol");
  const Mesh from = load_mesh(a.old_mesh);
  require_measurable(from, a.old_mesh);
  const Mesh to = load_mesh(a.new_mesh);
  require_measurable(to, a.new_mesh);
  const std::vector<Field> fields = read_sol(a.old_sol, from);
  write_sol(a.output, transfer_p1(from, fields, to), to.dim);
}

}  // namespace

void register_transfer(CLI::App& app) {
  auto a = std::make_shared<TransferArgs>();
  auto* cmd = app.add_subcommand(
      "transfer", "Interpolate vertex fields from one mesh to another of the same domain (P1)");
  cmd->add_option("old_mesh", a->old_mesh, "Mesh the fields live on")->required();
  cmd->add_option("old_sol", a->old_sol, "Vertex fields (.sol/.solb)")->required();
  cmd->add_option("new_mesh", a->new_mesh, "Mesh to carry them to")->required();
  cmd->add_option("-o,--output", a->output, "Output fields (.sol/.solb)");
  cmd->footer(
      "Each new vertex is located in the old mesh by walking and takes the linear interpolant; "
      "vertices outside the old mesh (curved boundaries) take the value at their projection. "
      "Planar triangle meshes and tetrahedral volumes. Conservative transfer of P0 (element) "
      "fields is not implemented yet.");
  cmd->callback([a] { run(*a); });
}

}  // namespace riemesh::cli
