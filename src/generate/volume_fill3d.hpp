#pragma once
// Interior points of a volume meshed from its boundary (issue #8, 3D). The tetrahedra of the
// recovered boundary join surface points only; they are filled in two steps:
// 1. field points: the boundary sizes (or --hsiz), interpolated linearly inside the recovered volume,
//    drive an octree subdivision of the volume's box (a cell is split while it is larger than
//    the size at its centre); the centre of each leaf cell inside the volume and farther than
//    1.5 of its size from the surface, moved by a small deterministic jitter (so that the points
//    are not cospherical), is a field point; the surface is then recovered again with these
//    points in the Delaunay tetrahedralisation (BoundaryRecoveryOptions::interior_points), which
//    inserts them at Delaunay speed instead of by one-by-one edge splits;
// 2. the 3D remesher optimises the result with the boundary kept as it is (adapt3d with
//    keep_surface: splits and collapses bring the lengths to 1, then swaps, smoothing and sliver
//    removal), the field points carrying the size they were made with.
#include <span>
#include <vector>

#include "generate/boundary_recovery3d.hpp"
#include "mesh/mesh.hpp"
#include "remesh/adapt3d.hpp"

namespace riemesh {

/// The size at each vertex from the boundary: the mean length of the boundary-triangle edges at
/// it (vertices on no boundary triangle: the mean over all boundary edges).
std::vector<double> boundary_sizes(const Mesh& volume);

/// Field points of a volume (tetrahedra and boundary triangles) for the sizes given at its
/// vertices (step 1 above): coordinates (3 per point) and the size at each point. Deterministic.
struct FieldPoints3 {
  std::vector<double> coords;
  std::vector<double> sizes;
  std::size_t size() const { return sizes.size(); }
};
FieldPoints3 field_points3d(const Mesh& volume, std::span<const double> sizes);

/// Optimises `volume` (e.g. recover_volume's) for the sizes given at its vertices, or with
/// hsiz > 0 for that uniform size; the boundary triangles and their vertices are kept.
/// options.keep_surface is forced on; the other options are adapt3d's (gradation, passes).
Adapt3dResult fill_volume(Mesh&& volume, std::span<const double> sizes, Adapt3dOptions options,
                          const PassCallback& on_pass = {});
Adapt3dResult fill_volume(Mesh&& volume, double hsiz, Adapt3dOptions options,
                          const PassCallback& on_pass = {});

/// The whole of it from a closed surface: recover_volume, field points for hsiz (> 0) or the
/// boundary sizes (hsiz == 0), clipped to [options.hmin, options.hmax], recover_volume with
/// them, fill_volume.
struct FilledVolume {
  Adapt3dResult adapted;
  BoundaryRecoveryStats stats;     ///< of the final recovery (with the field points)
  std::size_t field_points = 0;
};
/// recovery: keep_triangles and the holes (hole_points, no_holes) of BoundaryRecoveryOptions; its
/// refine_flat and interior_points are mesh_volume's own.
FilledVolume mesh_volume(const Mesh& surface, double hsiz, Adapt3dOptions options,
                         const PassCallback& on_pass = {},
                         const BoundaryRecoveryOptions& recovery = {});

}  // namespace riemesh
