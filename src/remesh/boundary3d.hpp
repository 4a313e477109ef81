#pragma once
// Curved boundaries of the 3D remesher (issue #7, internal to remesh/): the boundary patches
// that are not planar are remeshed with the volume on the smooth reconstruction of the input's
// boundary surface (surface_projection.hpp, as the surface remesher of issue #6).
//
// The surface is the input's listed boundary faces of the curved patches; its features are
// found by angle (Adapt3dOptions::angle_deg, detect_angles), ref changes and open edges (where
// a curved patch meets a planar one). Vertices of a curved patch are kSurface (new ones and
// smoothing targets are projected on the reconstruction), vertices inside a feature line
// kCurve (on the reconstructed curve), corners kFixed. A collapse or a move of such a vertex is
// accepted only when its new boundary triangles stay within hausd of the input surface and the
// input within hausd of them (surface_hausdorff.hpp), no boundary triangle turning by more than
// 30° or falling below Euclidean quality 0.1 (unless one was already worse); so is a split of a
// curved boundary edge. With curved patches, a boundary split may not create a tet whose four
// vertices are on the boundary with quality below kBoundaryTetFloor, nor may a collapse unless
// its ball had a worse one (such tets, at folds of the surface, no operation repairs).
#include <memory>
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "remesh/adapt3d.hpp"
#include "remesh/surface_hausdorff.hpp"
#include "remesh/surface_projection.hpp"
#include "remesh/tet_mesh.hpp"

namespace riemesh {

/// Quality below which a boundary split may not create a tet with four boundary vertices.
inline constexpr double kBoundaryTetFloor = 0.2;

/// True for the kinds that live on the curved boundary (kSurface, kCurve).
inline bool on_curved_boundary(VertexKind k) {
  return k == VertexKind::kSurface || k == VertexKind::kCurve;
}

class Boundary3d {
 public:
  /// Builds the reconstruction of the listed domain-boundary faces of m whose ref is in
  /// `curved_refs` (sorted), or of options.geometry's triangles with those refs when given (the
  /// vertex kinds still from m's faces). Throws InputError when the geometry has none.
  Boundary3d(const TetMesh& m, std::vector<std::int32_t> curved_refs, const Adapt3dOptions& options);
  Boundary3d(const Boundary3d&) = delete;
  Boundary3d& operator=(const Boundary3d&) = delete;

  bool curved(std::int32_t ref) const;
  /// The kind of vertex v of the mesh given to the constructor, when on a curved face:
  /// kSurface, kCurve (inside a feature line) or kFixed (corner).
  VertexKind kind(Id v) const;
  /// Whether the boundary edge (a, b) (face refs r0, r1) lies on a feature line.
  bool feature_edge(const TetMesh& m, Id a, Id b, std::int32_t r0, std::int32_t r1) const;
  /// p placed on the reconstruction (kSurface) or on the feature lines (kCurve).
  Vec3 place(VertexKind kind, const Vec3& p) const;
  /// Whether a split refused at `placed` (placed on the reconstruction) may go to its point on
  /// the edge instead: when `placed` is near the limit of the lift from the input polyhedron (at
  /// least 0.8 of it): the input's facets are there further from their smooth surface than
  /// hausd allows to follow (coarse facets).
  bool chord_instead(const Vec3& placed) const;
  /// The Hausdorff and normal checks of an operation replacing the boundary triangles old_t
  /// (all of them) by new_t, kept[i] (an old triangle) becoming new_t[i]; triangle qualities
  /// in `metric` (the operation's: a unit mesh of an anisotropic metric oblique to the surface
  /// has triangles that are poor in Euclidean terms).
  bool accepts(const std::vector<Tri3>& old_t, const std::vector<Tri3>& kept,
               const std::vector<Tri3>& new_t, const SymMat3& metric) const;

 private:
  /// The reconstruction of Adapt3dOptions::geometry's triangles with curved refs.
  std::unique_ptr<SurfaceProjection> geometry_projection(const Mesh& g,
                                                         const Adapt3dOptions& options) const;

  std::vector<std::int32_t> curved_refs_;
  std::vector<Id> surf_id_;         // per tet-mesh vertex: its surface vertex, or kNoId
  std::vector<std::uint8_t> tag_;   // per surface vertex: feature tags
  std::unique_ptr<SurfaceProjection> geo_;
  double hausd_;
};

/// The boundary checks of a collapse (to != kNoId: v goes into `to`) or a move (to == kNoId: v
/// goes to p) of a kSurface or kCurve vertex v with ball `ball`; true when m.surface is null.
bool curved_boundary_ok(const TetMesh& m, std::span<const Id> ball, Id v, Id to, const Vec3& p);

/// The same checks for the split of the boundary edge (a, b) (shell `shell`) at p.
bool curved_split_ok(const TetMesh& m, std::span<const Id> shell, Id a, Id b, const Vec3& p);

/// Intersects, at the vertices of the curved listed patches of `volume`, the metrics with the
/// geometric metric of that surface (surface_metric.hpp: sizes from curvature keeping the chords
/// within hausd). Nothing when every listed patch is planar or the counts do not match.
void intersect_curvature_sizes(const Mesh& volume, std::vector<SymMat3>& metrics,
                               const Adapt3dOptions& options);

}  // namespace riemesh
