#include "remesh/remesh2d_context.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "metric/metric.hpp"
#include "remesh/pass_summary.hpp"
#include "remesh/renumber_tail.hpp"
#include "remesh/tri_mesh_io.hpp"
#include "remesh/vertex_logs.hpp"

namespace riemesh {
namespace {

constexpr double kBandBadness = 1.4142135623730951;  // length_badness at both ends of the band

/// The background mesh of the input, its arrays built straight in their final form (no flat
/// metric copy, no zero fill before the copy): 1.76 M triangles, ~0.1 s less.
BackgroundMesh<2> make_background(const Mesh& input, std::span<const SymMat2> metrics,
                                  InterpScheme scheme, const Adjacency& adjacency) {
  const std::size_t nv = input.num_vertices();
  std::vector<Vec2> coords;
  reserve_huge(coords, nv);
  for (std::size_t v = 0; v < nv; ++v)
    coords.push_back(Vec2{{input.coords[2 * v], input.coords[2 * v + 1]}});
  std::vector<Id> simplices, neighbours;
  std::vector<SymMat2> vertex_metrics;
  reserve_huge(simplices, input.triangles.size());
  simplices.assign(input.triangles.begin(), input.triangles.end());
  reserve_huge(vertex_metrics, metrics.size());
  vertex_metrics.assign(metrics.begin(), metrics.end());
  reserve_huge(neighbours, adjacency.elem2elem.size());
  neighbours.assign(adjacency.elem2elem.begin(), adjacency.elem2elem.end());
  return BackgroundMesh<2>(std::move(coords), std::move(simplices), std::move(vertex_metrics),
                           scheme, std::move(neighbours));
}

/// Where to split an edge of metric length L running from density la to lb: at the fraction of
/// its length k/n, n = max(2, round(L)), k = ⌊n/2⌋, so that repeated splits cut it into n pieces
/// of length L/n ≈ 1 rather than into 2^j pieces (bisection refines a uniform coarse mesh to the
/// power of two below the target size: 1.6x the triangles of a unit mesh).
double split_fraction(double la, double lb) {
  const double q = lb / la;
  const double total = std::abs(q - 1.0) < 1e-9 ? la : la * (q - 1.0) / std::log(q);
  const long n = std::max(2L, std::lround(total));
  const double f = static_cast<double>(n / 2) / static_cast<double>(n);
  if (std::abs(q - 1.0) < 1e-9) return f;
  return std::log(1.0 + f * (q - 1.0)) / std::log(q);
}

}  // namespace

Remesh2dContext::Remesh2dContext(const Mesh& input, std::span<const SymMat2> metrics,
                                 const Adapt2dOptions& options, const Adjacency& adjacency)
    : options_(options),
      curves_(build_boundary_curves(input, {options.angle_deg, options.detect_angles}, &adjacency)),
      constant_(same_metric<2>(metrics)),
      num_input_vertices_(input.num_vertices()) {
  if (!constant_) background_.emplace(make_background(input, metrics, options.interp, adjacency));
  const std::size_t nv = input.num_vertices();
  std::vector<TriFeature> features;
  for (const FeatureEdge& f : curves_.edges) {
    const bool required = f.input_edge != kNoId && !input.edge_tag.empty() &&
                          (input.edge_tag[f.input_edge] & kTagRequired);
    features.push_back({f.v0, f.v1, static_cast<std::int32_t>(f.curve),
                        curves_.curves[f.curve].ref,
                        static_cast<std::uint8_t>(required ? kTagRequired : kTagNone)});
  }
  std::vector<VertexCurve> vcurves;
  reserve_huge(vcurves, nv);
  vcurves.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const auto at = curves_.curves_at(static_cast<Id>(v));
    if (!curves_.corner[v] && !at.empty())
      vcurves[v] = {static_cast<std::int32_t>(at[0].curve), at[0].param};
  }
  // Corners are tagged on the TriMesh (not on a tagged copy of the input: a copy of 1.76 M
  // triangles costs 0.15 s).
  mesh_ = build_tri_mesh(input, metrics, features, vcurves, &adjacency);
  for (std::size_t v = 0; v < nv; ++v)
    if (curves_.corner[v]) mesh_.vtag[v] |= kTagCorner;
  hint_.assign(nv, kNoId);
  for (std::size_t t = 0; t < input.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      Id& h = hint_[input.triangles[3 * t + i]];
      if (h == kNoId) h = static_cast<Id>(t);
    }
  // Boundary vertices get the metric tightened along their curve for hausd; corners along each
  // curve they end (untightened, a corner's metric halved the length of the chords next to it:
  // a circle in 5 refs at --hausd 1e-4 had chords 3 times too long there, 9.4 hausd off it).
  for (std::size_t v = 0; v < nv; ++v) {
    if (mesh_.on_curve(static_cast<Id>(v))) {
      mesh_.metric[v] =
          metric_for(mesh_.xy[v], mesh_.vcurve[v], mesh_.vparam[v], static_cast<Id>(v));
    } else if (curves_.corner[v]) {
      for (const CurveVertex& cv : curves_.curves_at(static_cast<Id>(v)))
        mesh_.metric[v] = tightened(mesh_.metric[v], static_cast<std::int32_t>(cv.curve), cv.param);
    } else {
      continue;
    }
    sync_log(mesh_.metric, mesh_.log_metric, v);
  }
}

