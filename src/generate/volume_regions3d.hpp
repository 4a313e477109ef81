#pragma once
// The regions of a tetrahedralisation cut by a closed surface (BOOK.md §4: removing the outside
// and the holes), for meshing a volume from its boundary.
//
// Regions are the sets of tets joined through faces that are no surface triangle. The outside is
// made of the regions reached from beyond the convex hull without crossing the surface; a region
// next to the outside is always meshed. Hole points, when given, alone decide which of the
// regions enclosed by others are holes; with no_holes none is. Otherwise an enclosed region is a
// hole when every surface
// triangle around it faces into it the way the outer boundary faces the outside (a cavity: its
// shell oriented against the shell around it), and a solid of its own otherwise: nested shells
// oriented alike (a sphere inside a box, as gmsh writes it) give two regions, and an interface
// listed once (a wall across a box, two solids sharing a face) separates two regions whatever its
// orientation. Each meshed region gets its own tet ref 1, 2, ..., numbered in the order of the
// first surface triangle around it. Same conventions as the planar domains (domain2d.hpp).
#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "generate/delaunay3d.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

namespace detail {
/// A triangle as its sorted vertex ids (faces of tets and surfaces compared as sets).
using Face = std::array<Id, 3>;
inline Face sorted_face(Id a, Id b, Id c) {
  Face f = {a, b, c};
  std::sort(f.begin(), f.end());
  return f;
}
}  // namespace detail

struct TetRegions {
  std::vector<int> ref;  ///< per tet: 0 outside or in a hole, else its region's ref
  int regions = 0;       ///< meshed regions (refs 1..regions)
  int holes = 0;         ///< regions left empty as holes
};

/// The regions of `tz` (a tetrahedralisation holding every triangle of `triangles`, 3 point ids
/// each, as tet faces) and which are meshed. coords: the points (3 doubles each), read only to
/// locate hole points (3 doubles each); no_holes: every region not outside is meshed (hole_points
/// must be empty). InputError when a hole point is outside every region or on the surface, or
/// when no region is left.
TetRegions tet_regions(const Tetrahedralization& tz, std::span<const Id> triangles,
                       std::span<const double> coords = {},
                       std::span<const double> hole_points = {}, bool no_holes = false);

/// InputError when the tets of `volume` around a vertex are not joined through faces (two solids
/// touching along an edge or at a point: no manifold, which the optimiser's walks need), naming
/// the first such place by its coordinates.
void require_no_pinch(const Mesh& volume);

}  // namespace riemesh
