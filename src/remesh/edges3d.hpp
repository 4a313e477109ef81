#pragma once
// The edges of a TetMesh as the 3D driver's sweeps list them (adapt3d.cpp): every live edge once
// with the lowest-id tet holding it, and the lists of too long and too short edges kept between
// full enumerations (issue #7: a full enumeration with its metric lengths was 6 per pass).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/ops3d.hpp"

namespace riemesh {

/// Calls f(a, b, tet) for each unique live edge (a < b), in increasing (a, b), with the lowest
/// id tet holding it. Bucketed by a (counting sort of 4-byte entries 6 t + k, edge k of tet t,
/// written in increasing t), then each bucket reduced to its distinct b — the first entry of a b
/// has the lowest tet — and only those sorted: linear in the tets. The entries are the largest
/// transient of a pass (issue #7): 24 bytes per tet, and no edge list.
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
  // last[b] == v: edge (v, b) already in v's bucket (with a lower tet).
  std::vector<Id> last(m.vertex_capacity(), kNoId);
  std::vector<std::pair<Id, Id>> bucket;  // (b, tet), distinct b
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    bucket.clear();
    for (std::size_t k = start[v]; k < start[v + 1]; ++k) {
      const Id b = std::max(end(e[k], 0), end(e[k], 1));
      if (last[b] == static_cast<Id>(v)) continue;
      last[b] = static_cast<Id>(v);
      bucket.emplace_back(b, static_cast<Id>(e[k] / 6));
    }
    std::sort(bucket.begin(), bucket.end());
    for (const auto& [b, t] : bucket) f(static_cast<Id>(v), b, t);
  }
}

/// An edge of metric length above the split threshold, with a tet holding it when it was listed
/// (the lowest id then: a hint for the shell walk; the mesh changes).
struct LongEdge {
  double length;
  Id a, b;
  Id tet;
};

/// A collapse candidate: no hint (collapses walk the ball), 16 bytes instead of 24 — there can
/// be about one per tet (memory, issue #7).
struct ShortEdge {
  double length;
  Id a, b;
};

/// The edges longer than `long_above` and shorter than `short_below` of a mesh state (a < b).
struct EdgeLists {
  double long_above = 0.0, short_below = 0.0;
  std::vector<LongEdge> long_edges;
  std::vector<ShortEdge> short_edges;

  /// Files edge (a < b) of length l.
  void add(double l, Id a, Id b, Id tet) {
    if (l > long_above) long_edges.push_back({l, a, b, tet});
    if (l < short_below) short_edges.push_back({l, a, b});
  }
};

/// Every vertex's neighbours as the mesh stood when the table was taken (m.clock then `taken`):
/// still exact for a vertex that no replaced cavity has held since (TetMesh::untouched_since),
/// whatever moved. Lets the collapse sweeps test new edge lengths without walking balls (issue
/// #7: most collapse candidates are refused by that test). 4 bytes per vertex and 8 per edge.
struct NeighbourTable {
  std::vector<std::uint32_t> start;  // neighbours of v: list[start[v], start[v + 1])
  std::vector<Id> list;
  std::uint32_t taken = 0;

  /// Whether the neighbours of v are known (v untouched since the table was taken).
  bool known(const TetMesh& m, Id v) const {
    return static_cast<std::size_t>(v) + 1 < start.size() && m.untouched_since(v, taken);
  }
  std::span<const Id> of(Id v) const {
    return std::span<const Id>(list).subspan(start[v], start[v + 1] - start[v]);
  }

  /// Builds the table from the edges (a < b) in increasing (a, b) order, `upper` holding the b
  /// of each and `count[a]` how many have that a; advances m's clock.
  void build(TetMesh& m, const std::vector<Id>& upper, std::vector<std::uint32_t>& count) {
    const std::size_t n = m.vertex_capacity();
    std::vector<std::uint32_t> lower(n, 0);  // edges (a, v) with a < v, then their fill
    for (const Id b : upper) ++lower[b];
    start.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) start[v + 1] = start[v] + lower[v] + count[v];
    list.resize(start[n]);
    // v's list: the lower neighbours (filled in increasing a), then its upper ones, in order.
    std::fill(lower.begin(), lower.end(), 0);
    std::size_t k = 0;
    for (std::size_t a = 0; a < n; ++a)
      for (std::uint32_t j = 0; j < count[a]; ++j, ++k) {
        const Id b = upper[k];
        list[start[a + 1] - count[a] + j] = b;
        list[start[b] + lower[b]++] = static_cast<Id>(a);
      }
    taken = ++m.clock;
  }
};

/// Whether v's closed ball (its tets, their vertices' positions and metrics) is as it was when
/// m's clock read `since`; false when that is not known (v's neighbours not in nbrs).
inline bool ball_unchanged(const TetMesh& m, Id v, std::uint32_t since, const NeighbourTable& nbrs) {
  if (!m.untouched_since(v, since) || !m.unmoved_since(v, since) || !nbrs.known(m, v)) return false;
  for (const Id x : nbrs.of(v))
    if (!m.unmoved_since(x, since)) return false;
  return true;
}

/// The tets on which a sweep's attempt failed, and when. The swaps and the sliver removal try on
/// a tet only operators that read the closed balls of its four vertices (the shells of its
/// edges, the tets across its faces, its vertices' balls), deterministically: while those balls
/// are unchanged (ball_unchanged) the attempt would fail again, and is skipped. A tet id reused
/// by a new tet has touched vertices, so it is tried. (Issue #7: measured in the log-Euclidean
/// mean, polar1-3d keeps ~1,000 tets below the sliver target that no operator can raise; the
/// sweeps spent most of each pass failing on them again.)
struct FailureMemo {
  std::vector<std::uint32_t> at;  // per tet: m.clock when an attempt on it failed (0: none)

  bool known_to_fail(const TetMesh& m, Id t, const NeighbourTable& nbrs) const {
    if (static_cast<std::size_t>(t) >= at.size() || at[t] == 0) return false;
    for (int i = 0; i < 4; ++i)
      if (!ball_unchanged(m, m.tv[4 * t + i], at[t], nbrs)) return false;
    return true;
  }
  /// Records a failed attempt on t; advances m's clock so that any later change is seen.
  void failed(TetMesh& m, Id t) {
    if (at.size() <= static_cast<std::size_t>(t)) at.resize(m.tet_capacity(), 0);
    at[t] = ++m.clock;
  }
};

/// Calls f(x, y, tet) once for each live edge (x, y) at a vertex of `verts` (distinct, live),
/// x in verts and, for an edge between two of them, x < y; tet: the lowest id tet holding it.
/// `in_verts[v]` must be nonzero exactly for the vertices of verts (sized to the vertices).
template <class F>
void for_each_edge_at(const TetMesh& m, std::span<const Id> verts,
                      const std::vector<std::uint8_t>& in_verts, F&& f) {
  thread_local std::vector<Id> ball;
  thread_local std::vector<std::pair<Id, Id>> nbrs;  // (y, lowest tet)
  for (const Id x : verts) {
    collect_ball(m, x, ball);
    nbrs.clear();
    for (const Id t : ball)
      for (int i = 0; i < 4; ++i) {
        const Id y = m.tv[4 * t + i];
        if (y == x || (in_verts[y] && y < x)) continue;
        auto it = std::find_if(nbrs.begin(), nbrs.end(), [y](const auto& n) { return n.first == y; });
        if (it == nbrs.end()) nbrs.emplace_back(y, t);
        else it->second = std::min(it->second, t);
      }
    for (const auto& [y, t] : nbrs) f(x, y, t);
  }
}

}  // namespace riemesh
