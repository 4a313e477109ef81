#include "mesh/hilbert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "core/error.hpp"
#include "core/huge_pages.hpp"

namespace riemesh {

namespace {

/// Spreads the low 21 bits of x to every third bit (bit i -> bit 3i).
inline std::uint64_t spread3(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

/// Spreads the low 31 bits of x to every other bit (bit i -> bit 2i).
inline std::uint64_t spread2(std::uint64_t x) {
  x &= 0x7fffffff;
  x = (x | x << 16) & 0x0000ffff0000ffffULL;
  x = (x | x << 8) & 0x00ff00ff00ff00ffULL;
  x = (x | x << 4) & 0x0f0f0f0f0f0f0f0fULL;
  x = (x | x << 2) & 0x3333333333333333ULL;
  x = (x | x << 1) & 0x5555555555555555ULL;
  return x;
}

template <int D, int b = hilbert_bits(D)>
std::uint64_t hilbert_key_d(const std::uint32_t* x_in) {
  std::uint32_t x[D];
  for (int i = 0; i < D; ++i) x[i] = x_in[i];
  // Inverse undo of the excess work (branch-free: for each bit q of x[i], either invert the
  // low bits of x[0] or exchange them with those of x[i]), then Gray encoding: x becomes the
  // "transposed" Hilbert index.
  for (std::uint32_t q = 1u << (b - 1); q > 1; q >>= 1) {
    const std::uint32_t p = q - 1;
    for (int i = 0; i < D; ++i) {
      const std::uint32_t set = 0u - ((x[i] & q) ? 1u : 0u);
      const std::uint32_t t = (x[0] ^ x[i]) & p & ~set;
      x[0] ^= t ^ (p & set);
      x[i] ^= t;
    }
  }
  for (int i = 1; i < D; ++i) x[i] ^= x[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = 1u << (b - 1); q > 1; q >>= 1)
    if (x[D - 1] & q) t ^= q - 1;
  for (int i = 0; i < D; ++i) x[i] ^= t;
  // Interleave, most significant level first: bits of x[0], x[1] (, x[2]) at each level.
  if constexpr (D == 3)
    return spread3(x[0]) << 2 | spread3(x[1]) << 1 | spread3(x[2]);
  else
    return spread2(x[0]) << 1 | spread2(x[1]);
}

}  // namespace

std::uint64_t hilbert_key(const std::uint32_t* x, int dim) {
  return dim == 2 ? hilbert_key_d<2>(x) : hilbert_key_d<3>(x);
}

namespace {

/// Bits per axis of the keys renumber_hilbert sorts by: 2^16 cells per side in 2D, 2^10 in 3D
/// (32-bit keys). Plenty for locality, and the keys cost about half as much as full-precision
/// ones and sort in two radix passes instead of four.
constexpr int renumber_bits(int dim) { return dim == 2 ? 16 : 10; }

/// Maps points of the bounding cube of a point set to integer grid coordinates, `bits` per axis
/// (hilbert_bits(d) for the public keys, renumber_bits(d) for renumbering).
struct Quantiser {
  int dim = 3;
  int bits = 21;
  double lo[3] = {0, 0, 0};
  double scale = 0.0;     // cells per unit length
  std::uint32_t top = 0;  // largest grid coordinate

  Quantiser(std::span<const double> coords, int d, int b) : dim(d), bits(b) {
    const std::size_t n = coords.size() / d;
    double hi[3] = {0, 0, 0};
    for (int c = 0; c < d; ++c) {
      lo[c] = std::numeric_limits<double>::infinity();
      hi[c] = -lo[c];
    }
    for (std::size_t v = 0; v < n; ++v)
      for (int c = 0; c < d; ++c) {
        const double x = coords[d * v + c];
        if (!std::isfinite(x)) continue;
        lo[c] = std::min(lo[c], x);
        hi[c] = std::max(hi[c], x);
      }
    double extent = 0.0;
    for (int c = 0; c < d; ++c) {
      if (!(lo[c] <= hi[c])) lo[c] = hi[c] = 0.0;  // no finite coordinate
      extent = std::max(extent, hi[c] - lo[c]);
    }
    top = static_cast<std::uint32_t>((std::uint64_t{1} << bits) - 1);
    scale = extent > 0.0 ? static_cast<double>(top) / extent : 0.0;
  }

