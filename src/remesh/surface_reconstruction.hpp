#pragma once
// A smooth (G0 everywhere, G1 at the vertices) reconstruction of a triangulated surface on which
// new points are placed: one cubic Bézier triangle per input triangle, built from the vertex
// normals (the PN triangles of Vlachos, Peters, Boyd and Mitchell 2001), and along feature edges
// a cubic curve from the feature line's tangents, so that both sides of a ridge share it and the
// ridge stays sharp (BOOK.md §3–7: "discrete surface remeshing against a smooth reconstruction").
//
// Vertex normals are the sector normals (surface_features.hpp): a triangle uses, at each corner,
// the normal of its own side of the ridge. Replacing sectors.normal by fitted_sector_normals
// (surface_curvature.hpp) before building is recommended: quadric-fit normals are O(h²) where
// angle-weighted ones are O(h) on irregular meshes, and the PN error follows the normal error
// (measured on the icosphere, subdivision 3: edge midpoints 17 -> 148 times closer to the
// sphere than the chord midpoints). On a smooth edge both triangles use the same two
// normals, hence the same boundary curve: the reconstruction has no cracks.
// Feature-line tangents: at a vertex inside a feature line (two feature edges, not a corner),
// the tangent at the vertex of the circle through it and its two neighbours on the line,
// |VA|²(B−V) − |VB|²(A−V) (exact on a circle whatever the spacing); at corners and line ends,
// the chord. Edge control points: P + (L/3) T (L the chord length).
#include <vector>

#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_features.hpp"

namespace riemesh {

/// Control net of a cubic Bézier triangle over corners P0, P1, P2. b[i] order:
/// 0 b300 (P0), 1 b030 (P1), 2 b003 (P2), 3 b210, 4 b120, 5 b021, 6 b012, 7 b102, 8 b201, 9 b111
/// (b_ijk: i, j, k the powers of the barycentric weights of P0, P1, P2).
struct CubicTriangle {
  Vec3 b[10];
};

/// The PN triangle of corners p and unit normals n: edge control points P_i + (P_j − P_i)/3
/// projected onto the tangent plane of P_i, centre b111 = E + (E − V)/2 (E mean of the six edge
/// points, V mean of the corners).
CubicTriangle pn_triangle(const Vec3 (&p)[3], const Vec3 (&n)[3]);

/// Recomputes b111 after edge control points were replaced (e.g. by a feature curve).
void update_centre(CubicTriangle& c);

/// The point of barycentric coordinates (1 − u − v, u, v) on (P0, P1, P2).
Vec3 evaluate(const CubicTriangle& c, double u, double v);

/// Point at parameter s in [0, 1] of the cubic Bézier curve p0, c0, c1, p1.
Vec3 cubic_curve(const Vec3& p0, const Vec3& c0, const Vec3& c1, const Vec3& p1, double s);

/// The tangent (unit, oriented from a to b) at v of the circle through a, v, b; the direction
/// of b − a when the three points are aligned.
Vec3 circle_tangent(const Vec3& a, const Vec3& v, const Vec3& b);

/// The piecewise cubic reconstruction of a surface mesh (one patch per triangle).
class SurfaceReconstruction {
 public:
  /// Builds every patch; `sectors` gives the corner normals, `features` the feature edges.
  /// Keeps references to `mesh` and `adj`, which must outlive it.
  SurfaceReconstruction(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& features,
                        const SurfaceSectors& sectors);

  /// Point at barycentric (1 − u − v, u, v) of triangle t's vertices (in the mesh's order).
  Vec3 point(Id t, double u, double v) const { return evaluate(patch_[static_cast<std::size_t>(t)], u, v); }
  /// Point at parameter s from a to b on the edge (a, b) (s = ½: the new point of a split).
  /// Throws InputError when (a, b) is not an edge of the mesh.
  Vec3 edge_point(Id a, Id b, double s) const;
  const CubicTriangle& patch(Id t) const { return patch_[static_cast<std::size_t>(t)]; }
  /// Unit tangent of the feature line at v, oriented from line neighbour 0 to 1 (zero off lines
  /// and at corners).
  const Vec3& line_tangent(Id v) const { return tangent_[static_cast<std::size_t>(v)]; }

 private:
  const Mesh& mesh_;
  const Adjacency& adj_;
  std::vector<CubicTriangle> patch_;
  std::vector<Vec3> tangent_;
};

}  // namespace riemesh
