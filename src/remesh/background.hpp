#pragma once
// The background mesh of an adaptation: the input simplices (triangles, D = 2, or tetrahedra,
// D = 3) with their vertex metrics, queried at arbitrary points. New vertices of the remeshed
// mesh take the metric interpolated here, from the *input* field, never from already
// interpolated values (issue 4; BOOK.md §1 "Interpolation of metrics", log-Euclidean by default),
// and vertex fields are transferred by P1 interpolation located by walking (BOOK.md §8).
//
// Point location: a visibility walk (the neighbour across the face with the most negative
// barycentric coordinate, first such face on ties), bounded in steps, from the hint when it lies
// within hint_reach() of p (a few grid cells: the remesher's hints are neighbours), otherwise
// from the simplex nearest the centre of p's cell in a uniform grid (a far hint would cost a
// walk across the mesh). When the walk leaves the domain (non-convex domain, hole, point
// outside) or reaches its step cap, a robust search takes over: the simplices overlapping p's
// cell are tested for containment, and if none contains p, rings of cells are searched for the
// closest boundary face (exact, by the distance lower bound of each ring; the last rings cover
// every face): the closest point of the domain to a point outside it is on its boundary.
// Predicates are plain doubles with a relative tolerance (kBaryTolerance), which is enough here:
// any simplex returned contains p up to that tolerance, and all choices are deterministic.
//
// Queries are const and may run concurrently; only set_metrics (between remeshing stages) changes
// the object.
#include <cstddef>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"
#include "metric/interpolation.hpp"

namespace riemesh {

/// A point located in a background mesh.
template <int D>
struct Location {
  Id simplex = kNoId;    ///< the simplex containing p, or the closest one when !inside
  double bary[D + 1]{};  ///< barycentric coordinates in it, each in [0, 1], summing to 1
  bool inside = false;   ///< false: p is outside the domain, bary are those of its projection
};

/// Counters of locate() calls, accumulated over the calls that receive the same object.
struct LocateStats {
  long queries = 0;
  long walk_steps = 0;  ///< simplices crossed by the walks
  long fallbacks = 0;   ///< walks that left the domain or hit the step cap
  long outside = 0;     ///< queries answered by a projection (inside == false)
};

/// Barycentric coordinates down to -kBaryTolerance count as inside (then clamped to 0).
inline constexpr double kBaryTolerance = 1e-12;

template <int D>
class BackgroundMesh {
  static_assert(D == 2 || D == 3, "BackgroundMesh is for triangles (2) or tetrahedra (3)");

 public:
  static constexpr int kVerts = D + 1;

  /// From flat arrays: D coordinates per vertex, D + 1 vertex ids per simplex, one packed
  /// SymMat<D> per vertex (core/symmat.hpp order). Copies what it needs. Throws InputError for
  /// a size mismatch, an id out of range, a simplex of zero or non-finite measure, or a metric
  /// that is not SPD (vertices and simplices named 1-based, as in Medit files).
  BackgroundMesh(std::span<const double> coords, std::span<const Id> simplices,
                 std::span<const double> metrics,
                 InterpScheme scheme = InterpScheme::kLogEuclidean);

  /// Taking over the arrays (no copy: memory, issue #7): vertices, D + 1 vertex ids per simplex,
  /// one metric per vertex, and optionally the neighbours (elem2elem of build_face_adjacency of
  /// the same simplices; empty: built here). Same checks and errors as the span constructor.
  BackgroundMesh(std::vector<Vec<D>>&& coords, std::vector<Id>&& simplices,
                 std::vector<SymMat<D>>&& metrics,
                 InterpScheme scheme = InterpScheme::kLogEuclidean,
                 std::vector<Id>&& elem2elem = {});

  /// From a mesh: its triangles (D = 2, mesh.dim == 2) or tetrahedra (D = 3, a volume).
  /// `adjacency`, when given, is build_adjacency of the same simplices (saves rebuilding it).
  BackgroundMesh(const Mesh& mesh, std::span<const double> metrics,
                 InterpScheme scheme = InterpScheme::kLogEuclidean,
                 const Adjacency* adjacency = nullptr);

  /// Replaces the vertex metrics (one per vertex, SPD), keeping the mesh and its search
  /// structures: the staged approach of a remesher to its target field (adapt3d.cpp). Throws
  /// InputError for a size mismatch or a metric that is not SPD, leaving the field unchanged.
  void set_metrics(std::vector<SymMat<D>>&& metrics);

  /// The vertex metrics.
  std::span<const SymMat<D>> metrics() const { return metrics_; }

  /// Locates p by walking from `hint` (a simplex id; kNoId, or a hint whose first vertex is
  /// farther than hint_reach() from p: from p's grid cell).
  /// Never fails: returns the containing simplex, or the closest one with inside == false.
  /// Throws InputError for a non-finite point or a hint out of range.
  Location<D> locate(const Vec<D>& p, Id hint = kNoId, LocateStats* stats = nullptr) const;

  /// The metric at a location: the vertex metrics of its simplex interpolated with its
  /// barycentric coordinates in the scheme given at construction (exactly the vertex metric
  /// when a coordinate is 1).
  SymMat<D> metric_at(const Location<D>& loc) const;