  std::uint64_t key(const double* p) const {
    std::uint32_t x[3] = {0, 0, 0};
    for (int c = 0; c < dim; ++c) {
      const double s = (p[c] - lo[c]) * scale;
      x[c] = s > 0.0 ? (s < top ? static_cast<std::uint32_t>(s) : top) : 0u;  // NaN -> 0
    }
    if (bits == hilbert_bits(dim)) return hilbert_key(x, dim);
    return dim == 2 ? hilbert_key_d<2, renumber_bits(2)>(x) : hilbert_key_d<3, renumber_bits(3)>(x);
  }
};

/// Stable sort of indices by key: LSD radix sort on 16-bit digits (skipping digits that are the
/// same for all keys), or a comparison sort for small inputs.
std::vector<Id> order_by_key(const std::vector<std::uint64_t>& keys) {
  const std::size_t n = keys.size();
  std::vector<Id> order = huge_vector<Id>(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<Id>(i);
  if (n < 4096) {
    std::stable_sort(order.begin(), order.end(), [&keys](Id a, Id b) { return keys[a] < keys[b]; });
    return order;
  }
  struct Item {
    std::uint64_t key;
    Id index;
  };
  std::vector<Item> a = huge_vector<Item>(n), b = huge_vector<Item>(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = {keys[i], static_cast<Id>(i)};
  std::vector<std::size_t> count(1 << 16);
  for (int shift = 0; shift < 64; shift += 16) {
    std::fill(count.begin(), count.end(), 0);
    for (const Item& it : a) ++count[(it.key >> shift) & 0xffff];
    if (count[(a[0].key >> shift) & 0xffff] == n) continue;  // one digit value: nothing to do
    std::size_t sum = 0;
    for (std::size_t& c : count) {
      const std::size_t k = c;
      c = sum;
      sum += k;
    }
    for (const Item& it : a) b[count[(it.key >> shift) & 0xffff]++] = it;
    a.swap(b);
  }
  for (std::size_t i = 0; i < n; ++i) order[i] = a[i].index;
  return order;
}

template <class T>
void gather(std::vector<T>& v, const std::vector<Id>& new2old, std::size_t width) {
  if (v.size() != new2old.size() * width) return;  // absent (e.g. empty tags): nothing to move
  std::vector<T> out(v.size());
  for (std::size_t i = 0; i < new2old.size(); ++i)
    std::copy_n(v.begin() + width * new2old[i], width, out.begin() + width * i);
  v.swap(out);
}

/// Sorts the entities of one connectivity array (k vertices each) by their centroid's key.
std::vector<Id> sort_entities(std::vector<Id>& conn, int k, const Mesh& m, const Quantiser& q) {
  const std::size_t n = conn.size() / k;
  std::vector<std::uint64_t> keys(n);
  const int d = m.dim;
  for (std::size_t e = 0; e < n; ++e) {
    double c[3] = {0, 0, 0};
    for (int i = 0; i < k; ++i)
      for (int a = 0; a < d; ++a)
        c[a] += m.coords[static_cast<std::size_t>(d) * conn[k * e + i] + a];
    for (int a = 0; a < d; ++a) c[a] /= k;
    keys[e] = q.key(c);
  }
  std::vector<Id> order = order_by_key(keys);
  gather(conn, order, k);
  return order;
}

void check_dim(int dim) {
  if (dim != 2 && dim != 3)
    throw InputError("hilbert: dimension must be 2 or 3, got " + std::to_string(dim));
}

}  // namespace

std::vector<std::uint64_t> hilbert_keys(const std::vector<double>& coords, int dim) {
  check_dim(dim);
  const Quantiser q(coords, dim, hilbert_bits(dim));
  std::vector<std::uint64_t> keys(coords.size() / dim);
  for (std::size_t v = 0; v < keys.size(); ++v) keys[v] = q.key(&coords[dim * v]);
  return keys;
}

std::vector<Id> hilbert_order(const std::vector<double>& coords, int dim) {
  return order_by_key(hilbert_keys(coords, dim));
}

std::vector<Id> hilbert_order_coarse(std::span<const double> coords, int dim) {
  check_dim(dim);
  const Quantiser q(coords, dim, renumber_bits(dim));
  std::vector<std::uint64_t> keys = huge_vector<std::uint64_t>(coords.size() / dim);
  for (std::size_t v = 0; v < keys.size(); ++v) keys[v] = q.key(&coords[dim * v]);
  return order_by_key(keys);
}

void permute_vertices(Mesh& m, const std::vector<Id>& new2old) {
  const std::size_t nv = m.num_vertices();
  RIEMESH_CHECK(new2old.size() == nv);
  std::vector<Id> old2new(nv, kNoId);
  for (std::size_t i = 0; i < nv; ++i) old2new[new2old[i]] = static_cast<Id>(i);
  gather(m.coords, new2old, m.dim);
  gather(m.vert_ref, new2old, 1);
  gather(m.vert_tag, new2old, 1);
  for (Field& f : m.fields) gather(f.values, new2old, field_components(f.kind, m.dim));
  auto remap = [&old2new, nv](Id& v) {
    if (v >= 0 && static_cast<std::size_t>(v) < nv) v = old2new[v];
  };
  for (auto* conn : {&m.edges, &m.triangles, &m.tets})
    for (Id& v : *conn) remap(v);
  for (auto* pairs : {&m.normal_at_vertex, &m.tangent_at_vertex})
    for (std::size_t i = 0; i < pairs->size(); i += 2) remap((*pairs)[i]);
}

Renumbering renumber_hilbert(Mesh& m) {
  check_dim(m.dim);
  if (m.coords.size() % m.dim != 0) throw InputError("renumber_hilbert: bad coordinate array");
  const std::size_t nv = m.num_vertices();
  for (const auto* conn : {&m.edges, &m.triangles, &m.tets})
    for (Id v : *conn)
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw InputError("renumber_hilbert: vertex id " + std::to_string(v) + " out of range");
  Renumbering r;
  const Quantiser q(m.coords, m.dim, renumber_bits(m.dim));
  r.vertices = hilbert_order_coarse(m.coords, m.dim);
  permute_vertices(m, r.vertices);
  r.tets = sort_entities(m.tets, 4, m, q);
  gather(m.tet_ref, r.tets, 1);
  r.triangles = sort_entities(m.triangles, 3, m, q);
  gather(m.tri_ref, r.triangles, 1);
  gather(m.tri_tag, r.triangles, 1);
  r.edges = sort_entities(m.edges, 2, m, q);
  gather(m.edge_ref, r.edges, 1);
  gather(m.edge_tag, r.edges, 1);
  return r;
}

}  // namespace riemesh
