#pragma once
// The boundary of a planar geometry (io/geo.hpp: points, segments, arcs, splines, curve loops,
// plane surfaces) meshed into a domain for mesh_domain2d (issue #8: parametric curves from a
// small geometry description, meshed with the curve's geometric metric).
//
// Each curve is meshed once (curve2d.hpp) to the size asked — --hsiz, else the sizes `lc` of its
// end points interpolated along it (as Gmsh does), else 1/25 of the diagonal of the points' box —
// limited by its geometric size for hausd (default 1e-3 of that diagonal) and clamped to [hmin,
// hmax]. Its nodes lie on the exact curve; the geometry's points are the shared end vertices.
// Each Plane Surface's outer loop is oriented counter-clockwise and its holes clockwise (by the
// signed area of the meshed loop), the orientation mesh_domain2d reads: a curve between two
// surfaces is then given in both directions (an interface), a hole no surface fills stays a hole.
// Refs: an edge takes the tag of the first Physical Curve holding its curve, else the curve's
// id; the triangles of a surface the tag of the first Physical Surface holding it, else its id
// — unless a group of that dimension has that tag: then a ref above every tag and id.
#include <string>
#include <vector>

#include "core/vec.hpp"
#include "io/geo.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

struct GeometryMeshOptions {
  double hsiz = 0.0;   ///< uniform size (0: the points' lc, else the default)
  double hausd = 0.0;  ///< chord-to-curve distance limit (0: 1e-3 of the box's diagonal)
  double hmin = 0.0;   ///< 0: 1e-6 of the box's diagonal
  double hmax = 0.0;   ///< 0: no limit

  /// Throws InputError naming the option when a value is negative, not finite, or hmin > hmax.
  void validate() const;
};

/// A Plane Surface's meshed loops (outer first, counter-clockwise; holes clockwise) and its ref.
struct SurfacePolygons {
  int ref = 0;
  int id = 0;  ///< the Plane Surface's id (for messages)
  std::vector<std::vector<Vec2>> loops;
};

struct GeometryBoundary {
  Mesh domain;  ///< dim 2: the curves' nodes, Edges with refs, oriented for mesh_domain2d
  std::vector<SurfacePolygons> surfaces;
  double size = 0.0, hausd = 0.0;  ///< the default or given size and hausd used
  int sized_by_points = 0;         ///< curves sized by their end points' lc
  int curves = 0;                  ///< curves meshed
};

/// Meshes the curves of the geometry's Plane Surfaces. Throws InputError "line N: message" (the
/// line of the entity at fault) for: no Plane Surface, a loop whose curves do not chain end to
/// start or do not close, a loop of zero area, a surface whose hole lies outside its outer loop,
/// two surfaces on the same side of a curve (overlapping), a curve twice in one surface's loops.
GeometryBoundary mesh_geometry_boundary(const Geometry2d& geometry,
                                        const GeometryMeshOptions& options);

/// Gives each triangle of a mesh of that domain (tri_ref = region 1, 2, ... from mesh_domain2d)
/// the ref of the Plane Surface holding its region (outer loop in, holes out; decided on up to 16
/// triangles' centroids per region, by majority). InputError when a region lies in no surface
/// (a hole inside a hole, a hole loop crossing or sharing a curve with its outer loop) or in
/// two (a surface inside another that does not list it as a hole, surfaces crossing at nodes).
void assign_surface_refs(const GeometryBoundary& boundary, Mesh& mesh);

/// Leaves the corner tag on the geometry's points only: mesh_domain2d, keeping the boundary, tags
/// every boundary vertex a corner, but the curves are smooth between the points, so a later
/// `riemesh adapt` may move and add nodes along them.
void keep_point_corners(const GeometryBoundary& boundary, Mesh& mesh);

}  // namespace riemesh
