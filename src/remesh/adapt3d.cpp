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
#include "metric/approach.hpp"
#include "metric/element.hpp"
#include "metric/gradation.hpp"
#include "metric/metric.hpp"
#include "remesh/boundary3d.hpp"
#include "remesh/edges3d.hpp"
#include "remesh/pass_summary.hpp"
#include "remesh/prepare_metrics.hpp"
#include "remesh/remesh3d_context.hpp"
#include "remesh/renumber_tail.hpp"
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
// With curved patches, a split may not create a tet below this quality: an interior edge between
// two boundary vertices whose chord lies in the surface (along a cylinder's straight direction)
// has a flat shell, and splitting it strung interior vertices along the surface, each with flat
// tets (a gmsh cylinder under a 1:100 metric oblique to it: 2,301 tets below quality 0.1 -> 240;
// a planar patch gives exactly flat tets, refused as such).
constexpr double kCurvedSplitFloor = 1e-3;
// Interfaces between subdomains are kept as given (their vertices fixed): splits near them get
// the kept surface's floor (two gmsh cubes side by side, sizes 0.04 at their interface of 0.2
// triangles: 29,322 of 70,426 tets below quality 0.1, q min 7e-6 -> 841 of 36,470, 0.05), and
// edges of theirs (or of the whole surface kept by --nosurf) longer than this in the metric are
// noted.
constexpr double kInterfaceNote = 2.0;
constexpr double kSwapBelow = 0.6;                 // swaps are tried around tets worse than this
constexpr double kSwapMaxLength = 1.5;            // swaps create no edge longer than this
constexpr double kBad = 0.45;                      // tets below this are removed by collapses
constexpr double kBadMaxLength = 1.6;               // ... creating edges no longer than this
constexpr double kVeryShort = 0.6;                 // shorter edges go with those limits too
constexpr double kGoodBall = 0.8;                  // smoothing skips vertices whose ball is better
constexpr double kLengthenFloor = 0.55;            // lengthening moves keep the ball above this
constexpr double kQualityDrop = 0.01;  // a pass lowering the worst quality more is not "still"
constexpr int kStagePasses = 2;  // passes toward each intermediate field of the staged approach

using Candidate = LongEdge;

/// Lists the edges of m longer than √2 (split) and shorter than kCollapseBelow (collapse) into
/// lists, each edge's length also fed to sum when given (the summary that ends a pass lists the
/// next pass's candidates: nothing changes the mesh in between).
/// `nbrs`, when given, receives every vertex's neighbours.
void list_edges(TetMesh& m, EdgeLists& lists, PassSummary* sum, NeighbourTable* nbrs) {
  lists.long_above = kLongEdge, lists.short_below = kCollapseBelow;
  lists.long_edges.clear(), lists.short_edges.clear();
  std::vector<Id> upper;
  std::vector<std::uint32_t> count(nbrs ? m.vertex_capacity() : 0, 0);
  for_each_edge(m, [&](Id a, Id b, Id t) {
    const double l = edge_length(m, a, b);
    if (sum) sum->edge(l);
    lists.add(l, a, b, t);
    if (nbrs) upper.push_back(b), ++count[a];
  });
  if (nbrs) nbrs->build(m, upper, count);
}

