// The 2D adaptation driver: prepare the metric field, then passes of split, collapse, swap and
// smoothing sweeps over the mesh until the edge lengths settle (BOOK.md §7).
#include "remesh/adapt2d.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/format.hpp"
#include "core/huge_pages.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/distance.hpp"
#include "mesh/hilbert.hpp"
#include "metric/gradation.hpp"
#include "metric/metric.hpp"
#include "remesh/pass_summary.hpp"
#include "remesh/prepare_metrics.hpp"
#include "remesh/remesh2d_context.hpp"
#include "remesh/renumber_tail.hpp"
#include "remesh/tri_mesh_io.hpp"

namespace riemesh {
namespace {

constexpr double kLongEdge = 1.4142135623730951;   // √2
// Collapse candidates: edges below 0.9 (not 1/√2), refused when they would create an edge
// longer than 1.45. Collapsing up to 0.9 lifts the mean length from about 0.90 to 0.97, so the
// element count comes within a few per cent of (4/√3) C(M) (measured on the PEERS.md cases).
constexpr double kCollapseBelow = 0.9;
// A swap must raise the smaller quality of its two triangles by more than this.
constexpr double kSwapGain = 1e-3;
// Lawson's flips around each new vertex of a split (swap_around), in the triangles of its ball
// below kNeedle in quality, at most kSwapsAfterSplit link edges tried. Without them, an edge
// split in a triangle that is a needle in the metric (a coarse isotropic mesh in a 1:1000 field)
// joins the new vertex to the far apexes by edges about as long as the halves, the next sweep
// splits those, and the three sweeps of a pass refine every direction: from sq.mesh (944
// triangles) in the 30-degree 1:1000 field of an_var.py (target (4/√3) C = 160 k), pass 2 split
// up to 1.43 M triangles (1.06 M after its collapses), 7 passes to 167 k triangles, 15 s; with
// the flips 11.2 k, 156 k, 167 k, 161 k triangles in 4 passes, 98.8% in band. kNeedle: the
// triangles of a uniform refinement never fall below it (Adapt2d.UniformRefinement* keep their
// meshes); 0.05 gave 179 k at pass 2 and 6 passes, 0.2 137 k but q min 0.668 instead of 0.692
// over linear2d's variants (s = 0.095..0.105; 0.683 with 0.1).
// kSwapsAfterSplit: 8 and unbounded gave the same counts within 0.5%.
constexpr double kNeedle = 0.1;
// A split may not leave a triangle on a boundary or interface edge below this quality, or below
// the one it cuts when that is poorer (as kCurvedSplitFloor in 3D): next to a boundary edge that
// cannot be split (the reconstructed curve bulges beyond the triangle's apex: a spike's side),
// the splits of the interior edges along it strung vertices ever closer to it, each pass's
// triangles flatter (the star20 domain at --hsiz 0.2 --hausd 0.001: quality 0.04, 1e-3, 5e-5,
// ... 7e-10 after 8 passes, exit 0; QA hunt 5 F12). The PEERS.md cases are unchanged
// (bench/adapt2d_identical.sh) but linear2d:h0=0.00001, q min 0.694 -> 0.718 after 5 passes.
constexpr double kSplitFloor = 1e-3;
constexpr int kSwapsAfterSplit = 16;
// Balls whose worst quality stays below this after the passes get a quality-driven relocation.
// polar2d, mean q min of passes 5-8 over 16 variants (s = 0.8..1.15, h0 = 0.0009, 0.0011), with
// the band measured by edge_length_gauss3 and two rounds: 0.5 0.448, 0.55 0.462, 0.6 0.458
// (and 97.8% in band instead of 98.0%).
constexpr double kPoorBall = 0.55;
// Rounds of the relocations after the passes (each stops the loop when it moved nothing).
// Same variants, with 0.55: one round 0.450, two 0.462, three 0.455 (one variant at 0.27).
constexpr int kRelocationRounds = 2;

/// True when the vertex numbering already follows the space closely enough for the caches: the
/// triangles spanning more than 4096 vertex ids plus those starting more than 4096 ids away from
/// the previous triangle's first vertex are fewer than 10% of the triangles (a Hilbert-ordered
/// mesh of 1.76 M triangles: 3.4% + 1.9%; a lexicographic grid: 0; a random numbering: ~200%).
/// Meshes under 16,384 vertices are always renumbered (it costs under 10 ms there, and keeps
/// the small benchmark cases as they were).
bool coherent_numbering(const Mesh& m) {
  constexpr long kWindow = 4096;
  if (m.num_vertices() < 16384) return false;
  const std::size_t nt = m.num_triangles();
  std::size_t far = 0;
  long prev = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    const long a = m.triangles[3 * t], b = m.triangles[3 * t + 1], c = m.triangles[3 * t + 2];
    const long spread = std::max({a, b, c}) - std::min({a, b, c});
    far += (spread > kWindow ? 1 : 0) + (t > 0 && std::abs(a - prev) > kWindow ? 1 : 0);
    prev = a;
  }
  return far * 10 < nt;
}

/// Calls f(slot) once per live edge (the slot of the lower triangle side for interior edges).
/// Slots created during the sweep are not visited.
template <class F>
void for_each_edge(const TriMesh& m, F f) {
  const std::size_t n = m.tadj.size();
  for (std::size_t s = 0; s < n; ++s) {
    if (!m.tri_alive(static_cast<Id>(s / 3))) continue;
    const Id r = m.tadj[s];
    if (r != kNoId && r < static_cast<Id>(s)) continue;
    f(static_cast<Id>(s));
  }
}

/// When each vertex last moved or had its ball re-cut by a split, collapse or swap (a sweep
/// counter), so that each swap and smoothing sweep after the first of the run only revisits what
/// changed since the previous one (of this pass or the last): an edge whose four quadrilateral
/// vertices are unchanged since the previous swap sweep was refused then and would be refused
/// again (the decision depends on nothing else); likewise a vertex whose ball vertices are all
/// unchanged since the previous smoothing sweep.
struct Changes {
  std::vector<std::uint32_t> stamp;  // per vertex; 0: never
  std::uint32_t now = 0;