double Remesh2dContext::param_on(Id v, std::int32_t c, double near) const {
  const BoundaryCurve& curve = curves_.curves[c];
  if (mesh_.vcurve[v] == c) return unwrap_near(curve, near, mesh_.vparam[v]);
  double best = near, dist = std::numeric_limits<double>::infinity();
  if (static_cast<std::size_t>(v) < num_input_vertices_) {
    for (const CurveVertex& cv : curves_.curves_at(v)) {
      if (cv.curve != c) continue;
      const double s = unwrap_near(curve, near, cv.param);
      if (std::abs(s - near) < dist) best = s, dist = std::abs(s - near);
    }
  }
  return best;
}

SymMat2 Remesh2dContext::metric_for(const Vec2& p, std::int32_t curve, double s,
                                    Id hint_vertex) const {
  Id found = kNoId;
  const Id hint = static_cast<std::size_t>(hint_vertex) < hint_.size() ? hint_[hint_vertex] : kNoId;
  SymMat2 m = constant_ ? *constant_ : background_->metric_at(p, hint, &found);
  last_found_ = found;
  return tightened(m, curve, s);
}

SymMat2 Remesh2dContext::tightened(SymMat2 m, std::int32_t curve, double s) const {
  if (curve == kNoCurve || !(options_.hausd > 0.0)) return m;
  const BoundaryCurve& c = curves_.curves[curve];
  // Unit edges may reach √2 in length and the sagitta grows as the square of the chord, so the
  // size along the curve is the hausd chord divided by √2: chords of metric length √2 then
  // still stay within hausd.
  const double h = std::max(hausd_size(c, s, options_.hausd) * 0.7071067811865476, options_.hmin);
  if (!std::isfinite(h)) return m;
  // Rank-one tightening along the unit tangent T: M + (1/h² − TᵀMT) TTᵀ when the metric allows
  // more than h along the curve; lengths across the curve are unchanged.
  const Vec2 t = normalize(tangent(c, s));
  const double add = 1.0 / (h * h) - quadratic(m, t);
  if (add > 0.0) m += add * outer(t);
  return m;
}

void Remesh2dContext::inherit_hint(Id v, Id /*near*/) {
  if (hint_.size() <= static_cast<std::size_t>(v)) hint_.resize(v + 1, kNoId);
  hint_[v] = last_found_;
}

std::vector<Id> Remesh2dContext::renumber_new_vertices() {
  std::vector<Id> old2new = renumber_tail(mesh_, static_cast<Id>(num_input_vertices_));
  detail::remap_records(hint_, old2new, mesh_.vertex_capacity(), kNoId);
  return old2new;
}

