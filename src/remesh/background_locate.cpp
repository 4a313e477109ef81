// Background mesh: point location (visibility walk, then grid containment scan, then the exact
// closest boundary face by rings of grid cells). See background.hpp for the strategy.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "remesh/background.hpp"
#include "remesh/simplex_geometry.hpp"

namespace riemesh {
namespace {

/// Calls f(cell) for every cell of grid n at Chebyshev distance exactly r from c0 (clipped to
/// the grid). Axes are taken from the last down; once an outer axis sits on the shell, inner
/// axes run over their whole range, otherwise axis 0 only takes its two extremes, so a ring
/// costs O(r^(D-1)).
template <int D, class F>
void for_shell(const int c0[D], int r, const int n[D], int axis, bool on_shell, int q[D], F& f) {
  const int lo = c0[axis] - r, hi = c0[axis] + r;
  if (axis == 0 && !on_shell) {
    for (int v : {lo, hi}) {
      if (v < 0 || v >= n[0] || (v == hi && hi == lo)) continue;
      q[0] = v;
      f(q);
    }
    return;
  }
  for (int v = std::max(lo, 0); v <= std::min(hi, n[axis] - 1); ++v) {
    q[axis] = v;
    const bool shell = on_shell || v == lo || v == hi;
    if (axis == 0) {
      f(q);
    } else {
      for_shell<D>(c0, r, n, axis - 1, shell, q, f);
    }
  }
}

}  // namespace

template <int D>
void BackgroundMesh<D>::cell_of(const Vec<D>& p, int c[D]) const {
  for (int a = 0; a < D; ++a) {
    const double x = std::clamp((p[a] - grid_.lo[a]) * grid_.inv_cell[a], 0.0,
                                static_cast<double>(grid_.n[a] - 1));
    c[a] = static_cast<int>(x);  // x >= 0: truncation is floor
  }
}

template <int D>
std::size_t BackgroundMesh<D>::cell_index(const int c[D]) const {
  std::size_t index = 0;
  for (int a = D - 1; a >= 0; --a) index = index * static_cast<std::size_t>(grid_.n[a]) + c[a];
  return index;
}

template <int D>
void BackgroundMesh<D>::barycentric(Id s, const Vec<D>& p, double b[kVerts]) const {
  const Id* v = &simplices_[kVerts * static_cast<std::size_t>(s)];
  Vec<D> x[kVerts];
  for (int i = 0; i < kVerts; ++i) x[i] = coords_[v[i]];
  simplex::sub_volumes(x, p, b);
  // The simplex's volume is computed here rather than stored (8 bytes per simplex, issue #7):
  // the same function of the same coordinates, so the same bits as at construction.
  const double inv = 1.0 / simplex::signed_volume(x);
  for (int i = 0; i < kVerts; ++i) b[i] *= inv;
}

namespace {

/// Smallest coordinate's index (the first on ties).
template <int N>
int argmin(const double b[N]) {
  int k = 0;
  for (int i = 1; i < N; ++i)
    if (b[i] < b[k]) k = i;
  return k;
}

/// Coordinates within the tolerance of the simplex, clamped to it and renormalised: each in
/// [0, 1], sum 1, and exactly 1 at a vertex (the others are exact zeros there).
template <int N>
void clamp_bary(const double b[N], double out[N]) {
  double sum = 0.0;
  for (int i = 0; i < N; ++i) sum += out[i] = b[i] > 0.0 ? b[i] : 0.0;
  for (int i = 0; i < N; ++i) out[i] /= sum;
}

}  // namespace

template <int D>
Id BackgroundMesh<D>::walk(const Vec<D>& p, Id start, double b[kVerts], long& steps) const {
  Id s = start;
  for (int k = 0;; ++k) {
    barycentric(s, p, b);
    const int i = argmin<kVerts>(b);
    if (b[i] >= -kBaryTolerance) return s;
    const Id next = neighbour(s, i);
    if (next == kNoId || k == max_walk_steps_) return kNoId;  // left the domain, or too long
    s = next;
    ++steps;
  }
}

template <int D>
Location<D> BackgroundMesh<D>::locate(const Vec<D>& p, Id hint, LocateStats* stats) const {
  for (int a = 0; a < D; ++a)
    if (!std::isfinite(p[a])) throw InputError("background mesh: locate at a non-finite point");
  if (hint != kNoId && (hint < 0 || static_cast<std::size_t>(hint) >= num_simplices()))
    throw InputError("background mesh: hint " + std::to_string(hint) + " is not a simplex id");
  Id start = hint;
  if (start != kNoId) {
    const Vec<D> d = p - coords_[simplices_[kVerts * static_cast<std::size_t>(start)]];
    if (dot(d, d) > hint_reach_ * hint_reach_) start = kNoId;
  }
  if (start == kNoId) {
    int c[D];
    cell_of(p, c);
    ensure_starts();
    start = grid_.start[cell_index(c)];
  }
  long steps = 0;
  Location<D> loc;
  double b[kVerts];
  const Id found = start == kNoId ? kNoId : walk(p, start, b, steps);
  if (found != kNoId) {
    loc.simplex = found;
    loc.inside = true;
    clamp_bary<kVerts>(b, loc.bary);
  } else {
    loc = robust_search(p);
  }
  if (stats) {
    ++stats->queries;
    stats->walk_steps += steps;
    stats->fallbacks += found == kNoId;
    stats->outside += !loc.inside;
  }
  return loc;
}

template <int D>
Location<D> BackgroundMesh<D>::robust_search(const Vec<D>& p) const {
  // Any simplex containing p overlaps p's cell (its bounding box holds p, and cell_of is
  // monotone); the first in id order wins. Else the one nearest to containing p (largest
  // smallest coordinate) is the candidate handed to closest_simplex.
  ensure_grid_lists();
  int c[D];
  cell_of(p, c);
  const std::size_t cell = cell_index(c);
  double b[kVerts];
  Id candidate = kNoId;
  double candidate_min = -std::numeric_limits<double>::infinity();
  for (std::size_t k = grid_.offsets[cell]; k < grid_.offsets[cell + 1]; ++k) {
    const Id s = grid_.ids[k];
    barycentric(s, p, b);
    const double lowest = b[argmin<kVerts>(b)];
    if (lowest >= -kBaryTolerance) {
      Location<D> loc;
      loc.simplex = s;
      loc.inside = true;
      clamp_bary<kVerts>(b, loc.bary);
      return loc;
    }
    if (lowest > candidate_min) candidate_min = lowest, candidate = s;
  }
  return closest_simplex(p, candidate);
}

namespace {

/// The point of facet x (D vertices: a segment in 2D, a triangle in 3D) closest to p, as weights
/// w of its vertices, and the squared distance.
inline double closest_on_facet(const Vec2 x[2], const Vec2& p, double w[2]) {
  const Vec2 d = x[1] - x[0];
  const double dd = dot(d, d);
  const double t = dd > 0.0 ? std::clamp(dot(p - x[0], d) / dd, 0.0, 1.0) : 0.0;
  w[0] = 1.0 - t, w[1] = t;
  const Vec2 q = w[0] * x[0] + w[1] * x[1];
  return dot(p - q, p - q);
}
inline double closest_on_facet(const Vec3 x[3], const Vec3& p, double w[3]) {
  return simplex::closest_on_triangle<3>(p, x[0], x[1], x[2], w);
}

}  // namespace

template <int D>
Location<D> BackgroundMesh<D>::closest_simplex(const Vec<D>& p, Id candidate) const {
  ensure_grid_lists();
  int c0[D];
  cell_of(p, c0);
  // Cells at ring r + 1 are at least r·h from the point of the grid box closest to p, hence from
  // p (projection onto a convex set shortens distances), h the smallest side of a split axis.
  double h = std::numeric_limits<double>::infinity();
  int r_max = 0;
  for (int a = 0; a < D; ++a) {
    if (grid_.n[a] > 1) h = std::min(h, grid_.cell[a]);
    r_max = std::max({r_max, c0[a], grid_.n[a] - 1 - c0[a]});
  }
  Location<D> best;
  double best_d2 = std::numeric_limits<double>::infinity();
  if (candidate != kNoId) {
    double w[kVerts];
    Vec<D> x[kVerts];
    for (int i = 0; i < kVerts; ++i) x[i] = coords_[simplices_[kVerts * candidate + i]];
    best_d2 = simplex::closest_in_simplex(x, p, w);
    best.simplex = candidate;
    clamp_bary<kVerts>(w, best.bary);
  }
  auto visit = [&](const int q[D]) {
    const std::size_t cell = cell_index(q);
    for (std::size_t k = grid_.face_offsets[cell]; k < grid_.face_offsets[cell + 1]; ++k) {
      const std::size_t slot = static_cast<std::size_t>(grid_.faces[k]);
      const std::size_t s = slot / kVerts, i = slot % kVerts;
      Vec<D> x[D];
      int local[D];
      for (int j = 0; j < D; ++j) {
        local[j] = static_cast<int>((i + 1 + j) % kVerts);
        x[j] = coords_[simplices_[kVerts * s + local[j]]];
      }
      double w[D];
      const double d2 = closest_on_facet(x, p, w);
      if (d2 < best_d2 || (d2 == best_d2 && static_cast<Id>(s) < best.simplex)) {
        best_d2 = d2;
        best.simplex = static_cast<Id>(s);
        double b[kVerts]{};
        for (int j = 0; j < D; ++j) b[local[j]] = w[j];
        clamp_bary<kVerts>(b, best.bary);
      }
    }
  };
  int q[D];
  for (int r = 0; r <= r_max; ++r) {
    for_shell<D>(c0, r, grid_.n, D - 1, false, q, visit);
    if (best.simplex != kNoId && best_d2 <= (r * h) * (r * h)) break;
  }
  RIEMESH_CHECK(best.simplex != kNoId);
  best.inside = best_d2 == 0.0;
  return best;
}

template Location<2> BackgroundMesh<2>::locate(const Vec<2>&, Id, LocateStats*) const;
template Location<3> BackgroundMesh<3>::locate(const Vec<3>&, Id, LocateStats*) const;
template void BackgroundMesh<2>::cell_of(const Vec<2>&, int*) const;
template void BackgroundMesh<3>::cell_of(const Vec<3>&, int*) const;
template std::size_t BackgroundMesh<2>::cell_index(const int*) const;
template std::size_t BackgroundMesh<3>::cell_index(const int*) const;

}  // namespace riemesh
