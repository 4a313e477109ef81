// The surface branch of `riemesh adapt` (adapt_surface.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/adapt_surface.hpp"
#include "apps/field_args.hpp"
#include "apps/mesh_args.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/mesh_file.hpp"
#include "io/sol.hpp"
#include "mesh/self_intersection.hpp"
#include "metric/metric.hpp"
#include "remesh/surface_fields.hpp"

namespace riemesh::cli {
void run_adapt_surface(const SurfaceAdaptArgs& args, const Mesh& mesh) {
  const auto start = std::chrono::steady_clock::now();
  SurfaceAdaptOptions options = args.options;
  if (!args.metric.empty()) options.metric = read_metric_file<3>(args.metric, mesh);
  MetricReport field_report;
  if (!args.field.empty()) {
    const std::vector<Field> sol = read_sol(args.field, mesh);
    const Field& u = select_field(sol, args.field_name, args.field);
    const std::vector<SymMat3> hessians = recover_surface_hessian(mesh, u.values);
    options.metric = surface_hessian_metric(mesh, hessians, args.hessian, &field_report);
  }
  const std::vector<Field> fields =
      args.fields.empty() ? std::vector<Field>{} : read_sol(args.fields, mesh);
  if (!args.quiet)
    options.on_cycle = [&start](const SurfaceCycle& c) {
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      char label[24];
      if (c.cycle > 0)
        std::snprintf(label, sizeof label, "cycle %2d", c.cycle);
      else
        std::snprintf(label, sizeof label, "final   ");
      std::fprintf(stderr,
                   "%s: %zu vertices %zu triangles; %zu splits %zu collapses %zu swaps %zu "
                   "moves (%.2f s)\n",
                   label, c.vertices, c.triangles, c.splits, c.collapses, c.swaps, c.moves, t);
    };
  options.validate();  // option errors named by the option, not prefixed with the mesh's name
  SurfaceAdaptReport r;
  const Mesh out = naming_file(args.input, [&] { return adapt_surface(mesh, options, &r); });
  // Sheets of the input closer than about --hausd may be merged into crossing triangles (two
  // spheres 0.01 apart at --hausd 0.02: 932 crossing pairs, exit 0): refused, nothing written.
  // The input was checked not to cross itself (surface_input.hpp).
  if (const SelfIntersections x = find_self_intersections(out, 1000); x.pairs > 0) {
    const Id* t = &out.triangles[3 * static_cast<std::size_t>(x.first_a)];
    char msg[320];
    std::snprintf(msg, sizeof msg,
                  "%s: the adapted surface crosses itself (%s%zu pairs of triangles, the first "
                  "near (%g, %g, %g)): parts of the input closer than about --hausd %g were "
                  "merged; give a smaller --hausd",
                  args.input.c_str(), x.pairs >= 1000 ? "at least " : "", x.pairs,
                  out.coords[3 * static_cast<std::size_t>(t[0])],
                  out.coords[3 * static_cast<std::size_t>(t[0]) + 1],
                  out.coords[3 * static_cast<std::size_t>(t[0]) + 2], options.hausd);
    throw InputError(msg);
  }
  // Transferred before anything is written: a failure leaves no file.
  const std::vector<Field> moved = fields.empty() ? fields : transfer_surface_p1(mesh, fields, out);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  OutputBatch batch;  // all outputs or none
  batch.write(args.output, [&](const std::string& path) { write_mesh(out, path); });
  if (!args.fields.empty())
    batch.write(args.out_fields, [&](const std::string& path) { write_sol(path, moved, 3); });
  batch.commit();
  if (args.quiet) return;
  for (const std::string& note : r.notes) std::fprintf(stderr, "riemesh: note: %s\n", note.c_str());
  if (!args.field.empty())
    std::fprintf(stderr,
                 "riemesh: field metric: complexity %.0f (a unit mesh of it: about %.0f "
                 "triangles), intersected with the geometric metric\n",
                 field_report.complexity, field_report.predicted_elements);
  std::fprintf(stderr,
               "riemesh: surface %zu -> %zu triangles, %zu vertices (%d cycles: %zu splits, %zu "
               "collapses, %zu swaps, %zu moves); %zu feature edges and %zu corners in the "
               "input; quality min %.3f mean %.3f; %.2fs\n",
               mesh.num_triangles(), out.num_triangles(), out.num_vertices(), r.cycles, r.splits,
               r.collapses, r.swaps, r.moves, r.input_feature_edges, r.input_corners, r.q_min,
               r.q_mean, seconds);
}

}  // namespace riemesh::cli
