// The 3D adaptation driver: prepare the metric field, then passes of split, collapse, swap and
// smoothing sweeps until the edge lengths settle (BOOK.md §7), as adapt2d.
#include "remesh/adapt3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/hilbert.hpp"
#include "metric/gradation.hpp"
#include "metric/metric.hpp"
#include "remesh/boundary3d.hpp"
#include "remesh/pass_summary.hpp"
#include "remesh/prepare_metrics.hpp"
#include "remesh/remesh3d_context.hpp"
#include "remesh/sliver3d.hpp"

namespace riemesh {
namespace {

constexpr double kLongEdge = 1.4142135623730951;   // √2
constexpr double kCollapseBelow = 0.9;             // as in 2D
constexpr int kSplitSweeps = 3;              // per pass, as in 2D (1 or 2: slower to settle)
// With the surface kept (volume fill), a split may not create a tet below this quality: where the
// volume is thinner than the sizes (rotor blades), splits would put vertices in a layer squeezed
// by the fixed surface, slivers no later operator removes (rotor: 111 -> 20 s, min dihedral
// 1e-6 -> 0.03 degrees; bunny, elephant unchanged).
constexpr double kKeptSurfaceSplitFloor = 0.05;
constexpr double kSwapBelow = 0.6;                 // swaps are tried around tets worse than this
constexpr double kSwapMaxLength = 1.5;            // swaps create no edge longer than this
constexpr double kBad = 0.45;                      // tets below this are removed by collapses
constexpr double kBadMaxLength = 1.6;               // ... creating edges no longer than this
constexpr double kVeryShort = 0.6;                 // shorter edges go with those limits too
constexpr double kGoodBall = 0.8;                  // smoothing skips vertices whose ball is better
constexpr double kLengthenFloor = 0.55;            // lengthening moves keep the ball above this

struct Candidate {
  double length;
  Id a, b;
  Id tet;  // a tet holding the edge when it was listed (a hint: the mesh changes)
};

/// A collapse candidate: no hint (collapses walk the ball), 16 bytes instead of 24 — there can
/// be about one per tet (memory, issue #7).
struct ShortEdge {
  double length;
  Id a, b;
};

/// Calls f(a, b, tet) for each unique live edge (a < b), in increasing (a, b), with the first
/// (lowest id) tet holding it. Bucketed by a (counting sort of 4-byte entries 6 t + k, edge k of
/// tet t), then each small bucket sorted by (b, tet) in a scratch array: linear in the tets. The
/// entries are the largest transient of a pass (issue #7): 24 bytes per tet, and no edge list.
template <class F>
void for_each_edge(const TetMesh& m, F&& f) {
  RIEMESH_CHECK(m.tet_capacity() < std::numeric_limits<std::uint32_t>::max() / 6);
  const auto end = [&](std::uint32_t x, int i) { return m.tv[4 * (x / 6) + kTetEdge[x % 6][i]]; };
  std::vector<std::uint32_t> start(m.vertex_capacity() + 1, 0);
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
    if (!m.tet_alive(static_cast<Id>(t))) continue;
    for (const auto& [i, j] : kTetEdge) ++start[std::min(m.tv[4 * t + i], m.tv[4 * t + j]) + 1];
  }
  for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t>& e = m.edge_scratch;  // entries [0, start.back()) are written
  if (e.size() < start.back()) {  // grown exactly (resize alone would double the capacity)
    std::vector<std::uint32_t>().swap(e);
    e.reserve(start.back() + start.back() / 64);
    e.resize(e.capacity());
  }
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
      if (!m.tet_alive(static_cast<Id>(t))) continue;
      for (std::uint32_t k = 0; k < 6; ++k) {
        const std::uint32_t x = static_cast<std::uint32_t>(6 * t) + k;
        e[fill[std::min(end(x, 0), end(x, 1))]++] = x;
      }
    }
  }
  std::vector<std::pair<Id, Id>> bucket;  // (b, tet)
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    bucket.clear();
    for (std::size_t k = start[v]; k < start[v + 1]; ++k)
      bucket.emplace_back(std::max(end(e[k], 0), end(e[k], 1)), static_cast<Id>(e[k] / 6));
    std::sort(bucket.begin(), bucket.end());
    for (std::size_t k = 0; k < bucket.size(); ++k)
      if (k == 0 || bucket[k].first != bucket[k - 1].first)
        f(static_cast<Id>(v), bucket[k].first, bucket[k].second);
  }
}

