#pragma once
// The A -> B half of the surface remesher's Hausdorff checks (surface_adapt_detail.hpp's check
// points): every point of the input's lattice stays within kCheckMargin × hausd of the mesh, each
// answered for by one current triangle. surface_ops.cpp asks before an operation and hands the
// points over after it.
#include <cmath>
#include <span>
#include <vector>

#include "mesh/distance.hpp"
#include "remesh/surface_adapt_detail.hpp"
#include "remesh/surface_hausdorff.hpp"

namespace riemesh::surface_detail {

/// The Hausdorff checks bound the distance by this fraction of hausd at the lattice points
/// (margin for rounding and for users who sample more densely).
inline constexpr double kCheckMargin = 0.95;

/// A new triangle prepared for the A -> B check: TriangleProbe's plane and edge lines with their
/// offsets folded in (one dot product each: these tests run millions of times).
struct CoverProbe {
  // Rows: the plane's unit normal, then the three edges' inward unit normals (edge e runs from
  // corner e), by component in pairs (rows 0-1, rows 2-3), with their offsets: the four signed
  // distances in two-lane vector arithmetic (the same operations, in the same order, as
  // dot(row, p) - offset).
  using V2 = double __attribute__((vector_size(16)));
  V2 x01{}, x23{}, y01{}, y23{}, z01{}, z23{}, off01{}, off23{};
  Tri3 t{};
  bool flat = false;

  explicit CoverProbe(const Tri3& tri) : t(tri) {
    const TriangleProbe tp(tri[0], tri[1], tri[2]);
    flat = tp.flat;
    const Vec3 rows[4] = {tp.n, tp.inward[0], tp.inward[1], tp.inward[2]};
    const Vec3* at[4] = {&tri[0], &tri[0], &tri[1], &tri[2]};
    double off[4];
    for (int i = 0; i < 4; ++i) off[i] = dot(rows[i], *at[i]);
    x01 = V2{rows[0][0], rows[1][0]}, x23 = V2{rows[2][0], rows[3][0]};
    y01 = V2{rows[0][1], rows[1][1]}, y23 = V2{rows[2][1], rows[3][1]};
    z01 = V2{rows[0][2], rows[1][2]}, z23 = V2{rows[2][2], rows[3][2]};
    off01 = V2{off[0], off[1]}, off23 = V2{off[2], off[3]};
  }
  /// Without the exact distance: 1 within r, 0 farther, 2 unknown (in the band along an edge,
  /// or a degenerate triangle).
  int quick(const Vec3& p, double r) const {
    if (!flat) return 2;
    const V2 px{p[0], p[0]}, py{p[1], p[1]}, pz{p[2], p[2]};
    const V2 v01 = x01 * px + y01 * py + z01 * pz - off01;
    const V2 v23 = x23 * px + y23 * py + z23 * pz - off23;
    if (std::abs(v01[0]) > r) return 0;
    if (v01[1] < -r || v23[0] < -r || v23[1] < -r) return 0;
    return v01[1] >= 0.0 && v23[0] >= 0.0 && v23[1] >= 0.0 ? 1 : 2;
  }
  bool exact(const Vec3& p, double r2) const {
    const Vec3 d = p - closest_point_on_triangle(p, t[0], t[1], t[2]);
    return dot(d, d) <= r2;
  }
};

/// Scratch of the A -> B check: the check points that leave their triangle and the new triangle
/// (index in new_t) that takes each, in the order met; run[j] is where old triangle j's begin.
struct CoverScratch {
  std::vector<CoverProbe> probe;
  std::vector<Id> pts;
  std::vector<int> by;
  std::vector<std::size_t> run;
};

/// The A -> B check (State::check_pts): every check point that the triangles `old_ids` answer
/// for is within kCheckMargin × hausd of a triangle of new_t, new_ids[k] being the id new_t[k]
/// takes once applied. A point is tried first against its own triangle's successor (the new
/// triangle with its id: it usually still answers, and the point then stays in its list), then
/// against the one that answered last. The points that move are kept in c for hand_over. A
/// point the old triangles were close to but do not answer for has another triangle,
/// unchanged, close to it: it is not tested.
bool new_triangles_cover(const State& s, std::span<const Id> old_ids,
                         const std::vector<Tri3>& new_t, std::span<const Id> new_ids,
                         CoverScratch& c);

/// After an applied operation: the points that new_triangles_cover found leaving their triangle
/// go to the front of their new triangle's list (new_ids[k]: the id of new_t[k] in s.tri,
/// possibly just appended); the others stay where they are.
void hand_over(State& s, std::span<const Id> old_ids, std::span<const Id> new_ids,
               const CoverScratch& c);

}  // namespace riemesh::surface_detail
