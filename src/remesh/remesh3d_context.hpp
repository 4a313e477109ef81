#pragma once
// The state of one 3D adaptation (internal to remesh/): the mesh being changed, the background
// mesh with the input metric field, the planes of the planar boundary patches, and the rules
// that place new and moved vertices and give them their metric.
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "remesh/adapt3d.hpp"
#include "remesh/background.hpp"
#include "remesh/boundary3d.hpp"
#include "remesh/ops3d.hpp"

namespace riemesh {

class Remesh3dContext {
 public:
  /// Takes the (clipped, graded) input metrics; the mesh's vertex ids become TetMesh ids.
  Remesh3dContext(const Mesh& input, std::span<const SymMat3> metrics,
                  const Adapt3dOptions& options);
  /// The same, taking over the input's tetrahedra and the metrics for the background mesh
  /// instead of copying them (memory, issue #7); `input` is left without tetrahedra.
  Remesh3dContext(Mesh&& input, std::vector<SymMat3>&& metrics, const Adapt3dOptions& options);

  TetMesh& mesh() { return mesh_; }
  const TetMesh& mesh() const { return mesh_; }

  /// The vertex to insert on edge (a, b) (at floor(n/2)/n of its metric length L, n = round(L)) and its kind; false when the
  /// boundary rules forbid splitting the edge. `hint`: a tet that may hold the edge.
  bool split_point(Id a, Id b, NewVertex3& out, Id hint = kNoId) const;

  /// The metric at p from the background field, the walk starting near hint_vertex.
  SymMat3 metric_for(const Vec3& p, Id hint_vertex) const;

  /// Where smoothing would put v: the mean of the unit-length points seen from its neighbours,
  /// projected on its plane for a planar boundary vertex, on its line for a ridge vertex.
  /// False when v may not move. `ball`, when given, receives v's ball (collect_ball) when v may
  /// move. `neighbours`: v's neighbours sorted, when the caller knows them (else from the ball).
  bool smoothing_target(Id v, NewVertex3& out, std::vector<Id>* ball = nullptr,
                        std::span<const Id> neighbours = {}) const;

  /// Puts p on v's plane (planar boundary vertex) or on its line (ridge vertex, the line through
  /// v's position), on the reconstructed surface or feature line (kSurface, kCurve vertex,
  /// boundary3d.hpp); false when v may not move (fixed).
  bool constrain(Id v, Vec3& p) const;

  /// Replaces the background field (one metric per input vertex, SPD) and gives every live
  /// vertex the metric of the new field at its position; the tet quality cache is cleared and
  /// every vertex counts as moved (m.clock advanced). For the staged approach to the target.
  void set_field(std::vector<SymMat3>&& metrics);

  /// The background field (one metric per input vertex).
  std::span<const SymMat3> field() const { return background_.metrics(); }

  /// True when some listed face between two tets (an interface between subdomains) is on a
  /// curved interface: kept as given with its vertices fixed, or, closed (a sphere in a box),
  /// remeshed like a curved patch on its reconstruction (planar interfaces are remeshed like
  /// planar patches: their vertices move in their plane, their edges are split and collapsed,
  /// their faces on both sides kept listed by replace_cavity).
  bool has_interfaces() const { return has_interfaces_; }
  /// True when `ref` is a curved interface (kept or rebuilt).
  bool curved_interface(std::int32_t ref) const {
    const auto it = planes_.find(ref);
    return it != planes_.end() && it->second.inner && !it->second.planar;
  }
  /// True when the faces of `ref` are kept as given as an interface (a curved interface that
  /// is not closed, or any with --nosurf).
  bool kept_interface(std::int32_t ref) const;

  /// Gives the faces of the planar pieces of a split ref (planar_pieces3d.hpp) their given ref
  /// again: before the mesh is written, after the passes.
  void restore_refs();

  /// Records, for vertex v just created or moved, the background tet of the last metric_for.
  void inherit_hint(Id v);

  /// Renumbers the vertices created since the start (ids from the input's vertex count on) and
  /// the tets for locality (renumber_tail), the hints in step. Returns old -> new vertex ids
  /// and the tets' in *tet_old2new (kNoId: dead, dropped) for the caller's data.
  std::vector<Id> renumber_new_vertices(std::vector<Id>* tet_old2new);