template <class C = Candidate, class Select>
std::vector<C> candidates(const TetMesh& m, Select select, bool longer_first) {
  std::vector<C> out;
  for_each_edge(m, [&](Id a, Id b, Id t) {
    const double l = edge_length(m, a, b);
    if (!select(l)) return;
    if constexpr (requires(C c) { c.tet; }) out.push_back({l, a, b, t});
    else out.push_back({l, a, b});
  });
  std::sort(out.begin(), out.end(), [longer_first](const C& x, const C& y) {
    if (x.length != y.length) return longer_first ? x.length > y.length : x.length < y.length;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return out;
}

long split_sweeps(Remesh3dContext& ctx, PassStats& st, double min_quality) {
  TetMesh& m = ctx.mesh();
  long total = 0;
  for (int sweep = 0; sweep < kSplitSweeps; ++sweep) {
    long done = 0;
    for (const Candidate& c : candidates(m, [](double l) { return l > kLongEdge; }, true)) {
      NewVertex3 nv;
      if (!m.vert_alive(c.a) || !m.vert_alive(c.b) || !ctx.split_point(c.a, c.b, nv, c.tet)) {
        ++st.rejected;
        continue;
      }
      Id created = kNoId;
      if (split_edge(m, c.a, c.b, nv, min_quality, &created, c.tet) == Outcome::kApplied) {
        ctx.inherit_hint(created);
        ++done;
      } else {
        ++st.rejected;
      }
    }
    total += done;
    if (done == 0) break;
  }
  return total;
}

long collapse_sweep(Remesh3dContext& ctx, PassStats& st) {
  TetMesh& m = ctx.mesh();
  const CollapseLimits limits{0.2, 1.45};
  long done = 0;
  const auto is_short = [](double l) { return l < kCollapseBelow; };
  for (const ShortEdge& c : candidates<ShortEdge>(m, is_short, false)) {
    if (!m.vert_alive(c.a) || !m.vert_alive(c.b)) continue;
    if (edge_length(m, c.a, c.b) >= kCollapseBelow) continue;
    bool applied = false;
    for (const auto& [from, to] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (collapse_edge(m, from, to, limits) == Outcome::kApplied) {
        applied = true;
        break;
      }
    if (applied) ++done;
    else ++st.rejected;
  }
  return done;
}

/// Edge swaps then face swaps around the tets worse than kSwapBelow (sliver removal).
long swap_sweep(TetMesh& m, PassStats& st) {
  std::vector<Id> bad;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t)) && cached_quality(m, static_cast<Id>(t)) < kSwapBelow)
      bad.push_back(static_cast<Id>(t));
  long done = 0;
  for (const Id t : bad) {
    if (!m.tet_alive(t) || cached_quality(m, t) >= kSwapBelow) continue;
    Id v[4];
    std::copy(&m.tv[4 * t], &m.tv[4 * t] + 4, v);
    bool applied = false;
    for (const auto& [i, j] : kTetEdge) {
      const Outcome o = swap_edge(m, v[i], v[j], 1e-3, kSwapMaxLength, t);
      if (o == Outcome::kApplied) {
        applied = true;
        break;
      }
    }
    for (int i = 0; i < 4 && !applied; ++i) {
      if (swap_face(m, 4 * t + i, 1e-3, kSwapMaxLength) == Outcome::kApplied) applied = true;
    }
    if (applied) ++done;
    else ++st.rejected;
  }
  return done;
}

