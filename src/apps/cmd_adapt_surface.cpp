// The surface branch of `riemesh adapt` (adapt_surface.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/adapt_surface.hpp"
#include "apps/field_args.hpp"
#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "io/sol.hpp"
#include "metric/metric.hpp"

namespace riemesh::cli {
void run_adapt_surface(const SurfaceAdaptArgs& args, const Mesh& mesh) {
  const auto start = std::chrono::steady_clock::now();
  SurfaceAdaptOptions options = args.options;
  if (!args.metric.empty()) options.metric = read_metric_file<3>(args.metric, mesh);
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
