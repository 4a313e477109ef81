// Adjacency by bucketing: every face (edge) is filed under its smallest vertex with a counting
// sort, then the few entries of each bucket are sorted by their remaining vertices, so equal
// faces become neighbours in memory. O(n) plus sorts of buckets of ~20 entries; no hashing, and
// the result depends only on the input order (deterministic).
#include "mesh/adjacency.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace riemesh {
namespace {

/// A face filed under its smallest vertex: the remaining vertices packed into one key.
struct FaceEntry {
  std::uint64_t key;
  Id face;  // element * verts_per_simplex + local face
};

/// The vertices of element e sorted increasingly, with their local positions.
template <int K>
inline void sorted_vertices(const Id* s, Id (&v)[K], int (&pos)[K]) {
  for (int i = 0; i < K; ++i) v[i] = s[i], pos[i] = i;
  for (int i = 1; i < K; ++i)  // insertion sort: 3 or 4 entries
    for (int j = i; j > 0 && v[j] < v[j - 1]; --j) {
      std::swap(v[j], v[j - 1]);
      std::swap(pos[j], pos[j - 1]);
    }
}

/// Face opposite sorted vertex j: (smallest vertex, key of the others).
template <int K>
inline Id face_key(const Id (&v)[K], int j, std::uint64_t& key) {
  Id rest[K - 1];
  for (int i = 0, n = 0; i < K; ++i)
    if (i != j) rest[n++] = v[i];
  key = static_cast<std::uint32_t>(rest[K - 2]);
  if constexpr (K == 4) key |= static_cast<std::uint64_t>(static_cast<std::uint32_t>(rest[1])) << 32;
  return rest[0];
}

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
  adj.vert2elem_offsets.assign(adj.num_vertices + 1, 0);
  for (Id v : s) ++adj.vert2elem_offsets[v];
  prefix_sum(adj.vert2elem_offsets);
  adj.vert2elem.resize(s.size());
  std::vector<Id> fill(adj.vert2elem_offsets.begin(), adj.vert2elem_offsets.end() - 1);
  for (std::size_t e = 0; e < ne; ++e)
    for (int i = 0; i < k; ++i) adj.vert2elem[fill[s[k * e + i]]++] = static_cast<Id>(e);
}

template <int K>
void build_neighbours(Adjacency& adj, const std::vector<Id>& s) {
  const std::size_t ne = s.size() / K;
  std::vector<Id> offsets(adj.num_vertices + 1, 0);
  for (std::size_t e = 0; e < ne; ++e) {
    Id v[K];
    int pos[K];
    sorted_vertices<K>(&s[K * e], v, pos);
    offsets[v[0]] += K - 1;  // every face but the one opposite the smallest vertex
    offsets[v[1]] += 1;      // which is filed under the second smallest
  }
  prefix_sum(offsets);
  std::vector<FaceEntry> faces(s.size());
  std::vector<Id> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t e = 0; e < ne; ++e) {
    Id v[K];
    int pos[K];
    sorted_vertices<K>(&s[K * e], v, pos);
    for (int j = 0; j < K; ++j) {
      std::uint64_t key;
      const Id a = face_key<K>(v, j, key);
      faces[fill[a]++] = {key, static_cast<Id>(K * e + pos[j])};
    }
  }
  adj.elem2elem.assign(s.size(), kNoId);
  auto less = [](const FaceEntry& x, const FaceEntry& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  };
  for (std::size_t a = 0; a < adj.num_vertices; ++a) {
    FaceEntry* first = faces.data() + offsets[a];
    FaceEntry* last = faces.data() + offsets[a + 1];
    sort_bucket(first, last, less);
    for (FaceEntry* r = first; r < last;) {
      FaceEntry* run = r + 1;
      while (run < last && run->key == r->key) ++run;
      if (run - r == 2) {
        adj.elem2elem[r[0].face] = r[1].face / K;
        adj.elem2elem[r[1].face] = r[0].face / K;
      } else if (run - r > 2) {
        for (FaceEntry* f = r; f < run; ++f) adj.nonmanifold_faces.push_back(f->face);
      }
      r = run;
    }
  }
  std::sort(adj.nonmanifold_faces.begin(), adj.nonmanifold_faces.end());
}

/// An edge occurrence filed under its smallest vertex.
struct EdgeEntry {
  Id other;  // the larger vertex
  Id occurrence;  // element * edges_per_simplex + local edge
};

template <int K>
void build_edges(Adjacency& adj, const std::vector<Id>& s) {
  constexpr int kNe = K == 4 ? 6 : 3;
  const int(*local)[2] = K == 4 ? kTetEdge : kTriEdge;
  const std::size_t ne = s.size() / K;
  std::vector<Id> offsets(adj.num_vertices + 1, 0);
  for (std::size_t e = 0; e < ne; ++e)
    for (int j = 0; j < kNe; ++j)
      ++offsets[std::min(s[K * e + local[j][0]], s[K * e + local[j][1]])];
  prefix_sum(offsets);
  std::vector<EdgeEntry> entries(ne * kNe);
  std::vector<Id> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t e = 0; e < ne; ++e)
    for (int j = 0; j < kNe; ++j) {
      const Id p = s[K * e + local[j][0]], q = s[K * e + local[j][1]];
      entries[fill[std::min(p, q)]++] = {std::max(p, q), static_cast<Id>(kNe * e + j)};
    }
  adj.elem2edge.assign(ne * kNe, kNoId);
  adj.edges.clear();
  adj.edges.reserve(ne * kNe / 2);  // ~ 1.2 edges per tet, 1.5 per triangle: an upper guess
  auto less = [](const EdgeEntry& x, const EdgeEntry& y) {
    return x.other != y.other ? x.other < y.other : x.occurrence < y.occurrence;
  };
  for (std::size_t a = 0; a < adj.num_vertices; ++a) {
    EdgeEntry* first = entries.data() + offsets[a];
    EdgeEntry* last = entries.data() + offsets[a + 1];
    sort_bucket(first, last, less);
    for (EdgeEntry* r = first; r < last; ++r) {
      if (r == first || r->other != (r - 1)->other) {
        adj.edges.push_back(static_cast<Id>(a));
        adj.edges.push_back(r->other);
      }
      adj.elem2edge[r->occurrence] = static_cast<Id>(adj.edges.size() / 2 - 1);
    }
  }
  adj.edges.shrink_to_fit();
}

}  // namespace

Adjacency build_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                          std::size_t num_vertices) {
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
    build_neighbours<4>(adj, simplices);
    build_edges<4>(adj, simplices);
  } else {
    build_neighbours<3>(adj, simplices);
    build_edges<3>(adj, simplices);
  }
  return adj;
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
    if (ma < a || (ma == a && mb < b)) lo = mid + 1;
    else hi = mid;
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
    if (adj.elem2elem[4 * e + c] == kNoId) start = e, cross = d;
    else if (adj.elem2elem[4 * e + d] == kNoId) start = e, cross = c;
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