/// The tets worse than kBad: each loses its worst edge by a collapse that does not lower the
/// worst quality of the ball (edges up to kBadMaxLength), its vertices tried in turn.
long bad_tet_sweep(TetMesh& m, PassStats& st) {
  std::vector<Id> bad;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t)) && cached_quality(m, static_cast<Id>(t)) < kBad)
      bad.push_back(static_cast<Id>(t));
  long done = 0;
  for (const Id t : bad) {
    if (!m.tet_alive(t) || cached_quality(m, t) >= kBad) continue;
    Candidate edges[6];
    for (int k = 0; k < 6; ++k) {
      const Id a = m.tv[4 * t + kTetEdge[k][0]], b = m.tv[4 * t + kTetEdge[k][1]];
      edges[k] = {edge_length(m, a, b), a, b, t};
    }
    std::sort(edges, edges + 6, [](const Candidate& x, const Candidate& y) {
      return x.length != y.length ? x.length < y.length : (x.a != y.a ? x.a < y.a : x.b < y.b);
    });
    bool applied = false;
    for (int k = 0; k < 6 && !applied; ++k)
      for (const auto& [from, to] : {std::pair{edges[k].a, edges[k].b}, std::pair{edges[k].b, edges[k].a}})
        if (collapse_edge(m, from, to, {1.0, kBadMaxLength}) == Outcome::kApplied) {
          applied = true;
          break;
        }
    if (applied) ++done;
    else ++st.rejected;
  }
  return done;
}

/// Moves v (an end of the short edge to `other`) toward its smoothing target, or away from
/// `other` to unit length, at full, half or quarter step, when that lengthens its shortest edge
/// without making its longest longer than kSwapMaxLength (or than it was) nor its ball's worst
/// quality lower than min(before, kLengthenFloor): for short edges whose collapse would create
/// long edges (issue #7: the shortest edge of polar2-3d, 0.45, left so by the sliver
/// optimiser's moves).
bool lengthen(Remesh3dContext& ctx, Id v, Id other, MoveCache& cache, std::vector<Id>& nbrs) {
  TetMesh& m = ctx.mesh();
  NewVertex3 target;
  if (!ctx.smoothing_target(v, target, &cache.ball)) return false;
  fill_move_cache(m, v, cache);
  const double l = edge_length(m, v, other);
  if (!(l > 0.0)) return false;
  Vec3 away = m.xyz[other] + (1.0 / l) * (m.xyz[v] - m.xyz[other]);
  if (!ctx.constrain(v, away)) return false;
  nbrs.clear();
  for (const Id t : cache.ball)
    for (int i = 0; i < 4; ++i)
      if (m.tv[4 * t + i] != v) nbrs.push_back(m.tv[4 * t + i]);
  std::sort(nbrs.begin(), nbrs.end());
  nbrs.erase(std::unique(nbrs.begin(), nbrs.end()), nbrs.end());
  const auto range = [&](const Vec3& p, const SymMat3& mp) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const Id x : nbrs) {
      const double lx = edge_length_geometric(mp, m.metric[x], m.xyz[x] - p);
      lo = std::min(lo, lx), hi = std::max(hi, lx);
    }
    return std::pair{lo, hi};
  };
  const Vec3 from = m.xyz[v];
  const auto [lo0, hi0] = range(from, m.metric[v]);
  for (const Vec3& to : {target.p, away})
    for (const double f : {1.0, 0.5, 0.25}) {
      Vec3 p = from + f * (to - from);
      if (f != 1.0 && !ctx.constrain(v, p)) return false;
      const SymMat3 mp = ctx.metric_for(p, v);
      const auto [lo, hi] = range(p, mp);
      if (!(lo > lo0) || hi > std::max(hi0, kSwapMaxLength)) continue;
      if (move_vertex(m, v, p, mp, &cache, kLengthenFloor) == Outcome::kApplied) {
        ctx.inherit_hint(v);
        return true;
      }
    }
  return false;
}

