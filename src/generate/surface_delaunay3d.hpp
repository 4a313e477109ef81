#pragma once
// First steps of meshing a volume from its boundary surface (BOOK.md §4, Delaunay meshing): the
// surface is validated (closed, manifold, consistently oriented), its vertices are
// tetrahedralised by the Delaunay kernel, the surface edges and triangles missing from that
// tetrahedralisation are counted and, when none is missing, the tetrahedra inside are kept.
// Boundary recovery (restoring missing edges and faces with Steiner points) is in
// generate/boundary_recovery3d.hpp, which reuses require_closed_surface and volume_inside.
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "generate/delaunay3d.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// Throws InputError naming the first defect that keeps the triangles of `surface` from bounding
/// a volume: no triangles, a triangle with a repeated vertex, a triangle listed twice, an edge on
/// one triangle only (a hole), two triangles traversing their common edge the same way when it
/// has only them (inconsistent orientation; tolerated on a surface with edges on three triangles
/// or more, whose interfaces separate their regions whichever way they face, and counted in the
/// result), a vertex where separate sheets of the surface touch
/// (non-manifold vertex), a triangle of zero area, two vertices at the same place, a coordinate
/// over 1e150 in magnitude or not finite (squared lengths would overflow). Edges on more than two
/// triangles are where regions meet (an interface listed once) and are accepted. Vertex numbers
/// in messages are 1-based, as in the files. Self-intersections are not detected.
std::size_t require_closed_surface(const Mesh& surface);

/// The surface with each pair of triangles on the same three vertices in opposite orientations
/// (an interface given by both its volumes, each shell closed on its own, as CAD tools export
/// assemblies) taken once: the first of the pair kept, with its ref and tag, the second dropped
/// (later triangles move up one place). *merged: the pairs found. std::nullopt when there is none.
std::optional<Mesh> merge_interfaces_listed_twice(const Mesh& surface, std::size_t* merged);

/// The Delaunay tetrahedralisation of a surface's vertices and how much of the surface it holds.
struct SurfaceDelaunay {
  std::vector<Id> vertices;     // the surface's vertices (ids in the surface mesh), increasing
  std::vector<double> coords;   // their coordinates; tets number vertices in this list
  Tetrahedralization tz;
  std::size_t num_edges = 0;      // distinct surface edges
  std::size_t missing_edges = 0;  // surface edges that are no tet edge
  std::size_t num_faces = 0;      // surface triangles
  std::size_t missing_faces = 0;  // surface triangles that are no tet face
  bool conforming() const { return missing_faces == 0; }
};

/// Validates the surface (require_closed_surface) and tetrahedralises the vertices of its
/// triangles (vertices of no triangle are ignored).
SurfaceDelaunay delaunay_of_surface(const Mesh& surface);

/// The volume mesh bounded by a conforming surface: the tetrahedra of its regions that are
/// neither outside nor holes (tet_regions in volume_regions3d.hpp: hole points, 3 doubles each,
/// or the orientation of enclosed shells decide), each region's tets with its ref 1, 2, ...; the
/// surface's triangles (refs kept) as boundary faces, and its vertices (refs kept), renumbered as
/// in d.vertices. Error if d is not conforming; InputError for a bad hole point or solids that
/// Turns each boundary triangle of the volume mesh `v` that is a face of its tets to face out of
/// its tet, or out of the region of lower tet ref between two (an interface), as the 3D
/// remesher writes them: a surface listed inward, or one whose triangles face both ways, gives
/// a volume whose triangles all face out.
void orient_boundary_triangles(Mesh& v);

/// touch along an edge or at a point (require_no_pinch).
Mesh volume_inside(const Mesh& surface, const SurfaceDelaunay& d,
                   std::span<const double> hole_points = {}, bool no_holes = false);

}  // namespace riemesh
