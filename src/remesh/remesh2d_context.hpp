#pragma once
// The state of one 2D adaptation (internal to remesh/): the mesh being changed, the background
// mesh with the input metric field, the input's boundary curves, and the geometric rules that
// place new and moved vertices (on the curves, at metric midpoints) and give them their metric.
#include <optional>
#include <vector>

#include "remesh/adapt2d.hpp"
#include "remesh/background.hpp"
#include "remesh/boundary_curves.hpp"
#include "remesh/ops2d.hpp"

namespace riemesh {

class Remesh2dContext {
 public:
  /// Takes the (clipped, graded) input metrics and the input's triangle adjacency; the mesh's
  /// vertex ids become TriMesh ids.
  Remesh2dContext(const Mesh& input, std::span<const SymMat2> metrics,
                  const Adapt2dOptions& options, const Adjacency& adjacency);

  TriMesh& mesh() { return mesh_; }
  const TriMesh& mesh() const { return mesh_; }
  const Adapt2dOptions& options() const { return options_; }

  /// The vertex to insert at the middle of the edge at `slot`: the metric midpoint of an interior
  /// edge, the arc-length midpoint along the curve of a feature edge.
  NewVertex split_point(Id slot) const;

  /// The metric for a vertex at p (on curve `curve` at parameter s, or kNoCurve), from the
  /// background field near the hint vertex's location, tightened along the curve for hausd.
  SymMat2 metric_for(const Vec2& p, std::int32_t curve, double s, Id hint_vertex) const;
  /// m tightened along curve `curve` at parameter s so that chords stay within hausd.
  SymMat2 tightened(SymMat2 m, std::int32_t curve, double s) const;

  /// Where smoothing would put v (inside: metric-weighted average of the unit-length points
  /// seen from its neighbours; on a curve: the curve point balancing the metric lengths to its
  /// two curve neighbours). False when v may not move, or when the move would be shorter than
  /// `min_move` in v's metric (then the background is not queried: that query is most of the
  /// cost of smoothing a converged mesh). `ball`: v's ball (collect_ball) when the caller has it.
  bool smoothing_target(Id v, NewVertex& out, double min_move = 0.0,
                        const Ball* ball = nullptr) const;

  /// Where v gives its ball the best worst quality, where the metric turns across the ball
  /// (a thin curved layer: there unit lengths and good shapes pull apart, and the length-driven
  /// smoothing_target leaves poor balls): a pattern search from v's position in steps measured
  /// in v's metric, or along its curve, each candidate with its metric from the background; no
  /// edge of v may leave [1/√2, √2] or get further from it, lengths by the 3-point Gauss rule
  /// (edge_length_gauss3: Simpson's rule reads the layer's tangential chords 6–19% short, and
  /// moves kept in its band pushed them out of the field's). False when the metrics of the
  /// ball commute or when no candidate raises the ball's worst quality `worst` by more than 1e-3.
  /// With `length_floor` > 0: the position where v's edges are least outside [1/√2, √2], no
  /// ball triangle below min(worst, length_floor); false when none is better by 1e-3 in the sum
  /// of their length_badness beyond √2.
  bool quality_target(Id v, const Ball& ball, double worst, NewVertex& out,
                      double length_floor = 0.0) const;

  /// For a collapse of `from` (on a curve) into `to`: true when the chord that replaces the two
  /// curve edges at `from` stays within hausd of the curve.
  bool collapse_keeps_hausd(Id from, Id to) const;

  /// Records, for vertex v just created or moved, the background triangle found by the last
  /// metric_for query (the start of its next walk).
  void inherit_hint(Id v, Id near);

  /// Renumbers the vertices created since the start (ids from the input's vertex count on) and
  /// the triangles for locality (renumber_tail), the hints in step. Returns old -> new vertex
  /// ids (kNoId: dead, dropped) for the caller's per-vertex data.
  std::vector<Id> renumber_new_vertices();

 private:
  /// Parameter of vertex v on curve c, in the unwrapped branch nearest to `near`.
  double param_on(Id v, std::int32_t c, double near) const;
  /// The two vertices joined to v by feature edges of v's curve (kNoId when missing); `ball`:
  /// v's ball when the caller has it.
  void curve_neighbours(Id v, Id& prev, Id& next, const Ball* ball = nullptr) const;

  Adapt2dOptions options_;
  BoundaryCurves curves_;
  /// The input field: its one metric when it is the same at every vertex (no background mesh
  /// built or searched: a 2.3 M-triangle 1:10⁴ lattice spent 59% of its run locating), else
  /// the background mesh that interpolates it.
  std::optional<SymMat2> constant_;
  std::optional<BackgroundMesh<2>> background_;
  TriMesh mesh_;
  std::vector<Id> hint_;            // per vertex: a background triangle near it
  mutable Id last_found_ = kNoId;   // background triangle of the last metric_for query
  std::size_t num_input_vertices_ = 0;
};

}  // namespace riemesh