  /// Starts a sweep; returns its stamp.
  std::uint32_t begin() { return ++now; }
  void mark(Id v) {
    if (stamp.size() <= static_cast<std::size_t>(v)) stamp.resize(static_cast<std::size_t>(v) + 1, 0);
    stamp[v] = now;
  }
  bool since(Id v, std::uint32_t t) const {
    return static_cast<std::size_t>(v) < stamp.size() && stamp[v] >= t;
  }
};

// Splits append their vertices and triangles at the end of the arrays: once more than this
// many vertices (and a quarter of the mesh) were created since the numbering last followed
// the space, the new ones are renumbered along the Hilbert curve (Remesh2dContext::
// renumber_new_vertices; Adapt2dOptions::renumber_after). Smaller meshes stay in the caches
// anyway (and keep their results).
constexpr std::size_t kRenumberAfter = 16384;

/// Renumbers the vertices created since `ordered` (the vertex count when the numbering last
/// followed the space) when they are many; `changes` follows.
void keep_locality(Remesh2dContext& ctx, Changes& changes, std::size_t& ordered) {
  const std::size_t after = ctx.options().renumber_after;
  if (!detail::renumber_due(ctx.mesh().vertex_capacity(), ordered, after ? after : kRenumberAfter))
    return;
  const std::vector<Id> old2new = ctx.renumber_new_vertices();
  ordered = ctx.mesh().vertex_capacity();
  detail::remap_records(changes.stamp, old2new, ordered, std::uint32_t{0});
}

/// An edge to split or collapse, by its end vertices (slots move as the mesh changes), and a
/// flag computed for it when the list was made (collapse candidates: refused by length both
/// ways).
struct Candidate {
  double length;
  Id a, b;
  std::uint8_t flag = 0;
};

/// No flag.
struct NoFlag {
  std::uint8_t operator()(const Candidate&) const { return 0; }
};

/// The edges of metric length above `limit` (longer = true) or below it, sorted by `longer`
/// first length (ties by ids, so the order is deterministic), each with flag(candidate)
/// computed in mesh order as they are found. Only the selected edges have their length
/// computed (compare_edge_length decides the others from cheap bounds).
/// `since` > 0: only the edges with a vertex of their two triangles changed at or after that
/// stamp.
template <class Flag = NoFlag>
std::vector<Candidate> candidates(const TriMesh& m, double limit, bool longer,
                                  const Changes& changes, std::uint32_t since = 0,
                                  Flag flag = {}) {
  // Sorted as pairs of integers: the bits of a positive double order as its value (flipped for
  // the longest first), then (a, b) packed; the same order as comparing (length, a, b). Each
  // edge is listed once, so no two keys are equal.
  struct Key {
    std::uint64_t length, ids;
    std::uint8_t flag;
  };
  std::vector<Key> keys;
  reserve_huge(keys, m.tadj.size() / 2 + 1);  // room for every edge (address space only)
  const int want = longer ? 1 : -1;
  const std::uint64_t flip = longer ? ~std::uint64_t{0} : 0;
  for_each_edge(m, [&](Id s) {
    const Id a = m.edge_from(s), b = m.edge_to(s);
    if (since > 0 && !changes.since(a, since) && !changes.since(b, since) &&
        !changes.since(m.tv[s], since) &&
        (m.tadj[s] == kNoId || !changes.since(m.tv[m.tadj[s]], since)))
      return;
    if (compare_edge_length(m, a, b, limit) != want) return;
    const double l = edge_length(m, a, b);
    keys.push_back({std::bit_cast<std::uint64_t>(l) ^ flip,
                    (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b),
                    flag(Candidate{l, a, b})});
  });
  std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
    return x.length != y.length ? x.length < y.length : x.ids < y.ids;
  });
  std::vector<Candidate> out;
  reserve_huge(out, keys.size());
  for (const Key& k : keys)
    out.push_back({std::bit_cast<double>(k.length ^ flip), static_cast<Id>(k.ids >> 32),
                   static_cast<Id>(k.ids & 0xffffffffu), k.flag});
  return out;
}