  /// locate then metric_at; *found receives the simplex (the hint for a nearby next query).
  SymMat<D> metric_at(const Vec<D>& p, Id hint, Id* found = nullptr) const;

  /// P1 interpolation of a vertex field of `components` doubles per vertex at a location:
  /// out[c] = Σ bᵢ values[components·vᵢ + c]. Throws InputError for mismatched sizes.
  void interpolate_fields(const Location<D>& loc, std::span<const double> values, int components,
                          std::span<double> out) const;

  std::size_t num_vertices() const { return coords_.size(); }
  std::size_t num_simplices() const { return simplices_.size() / kVerts; }
  InterpScheme scheme() const { return scheme_; }
  const Vec<D>& vertex(Id v) const { return coords_[static_cast<std::size_t>(v)]; }
  std::span<const Id, kVerts> simplex(Id s) const {
    return std::span<const Id, kVerts>(&simplices_[kVerts * static_cast<std::size_t>(s)], kVerts);
  }
  /// The neighbour of simplex s across its face i (opposite local vertex i), or kNoId.
  Id neighbour(Id s, int i) const { return elem2elem_[kVerts * static_cast<std::size_t>(s) + i]; }
  /// The walk's step cap (beyond it the robust search takes over).
  int max_walk_steps() const { return max_walk_steps_; }
  /// Hints farther than this from p (from their first vertex) are replaced by the grid start.
  double hint_reach() const { return hint_reach_; }

 private:
  /// Uniform grid over the vertices' bounding box; cell c lists the simplices whose bounding
  /// box overlaps it (CSR, increasing ids), and starts a hint-free walk at start[c].
  struct Grid {
    Vec<D> lo{};
    Vec<D> cell{};      // cell sides
    Vec<D> inv_cell{};  // 1 / cell sides
    int n[D]{};         // cells per axis
    std::size_t cells = 0;
    // The lists below are built at the first query that needs them (build_grid_lists): the
    // remesher's queries walk from nearby hints and often never do.
    std::vector<std::size_t> offsets;
    std::vector<Id> ids;
    std::vector<Id> start;  // the listed simplex with centroid nearest the cell centre, or kNoId
    // Boundary faces (slot kVerts·s + i: face i of simplex s, no neighbour) whose bounding box
    // overlaps the cell (CSR, increasing slots): the closest point of the domain to a point
    // outside it lies on one of them (closest_simplex).
    std::vector<std::size_t> face_offsets;
    std::vector<Id> faces;
  };

  void build(std::span<const double> coords, std::span<const Id> simplices,
             std::span<const double> metrics, const Adjacency* adjacency = nullptr);
  /// The checks, volumes, logs, neighbours (unless given) and grid of the arrays in place.
  void finish(std::vector<Id>&& elem2elem);
  /// The grid's shape (the cell lists wait for ensure_grid_lists).
  void build_grid();
  void build_grid_lists() const;
  /// The walk starts alone, without the lists (the same simplices as the lists would give).
  void build_starts() const;
  /// The cells [lo, hi] (per axis) overlapped by simplex s's bounding box.
  void simplex_cells(std::size_t s, int lo[D], int hi[D]) const;
  /// Builds the cell lists once (thread-safe: queries may run concurrently).
  void ensure_grid_lists() const {
    std::call_once(*grid_once_, [this] { build_grid_lists(); });
  }
  /// Builds the walk starts once (a far hint needs only them: ~10x less memory than the lists).
  void ensure_starts() const {
    std::call_once(*starts_once_, [this] { build_starts(); });
  }
  /// Signed sub-volumes Vᵢ(p) (p replacing vertex i) divided by the simplex's volume.
  void barycentric(Id s, const Vec<D>& p, double b[kVerts]) const;
  /// The walk: the simplex containing p, or kNoId when it left the domain or hit the cap.
  Id walk(const Vec<D>& p, Id start, double b[kVerts], long& steps) const;
  Location<D> robust_search(const Vec<D>& p) const;
  /// The simplex closest to p (outside every simplex listed in its cell): the closest boundary
  /// face, or `candidate` (a simplex of p's cell, kNoId: none) when it is at least as close — a
  /// point inside the domain that the containment tolerance missed.
  Location<D> closest_simplex(const Vec<D>& p, Id candidate = kNoId) const;
  void build_face_grid() const;
  void cell_of(const Vec<D>& p, int c[D]) const;
  std::size_t cell_index(const int c[D]) const;

  InterpScheme scheme_;
  std::vector<Vec<D>> coords_;
  std::vector<Id> simplices_;
  std::vector<Id> elem2elem_;
  std::vector<SymMat<D>> metrics_;
  std::vector<SymMat<D>> logs_;  // log M per vertex, for kLogEuclidean only
  mutable Grid grid_;  // the cell lists are filled by ensure_grid_lists
  std::unique_ptr<std::once_flag> grid_once_ = std::make_unique<std::once_flag>();
  std::unique_ptr<std::once_flag> starts_once_ = std::make_unique<std::once_flag>();
  int max_walk_steps_ = 0;
  double hint_reach_ = 0.0;
};

}  // namespace riemesh
