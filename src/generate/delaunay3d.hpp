#pragma once
// 3D Delaunay tetrahedralisation by Bowyer–Watson insertion (BOOK.md §4): each point is located
// by a visibility walk from the last created tetrahedron, the cavity of tetrahedra whose
// circumsphere strictly contains it is found with the exact in-sphere predicate, and the cavity
// is replaced by the ball of the point. The convex hull is closed by "ghost" tetrahedra joining
// each hull face to a vertex at infinity, so no bounding box is needed and the result is the
// Delaunay tetrahedralisation of the points themselves (convex hull included).
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "generate/delaunay2d.hpp"  // InsertionOrder, shared with the 2D kernel
#include "generate/filtered_predicates3d.hpp"
#include "generate/huge_page_allocator.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// A Delaunay tetrahedralisation of a point set.
struct Tetrahedralization {
  std::vector<Id> tets;     // 4 point ids per tetrahedron, positive volume
  std::vector<Id> tet2tet;  // 4 per tet: the neighbour across the face opposite vertex i, or
                            // kNoId on the convex hull
  std::vector<Id> duplicate_of;  // per point: kNoId, or the earlier point with equal coordinates
                                 // (a duplicate is not a vertex of the tetrahedralisation)
  std::size_t num_tets() const { return tets.size() / 4; }
};

/// The Delaunay tetrahedralisation of the points (3 doubles each). Deterministic. Degenerate
/// inputs (cospherical, coplanar subsets) are handled exactly: every tetrahedron's circumsphere
/// contains no point strictly inside; among the Delaunay tetrahedralisations of a degenerate set
/// the one returned depends on the insertion order. InputError when fewer than 4 distinct points
/// or all points are coplanar.
Tetrahedralization delaunay3d(const std::vector<double>& coords,
                              InsertionOrder order = InsertionOrder::kBrio);

/// The insertion order `delaunay3d` uses: order[k] = the point inserted k-th. kBrio: rounds
/// [n/2, n), [n/4, n/2), ... of a fixed-seed shuffle, each sorted along the Hilbert curve;
/// kRounds: brio_rounds over the given order (for points already sorted along a curve);
/// kCoarseFirst: coarse_first over the given order.
std::vector<Id> insertion_order(const std::vector<double>& coords, InsertionOrder order);

/// Counters of one run (for benchmarks and tests of the kernel's work).
struct Delaunay3dStats {
  std::size_t walk_steps = 0;      // tetrahedra crossed by the location walks
  std::size_t cavity_tets = 0;     // tetrahedra deleted, summed over the insertions
  std::size_t insphere_tests = 0;  // conflict tests on tetrahedra next to a cavity
};

/// The incremental kernel behind `delaunay3d`, for callers that insert points one at a time
/// (boundary recovery inserts Steiner points). Points are referenced by id into `coords`, which
/// the caller may grow between insertions (a point's coordinates are read, and copied, when it is
/// inserted; the others are not read again).
class Delaunay3d {
 public:
  /// Starts from the first 4 non-coplanar distinct points of `order` (InputError if none) and
  /// moves them to its front; the caller then inserts order[4..] in turn.
  Delaunay3d(const std::vector<double>* coords, std::vector<Id>& order);

  /// Reserves memory for about num_points vertices (6.7 tets per point, as uniform points give).
  void reserve(std::size_t num_points);

  /// Inserts point v; false (and nothing changes) when it coincides with a vertex, whose id is
  /// then stored in *same when same is given.
  bool insert(Id v, Id* same = nullptr);

  /// Replaces the edge (b, d) by (a, c) for each quad {a, b, c, d} given (point ids, as to
  /// insert) whose four points lie on one circle — a Delaunay tie: both diagonals are Delaunay —
  /// where (b, d) is an edge with exactly four tetrahedra around it (ghosts included), two through
  /// a and two through c, and the four new ones through (a, c) are positive (ac crosses bd).
  /// Each tetrahedron keeps its circumsphere, so the tetrahedralisation stays Delaunay. The
  /// other quads are left as they are. Returns the number flipped. For boundary recovery: a
  /// surface split into cocircular quads (a grid of right triangles on a planar face) has half
  /// its diagonals missing from the Delaunay tetrahedralisation, where splitting them cascades.
  std::size_t flip_cocircular(const std::vector<std::array<Id, 4>>& quads);

  /// The finite tetrahedra, compacted (deleted and ghost ones dropped); duplicate_of is left
  /// empty (the caller knows which insertions were refused).
  Tetrahedralization result() const;

  const Delaunay3dStats& stats() const { return stats_; }

  /// The cavity search has an AVX2 variant, used when the CPU has AVX2 (the default, on) and
  /// bitwise equivalent to the other: for tests, off forces the other.
  void set_avx2(bool on);