NewVertex Remesh2dContext::split_point(Id slot) const {
  const Id a = mesh_.edge_from(slot), b = mesh_.edge_to(slot);
  const Vec2 ab = mesh_.xy[b] - mesh_.xy[a];
  const double t = split_fraction(length(mesh_.metric[a], ab), length(mesh_.metric[b], ab));
  const Id near = t < 0.5 ? a : b;
  NewVertex nv;
  const std::int32_t c = mesh_.ecurve[slot];
  if (c == kNoCurve) {
    nv.p = mesh_.xy[a] + t * ab;
    nv.metric = metric_for(nv.p, kNoCurve, 0.0, near);
    return nv;
  }
  const BoundaryCurve& curve = curves_.curves[c];
  const double raw_a = mesh_.vcurve[a] == c ? mesh_.vparam[a] : param_on(a, c, 0.0);
  const double sb = param_on(b, c, raw_a);
  const double sa = param_on(a, c, sb);
  const double s = param_at_fraction(curve, sa, sb, t);
  nv.p = point(curve, s);
  nv.curve = c;
  nv.param = wrap_param(curve, s);
  nv.metric = metric_for(nv.p, c, s, near);
  return nv;
}

void Remesh2dContext::curve_neighbours(Id v, Id& prev, Id& next, const Ball* ball) const {
  prev = next = kNoId;
  thread_local Ball own;
  if (ball == nullptr) {
    collect_ball(mesh_, v, own);
    ball = &own;
  }
  const std::int32_t c = mesh_.vcurve[v];
  Id found[2] = {kNoId, kNoId};
  int n = 0;
  for (const Id t : ball->tris) {
    const int i = vertex_index(mesh_, t, v);
    const Id cand[2] = {mesh_.tv[3 * t + (i + 2) % 3], mesh_.tv[3 * t + (i + 1) % 3]};
    const Id slots[2] = {3 * t + (i + 1) % 3, 3 * t + (i + 2) % 3};
    for (int k = 0; k < 2; ++k)
      if (mesh_.ecurve[slots[k]] == c && n < 2 && (n == 0 || found[0] != cand[k]))
        found[n++] = cand[k];
  }
  if (n < 2) return;
  const double s = mesh_.vparam[v];
  const bool first_before = param_on(found[0], c, s) < s;
  prev = first_before ? found[0] : found[1];
  next = first_before ? found[1] : found[0];
}

bool Remesh2dContext::smoothing_target(Id v, NewVertex& out, double min_move,
                                       const Ball* ball) const {
  if (mesh_.frozen(v)) return false;
  const std::int32_t c = mesh_.vcurve[v];
  if (c == kNoCurve) {
    thread_local Ball own;
    if (ball == nullptr) {
      collect_ball(mesh_, v, own);
      ball = &own;
    }
    if (!ball->closed) return false;
    Vec2 sum = Vec2::zero();
    for (const Id t : ball->tris) {
      const Id x = mesh_.tv[3 * t + (vertex_index(mesh_, t, v) + 1) % 3];
      const double l = edge_length(mesh_, x, v);
      sum += mesh_.xy[x] + (mesh_.xy[v] - mesh_.xy[x]) / l;  // unit metric length from x
    }
    out.p = sum / static_cast<double>(ball->tris.size());
    if (min_move > 0.0 && length(mesh_.metric[v], out.p - mesh_.xy[v]) < min_move) return false;
    out.curve = kNoCurve;
    out.metric = metric_for(out.p, kNoCurve, 0.0, v);
    return true;
  }
  Id prev, next;
  curve_neighbours(v, prev, next, ball);
  if (prev == kNoId) return false;
  const BoundaryCurve& curve = curves_.curves[c];
  const double s = mesh_.vparam[v];
  const double sp = param_on(prev, c, s), sn = param_on(next, c, s);
  const double a1 = length(curve, sp, s), a2 = length(curve, s, sn);
  if (!(a1 > 0.0 && a2 > 0.0)) return false;
  // Metric length per unit arc on each side; balance the two metric lengths.
  const double d1 = edge_length(mesh_, prev, v) / a1, d2 = edge_length(mesh_, v, next) / a2;
  // (Sizes 1e7 times the domain's make both lengths 0: the fraction was NaN, and so the curve
  // parameter, which crashed the curve's evaluation: QA hunt 5 F1.)
  if (!(d1 + d2 > 0.0) || !std::isfinite(d1 + d2)) return false;
  const double snew = param_at_fraction(curve, sp, sn, d2 / (d1 + d2));
  // Sliding along the curve lengthens one of the two chords: keep both within hausd.
  if (options_.hausd > 0.0 && (chord_deviation(curve, sp, snew) > options_.hausd ||
                               chord_deviation(curve, snew, sn) > options_.hausd))
    return false;
  out.p = point(curve, snew);
  if (min_move > 0.0 && length(mesh_.metric[v], out.p - mesh_.xy[v]) < min_move) return false;
  out.curve = c;
  out.param = wrap_param(curve, snew);
  out.metric = metric_for(out.p, c, snew, v);
  return true;
}