/// Splits the edges longer than √2, longest first, sweep after sweep (a split's new edges wait
/// for the next sweep, so every long edge is reached and none is halved twice in a sweep).
long split_sweeps(Remesh2dContext& ctx, PassStats& st, Changes& changes, std::size_t& ordered) {
  TriMesh& m = ctx.mesh();
  long total = 0;
  // At most 3 sweeps a pass: refining a coarse mesh step by step, with collapses, swaps and
  // smoothing in between, places vertices better and is 3x faster than splitting to the end at
  // once (which overshoots the vertex count threefold on the PEERS.md cases).
  // After the first sweep, only the edges whose two triangles changed in the previous one: the
  // others were there with the same length, and their split refused (the decision depends on
  // nothing else: the four vertices, their metrics and the hints of the ends).
  std::uint32_t previous = 0;
  thread_local std::vector<Id> touched;
  for (int sweep = 0; sweep < 3; ++sweep) {
    const std::uint32_t stamp = changes.begin();
    const std::vector<Candidate> list = candidates(m, kLongEdge, true, changes, previous);
    previous = stamp;
    long done = 0;
    for (const Candidate& c : list) {
      const Id s = find_edge_slot(m, c.a, c.b);
      if (s == kNoId) continue;
      const Id apex = m.tv[s], other_apex = m.tadj[s] == kNoId ? kNoId : m.tv[m.tadj[s]];
      Id created = kNoId;
      if (split_edge(m, s, ctx.split_point(s), kSplitFloor, &created) == Outcome::kApplied) {
        ctx.inherit_hint(created, c.a);
        for (const Id v : {c.a, c.b, apex, created}) changes.mark(v);
        if (other_apex != kNoId) changes.mark(other_apex);
        ++done;
        if (ctx.options().swap) {
          touched.clear();
          st.swaps += swap_around(m, created, kSwapGain, kNeedle, kSwapsAfterSplit, touched);
          for (const Id v : touched) changes.mark(v);
        }
      } else {
        ++st.rejected;
      }
    }
    total += done;
    keep_locality(ctx, changes, ordered);
    if (done == 0) break;
  }
  return total;
}

