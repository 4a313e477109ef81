#pragma once
// Renumbering the vertices a remesher appended (splits add theirs at the end of the arrays, far
// in memory from their neighbours) along the Hilbert curve, and the elements by their smallest
// vertex, for the TriMesh and the TetMesh (renumber_tail in tri_mesh.hpp and tet_mesh.hpp).
#include <algorithm>
#include <cstddef>
#include <vector>

#include "core/huge_pages.hpp"
#include "mesh/hilbert.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::detail {

/// The new numbering of a mesh's vertices and elements, as new -> old and old -> new maps
/// (kNoId in old -> new: dead, dropped).
struct TailOrder {
  std::vector<Id> vertex_new2old, vertex_old2new, elem_new2old, elem_old2new;
};

/// Vertices below `first` keep their ids; the live ones from `first` on follow in Hilbert order
/// of their `dim` coordinates (point(v) gives them); the live elements (`k` vertex ids each in
/// conn, a dead one with conn[k e] == kNoId) follow by their smallest new vertex id, stably.
template <class Alive, class Point>
TailOrder tail_order(std::size_t num_vertices, std::size_t first, Alive alive, Point point,
                     int dim, const std::vector<Id>& conn, int k) {
  TailOrder o;
  std::vector<Id> tail;
  std::vector<double> coords;
  for (std::size_t v = first; v < num_vertices; ++v)
    if (alive(static_cast<Id>(v))) {
      tail.push_back(static_cast<Id>(v));
      const double* p = point(static_cast<Id>(v));
      coords.insert(coords.end(), p, p + dim);
    }
  o.vertex_new2old.resize(first);
  for (std::size_t v = 0; v < first; ++v) o.vertex_new2old[v] = static_cast<Id>(v);
  for (const Id i : hilbert_order(coords, dim)) o.vertex_new2old.push_back(tail[i]);
  o.vertex_old2new.assign(num_vertices, kNoId);
  for (std::size_t v = 0; v < o.vertex_new2old.size(); ++v)
    o.vertex_old2new[o.vertex_new2old[v]] = static_cast<Id>(v);
  // Elements: a counting sort by smallest new vertex id.
  const std::size_t ne = conn.size() / static_cast<std::size_t>(k);
  const auto smallest = [&](std::size_t e) {
    Id s = o.vertex_old2new[conn[k * e]];
    for (int i = 1; i < k; ++i) s = std::min(s, o.vertex_old2new[conn[k * e + i]]);
    return static_cast<std::size_t>(s);
  };
  std::vector<Id> start(o.vertex_new2old.size() + 1, 0);
  for (std::size_t e = 0; e < ne; ++e)
    if (conn[k * e] != kNoId) ++start[smallest(e) + 1];
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  o.elem_new2old.resize(static_cast<std::size_t>(start.back()));
  o.elem_old2new.assign(ne, kNoId);
  for (std::size_t e = 0; e < ne; ++e) {
    if (conn[k * e] == kNoId) continue;
    const Id at = start[smallest(e)]++;
    o.elem_new2old[static_cast<std::size_t>(at)] = static_cast<Id>(e);
    o.elem_old2new[e] = at;
  }
  return o;
}

/// a = the records new2old lists, `stride` values each, in that order; the storage reserved
/// with room for as many again (splits then append without copying).
template <class T>
void gather_records(std::vector<T>& a, const std::vector<Id>& new2old, std::size_t stride) {
  std::vector<T> out;
  reserve_huge(out, 2 * stride * new2old.size());
  for (const Id old : new2old)
    for (std::size_t j = 0; j < stride; ++j)
      out.push_back(a[stride * static_cast<std::size_t>(old) + j]);
  a.swap(out);
}

/// Per-entity data kept beside a renumbered mesh (hints, stamps, memos): a[old] moves to
/// a[old2new[old]], entries dropped (kNoId) or missing (a shorter than old2new) leave `fill`;
/// n entries after.
template <class T>
void remap_records(std::vector<T>& a, const std::vector<Id>& old2new, std::size_t n, T fill) {
  std::vector<T> out(n, fill);
  for (std::size_t i = 0; i < a.size() && i < old2new.size(); ++i)
    if (old2new[i] != kNoId) out[static_cast<std::size_t>(old2new[i])] = a[i];
  a.swap(out);
}

/// Whether the vertices created since the numbering last followed the space (`in_order`
/// vertices then, `n` now) are many enough to renumber: more than `after` and a quarter of n.
inline bool renumber_due(std::size_t n, std::size_t in_order, std::size_t after) {
  return n > in_order && n - in_order > std::max(after, n / 4);
}

/// Adjacency slots (k per element: k e + i) renumbered by the elements' old -> new map.
inline void renumber_slots(std::vector<Id>& adj, const std::vector<Id>& elem_old2new, int k) {
  for (Id& s : adj)
    if (s != kNoId) s = k * elem_old2new[static_cast<std::size_t>(s / k)] + s % k;
}

}  // namespace riemesh::detail
