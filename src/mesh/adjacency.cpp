// Adjacency from the vertex -> element incidence (a counting sort, O(n)): every face and edge is
// handled at its smallest vertex, among the few elements around it. O(n) overall, no hashing,
// and the result depends only on the input (deterministic).
#include "mesh/adjacency.hpp"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/huge_pages.hpp"

namespace riemesh {
namespace {

/// Sorts a small bucket by (key, face); insertion sort for the usual tiny buckets.
template <class T, class Less>
void sort_bucket(T* first, T* last, Less less) {
  if (last - first > 32) {
    std::sort(first, last, less);
    return;
  }
  for (T* i = first + 1; i < last; ++i) {
    T x = *i;
    T* j = i;
    for (; j > first && less(x, *(j - 1)); --j) *j = *(j - 1);
    *j = x;
  }
}

/// Exclusive prefix sum in place; counts[n] receives the total.
void prefix_sum(std::vector<Id>& counts) {
  Id sum = 0;
  for (Id& c : counts) {
    const Id n = c;
    c = sum;
    sum += n;
  }
}

void build_vert2elem(Adjacency& adj, const std::vector<Id>& s, int k) {
  const std::size_t ne = s.size() / k;
  reserve_huge(adj.vert2elem_offsets, adj.num_vertices + 1);
  adj.vert2elem_offsets.assign(adj.num_vertices + 1, 0);
  for (Id v : s) ++adj.vert2elem_offsets[v];
  prefix_sum(adj.vert2elem_offsets);
  reserve_huge(adj.vert2elem, s.size());
  adj.vert2elem.resize(s.size());
  std::vector<Id> fill(adj.vert2elem_offsets.begin(), adj.vert2elem_offsets.end() - 1);
  for (std::size_t e = 0; e < ne; ++e)
    for (int i = 0; i < k; ++i) adj.vert2elem[fill[s[k * e + i]]++] = static_cast<Id>(e);
}

/// A face met at its smallest vertex a, chained with the other faces sharing its second vertex.
struct LocalFace {
  Id c;       // third vertex (kNoId for an edge of a triangle)
  Id face;    // element * verts_per_simplex + local face
  Id next;    // next entry with the same second vertex, or -1
  Id group;   // first entry with the same vertices
  int count;  // on a group's first entry: how many entries share its vertices
};

/// Neighbours across faces. Each face is handled at its smallest vertex a: the faces of the
/// elements around a whose other vertices are all larger than a (about 20 in a tetrahedral
/// mesh) are matched through short chains per second vertex b (stamped arrays indexed by b).
/// Working vertex by vertex keeps the data in cache, and chains avoid sorting entries whose
/// order follows the vertex numbering (a sort costs 3x more on a Hilbert-numbered mesh).
template <int K>
void build_neighbours(Adjacency& adj, const std::vector<Id>& s) {
  adj.elem2elem.assign(s.size(), kNoId);
  std::vector<LocalFace> local;
  std::vector<Id> owner(adj.num_vertices, kNoId), head(adj.num_vertices, kNoId);
  for (std::size_t v = 0; v < adj.num_vertices; ++v) {
    const Id a = static_cast<Id>(v);
    local.clear();
    const auto around = ball(adj, a);
    for (std::size_t n = 0; n < around.size(); ++n) {
      const Id e = around[n];
      if (n > 0 && around[n - 1] == e) continue;  // a repeated vertex (invalid input)
      const Id* t = &s[K * e];
      const int p = local_index(t, K, a);
      for (int i = 0; i < K; ++i) {  // the faces opposite i != p contain a
        if (i == p) continue;
        Id rest[2] = {kNoId, kNoId};
        bool smallest = true;
        for (int j = 0, r = 0; j < K; ++j)
          if (j != i && j != p) {
            rest[r++] = t[j];
            smallest = smallest && t[j] > a;
          }
        if (!smallest) continue;
        const Id b = K == 4 ? std::min(rest[0], rest[1]) : rest[0];
        const Id c = K == 4 ? std::max(rest[0], rest[1]) : kNoId;
        if (owner[b] != a) owner[b] = a, head[b] = kNoId;
        const Id self = static_cast<Id>(local.size());
        Id group = self;
        for (Id x = head[b]; x != kNoId; x = local[x].next)
          if (local[x].c == c) {
            group = local[x].group;
            break;
          }
        local.push_back({c, static_cast<Id>(K * e + i), head[b], group, 0});
        head[b] = self;
        ++local[group].count;
      }
    }
    for (std::size_t x = 0; x < local.size(); ++x) {
      const LocalFace& f = local[x];
      const int count = local[f.group].count;
      if (count > 2) {
        adj.nonmanifold_faces.push_back(f.face);
      } else if (count == 2 && f.group != static_cast<Id>(x)) {  // the second of a pair
        const Id first = local[f.group].face;
        adj.elem2elem[first] = f.face / K;
        adj.elem2elem[f.face] = first / K;
      }
    }
  }
  std::sort(adj.nonmanifold_faces.begin(), adj.nonmanifold_faces.end());
}

/// Neighbours of triangles, the quick way for the usual manifold mesh: each side (a, b) not yet
/// matched looks for the other triangles holding b among those around a = min(a, b) (about 6).
/// Gives what build_neighbours<3> gives (a side in two triangles: neighbours; in one: none);
/// returns false, leaving the work to it, at a side in three or more triangles or a triangle
/// with a repeated vertex. 5x fewer instructions than the chains (no per-vertex arrays).
bool build_triangle_neighbours(Adjacency& adj, const std::vector<Id>& s) {
  const std::size_t ne = s.size() / 3;
  reserve_huge(adj.elem2elem, s.size());
  adj.elem2elem.assign(s.size(), kNoId);
  for (std::size_t t = 0; t < ne; ++t) {
    const Id* v = &s[3 * t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) return false;
    for (int i = 0; i < 3; ++i) {
      if (adj.elem2elem[3 * t + i] != kNoId) continue;  // matched from the other triangle
      const Id a = std::min(v[kTriEdge[i][0]], v[kTriEdge[i][1]]);
      const Id b = std::max(v[kTriEdge[i][0]], v[kTriEdge[i][1]]);
      Id other = kNoId;
      int face = -1;
      for (const Id u : ball(adj, a)) {
        if (u == static_cast<Id>(t)) continue;
        const Id* w = &s[3 * static_cast<std::size_t>(u)];
        const int jb = w[0] == b ? 0 : (w[1] == b ? 1 : (w[2] == b ? 2 : -1));
        if (jb < 0) continue;
        if (other != kNoId) return false;  // a third triangle on the side
        other = u;
        face = 3 - jb - local_index(w, 3, a);  // the side opposite u's third vertex
      }
      if (other == kNoId) continue;
      adj.elem2elem[3 * t + i] = other;
      adj.elem2elem[3 * static_cast<std::size_t>(other) + face] = static_cast<Id>(t);
    }
  }
  return true;
}

/// Unique edges, vertex by vertex: the larger ends b > a met around a are deduplicated with a
/// stamp array, sorted, numbered, then written back to the elements around a.
template <int K>
void build_edges(Adjacency& adj, const std::vector<Id>& s) {
  constexpr int kNe = K == 4 ? 6 : 3;
  const int(*local)[2] = K == 4 ? kTetEdge : kTriEdge;
  const std::size_t nv = adj.num_vertices;
  adj.elem2edge.assign(s.size() / K * kNe, kNoId);
  adj.edges.clear();
  adj.edges.reserve(s.size() / K * (K == 4 ? 3 : 4));  // ~1.2 edges per tet, 1.5 per triangle
  std::vector<Id> seen(nv, kNoId), edge_of(nv, kNoId), others;
  for (std::size_t v = 0; v < nv; ++v) {
    const Id a = static_cast<Id>(v);
    const auto around = ball(adj, a);
    // Branch-free selections: with a space-filling-curve numbering, "b > a" is a coin toss
    // for the branch predictor (branches made this loop 3x slower than on a lexicographic grid).
    others.resize(around.size() * K);
    std::size_t count = 0;
    for (Id e : around)
      for (int i = 0; i < K; ++i) {
        const Id b = s[K * e + i];
        const bool take = (b > a) & (seen[b] != a);
        others[count] = b;
        count += take;
        seen[b] = take ? a : seen[b];
      }
    sort_bucket(others.data(), others.data() + count, std::less<Id>());
    for (std::size_t x = 0; x < count; ++x) {
      edge_of[others[x]] = static_cast<Id>(adj.edges.size() / 2);
      adj.edges.push_back(a);
      adj.edges.push_back(others[x]);
    }
    for (Id e : around)
      for (int j = 0; j < kNe; ++j) {
        const Id p = s[K * e + local[j][0]], q = s[K * e + local[j][1]];
        const Id other = p == a ? q : p;
        const bool take = ((p == a) | (q == a)) & (other > a);
        Id& dst = adj.elem2edge[kNe * e + j];
        dst = take ? edge_of[other] : dst;
      }
  }
  adj.edges.shrink_to_fit();
}

}  // namespace

namespace {

Adjacency build(const std::vector<Id>& simplices, int verts_per_simplex,
                std::size_t num_vertices, bool with_edges, bool with_neighbours = true) {
  const int k = verts_per_simplex;
  if (k != 3 && k != 4)
    throw InputError("build_adjacency: verts_per_simplex must be 3 or 4, got " + std::to_string(k));
  if (simplices.size() % k != 0)
    throw InputError("build_adjacency: simplex array size " + std::to_string(simplices.size()) +
                     " is not a multiple of " + std::to_string(k));
  if (simplices.size() * 2 >= static_cast<std::size_t>(std::numeric_limits<Id>::max()) ||
      num_vertices >= static_cast<std::size_t>(std::numeric_limits<Id>::max()))
    throw InputError("build_adjacency: too many entities for 32-bit ids");
  for (std::size_t i = 0; i < simplices.size(); ++i)
    if (simplices[i] < 0 || static_cast<std::size_t>(simplices[i]) >= num_vertices)
      throw InputError("build_adjacency: vertex id " + std::to_string(simplices[i]) +
                       " of element " + std::to_string(i / k) + " is out of range [0, " +
                       std::to_string(num_vertices) + ")");
  Adjacency adj;
  adj.verts_per_simplex = k;
  adj.num_vertices = num_vertices;
  build_vert2elem(adj, simplices, k);
  if (k == 4) {
    if (with_neighbours) build_neighbours<4>(adj, simplices);
    if (with_edges) build_edges<4>(adj, simplices);
  } else {
    if (with_neighbours && !build_triangle_neighbours(adj, simplices)) {
      adj.elem2elem.clear();
      build_neighbours<3>(adj, simplices);
    }
    if (with_edges) build_edges<3>(adj, simplices);
  }
  return adj;
}

}  // namespace

Adjacency build_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                          std::size_t num_vertices) {
  return build(simplices, verts_per_simplex, num_vertices, true);
}

