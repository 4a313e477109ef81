#pragma once
// A planar domain given by its boundary edges, triangulated with no interior point: the
// constrained Delaunay triangulation of the boundary vertices, exterior and holes removed
// (BOOK.md §4). Field points come later (mesh2d.hpp).
//
// Conventions (FreeFem's buildmesh): each boundary edge a → b has the domain on its left, so outer
// loops turn counter-clockwise and hole loops clockwise. An edge given in both directions, or
// whose two sides end up in the domain, is an interface. The regions are the connected sets of
// triangles between edges; the one touching the outside is never meshed. Hole points, when
// given, alone decide which regions are holes; otherwise a region is a hole when every edge
// around it leaves it on its right (no_holes: none is, whatever the orientation). Each remaining
// region gets its own triangle ref 1, 2, ..., numbered in the order of the first input edge around
// it.
#include <span>
#include <string>
#include <vector>

#include "generate/delaunay2d.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

struct Domain2d {
  /// The boundary vertices (input order, vertices outside the domain dropped), the triangles
  /// (counter-clockwise, ref = region) and the kept edges (input orientation, refs and tags).
  Mesh mesh;
  std::vector<Id> input_vertex;  ///< per output vertex: its id in the input
  int regions = 0;               ///< meshed regions (distinct triangle refs)
  int holes = 0;                 ///< regions left empty as holes
};

/// Triangulates the domain bounded by the Edges of `boundary` (dim 2; its triangles, if any, are
/// ignored). hole_points: 2 doubles per point; no_holes: every region not outside is meshed
/// (hole_points must then be empty). Throws InputError for an open boundary, a
/// zero-length edge, crossing edges or a vertex inside an edge (naming the edges, 1-based, and
/// the place), a hole point outside every region, or a domain with no region left.
Domain2d triangulate_domain2d(const Mesh& boundary, std::span<const double> hole_points,
                              InsertionOrder order = InsertionOrder::kBrio, bool no_holes = false);

/// The boundary of a planar triangle mesh as a domain for triangulate_domain2d: its Edges (or, if
/// it has none, the edges of exactly one triangle, ref 1), each turned so that its triangle is on
/// its left when it has exactly one; the vertices they use, compacted. Refs and tags kept.
Mesh extract_boundary2d(const Mesh& mesh);

}  // namespace riemesh
