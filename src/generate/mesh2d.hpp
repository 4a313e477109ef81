#pragma once
// Meshing a planar domain from its boundary (issue #8, BOOK.md §4): the constrained Delaunay
// triangulation of the boundary vertices with exterior and holes removed (domain2d.hpp), field
// points inserted at unit metric spacing (field_points2d.hpp; a boundary to remesh is first cut
// to the sizes on its smooth reconstruction), then the mesh optimised by the 2D
// adaptation (adapt2d.hpp: splits, collapses, swaps and smoothing until the edges have unit length
// in the size field; with the boundary remeshed to the size field unless it is kept).
//
// Size field, in order of precedence: a metric per boundary vertex, a uniform size hsiz, or by
// default the mean length of the boundary edges at each boundary vertex, interpolated inside (the
// log-Euclidean interpolation of adapt2d's background mesh, graded by hgrad).
#include <vector>

#include "core/symmat.hpp"
#include "generate/domain2d.hpp"
#include "generate/field_points2d.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh {

struct Mesh2dOptions {
  double hsiz = 0.0;             ///< uniform size (0: none)
  std::vector<SymMat2> metric;   ///< one metric per vertex of the boundary mesh (empty: none)
  std::vector<double> holes;     ///< hole points, 2 doubles each (empty: orientation decides)
  bool no_holes = false;         ///< no region is a hole, whatever the orientation (no holes then)
  /// Keep the boundary vertices and edges exactly as given (required); false: the boundary
  /// curves are remeshed to the size field by adapt2d (within hausd of their reconstruction).
  bool keep_boundary = true;
  /// hmin, hmax, hgrad, hausd, passes, ... With a kept boundary, hgrad = 0 is advised: graded
  /// sizes smaller than the kept boundary edges leave only slivers along them.
  Adapt2dOptions adapt;

  /// Throws InputError naming the option when values are out of range or contradict.
  void validate() const;
};

struct Mesh2dResult {
  Mesh mesh;                     ///< the triangle mesh; triangle refs = regions 1, 2, ...
  std::vector<SymMat2> metrics;  ///< the metric at each output vertex
  int regions = 0, holes = 0;
  std::size_t lattice_points = 0;  ///< points of a constant metric's unit lattice (lattice2d.hpp)
  FieldPointStats field_points;    ///< points added along edges before the optimisation
  Adapt2dReport report;
};

/// Meshes the domain bounded by the Edges of `boundary` (see triangulate_domain2d for the
/// conventions and errors). Deterministic.
Mesh2dResult mesh_domain2d(const Mesh& boundary, const Mesh2dOptions& options,
                           const PassCallback& on_pass = {});

}  // namespace riemesh
