#pragma once
// The boundary and interface curves of a planar triangle mesh, with a smooth reconstruction on
// which the 2D remesher places its boundary vertices (BOOK.md §3 "Curves": discrete curves are
// reconstructed, then remeshed; §1 "Geometric metrics": the --hausd size).
//
// Every boundary vertex of the remeshed mesh carries (curve id, parameter); its position is always
// evaluated on the reconstruction of the INPUT curve, so errors never accumulate over passes.
//
// Reconstruction: per input edge one cubic Bézier (a Hermite segment) through the input vertices.
// The unit tangent at a vertex comes from the tangent angle reconstructed over a stencil of up to
// 5 consecutive vertices (one-sided at corners): chord directions are the mean tangent angles over
// the chords, their primitive is interpolated in chord length and differentiated. It is exact on
// straight lines and on uniformly sampled circles, and gives O(h⁴) positions on smooth curves;
// it falls back to the Bessel tangent (interior) or the symmetric-arc tangent (ends) when it
// strays from them by more than the local turning angle (irregular spacing). Each segment has one
// speed m (derivative magnitude at both ends) = 2c / (1 + cos φ), c the chord, φ the mean angle
// between the end tangents and the chord: the standard cubic approximation of a circular arc
// (error O(θ⁶)), and m = c on a straight chord, so collinear input stays exactly linear in the
// parameter.
// The curve is G1 (unit tangent continuous); the derivative magnitude jumps at input vertices.
//
// Parameters: s in [0, n] for a curve of n input edges; floor(s) is the input edge index along the
// curve and the fractional part the local Bézier parameter. On a closed curve s is taken modulo n
// and every function accepts any real s ("unwrapped" parameters): an arc between s0 and s1 is
// the set of reals between them, so the caller chooses the way round a closed curve by choosing
// the representative of s1 (see unwrap_near).
#include <cstdint>
#include <span>
#include <vector>

#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

struct CurveOptions {
  /// A vertex is a corner when the turning angle between its two feature edges exceeds this
  /// (degrees, in [0, 180]; MMG's -ar).
  double angle_deg = 45.0;
  /// false: no corner from angles (MMG's -nr) but turns of 90 degrees or more, which no smooth
  /// curve follows; tags, junctions and ref changes still make corners.
  bool detect_angles = true;

  /// Throws InputError when angle_deg is not a number in [0, 180].
  void validate() const;
};

/// One curve: a chain of feature edges between two corners (open) or a loop without a corner
/// (closed). Self-contained: evaluation needs no mesh.
struct BoundaryCurve {
  /// Input vertex ids along the curve, n + 1 of them. Open: both ends are corners (the same one
  /// when a loop has a single corner). Closed: vertices[n] == vertices[0], the smallest id.
  std::vector<Id> vertices;
  /// Feature edge ids (indices into BoundaryCurves::edges), n of them; edge k joins vertices k
  /// and k + 1.
  std::vector<Id> edges;
  /// Bézier control polygon, 3n + 1 points; bezier[3k] is the position of vertices[k].
  std::vector<Vec2> bezier;
  /// Cumulative arc length at each vertex: arc_length[0] = 0, arc_length[n] = total length.
  std::vector<double> arc_length;
  std::int32_t ref = 0;  ///< the edge ref shared by all edges of the curve
  bool closed = false;
  /// Open, its control polygon exactly on the line of its ends and in order along it: the
  /// curve is that segment (chord_deviation is 0 on it).
  bool straight = false;
  /// Triangle refs on the left and right of the curve walked by increasing parameter; kNoId
  /// where there is no triangle (outside the domain). Orientation: the domain is on the left of a
  /// boundary curve (outer boundaries counter-clockwise, holes clockwise); an interface has
  /// left_ref < right_ref; otherwise the curve starts at its smaller end vertex id (open) or goes
  /// from its start toward the smaller neighbour id (closed or single-corner loop).
  std::int32_t left_ref = kNoId;
  std::int32_t right_ref = kNoId;

  /// n, the number of segments (input edges).
  int num_edges() const { return static_cast<int>(bezier.size() / 3); }
  /// The parameter range: n.
  double param_end() const { return static_cast<double>(bezier.size() / 3); }
  double total_length() const { return arc_length.back(); }
};

/// A unique feature edge of the input mesh, v0 < v1.
struct FeatureEdge {
  Id v0 = kNoId, v1 = kNoId;
  std::int32_t ref = 0;   ///< ref of the mesh.edges entry, or 0 for an unlisted edge
  Id input_edge = kNoId;  ///< first index in mesh.edges listing it, or kNoId
  Id curve = kNoId;       ///< the curve it belongs to
  Id index = kNoId;       ///< its position k along the curve (parameters [k, k + 1])
};

/// Where an input vertex sits on a curve.
struct CurveVertex {
  Id curve = kNoId;
  double param = 0.0;
};

