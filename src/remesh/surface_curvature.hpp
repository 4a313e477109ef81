#pragma once
// Principal curvatures and directions at the vertices of a triangulated surface, by a local
// quadric fit in the tangent frame (BOOK.md §1: discrete surfaces have no σ; curvature tensors
// are estimated from the mesh).
//
// Method, per sector (surface_features.hpp) of each vertex p with sector normal n:
//   - a frame (t1, t2, n) at p; neighbours q written as (x, y, z) = ((q−p)·t1, (q−p)·t2, (q−p)·n);
//   - neighbours: the vertices of the sector's triangles (1-ring); when there are fewer than
//     kMinRingPoints of them, the vertices of every triangle that touches a 1-ring vertex and is
//     reachable from the sector without crossing a feature edge (2-ring). A quadric therefore
//     never spans a ridge: at a ridge or corner each side is fitted on its own points;
//   - when those points spread along one direction (rings of stretched triangles: second
//     moments in the tangent plane beyond 1:9), more are taken across smooth edges, within the
//     distance of the farthest so far and from triangles within 30° of the normal, until the
//     spread is even or 200 points are taken (else the quadric's term across the thin direction
//     absorbs the fit's residual: curvature 570 instead of 1 on a 10-sided prism in thin rows);
//   - least squares z = a x² + b xy + c y² + d x + e y (the linear terms absorb the error of the
//     estimated normal), coordinates scaled by the mean neighbour distance for conditioning;
//   - the graph σ(x, y) = (x, y, f(x, y)) goes to surface_geometry (metric/geometric.hpp), which
//     returns the normal, principal curvatures and directions at the origin, mapped back to space.
// The vertex keeps the sector of largest |k1| (the metric must follow the most curved side).
// Fewer than 5 usable points, or a singular fit, gives zero curvature and fitted = false.
//
// Measured accuracy (tests/remesh/test_surface_curvature.cpp): on meshes of sphere, cylinder,
// torus and saddle the error is O(h) to O(h²) and falls under a few per cent at ~40 vertices per
// unit curvature radius; see that file for the stated bounds.
#include <vector>

#include "metric/geometric.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"
#include "remesh/surface_features.hpp"

namespace riemesh {

/// Fewer 1-ring points than this and the fit uses the 2-ring (valence 6 -> 2-ring).
inline constexpr int kMinRingPoints = 9;

struct VertexCurvature {
  /// Normal, principal curvatures (signed along `normal`, |k1| >= |k2|), radii and directions
  /// (w1, w2 in space, (w1, w2, normal) right-handed). first_form, second_form, weingarten and
  /// the *_uv directions are those of the local graph (x, y, f) and of little use outside.
  SurfaceGeometry geometry{};
  int points = 0;       ///< neighbours used by the fit
  bool fitted = false;  ///< false: too few points or singular fit (zero curvature reported)
};

/// Quadric fit of one sector: neighbours `q` around `p`, frame normal `n` (unit).
VertexCurvature fit_quadric(const Vec3& p, const Vec3& n, const std::vector<Vec3>& q);

/// Curvature at each vertex (the sector of largest |k1|); a vertex of no triangle gets zero
/// curvature in the frame (x, y, z), fitted = false.
std::vector<VertexCurvature> vertex_curvatures(const Mesh& mesh, const Adjacency& adj,
                                               const SurfaceFeatures& features,
                                               const SurfaceSectors& sectors);

/// The normal of each sector refined by its quadric fit (the normal of the fitted graph at the
/// vertex; O(h²) on smooth surfaces where the angle-weighted normal is O(h) on irregular
/// meshes). Sectors whose fit fails keep their angle-weighted normal.
std::vector<Vec3> fitted_sector_normals(const Mesh& mesh, const Adjacency& adj,
                                        const SurfaceFeatures& features,
                                        const SurfaceSectors& sectors);

/// The quadric fit of every sector (frame normal: the sector's angle-weighted normal), from
/// which vertex_curvatures and fitted_sector_normals derive: callers needing both fit once.
std::vector<VertexCurvature> sector_curvatures(const Mesh& mesh, const Adjacency& adj,
                                               const SurfaceFeatures& features,
                                               const SurfaceSectors& sectors);
/// vertex_curvatures from the fits of sector_curvatures.
std::vector<VertexCurvature> vertex_curvatures(std::size_t num_vertices, const SurfaceSectors& sectors,
                                               const std::vector<VertexCurvature>& fits);
/// fitted_sector_normals from the fits of sector_curvatures.
std::vector<Vec3> fitted_sector_normals(const SurfaceSectors& sectors,
                                        const std::vector<VertexCurvature>& fits);

}  // namespace riemesh
