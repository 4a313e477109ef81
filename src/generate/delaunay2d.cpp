#include "generate/delaunay2d.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "generate/filtered_predicates2d.hpp"
#include "generate/huge_page_allocator.hpp"
#include "mesh/hilbert.hpp"

namespace riemesh {

namespace {

/// splitmix64: a fixed, well-mixed hash of the point index (BRIO's coin flips, deterministic).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// Triangle and slot of a half-edge 3·t + j (unsigned: division by a constant without sign fix).
inline Id tri_of(Id h) { return static_cast<Id>(static_cast<std::uint32_t>(h) / 3u); }
inline int slot_of(Id h) { return static_cast<int>(static_cast<std::uint32_t>(h) % 3u); }

/// The edge of a cavity's boundary: vertices a → b (counter-clockwise around the cavity) and the
/// half-edge of the triangle outside (kNoId on the super-triangle's sides).
struct BoundaryEdge {
  Id a, b, outside;
};

// Branch-free: 2-bit tables {1, 2, 0} and {2, 0, 1} (a slot's value is unpredictable).
inline int next_slot(int e) { return (0x09 >> (2 * e)) & 3; }
inline int prev_slot(int e) { return (0x12 >> (2 * e)) & 3; }

/// Bowyer–Watson insertion into a Triangulation2d, with scratch arrays owned by the builder.
class Builder {
 public:
  /// `extent`: the largest difference between two input points' coordinates (x or y).
  Builder(Triangulation2d& t, double extent)
      : t_(t), static_bound_(detail::incircle_static_bound(extent)) {
    // Each insertion adds two triangles to the super-triangle: room for the most there can be is
    // reserved once (in huge pages: a few hundred page faults instead of tens of thousands), and
    // the arrays grow into it by chunks small enough to stay in cache until the triangles are
    // written (no zero-filling pass over the whole arrays, no reallocation).
    const std::size_t most = 2 * (t.xy.size() / 2) + 1;
    reserve_huge(t_.tri, 3 * most);
    reserve_huge(t_.nbr, 3 * most);
    grow_scratch();
  }

  /// The super-triangle as the first triangle.
  void start(Id s0, Id s1, Id s2) {
    const Id first[3] = {s0, s1, s2};
    num_triangles_ = 1;
    grow();
    std::copy(first, first + 3, t_.tri.begin());
    std::fill(t_.nbr.begin(), t_.nbr.begin() + 3, kNoId);
    last_ = 0;
  }

  /// Trims the arrays to the triangles made.
  void finish() {
    t_.tri.resize(3 * num_triangles_);
    t_.nbr.resize(3 * num_triangles_);
  }

  /// Inserts vertex v; returns false if it coincides with an existing vertex (then *same is it).
  bool insert(Id v, Id* same) {
    const double* p = point(v);
    // The cavity is connected, so any triangle in conflict can seed it: the last one created often
    // is (points come in curve order), and then no walk is needed. A point equal to a vertex is in
    // conflict with no triangle (empty circles), so it always takes the walk and is caught below.
    turn_towards(p);
    if (in_conflict(last_, p)) {
      find_cavity(last_, p);
      fill_cavity(v);
      return true;
    }
    const Id t = locate(p);
    for (int i = 0; i < 3; ++i) {
      const Id w = t_.tri[3 * t + i];
      const double* q = point(w);
      if (q[0] == p[0] && q[1] == p[1]) {
        *same = w;
        return false;
      }
    }
    find_cavity(t, p);
    fill_cavity(v);
    return true;
  }

 private:
  const double* point(Id v) const { return &t_.xy[2 * static_cast<std::size_t>(v)]; }

  /// Visibility walk from the last triangle created: cross any edge that has p strictly on its
  /// outer side (never straight back). Terminates in a Delaunay triangulation (Edelsbrunner).
  Id locate(const double* p) {
    Id t = last_;
    int from = -1;  // edge slot we entered t through
    for (;;) {
      int cross = -1;
      for (int k = 0; k < 3; ++k) {
        const int e = (k + static_cast<int>(steps_++ % 3)) % 3;  // rotate the first edge tried
        if (e == from) continue;
        const Id a = t_.tri[3 * t + (e + 1) % 3], b = t_.tri[3 * t + (e + 2) % 3];
        if (detail::orient2d_sign(point(a), point(b), p) < 0) {
          cross = e;
          break;
        }
      }
      if (cross < 0) return t;
      const Id h = t_.nbr[3 * t + cross];
      RIEMESH_CHECK(h != kNoId);  // the super-triangle contains every point
      t = tri_of(h);
      from = slot_of(h);
    }
  }