/// Collapses the edges shorter than 0.9, shortest first.
/// On a converged mesh nearly all candidates are refused by the length test in both directions
/// (650 k of 652 k on 1.76 M triangles), and testing them in length order jumps across the mesh
/// (a cache miss per ball). So the length test runs first in mesh order, and the sorted sweep
/// skips the edges it refused whose ends have not been touched by a collapse since: a collapse
/// moves no vertex and changes the neighbours of the vertices of the removed vertex's ball only
/// (all marked), so for the others the test would give the same answer.
long collapse_sweep(Remesh2dContext& ctx, PassStats& st, Changes& changes) {
  TriMesh& m = ctx.mesh();
  const CollapseLimits limits{0.3, 1.45};
  // Edges far below unit length (clusters of near-duplicate vertices left where a first run
  // from a coarse mesh overshot) may be removed even if a triangle gets up to 2x worse.
  CollapseLimits tiny = limits;
  tiny.relative_floor = 0.5;
  // Candidates refused by length both ways, found as they are listed (in mesh order).
  const std::vector<Candidate> list =
      candidates(m, kCollapseBelow, false, changes, 0, [&](const Candidate& c) -> std::uint8_t {
        const CollapseLimits& lim = c.length < 0.25 ? tiny : limits;
        return (m.frozen(c.a) || collapse_too_long(m, c.a, c.b, lim)) &&
               (m.frozen(c.b) || collapse_too_long(m, c.b, c.a, lim));
      });
  std::vector<std::uint8_t> touched(m.vertex_capacity(), 0);
  thread_local Ball ball;
  thread_local std::vector<Id> around;
  long done = 0;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Candidate& c = list[i];
    if (c.flag && !touched[c.a] && !touched[c.b]) {
      ++st.rejected;
      continue;
    }
    if (!m.vert_alive(c.a) || !m.vert_alive(c.b)) continue;
    const Id s = find_edge_slot(m, c.a, c.b);
    if (s == kNoId || compare_edge_length(m, c.a, c.b, kCollapseBelow) >= 0) continue;
    bool applied = false;
    for (const auto& [from, to] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      if (m.frozen(from) || (m.on_curve(from) && !ctx.collapse_keeps_hausd(from, to))) continue;
      collect_ball(m, from, ball);  // its vertices: those whose neighbours change if it goes
      around.clear();
      for (const Id t : ball.tris) around.insert(around.end(), &m.tv[3 * t], &m.tv[3 * t] + 3);
      if (collapse_edge(m, s, from, to, c.length < 0.25 ? tiny : limits, &ball) ==
          Outcome::kApplied) {
        for (const Id v : around) touched[v] = 1, changes.mark(v);
        applied = true;
        break;
      }
    }
    if (applied) ++done;
    else ++st.rejected;
  }
  return done;
}


/// One swap sweep; `since` > 0: only the edges with a quadrilateral vertex changed at or after
/// that stamp (the others were refused by the sweep that began then).
long swap_sweep(TriMesh& m, PassStats& st, Changes& changes, std::uint32_t since) {
  long done = 0;
  for_each_edge(m, [&](Id s) {
    if (!m.tri_alive(s / 3) || m.tadj[s] == kNoId || m.is_feature(s)) return;
    const Id r = m.tadj[s];
    const Id quad[4] = {m.edge_from(s), m.edge_to(s), m.tv[s], m.tv[r]};  // tv[slot]: the apex
    if (since > 0 && !changes.since(quad[0], since) && !changes.since(quad[1], since) &&
        !changes.since(quad[2], since) && !changes.since(quad[3], since))
      return;
    const Outcome o = swap_edge(m, s, kSwapGain);
    if (o == Outcome::kApplied) {
      ++done;
      for (const Id v : quad) changes.mark(v);
    } else if (o == Outcome::kRejectedGeometry) {
      ++st.rejected;
    }
  });
  return done;
}

/// Moves each vertex whose ball holds a triangle of quality below 0.9 toward its smoothing
/// target. Vertices in good balls are skipped: on a converged mesh that is most of them, and the
/// triangle qualities are cached for the sweep (updated after each move). `since` > 0: only the
/// vertices with a ball vertex changed at or after that stamp (the others were left as they are
/// by the sweep that began then). `length_moves` false: no move toward the smoothing target;
/// `poor` > 0: a ball whose worst quality is below `poor` (after that move) has its vertex moved
/// where the ball's worst quality is best (Remesh2dContext::quality_target).
/// Triangle qualities cached by the smoothing sweeps, kept from sweep to sweep (one allocation
/// per run instead of two arrays of the triangle count per sweep): `known[t] == sweep` when
/// quality[t] was computed in the current sweep.
struct QualityCache {
  std::vector<double> quality;
  std::vector<std::uint32_t> known;
  std::uint32_t sweep = 0;
  std::vector<std::uint8_t> visit;  // per vertex, sweeps with `since`: a ball vertex changed