Adjacency build_face_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                               std::size_t num_vertices) {
  return build(simplices, verts_per_simplex, num_vertices, false);
}

Adjacency build_edge_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                               std::size_t num_vertices) {
  return build(simplices, verts_per_simplex, num_vertices, true, false);
}

void add_edges(Adjacency& adj, const std::vector<Id>& simplices) {
  RIEMESH_CHECK(simplices.size() == adj.vert2elem.size());
  if (adj.verts_per_simplex == 4) build_edges<4>(adj, simplices);
  else build_edges<3>(adj, simplices);
}

Adjacency build_adjacency(const Mesh& mesh) {
  if (mesh.kind() == MeshKind::kVolume) return build_adjacency(mesh.tets, 4, mesh.num_vertices());
  return build_adjacency(mesh.triangles, 3, mesh.num_vertices());
}

Id find_edge(const Adjacency& adj, Id a, Id b) {
  if (a > b) std::swap(a, b);
  std::size_t lo = 0, hi = adj.num_edges();
  while (lo < hi) {  // first edge >= (a, b)
    const std::size_t mid = (lo + hi) / 2;
    const Id ma = adj.edges[2 * mid], mb = adj.edges[2 * mid + 1];
    if (ma < a || (ma == a && mb < b))
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo < adj.num_edges() && adj.edges[2 * lo] == a && adj.edges[2 * lo + 1] == b)
    return static_cast<Id>(lo);
  return kNoId;
}