/// Edges shorter than kVeryShort: collapsed with the relaxed limits of the bad tets, or else
/// lengthened by moving an end (lengthen). Returns the collapses (moves go to st.moves).
long short_edge_sweep(Remesh3dContext& ctx, PassStats& st) {
  TetMesh& m = ctx.mesh();
  MoveCache cache;
  std::vector<Id> nbrs;
  long done = 0;
  const auto is_very_short = [](double l) { return l < kVeryShort; };
  for (const ShortEdge& c : candidates<ShortEdge>(m, is_very_short, false)) {
    if (!m.vert_alive(c.a) || !m.vert_alive(c.b) || edge_length(m, c.a, c.b) >= kVeryShort)
      continue;
    bool applied = false;
    for (const auto& [from, to] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (collapse_edge(m, from, to, {kBad, kBadMaxLength}) == Outcome::kApplied) {
        applied = true;
        break;
      }
    if (applied) {
      ++done;
      continue;
    }
    for (const auto& [v, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      cache.v = kNoId;
      if (lengthen(ctx, v, other, cache, nbrs)) {
        ++st.moves, applied = true;
        break;
      }
    }
    if (!applied) ++st.rejected;
  }
  return done;
}

long smooth_sweep(Remesh3dContext& ctx, PassStats& st) {
  TetMesh& m = ctx.mesh();
  std::vector<std::uint8_t> wanted(m.vertex_capacity(), 0);
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t)) && cached_quality(m, static_cast<Id>(t)) < kGoodBall)
      for (int i = 0; i < 4; ++i) wanted[m.tv[4 * t + i]] = 1;
  long done = 0;
  MoveCache cache;
  for (std::size_t vi = 0; vi < wanted.size(); ++vi) {
    const Id v = static_cast<Id>(vi);
    if (!wanted[vi] || !m.vert_alive(v)) continue;
    NewVertex3 target;
    if (!ctx.smoothing_target(v, target, &cache.ball)) continue;
    fill_move_cache(m, v, cache);  // the ball and its worst quality, once for the candidates
    bool moved = move_vertex(m, v, target.p, target.metric, &cache) == Outcome::kApplied;
    // A refused target: try the way there at half and a quarter.
    const Vec3 from = m.xyz[v];
    for (double f = 0.5; !moved && f > 0.2; f *= 0.5) {
      const Vec3 p = from + f * (target.p - from);
      moved = move_vertex(m, v, p, ctx.metric_for(p, v), &cache) == Outcome::kApplied;
    }
    if (moved) {
      ctx.inherit_hint(v);
      ++done;
    } else {
      ++st.rejected;
    }
  }
  return done;
}

void summarize(const TetMesh& m, PassStats& st) {
  PassSummary sum;
  for_each_edge(m, [&](Id a, Id b, Id) { sum.edge(edge_length(m, a, b)); });
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t))) sum.element(cached_quality(m, static_cast<Id>(t)));
  sum.fill(st, m.num_live_vertices(), m.num_live_tets());
}

std::string stall_reason(const TetMesh& m) {
  double worst = 0, worst_length = 1.0;
  Id wa = kNoId, wb = kNoId;
  for_each_edge(m, [&](Id a, Id b, Id) {
    const double l = edge_length(m, a, b);
    if (length_badness(l) > worst) worst = length_badness(l), worst_length = l, wa = a, wb = b;
  });
  if (wa == kNoId) return "no edge left";
  return stall_message<3>(worst_length, 0.5 * (m.xyz[wa] + m.xyz[wb]));
}

}  // namespace

Adapt3dResult adapt3d(const Mesh& input, std::span<const SymMat3> metrics,
                      const Adapt3dOptions& options, const PassCallback& on_pass) {
  return adapt3d(Mesh(input), std::vector<SymMat3>(metrics.begin(), metrics.end()), options,
                 on_pass);
}

Adapt3dResult adapt3d(Mesh&& input, std::span<const SymMat3> metrics,
                      const Adapt3dOptions& options, const PassCallback& on_pass) {
  return adapt3d(std::move(input), std::vector<SymMat3>(metrics.begin(), metrics.end()), options,
                 on_pass);
}