  /// Turns last_ around the last vertex inserted (vertex 0 of the fan triangles) to the fan
  /// triangle whose wedge holds the direction of p: the next point is usually close, so that
  /// triangle is often in conflict with it or contains it. At most a few steps each way.
  /// A turn tells on which side of the wedge's new edge p is (its vertex 1 or 2 is the old one's 2
  /// or 1), so after the first turn one orientation test per step is enough.
  void turn_towards(const double* p) {
    const Id* tri = t_.tri.data();
    const Id* nbr = t_.nbr.data();
    Id t = last_;
    const double* c = point(tri[3 * t]);
    int turned = 0;  // +1 after a counter-clockwise turn, -1 after a clockwise one
    for (int k = 0; k < 4; ++k) {
      const Id* w = tri + 3 * t;
      Id h;
      if (turned >= 0 && detail::orient2d_sign(c, point(w[2]), p) >= 0) {
        h = nbr[3 * t + 1];  // p beyond edge (v, b): turn ccw
        turned = 1;
      } else if (turned <= 0 && detail::orient2d_sign(c, point(w[1]), p) < 0) {
        h = nbr[3 * t + 2];  // p before edge (v, a): turn cw
        turned = -1;
      } else {
        break;
      }
      if (h == kNoId) break;
      t = tri_of(h);
    }
    last_ = t;
  }

  bool in_conflict(Id t, const double* p) const {
    const Id* v = &t_.tri[3 * t];
    return detail::incircle_sign(point(v[0]), point(v[1]), point(v[2]), p) > 0;
  }

  /// The triangles whose circumcircle contains p strictly, connected to t (which is one of them),
  /// and their boundary edges in counter-clockwise order. Depth-first, each triangle's edges in
  /// counter-clockwise order from the one it was entered by, so that a neighbour's boundary
  /// replaces the shared edge in sequence: a stack of the half-edges still to look across, a
  /// cavity triangle's two other edges pushed on top of its parent's. No marks are needed: the
  /// cavity of a point in a Delaunay triangulation is a disk with all its vertices on its boundary
  /// (they all join the point afterwards), so its triangles' adjacency is a tree and each is reached
  /// once. (A triangle outside may be tested twice, from two cavity triangles; the answer is the
  /// same.) The scratch arrays are used through local end pointers, their room checked once per
  /// cavity triangle: with c cavity triangles, at most 2c + 1 boundary edges and c + 2 pending
  /// half-edges (above the stack's bottom mark).
  void find_cavity(Id t, const double* p) {
    const Id* tri = t_.tri.data();
    const Id* nbr = t_.nbr.data();
    const double* xy = t_.xy.data();
    const auto num_points = static_cast<std::uint32_t>(t_.num_points);
    // End pointers (few registers for the loop); the stack's bottom holds kNoId, which ends it.
    Id* cavity = cavity_.data();
    Id* room = cavity + scratch_;
    BoundaryEdge* boundary = boundary_.data();
    Id* top = stack_.data();
    *cavity++ = t;
    *top = kNoId;
    *++top = 3 * t + 2;
    *++top = 3 * t + 1;
    *++top = 3 * t;
    for (;;) {
      const Id h = *top--;
      if (h < 0) break;
      const Id o = nbr[h];
      if (o == kNoId) {  // a side of the super-triangle: the edge's vertices from this side
        const int e = slot_of(h);
        const Id* w = tri + (h - e);
        *boundary++ = {w[next_slot(e)], w[prev_slot(e)], o};
        continue;
      }
      const Id n3 = o - slot_of(o);  // 3·n for the neighbour n, entered by its slot j
      const int j = o - n3;
      const Id* v = tri + n3;
      const auto v0 = static_cast<std::uint32_t>(v[0]), v1 = static_cast<std::uint32_t>(v[1]),
                 v2 = static_cast<std::uint32_t>(v[2]);
      const bool in_box = std::max(v0, std::max(v1, v2)) < num_points;
      if (detail::incircle_sign_in_box(xy + 2 * std::size_t{v0}, xy + 2 * std::size_t{v1},
                                       xy + 2 * std::size_t{v2}, p, in_box, static_bound_) > 0) {
        if (cavity == room) [[unlikely]] {
          const auto nc = static_cast<std::size_t>(cavity - cavity_.data());
          const auto nb = static_cast<std::size_t>(boundary - boundary_.data());
          const auto ns = static_cast<std::size_t>(top - stack_.data());
          // Never fails with exact predicates (a tree); bounds the search if the theory is broken.
          RIEMESH_CHECK(nc < num_triangles_);
          grow_scratch();
          cavity = cavity_.data() + nc, room = cavity_.data() + scratch_;
          boundary = boundary_.data() + nb, top = stack_.data() + ns;
        }
        *cavity++ = tri_of(o);
        *++top = n3 + prev_slot(j);
        *++top = n3 + next_slot(j);
      } else {
        // The shared edge, a → b on this side, is b → a on the neighbour's (opposite its j).
        *boundary++ = {v[prev_slot(j)], v[next_slot(j)], o};
      }
    }
    num_cavity_ = static_cast<std::size_t>(cavity - cavity_.data());
    num_boundary_ = static_cast<std::size_t>(boundary - boundary_.data());
  }