 private:
  static constexpr Id kInfinite = -1;
  static constexpr Id kDeleted = -2;  // in v[0] of a deleted tet

  /// A face of the cavity boundary: its vertices (a, b, c), oriented so that (a, b, c, new
  /// point) is positive, the outer tet's code 4 * (outer tet) + its face index, and the
  /// vertices' local numbers in this insertion (see local_id).
  struct BoundaryFace {
    Id v[3];
    std::uint32_t outer;
    std::uint32_t l[3];
  };

  /// A tetrahedron: its vertices and, across the face opposite v[i], the neighbour's code
  /// 4 * (neighbour) + (its face index). 32 bytes: two per cache line.
  struct Tet {
    Id v[4];
    std::uint32_t n[4];
  };

  // Vertex k is stored as 4 k, the offset of its record (x, y, z, tag) in xyz_ past a first
  // record that stands for the vertex at infinity (kInfinite = -1: its tag is at offset -1).
  static constexpr std::size_t kStride = 4;
  const double* xyz(Id v) const { return xyz_.data() + kStride + v; }
  static std::size_t vertex_index(Id v) { return static_cast<std::uint32_t>(v) >> 2; }
  // The record's 4th double holds the bits of vertex v's tag (at offset v | 3, kInfinite
  // included): (its local number) << 32 | epoch when v is on the boundary of this insertion's
  // cavity (find_cavity).
  bool is_ghost(std::uint32_t t) const {
    const Id* v = tets_[t].v;
    return (v[0] | v[1] | v[2] | v[3]) < 0;
  }
  std::uint32_t locate(const double* p);
  bool flip_quad(const Id (&q)[4], std::vector<std::uint32_t>& vertex_tet);
  bool ghost_in_conflict(std::uint32_t t, const double* p);
  template <bool kAvx2>
  void find_cavity(std::uint32_t start, const double* p);
  void find_cavity_base(std::uint32_t start, const double* p);
  void find_cavity_avx2(std::uint32_t start, const double* p);
  void fill_cavity(Id v);
  void grow_scratch(std::size_t cavity);

  const std::vector<double>* coords_;
  // The tets refer to the vertices by the kernel's own numbering, in insertion order: vertex k
  // is stored as 4 k (see xyz), its id in coords_ is original_[k]. The copy keeps the points
  // inserted one after the other (near each other in BRIO or Hilbert order) near each other in
  // memory, whatever the caller's numbering: fewer cache misses in the in-sphere tests; the tag
  // in each record numbers the cavity boundary's vertices without another array.
  std::vector<double, HugePageAllocator<double>> xyz_;  // records aligned to 32 bytes (AVX2)
  std::vector<Id> original_;
  detail::StaticFilter3d filter_;  // first stage of the predicates, over the points' box
  // kInfinite for the vertex at infinity, kDeleted in v[0]. Huge pages: hundreds of MB are
  // filled in order, and 4 KB page faults were ~15 % of the time.
  std::vector<Tet, HugePageAllocator<Tet>> tets_;
  // The marks of an insertion, in the top bit of the neighbour codes (free while there are fewer
  // than 2^29 tets): n[0]'s when the tet is in the cavity, n[1]'s when it was tested and is not
  // in conflict. In the tet record rather than an array of their own: the test reads the record
  // anyway. Cleared by fill_cavity (a tested tet is always next to the cavity).
  static constexpr std::uint32_t kMark = 0x80000000u, kCodeMask = 0x7fffffffu;
  std::vector<std::uint32_t> free_;  // deleted tets for reuse
  std::uint32_t epoch_ = 0;          // insertion count, in the vertices' tags
  std::uint32_t last_ = 0;   // where the next walk starts
  bool avx2_ = false;        // the CPU has AVX2: find_cavity_avx2
  std::uint32_t rng_ = 0x9e3779b9u;  // xorshift state of the walk's face order

  // Per-insertion scratch, kept between insertions to avoid allocations: sized to their
  // capacities, num_cavity_ and num_boundary_ used.
  std::vector<std::uint32_t> stack_;
  std::vector<std::uint32_t> cavity_;
  std::vector<BoundaryFace> boundary_;
  std::size_t num_cavity_ = 0, num_boundary_ = 0;
  // Up to kMostLocal boundary vertices the edge table has num_local_^2 entries (4 MB at most);
  // larger cavities (cospherical points) sort their edges instead.
  static constexpr std::size_t kMostLocal = 1024;
  std::uint32_t num_local_ = 0;       // vertices on the cavity boundary (local numbers 0..)
  std::vector<std::uint32_t> edges_;  // [la * num_local_ + lb]: the new tets' faces by edge
  std::vector<std::pair<std::uint64_t, std::uint32_t>> big_edges_;

  Delaunay3dStats stats_;
};

}  // namespace riemesh
