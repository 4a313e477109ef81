#include "generate/delaunay3d.hpp"

#include <algorithm>
#include <bit>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "generate/filtered_predicates3d.hpp"

namespace riemesh {

using detail::insphere_sign;
using detail::orient3d_sign;

namespace {

/// True when a, b, c are collinear: the plane through them (if any) would contain the three
/// points obtained from a by changing one coordinate, whose offsets from a are exactly along
/// the axes and hence span space.
bool collinear(const double* a, const double* b, const double* c) {
  for (int i = 0; i < 3; ++i) {
    double q[3] = {a[0], a[1], a[2]};
    q[i] = a[i] + 1.0 != a[i] ? a[i] + 1.0 : 2.0 * a[i];
    if (orient3d_sign(a, b, c, q) != 0) return false;
  }
  return true;
}

bool same_point(const double* a, const double* b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/// The position of the first point of order[from..) accepted by `ok`, or order.size().
template <class Ok>
std::size_t find_point(const std::vector<Id>& order, std::size_t from, Ok ok) {
  while (from < order.size() && !ok(order[from])) ++from;
  return from;
}

}  // namespace

Delaunay3d::Delaunay3d(const std::vector<double>* coords, std::vector<Id>& order)
    : coords_(coords) {
  // The first 4 non-coplanar points, found in order (each search keeps the earliest).
  const auto p = [&](Id v) { return coords->data() + 3 * static_cast<std::size_t>(v); };
  std::size_t k[4] = {0, 0, 0, 0};
  if (!order.empty()) {
    const Id a = order[0];
    k[1] = find_point(order, 1, [&](Id v) { return !same_point(p(a), p(v)); });
    if (k[1] < order.size()) {
      const Id b = order[k[1]];
      k[2] = find_point(order, k[1] + 1, [&](Id v) { return !collinear(p(a), p(b), p(v)); });
      if (k[2] < order.size()) {
        const Id c = order[k[2]];
        k[3] = find_point(order, k[2] + 1,
                          [&](Id v) { return orient3d_sign(p(a), p(b), p(c), p(v)) != 0; });
      }
    }
  }
  if (order.size() < 4 || k[1] >= order.size() || k[2] >= order.size() || k[3] >= order.size())
    throw InputError("Delaunay tetrahedralisation: the points are coplanar (or fewer than 4)");
  Id v[4];
  for (int i = 0; i < 4; ++i) v[i] = order[k[i]];
  for (int i = 3; i >= 1; --i) order.erase(order.begin() + static_cast<std::ptrdiff_t>(k[i]));
  order.erase(order.begin());
  order.insert(order.begin(), v, v + 4);
  if (orient3d_sign(p(v[0]), p(v[1]), p(v[2]), p(v[3])) < 0) std::swap(v[0], v[1]);
  // The kernel's own numbering: vertex i is v[i], then the points in their insertion order.
  xyz_.assign(kStride, 0.0);  // the vertex at infinity's record: only its tag is used
  for (int i = 0; i < 4; ++i) {
    original_.push_back(v[i]);
    xyz_.insert(xyz_.end(), {p(v[i])[0], p(v[i])[1], p(v[i])[2], 0.0});
    v[i] = static_cast<Id>(kStride) * i;
  }
  // The static filter's box: all points given now (later ones grow it when inserted).
  for (std::size_t i = 0; i < coords->size(); i += 3) filter_.extend(coords->data() + i);
  filter_.update();

  // One finite tet and a ghost on each face: the finite tet with the face's apex replaced by
  // the vertex at infinity and two finite vertices swapped (the ghost lies on the other side).
  tets_.assign(5, Tet{});
  std::copy(v, v + 4, tets_[0].v);
  for (int i = 0; i < 4; ++i) {
    Id* g = tets_[1 + i].v;
    std::copy(v, v + 4, g);
    g[i] = kInfinite;
    const int j = i == 0 ? 1 : 0, l = i == 3 ? 2 : 3;
    std::swap(g[j], g[l]);
  }
  // Faces are matched by vertex set (20 faces: a quadratic search is fine).
  const auto face_has = [&](std::uint32_t t, int f, Id w) {
    for (int i = 0; i < 4; ++i)
      if (i != f && tets_[t].v[i] == w) return true;
    return false;
  };
  for (std::uint32_t t = 0; t < 5; ++t)
    for (int f = 0; f < 4; ++f)
      for (std::uint32_t u = 0; u < 5; ++u)
        for (int g = 0; u != t && g < 4; ++g) {
          bool match = true;
          for (int i = 0; i < 4; ++i)
            if (i != g && !face_has(t, f, tets_[u].v[i])) match = false;
          if (match) tets_[t].n[f] = 4 * u + g;
        }
  last_ = 0;
  grow_scratch(64);
  set_avx2(true);
}

void Delaunay3d::set_avx2(bool on) {
#if defined(RIEMESH_HAVE_AVX2_KERNELS)
  avx2_ = on && __builtin_cpu_supports("avx2");
#else
  avx2_ = false;  // (no AVX2 variant on this target)
  (void)on;
#endif
}

void Delaunay3d::reserve(std::size_t num_points) {
  tets_.reserve(7 * num_points);
  xyz_.reserve(kStride * (num_points + 1));
  original_.reserve(num_points);
}

/// Visibility walk: crosses any face that separates the tetrahedron from p (faces tried in a
/// pseudo-random order, which guarantees termination), until a tetrahedron contains p (closed)
/// or a ghost is entered (p is then strictly outside the hull, beyond that ghost's face).
std::uint32_t Delaunay3d::locate(const double* p) {
  std::uint32_t t = last_;
  if (is_ghost(t)) {
    const Id* v = tets_[t].v;
    const int inf = v[0] == kInfinite ? 0 : v[1] == kInfinite ? 1 : v[2] == kInfinite ? 2 : 3;
    t = tets_[t].n[inf] >> 2;
  }
  std::uint32_t prev = ~0u;
  for (;;) {
    const Id* v = tets_[t].v;
    const double* q[4] = {xyz(v[0]), xyz(v[1]), xyz(v[2]), xyz(v[3])};
    rng_ ^= rng_ << 13;
    rng_ ^= rng_ >> 17;
    rng_ ^= rng_ << 5;
    const unsigned start = rng_ >> 30;
    std::uint32_t next = ~0u;
    for (unsigned r = 0; r < 4; ++r) {
      const unsigned i = (start + r) & 3;
      const std::uint32_t n = tets_[t].n[i] >> 2;
      if (n == prev) continue;
      const double* save = q[i];
      q[i] = p;
      const int s = orient3d_sign(filter_, q[0], q[1], q[2], q[3]);
      q[i] = save;
      if (s < 0) {
        next = n;
        break;
      }
    }
    if (next == ~0u) return t;
    ++stats_.walk_steps;
    prev = t;
    t = next;
    if (is_ghost(t)) return t;
  }
}

/// Does p conflict with ghost t? When p is strictly beyond its hull face, or on the face's plane
/// and in conflict with the finite tet behind it (i.e. strictly inside the face's circumcircle),
/// so the cavity stays star-shaped from p. (A finite tet conflicts when p is strictly inside its
/// circumsphere: tested inline in find_cavity.)
bool Delaunay3d::ghost_in_conflict(std::uint32_t t, const double* p) {
  const Id* v = tets_[t].v;
  const int inf = v[0] == kInfinite ? 0 : v[1] == kInfinite ? 1 : v[2] == kInfinite ? 2 : 3;
  const double* q[4];
  for (int i = 0; i < 4; ++i) q[i] = i == inf ? p : xyz(v[i]);
  const int s = orient3d_sign(filter_, q[0], q[1], q[2], q[3]);
  if (s != 0) return s > 0;
  const std::uint32_t n = (tets_[t].n[inf] & kCodeMask) >> 2;
  if (tets_[n].n[0] & kMark) return true;    // in the cavity
  if (tets_[n].n[1] & kMark) return false;   // tested, not in conflict
  const Id* w = tets_[n].v;
  return insphere_sign(filter_, xyz(w[0]), xyz(w[1]), xyz(w[2]), xyz(w[3]), p) > 0;
}

void Delaunay3d::grow_scratch(std::size_t cavity) {
  const std::size_t size = std::max(cavity, 2 * cavity_.size());
  cavity_.resize(size);
  stack_.resize(2 * size + 2);
  boundary_.resize(2 * size + 2);
}

/// The cavity: tets in conflict with p reachable from `start` (a depth-first search on an
/// explicit stack), and its boundary faces with their vertices' local numbers.
template <bool kAvx2>
[[gnu::always_inline]] inline void Delaunay3d::find_cavity(std::uint32_t start, const double* p) {
  if (++epoch_ == 0) {  // the tags' epochs wrapped around: forget them all
    for (std::size_t i = 3; i < xyz_.size(); i += kStride) xyz_[i] = 0.0;
    epoch_ = 1;
  }
  // The scratch arrays are written by index, their sizes their capacities. The tets processed
  // so far, P, are connected (a depth-first search tree), so they have at most 2 |P| + 2 faces
  // on their boundary, and both the boundary faces found so far and the stack (tets reached
  // through such faces) number at most that: grow_scratch keeps the stack and the boundary at
  // 2 C + 2 for a cavity array of C (one check per tet). Members in locals: the calls out of the
  // loop would make the compiler reload them.
  std::size_t ns = 0, nc = 0, nf = 0;
  std::uint32_t* stack = stack_.data();
  std::uint32_t* cavity = cavity_.data();
  BoundaryFace* boundary = boundary_.data();
  std::size_t max_cavity = cavity_.size();
  stack[ns++] = start;  // (the constructor made room)
  Tet* tets = tets_.data();
  double* base = xyz_.data() + kStride;  // xyz(v) is base + v
  const detail::StaticFilter3d filter = filter_;
  const std::uint32_t epoch = epoch_;
  std::uint32_t num_local = 0;
  // The local number of vertex w on the cavity boundary, given on first sight (in its tag).
  const auto local_id = [&](Id w) __attribute__((always_inline)) {
    double* slot = base + (w | 3);
    const auto tag = std::bit_cast<std::uint64_t>(*slot);
    if (static_cast<std::uint32_t>(tag) == epoch) return static_cast<std::uint32_t>(tag >> 32);
    *slot = std::bit_cast<double>(std::uint64_t{num_local} << 32 | epoch);
    return num_local++;
  };
  tets[start].n[0] |= kMark;
  std::size_t tests = 0;
  const detail::InsphereQuery query(p);
  const auto insphere = [&](const double* a, const double* b, const double* c, const double* d)
      __attribute__((always_inline)) {
#if defined(RIEMESH_HAVE_AVX2_KERNELS)
    if constexpr (kAvx2) return detail::insphere_sign_avx2(filter, query, a, b, c, d);
#endif
    return insphere_sign(filter, query, a, b, c, d);
  };
  while (ns != 0) {
    if (nc == max_cavity) {
      grow_scratch(nc + 1);
      stack = stack_.data();
      cavity = cavity_.data();
      boundary = boundary_.data();
      max_cavity = cavity_.size();
    }
    const std::uint32_t t = stack[--ns];
    cavity[nc++] = t;
    // Face f of a positive tet is, in order, {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}[f]
    // (vertex f on its positive side, as the new point): one case per face, constant indices.
    const auto face = [&](int i, int a, int b, int c) __attribute__((always_inline)) {
      const std::uint32_t code = tets[t].n[i] & kCodeMask;
      Tet& nt = tets[code >> 2];
      if (nt.n[0] & kMark) return;  // in the cavity
      if (!(nt.n[1] & kMark)) {     // not tested yet
        ++tests;
        const Id* w = nt.v;
        const bool conflict = (w[0] | w[1] | w[2] | w[3]) >= 0
                                  ? insphere(base + w[0], base + w[1], base + w[2], base + w[3]) > 0
                                  : ghost_in_conflict(code >> 2, p);
        if (conflict) {
          nt.n[0] |= kMark;
          stack[ns++] = code >> 2;
          // Its neighbours are tested next: their records fetched meanwhile (a cache miss per
          // tet on large meshes otherwise).
          for (int j = 0; j < 4; ++j) __builtin_prefetch(tets + ((nt.n[j] & kCodeMask) >> 2));
          return;
        }
        nt.n[1] |= kMark;
      }
      const Id* v = tets[t].v;
      boundary[nf++] =
          BoundaryFace{{v[a], v[b], v[c]}, code, {local_id(v[a]), local_id(v[b]), local_id(v[c])}};
    };
    face(0, 1, 3, 2);
    face(1, 0, 2, 3);
    face(2, 0, 3, 1);
    face(3, 0, 1, 2);
  }
  num_local_ = num_local;
  num_cavity_ = nc;
  num_boundary_ = nf;
  stats_.insphere_tests += tests;
  stats_.cavity_tets += nc;
}

// find_cavity compiled twice: for any x86-64 and for AVX2 (chosen at run time), where the same
// SSE2 operations get three-operand encodings (fewer register copies). No FMA is enabled (the
// filters' error bounds count every rounding): the results are bitwise the same.
void Delaunay3d::find_cavity_base(std::uint32_t start, const double* p) {
  find_cavity<false>(start, p);
}

#if defined(RIEMESH_HAVE_AVX2_KERNELS)
__attribute__((target("avx2"))) void Delaunay3d::find_cavity_avx2(std::uint32_t start,
                                                                  const double* p) {
  find_cavity<true>(start, p);
}
#endif

/// Replaces the cavity by the tets (a, b, c, v) on its boundary faces (a, b, c), in two sweeps.
/// The cavity boundary is a triangulated sphere: each of its edges is on two boundary faces,
/// which run through it in opposite directions, and the two new tets on them are neighbours
/// across their faces through that edge and v. The first sweep files each new tet's three inner
/// faces under their directed edges (a, b) in a table indexed by the vertices' local numbers, the
/// second reads each tet's neighbours there under the reversed edges (b, a).
void Delaunay3d::fill_cavity(Id v) {
  const std::size_t nb = num_boundary_;
  // The new tets: the cavity's, then deleted ones, then fresh ones.
  const std::size_t num_cavity = num_cavity_;
  if (nb > num_cavity) {
    if (cavity_.size() < nb) grow_scratch(nb);
    std::size_t k = num_cavity;
    for (; k < nb && !free_.empty(); ++k) {
      cavity_[k] = free_.back();
      free_.pop_back();
    }
    if (k < nb) {
      const std::size_t first = tets_.size();
      // 4 * t + face fits 31 bits (the 32nd holds the marks)
      RIEMESH_CHECK(first + (nb - k) <= (std::size_t{1} << 29));
      tets_.resize(first + (nb - k));
      for (std::size_t t = first; k < nb; ++k, ++t) cavity_[k] = static_cast<std::uint32_t>(t);
    }
  }
  Tet* tets = tets_.data();
  const std::uint32_t* ids = cavity_.data();
  const BoundaryFace* faces = boundary_.data();
  // The outer tets' links to the new ones (each clears the outer tet's mark: a tested tet is
  // always outside a boundary face); then each new tet written whole (the cavity's records are
  // no longer read). Edge (a, b) of face (a, b, c) is on the new tet's face opposite c (2),
  // (b, c) opposite a (0), (c, a) opposite b (1).
  const std::size_t nl = num_local_;
  const auto link_outer = [&](std::size_t k) __attribute__((always_inline)) {
    const std::uint32_t outer = faces[k].outer;
    Tet& o = tets[outer >> 2];
    o.n[1] &= kCodeMask;
    o.n[outer & 3] = 4 * ids[k] + 3;
  };
  if (nl <= kMostLocal) {
    if (edges_.size() < nl * nl) edges_.resize(nl * nl);
    std::uint32_t* table = edges_.data();
    for (std::size_t k = 0; k < nb; ++k) {
      link_outer(k);
      const std::uint32_t code = 4 * ids[k];
      const std::uint32_t* l = faces[k].l;
      table[l[0] * nl + l[1]] = code + 2;
      table[l[1] * nl + l[2]] = code;
      table[l[2] * nl + l[0]] = code + 1;
    }
    for (std::size_t k = 0; k < nb; ++k) {
      const BoundaryFace& f = faces[k];
      const std::uint32_t* l = f.l;
      tets[ids[k]] =
          Tet{{f.v[0], f.v[1], f.v[2], v},
              {table[l[2] * nl + l[1]], table[l[0] * nl + l[2]], table[l[1] * nl + l[0]], f.outer}};
    }
  } else {
    // A huge cavity (cospherical points): the directed edges (a << 32 | b) sorted instead.
    big_edges_.clear();
    const auto key = [](std::uint64_t a, std::uint64_t b) { return a << 32 | b; };
    for (std::size_t k = 0; k < nb; ++k) {
      link_outer(k);
      const std::uint32_t code = 4 * ids[k];
      const std::uint32_t* l = faces[k].l;
      big_edges_.emplace_back(key(l[0], l[1]), code + 2);
      big_edges_.emplace_back(key(l[1], l[2]), code);
      big_edges_.emplace_back(key(l[2], l[0]), code + 1);
    }
    std::sort(big_edges_.begin(), big_edges_.end());
    const auto find = [&](std::uint64_t a, std::uint64_t b) {
      const auto it = std::lower_bound(big_edges_.begin(), big_edges_.end(),
                                       std::pair<std::uint64_t, std::uint32_t>{key(a, b), 0});
      RIEMESH_CHECK(it != big_edges_.end() && it->first == key(a, b));
      return it->second;
    };
    for (std::size_t k = 0; k < nb; ++k) {
      const BoundaryFace& f = faces[k];
      const std::uint32_t* l = f.l;
      tets[ids[k]] = Tet{{f.v[0], f.v[1], f.v[2], v},
                         {find(l[2], l[1]), find(l[0], l[2]), find(l[1], l[0]), f.outer}};
    }
  }
  for (std::size_t k = nb; k < num_cavity; ++k) {
    tets[ids[k]].v[0] = kDeleted;  // its mark stays until it is reused (codes rewritten)
    free_.push_back(ids[k]);
  }
  last_ = ids[nb - 1];
}

bool Delaunay3d::insert(Id v, Id* same) {
  const double* p = coords_->data() + 3 * static_cast<std::size_t>(v);
  if (!filter_.contains(p)) {
    filter_.extend(p);
    filter_.update();
  }
  const std::uint32_t t = locate(p);
  if (!is_ghost(t)) {
    for (int i = 0; i < 4; ++i) {
      const Id w = tets_[t].v[i];
      if (same_point(xyz(w), p)) {
        if (same) *same = original_[vertex_index(w)];
        return false;
      }
    }
  }
  RIEMESH_CHECK(original_.size() < 0x7fffffff / kStride);  // the record's offset fits an Id
  const auto local = static_cast<Id>(kStride * original_.size());
  original_.push_back(v);
  xyz_.insert(xyz_.end(), {p[0], p[1], p[2], 0.0});
#if defined(RIEMESH_HAVE_AVX2_KERNELS)
  if (avx2_)
    find_cavity_avx2(t, p);
  else
#endif
    find_cavity_base(t, p);
  fill_cavity(local);
  return true;
}

Tetrahedralization Delaunay3d::result() const {
  Tetrahedralization out;
  const std::size_t n = tets_.size();
  // Huge pages for the large arrays (fewer page faults), then sized once and written in place:
  // no per-element capacity checks.
  const auto sized = [](std::vector<Id>& a, std::size_t size) {
    a.reserve(size);
    detail::advise_huge_pages(a.data(), size * sizeof(Id));
    a.resize(size);
  };
  std::vector<Id> old2new;
  sized(old2new, n);
  Id count = 0;
  for (std::size_t t = 0; t < n; ++t)
    old2new[t] = is_ghost(static_cast<std::uint32_t>(t)) ? kNoId : count++;
  sized(out.tets, 4 * static_cast<std::size_t>(count));
  sized(out.tet2tet, 4 * static_cast<std::size_t>(count));
  Id* v = out.tets.data();
  Id* a = out.tet2tet.data();
  for (std::size_t t = 0; t < n; ++t) {
    if (old2new[t] == kNoId) continue;
    for (int i = 0; i < 4; ++i) {
      *v++ = original_[vertex_index(tets_[t].v[i])];
      *a++ = old2new[tets_[t].n[i] >> 2];
    }
  }
  return out;
}

Tetrahedralization delaunay3d(const std::vector<double>& coords, InsertionOrder order) {
  RIEMESH_CHECK(coords.size() % 3 == 0);
  std::vector<Id> ids = insertion_order(coords, order);
  Delaunay3d kernel(&coords, ids);
  kernel.reserve(ids.size());
  std::vector<Id> duplicate_of(coords.size() / 3, kNoId);
  for (std::size_t k = 4; k < ids.size(); ++k) {
    Id same = kNoId;
    if (!kernel.insert(ids[k], &same)) duplicate_of[static_cast<std::size_t>(ids[k])] = same;
  }
  Tetrahedralization out = kernel.result();
  out.duplicate_of = std::move(duplicate_of);
  return out;
}

}  // namespace riemesh