  /// Room for scratch_ cavity triangles (twice as much as before).
  void grow_scratch() {
    scratch_ = std::max<std::size_t>(64, 2 * scratch_);
    cavity_.resize(scratch_ + 3);
    boundary_.resize(2 * scratch_ + 1);
    stack_.resize(scratch_ + 3);
  }

  /// Replaces the cavity by the fan (v, a, b) over its boundary edges a → b, reusing the cavity's
  /// triangle ids first. Consecutive boundary edges make consecutive fan triangles: across (b, v)
  /// from the k-th is the (k + 1)-th's edge (v, a), opposite its vertex b.
  void fill_cavity(Id v) {
    const std::size_t nb = num_boundary_, nc = num_cavity_;
    RIEMESH_CHECK(nb == nc + 2);  // a disk with every vertex on its boundary
    Id* ids = cavity_.data();  // room for nc + 3
    ids[nc] = static_cast<Id>(num_triangles_);
    ids[nc + 1] = static_cast<Id>(num_triangles_ + 1);
    ids[nb] = ids[0];  // the fan closes
    num_triangles_ += 2;
    if (3 * num_triangles_ > t_.tri.size()) grow();
    Id* tri = t_.tri.data();
    Id* nbr = t_.nbr.data();
    const BoundaryEdge* boundary = boundary_.data();
    Id prev = ids[nb - 1];
    for (std::size_t k = 0; k < nb; ++k) {
      const Id t = ids[k], next = ids[k + 1];
      const BoundaryEdge& be = boundary[k];
      Id* tv = tri + 3 * t;
      tv[0] = v, tv[1] = be.a, tv[2] = be.b;
      Id* tn = nbr + 3 * t;
      tn[0] = be.outside, tn[1] = 3 * next + 2, tn[2] = 3 * prev + 1;
      if (be.outside != kNoId) nbr[be.outside] = 3 * t;
      prev = t;
    }
    last_ = prev;
  }

  /// Makes room for num_triangles_ triangles (within the reserved capacity). The new chunk is left
  /// unwritten (TriangleIds: no zero fill); fill_cavity writes every triangle it makes.
  void grow() {
    constexpr std::size_t kChunk = 3 * 4096;  // 48 KB per array
    const std::size_t size =
        std::min(std::max(3 * num_triangles_, t_.tri.size() + kChunk), t_.tri.capacity());
    RIEMESH_CHECK(3 * num_triangles_ <= size);
    t_.tri.resize(size);
    t_.nbr.resize(size);
  }

