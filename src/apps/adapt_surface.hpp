#pragma once
// `riemesh adapt SURFACE.mesh ...`: the surface branch of the adapt command (cmd_adapt.cpp
// dispatches here when the input is a surface mesh).
#include <string>

#include "mesh/mesh.hpp"
#include "metric/hessian_metric.hpp"
#include "remesh/surface_adapt.hpp"

namespace riemesh::cli {

struct SurfaceAdaptArgs {
  std::string input, output;
  std::string metric;  ///< .sol with a 3D tensor or a size per vertex (may be empty)
  /// --field: a solution .sol whose tangent Hessian gives an Lp metric of complexity
  /// `hessian.complexity`, intersected with the geometric one (may be empty).
  std::string field, field_name;
  HessianMetricOptions hessian;
  /// --fields/--out-fields: vertex fields transferred to the output (P1 from the nearest point).
  std::string fields, out_fields;
  SurfaceAdaptOptions options;
  bool quiet = false;
};

/// Remeshes `mesh` (read from args.input), writes args.output, reports on stderr unless quiet.
void run_adapt_surface(const SurfaceAdaptArgs& args, const Mesh& mesh);

}  // namespace riemesh::cli
