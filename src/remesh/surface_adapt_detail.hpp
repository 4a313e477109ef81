#pragma once
// Internal state of the surface remesher (surface_adapt.cpp drives, surface_ops.cpp operates,
// surface_cover.cpp keeps the input's check points covered).
#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/surface_adapt.hpp"
#include "remesh/surface_projection.hpp"

namespace riemesh::surface_detail {

inline std::uint64_t edge_key(Id a, Id b) {
  const auto lo = static_cast<std::uint64_t>(a < b ? a : b), hi = static_cast<std::uint64_t>(a < b ? b : a);
  return (hi << 32) | lo;
}

/// Triangles around each edge of the current mesh (built at the start of a pass
/// unless the previous one left it valid).
struct Topology {
  Adjacency adj;
  std::vector<int> edge_count;  // triangles per edge
  std::vector<Id> edge_tris;    // 2 per edge (first two triangles)
};

/// The mesh being remeshed: vertices with their size, tags and projection hints; triangles
/// (dead ones have tri[3t] == kNoId until the pass compacts them); feature edges by key.
struct State {
  std::vector<Vec3> x;
  std::vector<SymMat3> m;  // the metric the mesh must be unit in (I/h² when isotropic)
  std::vector<std::uint8_t> tag;  // kTagCorner, kTagRidge
  std::vector<Id> surf_hint, line_hint;
  std::vector<Id> tri;
  std::vector<std::int32_t> tref;
  std::unordered_map<std::uint64_t, std::int32_t> feature;  // edge key -> ref
  std::unordered_map<std::uint64_t, std::uint8_t> feature_tag;  // edge key -> kTagRidge if by angle

  /// The topology of `tri` as a pass built it, while still valid: a pass that changes no
  /// triangle (smoothing; a pass that applied nothing) leaves it to the next one.
  Topology topo;
  bool topo_valid = false;

  /// The input's check points (SurfaceProjection::check_points_by_triangle) and which current
  /// triangle answers for each: one within kCheckMargin × hausd of it (at the start, the input
  /// triangle it lies on). An operation must find a new triangle close enough for every point
  /// its old triangles answer for, and hands them over: every check point then stays within
  /// hausd of the mesh (the A -> B half of the Hausdorff distance), and an operation tests only
  /// the points of its own triangles. Per triangle a list: cover_head[t], then cover_next.
  std::vector<Vec3> check_pts;
  std::vector<Id> cover_head;  // per triangle: its first check point, kNoId if none
  std::vector<Id> cover_next;  // per check point: the next one of the same triangle

  /// Change stamps: `ops` counts the applied operations (from 1); changed[v] is the count when
  /// a triangle of v's ball last changed (a vertex of it moved, it was split, swapped or
  /// collapsed), smooth_failed[v] the count when smoothing v last failed (0: never). A vertex
  /// whose ball has not changed since is not tried again: the same ball gives the same answer.
  std::uint32_t ops = 1;
  std::vector<std::uint32_t> changed, smooth_failed;

  const SurfaceProjection* geo = nullptr;
  const SurfaceAdaptOptions* opt = nullptr;

  std::size_t num_vertices() const { return x.size(); }
  std::size_t num_triangles() const { return tri.size() / 3; }
  bool is_feature(Id a, Id b) const { return feature.count(edge_key(a, b)) != 0; }
  /// Length of ab in the metric field (mean of the lengths in the end metrics).
  double size_length(Id a, Id b) const {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    const Vec3 d = x[ub] - x[ua];
    return 0.5 * (std::sqrt(quadratic(m[ua], d)) + std::sqrt(quadratic(m[ub], d)));
  }
  Id add_vertex(const Vec3& p, const SymMat3& metric, std::uint8_t t, Id sh, Id lh) {
    x.push_back(p);
    m.push_back(metric);
    tag.push_back(t);
    surf_hint.push_back(sh);
    line_hint.push_back(lh);
    changed.push_back(ops);
    smooth_failed.push_back(0);
    return static_cast<Id>(x.size() - 1);
  }
  /// A new operation changes triangles t: stamps their vertices.
  void touch(std::span<const Id> tris) {
    ++ops;
    for (Id t : tris)
      for (int i = 0; i < 3; ++i)
        changed[static_cast<std::size_t>(tri[3 * static_cast<std::size_t>(t) + i])] = ops;
  }
  /// Drops dead triangles and unused vertices (renumbering, order kept).
  void compact();
  /// The check points and their triangles for a state whose triangles are the input's.
  void init_cover(const SurfaceProjection& projection);
};

Topology build_topology(const State& s);
/// s.topo, rebuilt first unless valid.
const Topology& topology(State& s);

/// Splits edges longer than √2 in the size field; with bad_quality > 0, instead the longest edge
/// of every triangle of quality below it.
std::size_t split_pass(State& s, double bad_quality = 0.0);
std::size_t collapse_pass(State& s);
std::size_t swap_pass(State& s);
std::size_t smooth_pass(State& s);

Vec3 tri_normal(const Vec3& a, const Vec3& b, const Vec3& c);  // unit, zero if degenerate
double quality(const Vec3& a, const Vec3& b, const Vec3& c);
/// Quality 4√3 A_M / Σ l_M² of triangle abc in the metric M (the Euclidean one for M = I/h²):
/// A_M = ½ sqrt(det G), G the Gram matrix of two edges in M.
double quality(const SymMat3& m, const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace riemesh::surface_detail