  /// Starts a sweep over a mesh of `triangles` slots: no quality known yet.
  void begin(std::size_t triangles) {
    if (quality.empty()) reserve_huge(quality, triangles), reserve_huge(known, triangles);
    if (quality.size() < triangles) quality.resize(triangles), known.resize(triangles, 0);
    ++sweep;
  }
};

long smooth_sweep(Remesh2dContext& ctx, PassStats& st, Changes& changes, std::uint32_t since,
                  QualityCache& cache, bool length_moves = true, double poor = 0.0) {
  constexpr double kGoodBall = 0.9;
  TriMesh& m = ctx.mesh();
  // Exact qualities (move_vertex takes the ball's worst from here); the good-ball test compares
  // them rounded to float, as it always has. Computed at the first look (a sweep with `since`
  // visits few balls) and after each move: the same values as computing them all up front.
  cache.begin(m.triangle_capacity());
  std::vector<double>& quality = cache.quality;
  std::vector<std::uint32_t>& known = cache.known;
  const std::uint32_t sweep = cache.sweep;
  auto quality_of = [&](Id t) {
    if (known[t] != sweep) quality[t] = tri_quality(m, t), known[t] = sweep;
    return quality[t];
  };
  // With `since`: the vertices sharing a triangle with a vertex changed since then, found in
  // one pass over the triangles (not a ball walk per vertex), then kept up to date as vertices
  // move in this sweep (a move marks the vertices of its ball): the vertices whose ball holds a
  // changed vertex when they are reached, as testing each ball would find.
  std::vector<std::uint8_t>& visit = cache.visit;
  if (since > 0) {
    visit.assign(m.vertex_capacity(), 0);
    for (std::size_t t = 0; t < m.triangle_capacity(); ++t) {
      const Id* tv = &m.tv[3 * t];
      if (tv[0] == kNoId) continue;
      if (changes.since(tv[0], since) || changes.since(tv[1], since) ||
          changes.since(tv[2], since))
        visit[tv[0]] = visit[tv[1]] = visit[tv[2]] = 1;
    }
  }
  thread_local Ball ball;
  long done = 0;
  for (std::size_t vi = 0; vi < m.vertex_capacity(); ++vi) {
    const Id v = static_cast<Id>(vi);
    if (!m.vert_alive(v) || m.frozen(v)) continue;
    if (since > 0 && !visit[v]) continue;
    collect_ball(m, v, ball);
    float worst = 1.0f;
    double worst_exact = 2.0;
    for (const Id t : ball.tris) {
      const double q = quality_of(t);
      worst = std::min(worst, static_cast<float>(q));
      worst_exact = std::min(worst_exact, q);
    }
    if (worst >= kGoodBall) continue;
    NewVertex target;
    const auto moved = [&] {
      ctx.inherit_hint(v, v);
      changes.mark(v);
      worst_exact = 2.0;
      for (const Id t : ball.tris) {
        quality[t] = tri_quality(m, t), known[t] = sweep;
        worst_exact = std::min(worst_exact, quality[t]);
      }
      if (since > 0)
        for (const Id t : ball.tris)
          for (int i = 0; i < 3; ++i) visit[m.tv[3 * t + i]] = 1;
      ++done;
    };
    if (length_moves && ctx.smoothing_target(v, target, 0.0, &ball)) {
      if (move_vertex(m, v, target.p, target.metric, target.param, 0.6, &ball, &worst_exact) ==
          Outcome::kApplied)
        moved();
      else
        ++st.rejected;
    }
    // A ball still poor after the length-driven move: the position of the best worst quality.
    if (worst_exact < poor && ctx.quality_target(v, ball, worst_exact, target) &&
        move_vertex(m, v, target.p, target.metric, target.param, 1.0, &ball, &worst_exact) ==
            Outcome::kApplied)
      moved();
  }
  return done;
}

