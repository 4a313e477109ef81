#pragma once
// Meshing a volume from its closed boundary surface, for `riemesh mesh SURFACE.mesh -o VOL.mesh`
// (`riemesh mesh` calls this when its input is a surface in 3D).
#include <limits>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// What `riemesh mesh SURFACE.mesh` does inside the recovered volume.
struct VolumeFillArgs {
  bool fill = true;    ///< false (--nofill): the tetrahedra of the boundary points only
  double hsiz = 0.0;   ///< interior size; 0: from the boundary edges
  double hgrad = 1.3;  ///< size gradation of the fill (0: off)
  double hmin = 0.0;   ///< sizes clipped to [hmin, hmax] (--hmin, --hmax)
  double hmax = std::numeric_limits<double>::infinity();
  int passes = 15;  ///< largest number of the fill's optimisation passes (--passes)
  bool keep_triangles = false;  ///< --keep-triangles: planar patches not re-triangulated
  std::vector<double> holes;    ///< --hole points (x, y, z each): these regions left empty
  bool no_holes = false;        ///< --no-holes: every enclosed region a solid of its own
  bool quiet = false;
  int verbosity = 0;  ///< 1: per-pass statistics of the fill
};

/// Tetrahedralises the closed surface `surface` read from `input` (boundary recovered with
/// Steiner points on the surface), fills it with interior points (unless fill is off) and writes
/// the volume to `output`; prints one summary line unless quiet. Throws InputError naming `input`
/// for a surface with a defect (hole, triangle listed twice, inconsistent orientation, coincident
/// vertices, self-intersection); nothing is written then.
void mesh_volume_from_surface(const std::string& input, const Mesh& surface,
                              const std::string& output, const VolumeFillArgs& args);

}  // namespace riemesh::cli