Adapt3dResult adapt3d(Mesh&& input, std::vector<SymMat3>&& metrics,
                      const Adapt3dOptions& options, const PassCallback& on_pass) {
  options.validate();
  if (input.dim != 3 || input.num_tets() == 0)
    throw InputError("3D remeshing needs a tetrahedral mesh");
  Adapt3dResult result;
  // Memory (issue #7): the renumbered copy of the input, its adjacency and the metric copies
  // are only needed to build the context; they go before the passes, as the context (background
  // mesh) goes before the output mesh is built.
  std::optional<Remesh3dContext> ctx;
  {
    const std::size_t input_vertices = input.num_vertices();
    Mesh ordered = std::move(input);
    const Renumbering order = renumber_hilbert(ordered);
    std::vector<SymMat3> prepared;
    {
      std::vector<SymMat3> permuted = std::move(metrics);
      if (permuted.size() == input_vertices) {
        const std::vector<SymMat3> given = permuted;
        for (std::size_t v = 0; v < permuted.size(); ++v) permuted[v] = given[order.vertices[v]];
      }
      if (!options.keep_surface) intersect_curvature_sizes(ordered, permuted, options);
      // The full adjacency (balls, edges) only for the gradation.
      const Adjacency adjacency = options.hgrad > 0.0
                                      ? build_adjacency(ordered.tets, 4, ordered.num_vertices())
                                      : Adjacency{};
      prepared = prepare_metrics<3>(ordered, adjacency, std::span<const SymMat3>(permuted),
                                    options, result.report);
    }
    ctx.emplace(std::move(ordered), std::move(prepared), options);
  }
  TetMesh& m = ctx->mesh();
  long best_ops = std::numeric_limits<long>::max();
  int best_pass = 0;
  double prev_in = 0.0, prev_qmin = 0.0;
  for (int pass = 1; pass <= options.max_passes; ++pass) {
    const auto t0 = std::chrono::steady_clock::now();
    PassStats st;
    st.pass = pass;
    if (options.insert) {
      st.splits = split_sweeps(*ctx, st, options.keep_surface ? kKeptSurfaceSplitFloor : 0.0);
      st.collapses = collapse_sweep(*ctx, st);
    }
    for (int k = 0; k < 2; ++k) {
      if (options.swap) st.swaps += swap_sweep(m, st);
      if (options.move) st.moves += smooth_sweep(*ctx, st);
    }
    // Clean-up: very short edges, then the worst tets (twice, with swaps in between).
    if (options.insert) st.collapses += short_edge_sweep(*ctx, st);
    for (int k = 0; k < 2; ++k) {
      if (options.insert) st.collapses += bad_tet_sweep(m, st);
      if (options.swap) st.swaps += swap_sweep(m, st);
    }
    // Last: sliver removal around the tets still below the quality target.
    SliverLimits sl;
    sl.swap = options.swap, sl.move = options.move, sl.collapse = options.insert;
    sliver_sweeps(*ctx, sl, st);
    // Again: the sliver optimiser's moves do not look at lengths.
    if (options.insert) st.collapses += short_edge_sweep(*ctx, st);
    summarize(m, st);
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    result.report.passes.push_back(st);
    if (on_pass) on_pass(st);
    // Converged when fewer than 2% of the vertices were inserted or removed (0.5% in 2D: in 3D
    // a few edges cycle between split and collapse), when that count has not reached a new low
    // for 3 passes, or when a pass changed neither the fraction of edges in band (by 0.1%) nor
    // the worst quality (by 0.001).
    const long ops = st.splits + st.collapses;
    const bool still =
        pass > 1 && std::abs(st.len_in - prev_in) < 1e-3 && st.q_min < prev_qmin + 1e-3;
    prev_in = st.len_in, prev_qmin = st.q_min;
    if (ops <= static_cast<long>(st.vertices / 50) || pass - best_pass >= 3 || still) {
      result.report.converged = true;
      break;
    }
    if (ops < best_ops) best_ops = ops, best_pass = pass;
  }
  if (!result.report.converged) result.report.stall_reason = stall_reason(m);
  const TetMesh final_mesh = std::move(m);
  std::vector<std::uint32_t>().swap(final_mesh.edge_scratch);
  const std::vector<std::int32_t> edge_refs = ctx->edge_refs();
  ctx.reset();
  result.mesh = to_mesh(final_mesh, edge_refs, &result.metrics);
  return result;
}

}  // namespace riemesh
