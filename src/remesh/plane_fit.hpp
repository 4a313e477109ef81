#pragma once
// Whether a boundary patch of a 3D mesh is planar (internal to remesh/), decided alike wherever
// the remesher asks (Remesh3dContext's planar patches and interfaces, the planar pieces of a
// ref, the curvature sizes of the curved ones): its faces' normals agree within kPlaneNormal
// and its vertices lie within kFlatness of the diagonal from the plane fitted to all its faces
// (area-weighted normal, mean offset). A file written with 6 or 7 significant digits rounds a
// slanted plane by ~1e-7 of its size, and the plane of one small face tilts with that rounding:
// such faces were taken for curved (tolerances 1e-9 and 1e-10 of the diagonal, first face's
// plane), and an interface meeting them was kept as given.
#include <span>

#include "core/vec.hpp"
#include "remesh/surface_hausdorff.hpp"

namespace riemesh {

/// Largest 1 − |n · n'| between the normals of one plane's faces.
inline constexpr double kPlaneNormal = 1e-6;
/// Largest distance of a planar patch's vertices to its plane, relative to the diagonal.
inline constexpr double kFlatness = 1e-6;

struct PlaneFit {
  Vec3 n{};                ///< unit normal (the side of the first face)
  double d = 0.0;          ///< offset: n . p = d on the plane
  bool aligned = true;     ///< every face's normal within kPlaneNormal of the first's
  double deviation = 0.0;  ///< largest |n . p − d| over the vertices
};

/// The plane fitted to `faces` (at least one; faces of either orientation).
PlaneFit fit_plane(std::span<const Tri3> faces);

/// fit_plane's verdict: aligned and within kFlatness · diagonal.
inline bool is_planar(const PlaneFit& f, double diagonal) {
  return f.aligned && f.deviation <= kFlatness * diagonal;
}

}  // namespace riemesh