template <class C>
void sort_candidates(std::vector<C>& c, bool longer_first) {
  std::sort(c.begin(), c.end(), [longer_first](const C& x, const C& y) {
    if (x.length != y.length) return longer_first ? x.length > y.length : x.length < y.length;
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
}

/// v's neighbours, sorted: from nbrs when it still holds them, else from v's ball (`scratch`).
std::span<const Id> neighbours(const TetMesh& m, Id v, const NeighbourTable& nbrs,
                               std::vector<Id>& scratch) {
  if (nbrs.known(m, v)) return nbrs.of(v);
  thread_local std::vector<Id> ball;
  collect_ball(m, v, ball);
  ball_neighbours(m, v, ball, scratch);
  return scratch;
}

/// The edges (a < b) shorter than `below`, shortest first: each from its lower end's neighbours
/// (a full enumeration is not needed for the few short edges left after the collapse sweep); the
/// logarithm of the length only for the edges whose end lengths do not decide (edge_longer_than).
std::vector<ShortEdge> edges_shorter_than(const TetMesh& m, const NeighbourTable& nbrs,
                                          double below) {
  std::vector<ShortEdge> out;
  std::vector<Id> scratch;
  for (std::size_t vi = 0; vi < m.vertex_capacity(); ++vi) {
    const Id a = static_cast<Id>(vi);
    if (!m.vert_alive(a)) continue;
    for (const Id b : neighbours(m, a, nbrs, scratch)) {
      if (b < a) continue;
      if (compare_edge_length(m, a, b, below) < 0) out.push_back({edge_length(m, a, b), a, b});
    }
  }
  sort_candidates(out, false);
  return out;
}

/// Adds to lists the edges at the vertices `created` (live, distinct) that it selects.
void list_edges_at(const TetMesh& m, std::span<const Id> created, EdgeLists& lists) {
  std::vector<std::uint8_t> in(m.vertex_capacity(), 0);
  for (const Id x : created) in[x] = 1;
  for_each_edge_at(m, created, in, [&](Id x, Id y, Id t) {
    const Id a = std::min(x, y), b = std::max(x, y);
    lists.add(edge_length(m, a, b), a, b, t);
  });
}

/// The lowest id tet holding edge (a, b) (joined), from a tet that may hold it.
Id lowest_edge_tet(const TetMesh& m, Id a, Id b, Id hint) {
  thread_local std::vector<Id> shell;
  collect_shell(m, a, b, shell, hint);
  RIEMESH_CHECK(!shell.empty());
  return *std::min_element(shell.begin(), shell.end());
}

/// collapse_edge(m, from, to, limits) == kApplied, without its ball walk when nbrs knows from's
/// neighbours and the new edge lengths refuse the collapse (the same decision).
bool try_collapse(TetMesh& m, Id from, Id to, const CollapseLimits& limits,
                  const NeighbourTable& nbrs) {
  if (nbrs.known(m, from) && collapse_too_long(m, nbrs.of(from), to, limits)) return false;
  return collapse_edge(m, from, to, limits) == Outcome::kApplied;
}

/// Split sweeps: the edges longer than √2, longest first, each split at split_point. The first
/// sweep's candidates are lists.long_edges (the mesh's state); the next sweep's are the edges
/// still longer than √2: a split keeps every edge but the one it cuts and moves no vertex, so
/// these are the refused candidates and the long edges at the vertices just created, listed as
/// an enumeration would (lowest id tet as the hint). On return lists.short_edges holds the edges
/// shorter than kCollapseBelow (the old ones and those at the new vertices).
long split_sweeps(Remesh3dContext& ctx, PassStats& st, double min_quality, EdgeLists& lists) {
  TetMesh& m = ctx.mesh();
  long total = 0;
  std::vector<Candidate> list = std::move(lists.long_edges), refused;
  std::vector<Id> created_all;  // the vertices created by the sweeps, in order
  for (int sweep = 0; sweep < kSplitSweeps; ++sweep) {
    sort_candidates(list, true);
    const std::size_t first_created = created_all.size();
    refused.clear();
    long done = 0;
    for (const Candidate& c : list) {
      NewVertex3 nv;
      if (!m.vert_alive(c.a) || !m.vert_alive(c.b) || !ctx.split_point(c.a, c.b, nv, c.tet)) {
        ++st.rejected;
        refused.push_back(c);
        continue;
      }
      Id created = kNoId;
      if (split_edge(m, c.a, c.b, nv, min_quality, &created, c.tet) == Outcome::kApplied) {
        ctx.inherit_hint(created);
        created_all.push_back(created);
        ++done;
      } else {
        ++st.rejected;
        refused.push_back(c);
      }
    }
    total += done;
    if (done == 0 || sweep + 1 == kSplitSweeps) break;
    EdgeLists next{kLongEdge, -1.0, {}, {}};
    for (Candidate& c : refused) {
      c.tet = lowest_edge_tet(m, c.a, c.b, c.tet);
      next.long_edges.push_back(c);
    }
    list_edges_at(m, std::span<const Id>(created_all).subspan(first_created), next);
    list.swap(next.long_edges);
  }
  EdgeLists at_new{std::numeric_limits<double>::infinity(), kCollapseBelow, {}, {}};
  list_edges_at(m, created_all, at_new);
  lists.short_edges.insert(lists.short_edges.end(), at_new.short_edges.begin(),
                           at_new.short_edges.end());
  return total;
}

/// Collapses of the edges shorter than kCollapseBelow (`list`: all of them as the mesh stands),
/// shortest first. A collapse moves no vertex and joins no new pair of vertices, so a listed
/// edge keeps its length while both its ends live.
long collapse_sweep(Remesh3dContext& ctx, PassStats& st, std::vector<ShortEdge> list,
                    const NeighbourTable& nbrs) {
  TetMesh& m = ctx.mesh();
  const CollapseLimits limits{0.2, 1.45};
  long done = 0;
  sort_candidates(list, false);
  for (const ShortEdge& c : list) {
    if (!m.vert_alive(c.a) || !m.vert_alive(c.b)) continue;
    bool applied = false;
    for (const auto& [from, to] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (try_collapse(m, from, to, limits, nbrs)) {
        applied = true;
        break;
      }
    if (applied) ++done;
    else ++st.rejected;
  }
  return done;
}

/// Edge swaps then face swaps around the tets worse than kSwapBelow (sliver removal), except
/// those on which they failed with nothing changed since (memo).
long swap_sweep(TetMesh& m, PassStats& st, const NeighbourTable& nbrs, FailureMemo& memo) {
  std::vector<Id> bad;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t)) && cached_quality(m, static_cast<Id>(t)) < kSwapBelow)
      bad.push_back(static_cast<Id>(t));
  long done = 0;
  for (const Id t : bad) {
    if (!m.tet_alive(t) || cached_quality(m, t) >= kSwapBelow) continue;
    if (memo.known_to_fail(m, t, nbrs)) {
      ++st.rejected;
      continue;
    }
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
    if (applied) {
      ++done;
    } else {
      ++st.rejected;
      memo.failed(m, t);
    }
  }
  return done;
}