/// All feature curves of a planar mesh, and the maps from input entities to curves.
struct BoundaryCurves {
  std::vector<BoundaryCurve> curves;
  /// Unique feature edges sorted by (v0, v1).
  std::vector<FeatureEdge> edges;
  /// mesh.edges index -> feature edge id (every listed edge is a feature edge).
  std::vector<Id> input_edge2feature;
  /// Per input vertex: 1 when it is a corner (never moves), else 0.
  std::vector<std::uint8_t> corner;
  /// Per input vertex, the curve positions (CSR): vert2curve[vert2curve_offsets[v] ..
  /// vert2curve_offsets[v + 1]). A non-corner feature vertex has exactly one; a corner one per
  /// curve end touching it (two for the single corner of a loop: params 0 and n); a vertex on no
  /// feature edge none.
  std::vector<Id> vert2curve_offsets;
  std::vector<CurveVertex> vert2curve;

  std::span<const CurveVertex> curves_at(Id v) const {
    const auto b = static_cast<std::size_t>(vert2curve_offsets[v]);
    const auto e = static_cast<std::size_t>(vert2curve_offsets[v + 1]);
    return std::span<const CurveVertex>(vert2curve).subspan(b, e - b);
  }
  /// The feature edge (a, b) in either order, or kNoId.
  Id find_feature_edge(Id a, Id b) const;
};

/// Feature edges of a planar (dim 2) triangle mesh: edges of one triangle (domain boundary, and
/// non-manifold edges), edges between triangles of different refs (interfaces), and every edge of
/// mesh.edges (also inside a subdomain or with no triangle at all). Corners: vertices tagged
/// kTagCorner or kTagRequired, feature degree other than 2, a ref change or a change of the
/// triangle refs on either side, and a turning angle above options.angle_deg. Deterministic: the
/// result depends on the vertex ids, edge refs and triangle refs only, not on the order of the
/// triangles. Throws InputError for a non-planar mesh, bad ids or a zero-length feature edge.
/// `adjacency`, when given, is build_face_adjacency (or build_adjacency) of mesh.triangles
/// (saves rebuilding it; only the neighbours are read).
BoundaryCurves build_boundary_curves(const Mesh& mesh, const CurveOptions& options = {},
                                     const Adjacency* adjacency = nullptr);

/// Sets c.bezier and c.arc_length from the positions of its n + 1 vertices (closed:
/// points[n] == points[0]) and c.closed: the reconstruction described in the file comment.
/// Throws InputError for fewer than 2 points or a zero-length chord.
void build_curve_geometry(BoundaryCurve& c, std::span<const Vec2> points);

// ---- Evaluation (parameters as described in the file comment) ----

/// s reduced to [0, n) on a closed curve, clamped to [0, n] on an open one.
double wrap_param(const BoundaryCurve& c, double s);
/// The representative s + kn (closed curve) nearest to s_ref; s itself on an open curve. For an
/// edge between parameters s0 and s1 on a closed curve, unwrap_near(c, s0, s1) picks the short
/// way round.
double unwrap_near(const BoundaryCurve& c, double s_ref, double s);
/// Position γ(s).
Vec2 point(const BoundaryCurve& c, double s);
/// Derivative dγ/ds (one-sided from the segment on the right at an input vertex, from the left
/// at s = n on an open curve).
Vec2 tangent(const BoundaryCurve& c, double s);
/// Signed curvature (positive where the curve turns left, e.g. on a convex outer boundary).
double curvature(const BoundaryCurve& c, double s);
/// Parameter of the curve's k-th vertex: k.
inline double param_of_vertex(const BoundaryCurve& /*c*/, int k) { return static_cast<double>(k); }
/// Arc length between s0 and s1 (either order; ≥ 0), 8-point Gauss–Legendre per segment piece.
double length(const BoundaryCurve& c, double s0, double s1);
/// The parameter at arc length `fraction` of the way from s0 to s1 (either order; on a closed
/// curve in the same unwrapped branch as s0 and s1).
double param_at_fraction(const BoundaryCurve& c, double s0, double s1, double fraction);
/// The parameter halfway in arc length between s0 and s1: param_at_fraction(c, s0, s1, 0.5).
double midpoint(const BoundaryCurve& c, double s0, double s1);
/// The parameter of the point of the curve nearest to p, searched on the segment containing
/// s_hint and its two neighbours (Newton from sampled starts); on a closed curve in the
/// unwrapped branch of s_hint.
double project(const BoundaryCurve& c, const Vec2& p, double s_hint);

/// Chord length whose sagitta on a circle of radius `radius` is `hausd`:
/// 2 sqrt(hausd (2 radius − hausd)) (= radius · alpha_from_gap(hausd / radius)); 2 radius when
/// hausd ≥ radius; +inf for an infinite radius.
double hausd_chord_length(double radius, double hausd);
/// The size --hausd allows at parameter s: hausd_chord_length(1 / |curvature(c, s)|, hausd);
/// +inf on a straight piece.
double hausd_size(const BoundaryCurve& c, double s, double hausd);
/// Largest distance from the curve between s0 and s1 to the chord [γ(s0), γ(s1)], sampled at
/// max(samples, 8 per input segment spanned) parameters.
double chord_deviation(const BoundaryCurve& c, double s0, double s1, int samples = 32);

}  // namespace riemesh
