#pragma once
// Local operators of the 2D remesher on a TriMesh: edge split, edge collapse, edge swap and vertex
// relocation (BOOK.md §7). Each checks its own admissibility and returns an Outcome: a rejection
// is a normal answer, counted by the driver, not an error. They never create an inverted or
// degenerate triangle and never change the domain's boundary curves or refs.
#include <cmath>
#include <vector>

#include "metric/edge_length.hpp"
#include "remesh/tri_mesh.hpp"
#include "remesh/vertex_logs.hpp"

namespace riemesh {

enum class Outcome { kApplied, kRejectedTopology, kRejectedGeometry, kRejectedQuality };

/// Metric length of edge (a, b): Simpson's rule on the log-Euclidean interpolated field, or the
/// UGAWG closed form (l_a − l_b)/ln(l_a/l_b) when the end metrics commute (edge_length_simpson).
inline double edge_length(const TriMesh& m, Id a, Id b) {
  return edge_length_simpson(m.metric[a], m.metric[b], m.xy[b] - m.xy[a], log_of(m.log_metric, a),
                             log_of(m.log_metric, b));
}

/// Metric length of edge (a, b) by the 3-point Gauss–Legendre rule where the end metrics do not
/// commute (edge_length_gauss3: closer to the field's length than Simpson's rule across a curved
/// layer), else the closed form. The relocations after the passes measure the band with it.
inline double edge_length_gauss3(const TriMesh& m, Id a, Id b) {
  return edge_length_gauss3(m.metric[a], m.metric[b], m.xy[b] - m.xy[a], log_of(m.log_metric, a),
                            log_of(m.log_metric, b));
}

/// The sign of edge_length(m, a, b) − limit (0 only when equal); for commuting end metrics the
/// logarithm only when needed (compare_edge_length_geometric).
inline int compare_edge_length(const TriMesh& m, Id a, Id b, double limit) {
  return compare_edge_length_simpson(m.metric[a], m.metric[b], m.xy[b] - m.xy[a], limit,
                                     log_of(m.log_metric, a), log_of(m.log_metric, b));
}

/// Mean-ratio quality 4√3 |K|_M / Σ l_M² of triangle (pa, pb, pc) in the metric `mm` (1 for the
/// unit equilateral triangle, <= 0 when inverted).
inline double quality_in(const SymMat2& mm, const Vec2& pa, const Vec2& pb, const Vec2& pc) {
  const Vec2 e0 = pb - pa, e1 = pc - pb, e2 = pa - pc;
  const double l2 = quadratic(mm, e0) + quadratic(mm, e1) + quadratic(mm, e2);
  const double area = std::sqrt(det(mm)) * 0.5 * cross(e0, pc - pa);
  return 6.928203230275509 * area / l2;  // 4√3
}

/// The metric a triangle is measured in, from its vertex metrics and their logarithms: the
/// coefficient-wise mean when they commute (isotropic or axis-aligned: cheap and close), else the
/// log-Euclidean mean exp(Σ log M_i / 3). Where the metric turns across the triangle (a thin
/// layer along a curved wall) the plain mean overweights the largest eigenvalues and sees the
/// triangle as far better than it is (as tet_metric in 3D).
inline SymMat2 tri_metric(const SymMat2& ma, const SymMat2* la, const SymMat2& mb,
                          const SymMat2* lb, const SymMat2& mc, const SymMat2* lc) {
  if (commute(ma, mb) && commute(ma, mc) && commute(mb, mc)) return (1.0 / 3.0) * (ma + mb + mc);
  const auto log_or = [](const SymMat2& m, const SymMat2* l) { return l ? *l : log_spd(m); };
  return exp_sym_2d((1.0 / 3.0) * (log_or(ma, la) + log_or(mb, lb) + log_or(mc, lc)));
}

/// Quality of a triangle in tri_metric, used consistently for every decision.
inline double tri_quality(const TriMesh& m, Id a, Id b, Id c) {
  // No logarithms kept: every vertex metric is diagonal, so they commute (tri_metric's mean).
  const SymMat2 mm =
      m.log_metric.empty()
          ? (1.0 / 3.0) * (m.metric[a] + m.metric[b] + m.metric[c])
          : tri_metric(m.metric[a], log_of(m.log_metric, a), m.metric[b], log_of(m.log_metric, b),
                       m.metric[c], log_of(m.log_metric, c));
  return quality_in(mm, m.xy[a], m.xy[b], m.xy[c]);
}
inline double tri_quality(const TriMesh& m, Id t) {
  return tri_quality(m, m.tv[3 * t], m.tv[3 * t + 1], m.tv[3 * t + 2]);
}

/// A vertex to insert: position, metric and, on a feature curve, its curve and parameter.
struct NewVertex {
  Vec2 p;
  SymMat2 metric;
  std::int32_t curve = kNoCurve;
  double param = 0.0;
};

/// Splits the edge at `slot` (and its neighbour's copy) at nv. Rejected (geometry) when a new
/// triangle would not have a positive area, or (quality) when one on a boundary or interface edge
/// (a feature edge of the triangle cut, not the split edge) would be below both min_quality and
/// the quality of the triangle it is cut from. On success *created is the new vertex.
Outcome split_edge(TriMesh& m, Id slot, const NewVertex& nv, double min_quality, Id* created);

/// Limits a collapse must respect in the triangles it changes.
struct CollapseLimits {
  double min_quality = 0.3;   // no changed triangle below this
  double max_length = 1.5;    // no new edge longer than this in the metric
  /// Below min_quality, a changed triangle must stay at least this fraction of the ball's worst
  /// quality (1: never worse than before; lower values let collapses clear clusters of
  /// near-duplicate vertices whose every collapse makes some sliver slightly worse).
  double relative_floor = 1.0;
};

/// Removes vertex `from` by merging it into `to` along the edge at `slot` (which joins them).
/// Frozen vertices never go; a vertex on a feature curve only moves along its curve.
/// `from_ball`: from's ball (collect_ball) when the caller has it.
Outcome collapse_edge(TriMesh& m, Id slot, Id from, Id to, const CollapseLimits& limits,
                      const Ball* from_ball = nullptr);

/// True when collapse_edge(m, slot, from, to, limits) would be refused by its length test alone
/// (a new edge (to, x) longer than limits.max_length). The test depends only on from's
/// neighbours and on the positions and metrics of from's neighbours and of to.
bool collapse_too_long(const TriMesh& m, Id from, Id to, const CollapseLimits& limits);

/// Flips the interior edge at `slot` when the smaller quality of the two triangles grows by more
/// than `min_gain`. Feature edges are never flipped.
Outcome swap_edge(TriMesh& m, Id slot, double min_gain);

/// Lawson's flips around a vertex v just inserted: each edge opposite v in its ball (its link)
/// whose triangle with v has a quality below `below` is flipped by swap_edge(min_gain), and the
/// two link edges a flip gives v's ball are tried in turn, at most `max_tries` edges in all.
/// Appends the vertices of each flipped quadrilateral other than v to `touched`; returns the
/// flips.
int swap_around(TriMesh& m, Id v, double min_gain, double below, int max_tries,
                std::vector<Id>& touched);

/// Moves vertex v to p (with its new metric and curve parameter) when every triangle of its ball
/// stays valid and the smallest quality of the ball does not drop below min(old, floor).
/// `ball`: v's ball (collect_ball) when the caller has it; `worst`: the smallest tri_quality of
/// its triangles when the caller has it.
Outcome move_vertex(TriMesh& m, Id v, const Vec2& p, const SymMat2& metric, double param,
                    double floor, const Ball* ball = nullptr, const double* worst = nullptr);

}  // namespace riemesh