 private:
  struct Plane {
    Vec3 n{};
    double d = 0.0;
    bool planar = true;
    bool outer = false;  ///< some face of the ref is on the outer boundary (not an interface)
    bool inner = false;  ///< some face of the ref is an interface (between two tets)
  };
  void find_planes();
  /// Whether `ref` is a curved interface the reconstruction can hold: on interface faces only,
  /// no edge on more than two of them (a manifold surface, closed or with rims on other
  /// patches).
  bool rebuildable_interface(std::int32_t ref) const;
  /// The vertices' kinds; true when it found planar interfaces to keep as given (made
  /// non-planar: classify again).
  bool classify_vertices();
  /// The kinds of the vertices on the lines of the input's Edges (TetMesh::line_ref): inside a
  /// line (two line edges of one ref on the same patches) a ridge or curve vertex stays so, a
  /// planar one becomes a ridge of its patch (vplane: the patch twice) when the line is straight
  /// there; the others are fixed (line ends, junctions, ref changes, bends in a planar patch).
  void classify_line_vertices();
  /// The direction of the line of the input's Edges through ridge vertex v inside a planar
  /// patch (towards a neighbour on it); false when v has none.
  bool line_direction(Id v, Vec3& d) const;
  const Plane* plane(std::int32_t ref) const;
  /// The refs r[0..n) at a vertex or edge are rebuilt curved patches (boundary_) and coplanar
  /// planar patches, at least one of each: the rim of a curved patch on a plane (a cylinder
  /// through a box, an inclusion's side meeting its planar caps). True with one of each.
  bool rim(const std::int32_t* r, int n, std::int32_t& curved, std::int32_t& flat) const;
  /// Whether p, placed on a feature line for a vertex where a curved patch meets the planar
  /// patch r1 or r2, is in that plane (within flat_tol_): the reconstructed rim of a planar
  /// patch is in its plane within rounding; a point far from it was placed on another line
  /// (the top rim of a cylinder for a vertex of the bottom one).
  bool on_rim_plane(std::int32_t r1, std::int32_t r2, const Vec3& p) const;
  /// The direction of the line where planar patches r1 < r2 meet: their normals' cross product,
  /// or for coplanar patches the direction of their straight common boundary; false if none.
  bool ridge_direction(std::int32_t r1, std::int32_t r2, Vec3& d) const;
  /// The 3 or 4 refs r[0..n) at a vertex or edge are planar, one at least an interface, and
  /// their planes hold one common line (an interface meeting coplanar outer patches split
  /// there, three or four interfaces meeting, an interface along an edge of the outer boundary):
  /// true, with the first two refs whose planes cross (r1 < r2), which give the line. False
  /// otherwise (a corner).
  bool interface_line(const std::int32_t* r, int n, std::int32_t& r1, std::int32_t& r2) const;

  Adapt3dOptions options_;
  TetMesh mesh_;  // built first: the background then takes over the input's arrays
  BackgroundMesh<3> background_;
  /// The field's one metric when every input vertex carries the same (metric_for then answers it
  /// without locating the point; as 2D's Remesh2dContext).
  std::optional<SymMat3> constant_;
  std::map<std::int32_t, Plane> planes_;
  /// Refs of the planar pieces of split refs -> the given ref (planar_pieces3d.hpp).
  std::map<std::int32_t, std::int32_t> pieces_;
  /// Coplanar planar patches (r1 < r2) meeting along a straight line: its unit direction.
  std::map<std::pair<std::int32_t, std::int32_t>, Vec3> coplanar_lines_;
  std::vector<Id> hint_;  // per vertex: a background tet near it
  std::size_t num_input_vertices_ = 0;
  double flat_tol_ = 0.0;  // kFlatness x the bounding box's diagonal (plane_fit.hpp)
  bool has_interfaces_ = false;
  mutable Id last_found_ = kNoId;
  std::unique_ptr<Boundary3d> boundary_;  // the curved patches (null: none, or kept)
};

}  // namespace riemesh