/// The tets worse than kBad: each loses its worst edge by a collapse that does not lower the
/// worst quality of the ball (edges up to kBadMaxLength), its vertices tried in turn.
long bad_tet_sweep(TetMesh& m, PassStats& st, const NeighbourTable& nbrs) {
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
        if (try_collapse(m, from, to, {1.0, kBadMaxLength}, nbrs)) {
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
bool lengthen(Remesh3dContext& ctx, Id v, Id other, MoveCache& cache, const NeighbourTable& nbrs,
              std::vector<Id>& scratch) {
  TetMesh& m = ctx.mesh();
  const std::span<const Id> around = neighbours(m, v, nbrs, scratch);
  NewVertex3 target;
  if (!ctx.smoothing_target(v, target, &cache.ball, around)) return false;
  fill_move_cache(m, v, cache);
  const double l = edge_length(m, v, other);
  if (!(l > 0.0)) return false;
  Vec3 away = m.xyz[other] + (1.0 / l) * (m.xyz[v] - m.xyz[other]);
  if (!ctx.constrain(v, away)) return false;
  const auto range = [&](const Vec3& p, const SymMat3& mp, const SymMat3* log_mp) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (const Id x : around) {
      const double lx =
          edge_length_simpson(mp, m.metric[x], m.xyz[x] - p, log_mp, log_of(m.log_metric, x));
      lo = std::min(lo, lx), hi = std::max(hi, lx);
    }
    return std::pair{lo, hi};
  };
  const Vec3 from = m.xyz[v];
  const auto [lo0, hi0] = range(from, m.metric[v], log_of(m.log_metric, v));
  for (const Vec3& to : {target.p, away})
    for (const double f : {1.0, 0.5, 0.25}) {
      Vec3 p = from + f * (to - from);
      if (f != 1.0 && !ctx.constrain(v, p)) return false;
      const SymMat3 mp = ctx.metric_for(p, v);
      SymMat3 log_mp{};  // only when some length may need it
      const bool turning = !m.log_metric.empty() || !is_diagonal(mp);
      if (turning) log_mp = log_spd(mp);
      const auto [lo, hi] = range(p, mp, turning ? &log_mp : nullptr);
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
long short_edge_sweep(Remesh3dContext& ctx, PassStats& st, const NeighbourTable& nbrs) {
  TetMesh& m = ctx.mesh();
  MoveCache cache;
  std::vector<Id> scratch;
  long done = 0;
  for (const ShortEdge& c : edges_shorter_than(m, nbrs, kVeryShort)) {
    if (!m.vert_alive(c.a) || !m.vert_alive(c.b) || edge_length(m, c.a, c.b) >= kVeryShort)
      continue;
    bool applied = false;
    for (const auto& [from, to] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}})
      if (try_collapse(m, from, to, {kBad, kBadMaxLength}, nbrs)) {
        applied = true;
        break;
      }
    if (applied) {
      ++done;
      continue;
    }
    for (const auto& [v, other] : {std::pair{c.a, c.b}, std::pair{c.b, c.a}}) {
      cache.v = kNoId;
      if (lengthen(ctx, v, other, cache, nbrs, scratch)) {
        ++st.moves, applied = true;
        break;
      }
    }
    if (!applied) ++st.rejected;
  }
  return done;
}

/// Moves the vertices of the tets below kGoodBall toward their smoothing targets. `since` > 0:
/// the clock at the start of the previous smoothing sweep; a vertex whose closed ball has not
/// changed since was refused then (its move depends on nothing else: the ball, the background
/// metric, v's hint) and is counted refused again without the work (as 2D). `began` receives
/// this sweep's clock.
long smooth_sweep(Remesh3dContext& ctx, PassStats& st, const NeighbourTable& nbrs,
                  std::uint32_t since, std::uint32_t& began) {
  TetMesh& m = ctx.mesh();
  began = ++m.clock;
  std::vector<std::uint8_t> wanted(m.vertex_capacity(), 0);
  for (std::size_t t = 0; t < m.tet_capacity(); ++t)
    if (m.tet_alive(static_cast<Id>(t)) && cached_quality(m, static_cast<Id>(t)) < kGoodBall)
      for (int i = 0; i < 4; ++i) wanted[m.tv[4 * t + i]] = 1;
  long done = 0;
  MoveCache cache;
  cache.any_refusal = true;  // only kApplied counts here
  for (std::size_t vi = 0; vi < wanted.size(); ++vi) {
    const Id v = static_cast<Id>(vi);
    if (!wanted[vi] || !m.vert_alive(v)) continue;
    if (since > 0 && ball_unchanged(m, v, since, nbrs)) {
      if (m.vkind[v] != VertexKind::kFixed) ++st.rejected;  // smoothing_target refuses fixed ones
      continue;
    }
    NewVertex3 target;
    const std::span<const Id> known = nbrs.known(m, v) ? nbrs.of(v) : std::span<const Id>();
    if (!ctx.smoothing_target(v, target, &cache.ball, known)) continue;
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

/// The pass's statistics into st; lists receives the next pass's split and collapse candidates.
void summarize(TetMesh& m, PassStats& st, EdgeLists& lists, NeighbourTable* nbrs) {
  PassSummary sum;
  list_edges(m, lists, &sum, nbrs);
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

/// The longest metric length (edge_length_geometric) of the tets' edges in the field.
double longest_edge(const Mesh& mesh, std::span<const SymMat3> field) {
  double out = 0.0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (const auto& [i, j] : kTetEdge) {
      const Id a = mesh.tets[4 * t + i], b = mesh.tets[4 * t + j];
      const Vec3 ab{{mesh.coords[3 * b] - mesh.coords[3 * a],
                     mesh.coords[3 * b + 1] - mesh.coords[3 * a + 1],
                     mesh.coords[3 * b + 2] - mesh.coords[3 * a + 2]}};
      out = std::max(out, edge_length_geometric(field[a], field[b], ab));
    }
  return out;
}

// Splits append their vertices and tets at the end of the arrays: once the split sweeps of a
// pass leave more than this many vertices (and more than a quarter of the mesh) created since
// the numbering last followed the space, the new ones are renumbered along the Hilbert curve
// (Remesh3dContext::renumber_new_vertices), as in 2D. Fewer leave the mesh in the caches
// enough (the UGAWG cases, up to ~18 k vertices, keep their results).
constexpr std::size_t kRenumberAfter = 65536;

/// Renumbers the vertices created since `in_order` (the vertex count when the numbering last
/// followed the space) when they are many; the memos and the collapse candidates follow, and
/// the neighbour table is dropped (a cache: without it the sweeps walk the balls). True when
/// it renumbered.
bool keep_locality(Remesh3dContext& ctx, std::size_t renumber_after, SweepMemos& memos,
                   std::size_t& in_order, std::vector<ShortEdge>& short_edges,
                   NeighbourTable& nbrs) {
  const std::size_t after = renumber_after ? renumber_after : kRenumberAfter;
  if (!detail::renumber_due(ctx.mesh().vertex_capacity(), in_order, after)) return false;
  std::vector<Id> tet_old2new;
  const std::vector<Id> old2new = ctx.renumber_new_vertices(&tet_old2new);
  in_order = ctx.mesh().vertex_capacity();
  const std::size_t tets = ctx.mesh().tet_capacity();
  detail::remap_records(memos.swaps.at, tet_old2new, tets, std::uint32_t{0});
  detail::remap_records(memos.slivers.at, tet_old2new, tets, std::uint32_t{0});
  std::erase_if(short_edges, [&old2new](ShortEdge& e) {
    e.a = old2new[e.a], e.b = old2new[e.b];
    if (e.a > e.b) std::swap(e.a, e.b);
    return e.a == kNoId;
  });
  nbrs = NeighbourTable{};
  return true;
}

/// The longest edge, in the metric, of the listed faces kept as given or on curved interfaces
/// between subdomains (remeshed when their faces form a manifold surface, but coarse facets far
/// from their smooth surface may refuse their splits) or, with `outer`, of all listed faces; 0
/// when there is none.
double longest_kept_edge(const Remesh3dContext& ctx, bool outer) {
  const TetMesh& m = ctx.mesh();
  double longest = 0.0;
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    const Id t = static_cast<Id>(s / 4);
    if (!m.fbdy[s] || !m.tet_alive(t)) continue;
    if (!outer && (m.tadj[s] == kNoId || !ctx.curved_interface(m.face_ref(s)))) continue;
    const int i = static_cast<int>(s % 4);
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, edge_length(m, m.tv[4 * t + kTetFace[i][k]],
                                              m.tv[4 * t + kTetFace[i][(k + 1) % 3]]));
  }
  return longest;
}

/// One pass: splits and collapses, swaps and smoothing, clean-up, sliver removal.
void run_pass(Remesh3dContext& ctx, const Adapt3dOptions& options, EdgeLists& lists,
              NeighbourTable& nbrs, SweepMemos& memos, std::size_t& in_order, PassStats& st) {
  TetMesh& m = ctx.mesh();
  if (options.insert) {
    st.splits = split_sweeps(ctx, st,
                             options.keep_surface || ctx.has_interfaces()
                                 ? kKeptSurfaceSplitFloor
                                 : (m.surface ? kCurvedSplitFloor : 0.0),
                             lists);
    keep_locality(ctx, options.renumber_after, memos, in_order, lists.short_edges, nbrs);
    st.collapses = collapse_sweep(ctx, st, std::move(lists.short_edges), nbrs);
  }
  std::uint32_t smoothed = 0;  // the clock at the start of the last smoothing sweep
  for (int k = 0; k < 2; ++k) {
    if (options.swap) st.swaps += swap_sweep(m, st, nbrs, memos.swaps);
    if (options.move) st.moves += smooth_sweep(ctx, st, nbrs, smoothed, smoothed);
  }
  // Clean-up: very short edges, then the worst tets (twice, with swaps in between).
  if (options.insert) st.collapses += short_edge_sweep(ctx, st, nbrs);
  for (int k = 0; k < 2; ++k) {
    if (options.insert) st.collapses += bad_tet_sweep(m, st, nbrs);
    if (options.swap) st.swaps += swap_sweep(m, st, nbrs, memos.swaps);
  }
  // Last: sliver removal around the tets still below the quality target.
  SliverLimits sl;
  sl.swap = options.swap, sl.move = options.move, sl.collapse = options.insert;
  sl.split_fixed = options.keep_surface && options.insert && options.move;
  sliver_sweeps(ctx, sl, st, &nbrs, &memos.slivers);
  // Again: the sliver optimiser's moves do not look at lengths.
  if (options.insert) st.collapses += short_edge_sweep(ctx, st, nbrs);
}

/// Passes toward the field the context holds, each recorded in the report and given to on_pass.
struct PassLoop {
  Remesh3dContext& ctx;
  const Adapt3dOptions& options;
  EdgeLists& lists;
  NeighbourTable& nbrs;
  SweepMemos& memos;
  Adapt2dReport& report;
  const PassCallback& on_pass;
  std::size_t& in_order;  // vertices numbered in space order (keep_locality)

  /// At most max_passes passes (at least one), stage k of n (0, 0: the target field, no
  /// stages). True when they converged: fewer than 2% of the vertices inserted or removed (0.5%
  /// in 2D: in 3D a few edges cycle between split and collapse), no new low of that count for 3
  /// passes, or a pass that changed neither the fraction of edges in band (by 0.1%) nor the
  /// worst quality (by 0.001).
  bool run(int max_passes, int k, int n) {
    TetMesh& m = ctx.mesh();
    long best_ops = std::numeric_limits<long>::max();
    int best_pass = 0;
    double prev_in = 0.0, prev_qmin = 0.0;
    for (int pass = 1; pass <= std::max(1, max_passes); ++pass) {
      const auto t0 = std::chrono::steady_clock::now();
      PassStats st;
      st.pass = static_cast<int>(report.passes.size()) + 1;
      st.stage = k, st.stages = n;
      run_pass(ctx, options, lists, nbrs, memos, in_order, st);
      summarize(m, st, lists, options.insert ? &nbrs : nullptr);
      st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      report.passes.push_back(st);
      if (on_pass) on_pass(st);
      const long ops = st.splits + st.collapses;
      // Still: the fraction in band did not move and the worst quality did not rise (nor drop
      // by more than kQualityDrop: a pass whose splits left a worse tet is not the last one for
      // that reason; the bunny shell's third run ended on a 0.172 tet so, from 0.477).
      const bool still = pass > 1 && std::abs(st.len_in - prev_in) < 1e-3 &&
                         st.q_min < prev_qmin + 1e-3 && st.q_min > prev_qmin - kQualityDrop;
      prev_in = st.len_in, prev_qmin = st.q_min;
      if (ops <= static_cast<long>(st.vertices / 50) || pass - best_pass >= 3 || still) return true;
      if (ops < best_ops) best_ops = ops, best_pass = pass;
    }
    return false;
  }
};

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
  if (options.approach_growth != 0.0) approach_stages(1.0, options.approach_growth);  // checks
  if (input.dim != 3 || input.num_tets() == 0)
    throw InputError("3D remeshing needs a tetrahedral mesh");
  require_valid_input<3>(input, metrics);
  Adapt3dResult result;
  // Memory (issue #7): the renumbered copy of the input, its adjacency and the metric copies
  // are only needed to build the context; they go before the passes, as the context (background
  // mesh) goes before the output mesh is built.
  std::optional<Remesh3dContext> ctx;
  std::optional<MetricApproach<3>> approach;
  int stages = 0;  // of the staged approach (0: none)
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
    if (options.insert && options.approach_growth > 0.0) {
      const int n = approach_stages(longest_edge(ordered, prepared), options.approach_growth);
      if (n > 1) {
        std::vector<bool> in_tet;
        std::vector<SymMat3> implied = implied_log_metric<3>(ordered.coords, ordered.tets, &in_tet);
        approach.emplace(std::move(implied), in_tet, prepared);
        stages = n;
      }
    }
    ctx.emplace(std::move(ordered), std::move(prepared), options);
  }
  TetMesh& m = ctx->mesh();
  EdgeLists lists;  // the split and collapse candidates of the mesh as it stands
  NeighbourTable nbrs;  // the vertices' neighbours, for the collapses' length test
  NeighbourTable* const nbrs_wanted = options.insert ? &nbrs : nullptr;
  SweepMemos memos;    // the tets on which the swap and sliver sweeps failed
  std::size_t in_order = m.vertex_capacity();
  PassLoop loop{*ctx, options, lists, nbrs, memos, result.report, on_pass, in_order};
  const int n = stages;
  if (approach) {  // the staged approach: a few passes toward each intermediate field
    for (int k = 1; k < n; ++k) {
      ctx->set_field(approach->field(static_cast<double>(k) / n));
      if (options.insert) list_edges(m, lists, nullptr, nbrs_wanted);
      loop.run(kStagePasses, k, n);
    }
    ctx->set_field(approach->field(1.0));
    approach.reset();
  }
  if (options.insert) list_edges(m, lists, nullptr, nbrs_wanted);
  result.report.converged = loop.run(options.max_passes, n, n);
  lists = EdgeLists{}, nbrs = NeighbourTable{};
  if (!result.report.converged) result.report.stall_reason = stall_reason(m);
  if (const double l = longest_kept_edge(*ctx, options.keep_surface); l > kInterfaceNote) {
    char note[320];
    if (options.keep_surface)
      std::snprintf(note, sizeof note,
                    "the surface is kept as given (--nosurf): its edges are up to %.3g long in "
                    "the metric, and the tets along it cannot follow the sizes",
                    l);
    else
      std::snprintf(note, sizeof note,
                    "curved interfaces between subdomains keep edges up to %.3g long in the "
                    "metric (3D remeshing refines them within --hausd of their facets, but keeps "
                    "as given those with three faces of one ref at an edge, and the lines where "
                    "one meets two planes or a kept interface): the tets along them cannot "
                    "follow the sizes",
                    l);
    result.report.notes.push_back(note);
  }
  ctx->restore_refs();
  const TetMesh final_mesh = std::move(m);
  std::vector<std::uint32_t>().swap(final_mesh.edge_scratch);
  ctx.reset();
  result.mesh = to_mesh(final_mesh, &result.metrics);
  return result;
}

}  // namespace riemesh