/// Moves each end of an edge outside [1/√2, √2] across which the metric turns where its edges
/// are least outside the band, none further out and no ball triangle below min(its ball's worst,
/// `floor`) (Remesh2dContext::quality_target with a length floor); lengths by the 3-point Gauss
/// rule (edge_length_gauss3), as in quality_target. Returns the moves.
long length_sweep(Remesh2dContext& ctx, Changes& changes, double floor) {
  TriMesh& m = ctx.mesh();
  if (m.log_metric.empty()) return 0;  // every metric diagonal: they all commute
  std::vector<Id> ends;
  for_each_edge(m, [&](Id s) {
    const Id a = m.edge_from(s), b = m.edge_to(s);
    if (commute(m.metric[a], m.metric[b])) return;
    const double l = edge_length_gauss3(m, a, b);
    if (l < 0.7071067811865476 || l > kLongEdge) ends.push_back(a), ends.push_back(b);
  });
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  thread_local Ball ball;
  long done = 0;
  for (const Id v : ends) {
    if (m.frozen(v)) continue;
    collect_ball(m, v, ball);
    double worst = 2.0;
    for (const Id t : ball.tris) worst = std::min(worst, tri_quality(m, t));
    NewVertex target;
    if (ctx.quality_target(v, ball, worst, target, floor) &&
        move_vertex(m, v, target.p, target.metric, target.param, floor, &ball, &worst) ==
            Outcome::kApplied) {
      ctx.inherit_hint(v, v);
      changes.mark(v);
      ++done;
    }
  }
  return done;
}

void summarize(const TriMesh& m, PassStats& st) {
  PassSummary sum;
  for_each_edge(m, [&](Id s) { sum.edge(edge_length(m, m.edge_from(s), m.edge_to(s))); });
  for (std::size_t t = 0; t < m.triangle_capacity(); ++t)
    if (m.tri_alive(static_cast<Id>(t))) sum.element(tri_quality(m, static_cast<Id>(t)));
  sum.fill(st, m.num_live_vertices(), m.num_live_triangles());
}

/// Where and why the passes stalled: the longest (or shortest) edge left and its place.
std::string stall_reason(const TriMesh& m) {
  double worst = 0, worst_length = 1.0;
  Id where = kNoId;
  for_each_edge(m, [&](Id s) {
    const double l = edge_length(m, m.edge_from(s), m.edge_to(s));
    if (length_badness(l) > worst) worst = length_badness(l), worst_length = l, where = s;
  });
  if (where == kNoId) return "no edge left";
  return stall_message<2>(worst_length, 0.5 * (m.xy[m.edge_from(where)] + m.xy[m.edge_to(where)]));
}

}  // namespace

void Adapt2dOptions::validate() const {
  // Sizes whose metric 1/h² under- or overflows cannot be stored (--hmin 1e300 was reported as
  // "gradation: vertex 0: metric is not positive definite", blaming the mesh).
  const auto storable = [](double h) {
    return h > 0.0 && std::isnormal(1.0 / (h * h)) && std::isfinite(h * h);
  };
  if (!(hmin == 0.0 || storable(hmin)))
    throw InputError("--hmin must be 0 or a finite size from 1e-150 to 1e150, got " +
                     format_g(hmin));
  if (!(hmax == std::numeric_limits<double>::infinity() || storable(hmax)))
    throw InputError("--hmax must be a size from 1e-150 to 1e150, got " + format_g(hmax));
  if (hmin > 0.0 && hmax < hmin)
    throw InputError("--hmin " + format_g(hmin) + " is larger than --hmax " + format_g(hmax));
  if (!(hgrad == 0.0 || (hgrad > 1.0 && std::isfinite(hgrad))))
    throw InputError("--hgrad must be 0 (off) or a ratio > 1, got " + format_g(hgrad));
  if (!(hausd >= 0.0) || !std::isfinite(hausd)) throw InputError("--hausd must be a distance >= 0");
  if (!(angle_deg >= 0.0 && angle_deg <= 180.0))
    throw InputError("--angle must be in [0, 180] degrees, got " + format_g(angle_deg));
  if (max_passes < 1 || max_passes > 1000) throw InputError("--passes must be in 1..1000");
}

double default_hausd(const Mesh& domain) {
  return std::max(Adapt2dOptions{}.hausd, kSmallestHausd * bounding_box_diagonal(domain));
}

