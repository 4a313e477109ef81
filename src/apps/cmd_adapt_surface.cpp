// The surface branch of `riemesh adapt` (adapt_surface.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/adapt_surface.hpp"
#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "io/sol.hpp"
#include "metric/metric.hpp"

namespace riemesh::cli {
namespace {

/// The metric of a .sol file on the surface: a symmetric 3x3 tensor (m11 m12 m22 m13 m23 m33)
/// or a size per vertex (as MMG accepts).
std::vector<SymMat3> load_surface_metric(const std::string& path, const Mesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  for (const Field& f : read_sol(path, mesh)) {
    std::vector<SymMat3> out(nv);
    if (f.kind == FieldKind::kSymTensor) {
      for (std::size_t v = 0; v < nv; ++v) {
        for (int k = 0; k < 6; ++k) out[v].c[k] = f.values[6 * v + k];
        require_metric(out[v], path + ": vertex " + std::to_string(v + 1));
      }
      return out;
    }
    if (f.kind == FieldKind::kScalar) {
      for (std::size_t v = 0; v < nv; ++v) {
        const double h = f.values[v];
        if (!(h > 0.0) || !std::isfinite(h))
          throw InputError(path + ": size at vertex " + std::to_string(v + 1) +
                           " is not a positive number");
        out[v] = isotropic_metric<3>(h);
      }
      return out;
    }
  }
  throw InputError(path + ": no scalar or symmetric tensor field in SolAtVertices");
}

}  // namespace

void run_adapt_surface(const SurfaceAdaptArgs& args, const Mesh& mesh) {
  const auto start = std::chrono::steady_clock::now();
  SurfaceAdaptOptions options = args.options;
  if (!args.metric.empty()) options.metric = load_surface_metric(args.metric, mesh);
  SurfaceAdaptReport r;
  const Mesh out = adapt_surface(mesh, options, &r);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_mesh(out, args.output);
  if (args.quiet) return;
  std::fprintf(stderr,
               "riemesh: surface %zu -> %zu triangles, %zu vertices (%d cycles: %zu splits, %zu "
               "collapses, %zu swaps, %zu moves); %zu feature edges and %zu corners in the "
               "input; quality min %.3f mean %.3f; %.2fs\n",
               mesh.num_triangles(), out.num_triangles(), out.num_vertices(), r.cycles, r.splits,
               r.collapses, r.swaps, r.moves, r.input_feature_edges, r.input_corners, r.q_min,
               r.q_mean, seconds);
}

}  // namespace riemesh::cli