  Triangulation2d& t_;
  const double static_bound_;  // of incircle_sign_in_box, for triangles of input points
  // Scratch of the cavity search (sized by grow_scratch): cavity triangles, then the fan's new ids
  // and its first again.
  std::vector<Id> cavity_, stack_;
  std::vector<BoundaryEdge> boundary_;
  std::size_t scratch_ = 0, num_cavity_ = 0, num_boundary_ = 0;
  Id last_ = 0;
  std::size_t num_triangles_ = 0;
  std::uint64_t steps_ = 0;
};

/// Appends the three vertices of a triangle that strictly contains the bounding box of the points
/// with a wide margin (so that it hardly changes the triangulation of the points near the hull).
/// Returns the larger side of the bounding box.
double add_super_triangle(Triangulation2d& t) {
  double lo[2] = {0, 0}, hi[2] = {0, 0};
  if (t.num_points > 0) {
    const double* xy = t.xy.data();
    lo[0] = hi[0] = xy[0], lo[1] = hi[1] = xy[1];
    for (std::size_t v = 1; v < t.num_points; ++v)
      for (int c = 0; c < 2; ++c) {
        lo[c] = std::min(lo[c], xy[2 * v + c]);
        hi[c] = std::max(hi[c], xy[2 * v + c]);
      }
  }
  const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
  double size = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(size > 0)) size = std::max(1.0, std::max(std::fabs(cx), std::fabs(cy)));
  // Box ⊂ [c − size/2, c + size/2]²; the triangle's sides pass at least 12 sizes away from it.
  const double s = 20.0 * size;
  t.xy.insert(t.xy.end(), {cx - s, cy - 0.5 * s, cx + s, cy - 0.5 * s, cx, cy + s});
  for (std::size_t i = t.xy.size() - 6; i < t.xy.size(); ++i)
    if (!std::isfinite(t.xy[i])) {
      char msg[160];
      std::snprintf(msg, sizeof msg,
                    "delaunay2d: the points span [%g, %g] x [%g, %g], too large for the enclosing "
                    "triangle (coordinates up to about 1e306)",
                    lo[0], hi[0], lo[1], hi[1]);
      throw InputError(msg);
    }
  return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

}  // namespace

std::vector<Id> brio_order(std::span<const double> xy) {
  return brio_rounds(hilbert_order(std::vector<double>(xy.begin(), xy.end()), 2));
}

std::vector<Id> brio_rounds(const std::vector<Id>& along) {
  const std::size_t n = along.size();
  // Round of a point: the last round holds about half the points, the one before a quarter, ...
  // down to rounds of ~1000 points (smaller first rounds would only add cache misses).
  int rounds = 1;
  while ((std::size_t{1000} << rounds) < n && rounds < 30) ++rounds;
  std::vector<std::uint8_t> round(n);
  std::vector<std::size_t> count(rounds + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int z = std::countr_zero(mix(i) | (std::uint64_t{1} << 40));
    round[i] = static_cast<std::uint8_t>(rounds - 1 - std::min(z, rounds - 1));
    ++count[round[i] + 1];
  }
  for (int r = 0; r < rounds; ++r) count[r + 1] += count[r];
  std::vector<Id> order(n);
  for (const Id v : along) order[count[round[v]]++] = v;  // stable: the sequence's order
  return order;
}

std::vector<Id> coarse_first(const std::vector<Id>& along) {
  const std::size_t n = along.size();
  int top = 0;  // J: 8^J · 64 <= n
  while (top < 20 && (std::size_t{64} << (3 * (top + 1))) <= n) ++top;
  // Round of position k: J − (the largest j <= J with 8^j dividing k), 0 first.
  const auto round = [top](std::size_t k) {
    return k == 0 ? 0 : top - std::min(top, std::countr_zero(k) / 3);
  };
  std::vector<std::size_t> start(static_cast<std::size_t>(top) + 2, 0);
  for (std::size_t k = 0; k < n; ++k) ++start[static_cast<std::size_t>(round(k)) + 1];
  for (int r = 0; r <= top; ++r) start[r + 1] += start[r];
  std::vector<Id> out(n);
  for (std::size_t k = 0; k < n; ++k) out[start[static_cast<std::size_t>(round(k))]++] = along[k];
  return out;
}

namespace {

/// Room for n points and the super-triangle's 3 vertices, in huge pages.
std::vector<double> points_with_room(std::size_t n) {
  std::vector<double> xy;
  reserve_huge(xy, 2 * n + 6);
  return xy;
}

/// The points inserted in the order of `sequence` (empty: of their ids). `xy` (from
/// points_with_room) becomes the triangulation's.
Triangulation2d insert_points(std::vector<double>&& xy, std::span<const Id> sequence) {
  Triangulation2d t;
  t.num_points = xy.size() / 2;
  t.xy = std::move(xy);
  const double extent = add_super_triangle(t);
  const Id n = static_cast<Id>(t.num_points);
  reserve_huge(t.representative, t.num_points);
  t.representative.resize(t.num_points);
  Builder builder(t, extent);
  builder.start(n, n + 1, n + 2);
  Id* representative = t.representative.data();
  const std::size_t count = sequence.empty() ? t.num_points : sequence.size();
  for (std::size_t k = 0; k < count; ++k) {
    const Id v = sequence.empty() ? static_cast<Id>(k) : sequence[k];
    representative[v] = v;
    builder.insert(v, &representative[v]);
  }
  builder.finish();
  return t;
}

}  // namespace

Triangulation2d delaunay2d(std::span<const double> xy, InsertionOrder order) {
  const std::size_t n = xy.size() / 2;
  for (std::size_t i = 0; i < 2 * n; ++i)
    if (!std::isfinite(xy[i])) {
      std::string msg = "delaunay2d: point ";
      msg += std::to_string(i / 2);
      msg += " has a non-finite coordinate";
      throw InputError(msg);
    }
  if (order == InsertionOrder::kAsGiven || order == InsertionOrder::kRounds ||
      order == InsertionOrder::kCoarseFirst) {
    // Orders that keep the given one inside each round: the coordinates are read in sequence
    // as they are (a sparse first round reads few).
    std::vector<Id> sequence;
    if (order != InsertionOrder::kAsGiven) {
      std::vector<Id> given(n);
      std::iota(given.begin(), given.end(), Id{0});
      sequence = order == InsertionOrder::kRounds ? brio_rounds(given) : coarse_first(given);
    }
    std::vector<double> copy = points_with_room(n);
    copy.assign(xy.begin(), xy.begin() + 2 * n);
    return insert_points(std::move(copy), sequence);
  }
  // sequence[k]: the point inserted k-th
  const std::vector<Id> sequence = order == InsertionOrder::kBrio
                                       ? brio_order(xy)
                                       : coarse_first(hilbert_order_coarse(xy.first(2 * n), 2));
  // The points renumbered in insertion order, triangulated, and the ids put back: the same
  // triangles as inserting by the input ids (nothing in the kernel depends on an id's value but
  // whether it is a super-triangle vertex), with the coordinates read in sequence (1.15 M
  // lattice points along the Hilbert curve: 0.64 s -> 0.3 s).
  std::vector<double> sorted = points_with_room(n);
  sorted.resize(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    sorted[2 * k] = xy[2 * static_cast<std::size_t>(sequence[k])];
    sorted[2 * k + 1] = xy[2 * static_cast<std::size_t>(sequence[k]) + 1];
  }
  Triangulation2d t = insert_points(std::move(sorted), {});
  std::copy_n(xy.begin(), 2 * n, t.xy.begin());
  const auto original = [&](Id v) {
    return static_cast<std::size_t>(v) < n ? sequence[static_cast<std::size_t>(v)] : v;
  };
  for (Id& v : t.tri) v = original(v);
  std::vector<Id> representative = huge_vector<Id>(n);
  for (std::size_t k = 0; k < n; ++k)
    representative[static_cast<std::size_t>(sequence[k])] = original(t.representative[k]);
  std::copy(representative.begin(), representative.end(), t.representative.begin());
  return t;
}

std::vector<Id> delaunay_triangles(const Triangulation2d& t) {
  std::vector<Id> out;
  for (std::size_t k = 0; k < t.num_triangles(); ++k) {
    const Id* v = &t.tri[3 * k];
    if (!t.is_super(v[0]) && !t.is_super(v[1]) && !t.is_super(v[2]))
      out.insert(out.end(), v, v + 3);
  }
  return out;
}

}  // namespace riemesh
