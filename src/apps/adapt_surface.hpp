#pragma once
// `riemesh adapt SURFACE.mesh ...`: the surface branch of the adapt command (cmd_adapt.cpp
// dispatches here when the input is a surface mesh).
#include <string>

#include "mesh/mesh.hpp"
#include "remesh/surface_adapt.hpp"

namespace riemesh::cli {

struct SurfaceAdaptArgs {
  std::string input, output;
  std::string metric;  ///< .sol with a 3D tensor or a size per vertex (may be empty)
  SurfaceAdaptOptions options;
  bool quiet = false;
};

/// Remeshes `mesh` (read from args.input), writes args.output, reports on stderr unless quiet.
void run_adapt_surface(const SurfaceAdaptArgs& args, const Mesh& mesh);

}  // namespace riemesh::cli