namespace {

/// Local indices of the two vertices of tetrahedron t that are not a or b.
inline void other_two(const Id* t, Id a, Id b, int& c, int& d) {
  c = d = -1;
  for (int i = 0; i < 4; ++i)
    if (t[i] != a && t[i] != b) (c < 0 ? c : d) = i;
}

}  // namespace

Shell shell(const Adjacency& adj, const std::vector<Id>& simplices, Id a, Id b) {
  const int k = adj.verts_per_simplex;
  RIEMESH_CHECK(simplices.size() == adj.elem2elem.size());
  std::vector<Id> candidates;
  for (Id e : ball(adj, a))
    if (local_index(&simplices[k * e], k, b) >= 0) candidates.push_back(e);
  Shell sh;
  if (k == 3 || candidates.empty()) {
    sh.ordered = candidates.size() <= 2;
    sh.elements = std::move(candidates);
    return sh;
  }
  // Start at a tet with a boundary face on the edge (walking away from it), else at the first.
  Id start = candidates.front();
  int cross = -1;  // the local vertex whose opposite face we cross next
  for (Id e : candidates) {
    int c, d;
    other_two(&simplices[4 * e], a, b, c, d);
    if (adj.elem2elem[4 * e + c] == kNoId)
      start = e, cross = d;
    else if (adj.elem2elem[4 * e + d] == kNoId)
      start = e, cross = c;
    if (cross >= 0) break;
  }
  if (cross < 0) {
    int d;
    other_two(&simplices[4 * start], a, b, cross, d);
  }
  sh.elements.push_back(start);
  for (Id cur = start; sh.elements.size() <= candidates.size();) {
    const Id* t = &simplices[4 * cur];
    const Id next = adj.elem2elem[4 * cur + cross];
    if (next == kNoId) break;
    if (next == start) {
      sh.closed = true;
      break;
    }
    if (sh.elements.size() == candidates.size()) break;  // inconsistent: more than the candidates
    // The crossed face holds a, b and y; in `next` the following face is the one opposite y.
    Id y = kNoId;
    for (int i = 0; i < 4; ++i)
      if (i != cross && t[i] != a && t[i] != b) y = t[i];
    cross = local_index(&simplices[4 * next], 4, y);
    RIEMESH_CHECK(cross >= 0);
    sh.elements.push_back(next);
    cur = next;
  }
  std::vector<Id> seen = sh.elements;
  std::sort(seen.begin(), seen.end());
  sh.ordered = seen == candidates;  // candidates are sorted (ball order)
  if (!sh.ordered) {  // non-manifold shell: the walk missed some, give them all in id order
    sh.closed = false;
    sh.elements = std::move(candidates);
  }
  return sh;
}

}  // namespace riemesh