namespace {

/// A --hausd below 1e-9 of the domain's bounding-box diagonal is refused: chords that close to
/// the curve ask for millions of boundary vertices, beyond what the size checks see (1e-12 on
/// the NACA domain ran away, 671 k vertices after 4 passes and growing; 1e-300 was ignored).
void require_hausd_above_roundoff(const Mesh& input, double hausd) {
  if (!(hausd > 0.0)) return;  // 0: no bound
  const double diag = bounding_box_diagonal(input);
  if (hausd >= kSmallestHausd * diag) return;
  throw InputError("--hausd " + format_g(hausd) + " as given is below " + format_g(kSmallestHausd) +
                   " of the domain's size (bounding-box diagonal " + format_g(diag) +
                   "): give 0 for no bound, or a larger distance");
}

/// adapt2d; `owned_input` and `owned_metrics`, when given, are `input` and `metrics` themselves,
/// released once the remesher has its own copy.
Adapt2dResult adapt2d_impl(const Mesh& input, std::span<const SymMat2> metrics,
                           const Adapt2dOptions& options, const PassCallback& on_pass,
                           Mesh* owned_input, std::vector<SymMat2>* owned_metrics) {
  options.validate();
  if (input.dim != 2) throw InputError("2D remeshing needs a planar mesh (Dimension 2)");
  if (input.num_triangles() == 0) throw InputError("the mesh has no triangles");
  require_hausd_above_roundoff(input, options.hausd);
  require_valid_input<2>(input, metrics);
  Adapt2dResult result;
  // Work on a Hilbert-ordered copy (every adjacency build and walk below is cache-friendly),
  // unless the input is already numbered coherently (e.g. the output of a previous run): then
  // renumbering costs more than it saves (0.9 s of copy and sort on 1.76 M triangles).
  Mesh ordered;
  std::vector<SymMat2> permuted;
  const bool renumber = !coherent_numbering(input);
  if (renumber) {
    ordered = input;
    const Renumbering order = renumber_hilbert(ordered);
    permuted.resize(metrics.size());
    if (metrics.size() == input.num_vertices())
      for (std::size_t v = 0; v < permuted.size(); ++v) permuted[v] = metrics[order.vertices[v]];
    else
      permuted.assign(metrics.begin(), metrics.end());  // prepare_metrics reports the mismatch
  }
  const Mesh& work = renumber ? ordered : input;
  const std::span<const SymMat2> work_metrics =
      renumber ? std::span<const SymMat2>(permuted) : metrics;
  // The edge numbering only for the gradation (the rest reads the neighbours and vertex balls).
  Adjacency adjacency = build_face_adjacency(work.triangles, 3, work.num_vertices());
  require_unfolded(work, adjacency);
  if (options.hgrad > 0.0) add_edges(adjacency, work.triangles);
  std::vector<SymMat2> prepared =
      prepare_metrics<2>(work, adjacency, work_metrics, options, result.report);
  Remesh2dContext ctx(work, prepared, options, adjacency);
  // The context has what it needs (the mesh, metrics and curves copied): the adjacency, the
  // prepared metrics and the renumbered copy are released before the passes (peak memory).
  adjacency = Adjacency{};
  prepared = {};
  ordered = Mesh{};
  permuted = {};
  if (owned_input) *owned_input = Mesh{};
  if (owned_metrics) *owned_metrics = {};
  TriMesh& m = ctx.mesh();
  long best_ops = std::numeric_limits<long>::max();
  int best_pass = 0;
  double prev_in = 0.0, prev_qmin = 0.0, prev_qmean = 0.0;
  Changes changes;
  std::size_t in_order = m.vertex_capacity();  // vertices numbered in space order
  QualityCache qualities;
  std::uint32_t swap_from = 0, smooth_from = 0;  // stamps of the previous swap and smoothing sweeps
  for (int pass = 1; pass <= options.max_passes; ++pass) {
    const auto t0 = std::chrono::steady_clock::now();
    PassStats st;
    st.pass = pass;
    if (options.insert) {
      st.splits = split_sweeps(ctx, st, changes, in_order);
      st.collapses = collapse_sweep(ctx, st, changes);
    }
    for (int k = 0; k < 2; ++k) {
      const std::uint32_t swap_stamp = changes.begin();
      if (options.swap) st.swaps += swap_sweep(m, st, changes, swap_from);
      const std::uint32_t smooth_stamp = changes.begin();
      if (options.move) st.moves += smooth_sweep(ctx, st, changes, smooth_from, qualities);
      swap_from = swap_stamp, smooth_from = smooth_stamp;
    }
    summarize(m, st);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    result.report.passes.push_back(st);
    if (on_pass) on_pass(st);
    // Converged when fewer than 0.5% of the vertices were inserted or removed, or, with fewer
    // than 5% of them, when the count of insertions and removals has not reached a new low for
    // 3 passes (a few edges then only cycle between split and collapse) or a pass changed
    // neither the fraction of edges in band (by 0.1%) nor raised the worst or the mean quality
    // (by 0.001). (Without the 5%: --hsiz 1e-4 on a square stopped after its second pass, 1.9 M
    // splits, every edge still 4-12 long, the band at 0% both times; a 1:1000 field after its
    // fourth, 161 k collapses, 90% in band, the first pass's few operations the "low".)
    const long ops = st.splits + st.collapses;
    const bool still = pass > 1 && std::abs(st.len_in - prev_in) < 1e-3 &&
                       st.q_min < prev_qmin + 1e-3 && st.q_mean < prev_qmean + 1e-3;
    const bool few = ops <= static_cast<long>(st.vertices / 20);
    prev_in = st.len_in, prev_qmin = st.q_min, prev_qmean = st.q_mean;
    if (ops <= static_cast<long>(st.vertices / 200) || (few && (pass - best_pass >= 3 || still))) {
      result.report.converged = true;
      break;
    }
    if (ops < best_ops) best_ops = ops, best_pass = pass;
  }
  // After the passes, where the metric turns (a thin curved layer: splits, collapses and the
  // length-driven smoothing leave poor shapes and edges out of band there, a tangential chord's
  // length growing as its square across the turn), kRelocationRounds rounds of one sweep of
  // each, with swaps around what moved:
  // - the vertices of the balls still poor (worst below kPoorBall) go where their ball's worst
  //   quality is best, no edge leaving [1/√2, √2] or getting further from it (inside the
  //   passes the same moves lowered the fraction in band: the next splits and collapses answer
  //   the moved lengths, 96.2 -> 95.8%);
  // - the ends of the edges still out of band go where their edges are least outside it, never
  //   lowering their ball's worst quality (a floor of 0.5 instead gave polar2d 1% more in band
  //   but cost polar2d-2 and polar2d:s=0.1 0.02 of q min).
  // Both measure the band by the 3-point Gauss rule (edge_length_gauss3), not Simpson's.
  // polar2d, mean of passes 5-8 over 8 variants (s = 0.85..1.1, h0 = 0.0009, 0.0011): in band
  // 96.2 -> 97.8%, q min 0.378 -> 0.440 with one round, 0.5 and Simpson's rule; 98.1%, 0.471
  // now. Metrics that commute everywhere (linear2d) keep their outputs.
  // Without logarithms kept every vertex metric is diagonal: they all commute, and neither
  // relocation would move a vertex (both look only where the metric turns), so the rounds, a
  // full ball sweep each, are skipped.
  for (int round = 0; round < kRelocationRounds && options.move && !m.log_metric.empty(); ++round) {
    PassStats st;
    std::uint32_t stamp = changes.begin();
    const long poor = smooth_sweep(ctx, st, changes, 0, qualities, false, kPoorBall);
    if (poor > 0 && options.swap) swap_sweep(m, st, changes, stamp);
    stamp = changes.begin();
    const long out = length_sweep(ctx, changes, 1.0);
    if (out > 0 && options.swap) swap_sweep(m, st, changes, stamp);
    if (poor + out == 0) break;
  }
  if (!result.report.converged) result.report.stall_reason = stall_reason(m);
  result.mesh = to_mesh(m, &result.metrics);
  return result;
}

}  // namespace

Adapt2dResult adapt2d(const Mesh& input, std::span<const SymMat2> metrics,
                      const Adapt2dOptions& options, const PassCallback& on_pass) {
  return adapt2d_impl(input, metrics, options, on_pass, nullptr, nullptr);
}

Adapt2dResult adapt2d(Mesh&& input, std::vector<SymMat2>&& metrics, const Adapt2dOptions& options,
                      const PassCallback& on_pass) {
  return adapt2d_impl(input, metrics, options, on_pass, &input, &metrics);
}

}  // namespace riemesh