bool Remesh2dContext::quality_target(Id v, const Ball& ball, double worst, NewVertex& out,
                                     double length_floor) const {
  const std::int32_t curve = mesh_.vcurve[v];
  if (mesh_.frozen(v) || (curve == kNoCurve && !ball.closed)) return false;
  // Only where the metric turns across the ball: elsewhere (isotropic or axis-aligned fields)
  // the length-driven smoothing already gives good shapes, and their outputs stay as they were
  // (linear2d h0 = 1e-5 lost 0.14 of q min through a different path from the coarse start).
  // Its neighbours (on a curve the ball is open: one more than its triangles).
  thread_local std::vector<Id> around;
  around.clear();
  bool turns = false;
  for (const Id t : ball.tris) {
    const int i = vertex_index(mesh_, t, v);
    for (const Id x : {mesh_.tv[3 * t + (i + 1) % 3], mesh_.tv[3 * t + (i + 2) % 3]}) {
      if (std::find(around.begin(), around.end(), x) != around.end()) continue;
      around.push_back(x);
      turns = turns || !commute(mesh_.metric[v], mesh_.metric[x]);
    }
  }
  if (!turns) return false;
  // The score of v at p (on the curve at parameter s): the ball's worst quality, or with
  // `length_floor` the opposite of how far v's edges are outside [1/√2, √2] in all (their
  // length_badness beyond √2). −inf when not above `beat` (scores), when a triangle would not be
  // positive, when one of v's edges would leave the band or, outside, get further from it than
  // it is now (`before[k]`: the edge to around[k]), or with `length_floor` when a
  // triangle would fall below min(worst, length_floor). Cheapest tests first: areas, then the
  // metric at p, then the qualities (from the triangle that was worst last time), then lengths.
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  const bool lengths = length_floor > 0.0;
  const double q_floor = std::min(worst, length_floor);
  thread_local std::vector<double> before;
  before.clear();
  double excess_now = 0.0;
  for (const Id a : around) {
    const double bad = length_badness(edge_length_gauss3(mesh_, v, a));
    before.push_back(std::max(kBandBadness, bad));
    excess_now += std::max(0.0, bad - kBandBadness);
  }
  if (lengths && !(excess_now > 0.0)) return false;
  const std::size_t n = ball.tris.size();
  std::size_t first = 0;
  const auto ball_worst = [&](const Vec2& p, double s, double beat) {
    for (const Id t : ball.tris) {
      const int i = vertex_index(mesh_, t, v);
      const Id a = mesh_.tv[3 * t + (i + 1) % 3], b = mesh_.tv[3 * t + (i + 2) % 3];
      if (!(signed_area(p, mesh_.xy[a], mesh_.xy[b]) >
            1e-6 * std::abs(signed_area(mesh_.xy[v], mesh_.xy[a], mesh_.xy[b]))))
        return kNone;
    }
    const SymMat2 mp = metric_for(p, curve, s, v);
    const SymMat2 lp = log_spd(mp);
    double q = 2.0;
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t k = (first + j) % n;
      const Id t = ball.tris[k];
      const int i = vertex_index(mesh_, t, v);
      const Id a = mesh_.tv[3 * t + (i + 1) % 3], b = mesh_.tv[3 * t + (i + 2) % 3];
      const SymMat2 mm = tri_metric(mp, &lp, mesh_.metric[a], log_of(mesh_.log_metric, a),
                                    mesh_.metric[b], log_of(mesh_.log_metric, b));
      const double qk = quality_in(mm, p, mesh_.xy[a], mesh_.xy[b]);
      if (lengths ? !(qk >= q_floor) : !(qk > beat)) {
        first = k;
        return kNone;
      }
      q = std::min(q, qk);
    }
    double excess = 0.0;
    for (std::size_t k = 0; k < around.size(); ++k) {
      const Id a = around[k];
      const double bad = length_badness(edge_length_gauss3(
          mp, mesh_.metric[a], mesh_.xy[a] - p, &lp, log_of(mesh_.log_metric, a)));
      if (bad > before[k]) return kNone;
      excess += std::max(0.0, bad - kBandBadness);
    }
    if (!lengths) return q;
    return -excess > beat ? -excess : kNone;
  };
  const double start = lengths ? -excess_now : worst;
  double best = start;
  if (curve != kNoCurve) {
    // On a curve: along it between v's two curve neighbours, by the fraction f of the arc
    // length from the previous one (steps of 0.1 halved down to 0.005; f within [0.1, 0.9]).
    Id prev, next;
    curve_neighbours(v, prev, next, &ball);
    if (prev == kNoId) return false;
    const BoundaryCurve& c = curves_.curves[curve];
    const double s = mesh_.vparam[v];
    const double sp = param_on(prev, curve, s), sn = param_on(next, curve, s);
    const double a1 = length(c, sp, s), a2 = length(c, s, sn);
    if (!(a1 > 0.0 && a2 > 0.0)) return false;
    double f = a1 / (a1 + a2), best_s = s;
    for (double step = 0.1; step > 0.005;) {
      double pick_f = f, pick_s = best_s, pick_q = best;
      for (const double fc : {f - step, f + step}) {
        if (!(fc >= 0.1 && fc <= 0.9)) continue;
        const double sc = param_at_fraction(c, sp, sn, fc);
        const double q = ball_worst(point(c, sc), sc, pick_q);
        if (q > pick_q) pick_f = fc, pick_s = sc, pick_q = q;
      }
      if (pick_q > best) f = pick_f, best_s = pick_s, best = pick_q;
      else step *= 0.5;
    }
    // Sliding lengthens one of the two chords: both must stay within hausd (tested once, at
    // the end: the sampled deviation costs more than the search).
    if (!(best > start + 1e-3) ||
        (options_.hausd > 0.0 && (chord_deviation(c, sp, best_s) > options_.hausd ||
                                  chord_deviation(c, best_s, sn) > options_.hausd)))
      return false;
    out.p = point(c, best_s);
    out.curve = curve;
    out.param = wrap_param(c, best_s);
    out.metric = metric_for(out.p, curve, best_s, v);  // also leaves last_found_ for inherit_hint
    return true;
  }
  // Inside: unit metric steps along v's principal directions, 0.25 halved down to 0.01 (their
  // diagonals too cost 20% more instructions for no better result on polar2d).
  const SymEigen<2> e = eigen(mesh_.metric[v]);
  const double h0 = 1.0 / std::sqrt(e.values[0]), h1 = 1.0 / std::sqrt(e.values[1]);
  const Vec2 u0{{e.vectors(0, 0) * h0, e.vectors(1, 0) * h0}};
  const Vec2 u1{{e.vectors(0, 1) * h1, e.vectors(1, 1) * h1}};
  const Vec2 dirs[4] = {u0, u1, -1.0 * u0, -1.0 * u1};
  Vec2 p = mesh_.xy[v];
  double step = 0.25;
  for (int round = 0; round < 12 && step > 0.01; ++round) {
    Vec2 pick_p = p;
    double pick_q = best;
    for (int k = 0; k < 4; ++k) {
      const Vec2 c = p + step * dirs[k];
      const double q = ball_worst(c, 0.0, pick_q);
      if (q > pick_q) pick_p = c, pick_q = q;
    }
    if (pick_q > best) p = pick_p, best = pick_q;
    else step *= 0.5;
  }
  if (!(best > start + 1e-3)) return false;
  out.p = p;
  out.metric = metric_for(p, kNoCurve, 0.0, v);  // also leaves last_found_ for inherit_hint
  out.curve = kNoCurve;
  out.param = 0.0;
  return true;
}

bool Remesh2dContext::collapse_keeps_hausd(Id from, Id to) const {
  if (!(options_.hausd > 0.0)) return true;
  Id prev, next;
  curve_neighbours(from, prev, next);
  if (prev == kNoId) return false;
  const Id other = prev == to ? next : prev;
  const std::int32_t c = mesh_.vcurve[from];
  const double s = mesh_.vparam[from];
  return chord_deviation(curves_.curves[c], param_on(to, c, s), param_on(other, c, s)) <=
         options_.hausd;
}

}  // namespace riemesh
