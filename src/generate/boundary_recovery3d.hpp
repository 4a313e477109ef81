#pragma once
// Conforming boundary recovery in 3D (BOOK.md §4: Delaunay meshing, boundary recovery): the volume
// bounded by a closed surface, tetrahedralised so that the surface is a union of tet faces, with
// Steiner points added on the surface only where the Delaunay tetrahedralisation of the surface
// vertices misses part of it.
//
// Method (conforming Delaunay recovery; every point goes through the incremental kernel
// Delaunay3d::insert, so the tetrahedralisation stays Delaunay throughout):
// - each input triangle keeps its own triangulation into "subfaces" (points on its edges and
//   inside it), made by splitting and then Lawson-flipping towards 2D Delaunay in the triangle's
//   plane; the subsegments (pieces of the input edges) are never flipped;
// - rounds: every subsegment that is no tet edge is split (at its middle, or, next to an input
//   vertex, at a power-of-two distance from that vertex — Shewchuk's concentric shells, so that
//   small input angles do not cascade); when all are present, every subface that is no tet face
//   gets a point at its circumcentre, unless that point encroaches (lies in the diametral circle
//   of) a subsegment of its triangle or falls outside, in which case that subsegment is split;
// - a point on edge (a, b) is (1 − t)·a + t·b and a point in triangle abc is λ0·a + λ1·b + λ2·c
//   (barycentric interpolation), so the recovered boundary lies on the input surface up to
//   rounding; the subface triangulations are built on the exact barycentric coordinates (points
//   of an edge are exactly collinear there), so neighbouring triangles always agree on the
//   subsegments of their common edge;
// - the tetrahedra kept are those of the regions between the subfaces that are neither outside nor
//   holes, each region with its own tet ref (volume_regions3d.hpp: an interface listed once
//   separates two regions; an enclosed shell oriented like the one around it is a solid); the
//   subfaces are written as boundary triangles with their input refs.
// No Steiner point is placed inside the volume. Self-intersecting surfaces are refused up front
// (they would never converge); a surface that needs more than max_steiner_per_vertex Steiner
// points per surface vertex gives an InputError instead of a hang.
#include <cstddef>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

struct BoundaryRecoveryOptions {
  double max_steiner_per_vertex = 20;  // cap on Steiner points / surface vertices
  /// Near-flat inside tets (four nearly cocircular surface points) get a subsegment split or a
  /// subface refined, so that the recovered volume has none. false: they are left to an
  /// optimiser that follows (mesh_volume's, whose sliver sweeps remove them): on grids of
  /// nearly cocircular squares the splits cascade (a cube's faces remeshed to 1/10: 175 Steiner
  /// points and tets of quality 0.13 with them, 84 and 0.55 without).
  bool refine_flat = true;
  /// Every input triangle recovered as given. false (the default): a planar patch (exactly
  /// coplanar triangles of one ref and tag, joined by edges) with triangles that are no faces of
  /// the tetrahedralisation takes its faces on the patch's plane instead, when they tile it
  /// (planar_patches3d.hpp): fans of thin triangles on a CAD model's flat faces cascaded into
  /// thousands of Steiner points.
  bool keep_triangles = false;
  /// Points strictly inside the volume (x, y, z each), inserted with the surface vertices (field
  /// points, volume_fill3d.hpp); they become the volume's vertices after the surface's, before
  /// the Steiner points. InputError when one is not a vertex of an inside tetrahedron (outside,
  /// or on the surface) or coincides with another point.
  std::vector<double> interior_points;
  /// Points (x, y, z each) inside regions to leave empty; when given they alone decide which
  /// regions are holes, otherwise the orientation of enclosed shells does (volume_regions3d.hpp).
  std::vector<double> hole_points;
  /// No region is a hole, whatever the orientation of its shell (hole_points must be empty).
  bool no_holes = false;
};

struct BoundaryRecoveryStats {
  std::size_t surface_vertices = 0;
  std::size_t delaunay_tets = 0;     // tetrahedralisation of the surface vertices alone
  std::size_t missing_edges = 0;     // surface edges that are no edge of that tetrahedralisation
  std::size_t missing_faces = 0;     // surface triangles that are no face of it
  std::size_t steiner_on_edges = 0;  // Steiner points on input edges
  std::size_t steiner_in_faces = 0;  // Steiner points inside input triangles
  std::size_t steiner_inside = 0;    // Steiner points inside the volume (always 0 here)
  std::size_t rounds = 0;            // recovery rounds (one tetrahedralisation scan each)
  /// Steiner points (of those above) added once nothing was missing, to break up near-flat
  /// inside tets (refine_flat: four nearly cocircular points of an interface or of a surface's
  /// concave part), with those that recovered the pieces they split.
  std::size_t steiner_for_flat_tets = 0;
  std::size_t flips = 0;  // missing edges recovered by a flip (cocircular quads: no Steiner point)
  std::size_t planar_patches = 0;   // planar patches re-triangulated (planar_patches3d.hpp)
  std::size_t patch_triangles = 0;  // input triangles they held
  /// Pairs of triangles on the same vertices in opposite orientations (an interface given by
  /// both its volumes) taken once (merge_interfaces_listed_twice).
  std::size_t interfaces_listed_twice = 0;
  /// Edges traversed the same way by their two triangles, tolerated on a surface of several
  /// regions (an interface's triangles may face either way: require_closed_surface).
  std::size_t inconsistent_edges = 0;
  std::size_t steiner() const { return steiner_on_edges + steiner_in_faces + steiner_inside; }
};

struct RecoveredVolume {
  /// Vertices: the surface's vertices of triangles (in increasing id order, refs and tags kept),
  /// then the interior points of the options, then the Steiner points (ref 0). Boundary triangles:
  /// the subfaces of each input triangle, oriented like it, with its ref and tag. Tet refs: the
  /// regions', 1, 2, ...
  Mesh volume;
  BoundaryRecoveryStats stats;
};

/// The tetrahedralised volume bounded by `surface` (closed, consistently oriented, not
/// self-intersecting: checked by require_closed_surface, then find_self_intersections, after
/// merge_interfaces_listed_twice: an interface given by both its volumes is taken once), its
/// boundary recovered by Steiner points on the surface. Deterministic. InputError for a defective
/// surface (naming the defect) or when the Steiner cap is reached.
RecoveredVolume recover_volume(const Mesh& surface, const BoundaryRecoveryOptions& options = {});

}  // namespace riemesh
