// Planar patches re-triangulated with a tetrahedralisation's faces (planar_patches3d.hpp).
#include "generate/planar_patches3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>

#include "core/predicates.hpp"
#include "generate/filtered_predicates3d.hpp"

namespace riemesh {

namespace {

using Tri = std::array<Id, 3>;

std::uint64_t edge_key(Id a, Id b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32) | hi;
}

Tri sorted3(Tri t) {
  std::sort(t.begin(), t.end());
  return t;
}

int sign(double x) { return (x > 0) - (x < 0); }

/// One patch's attempt: the faces of tz tiling it, oriented like it, or nothing.
class PatchTiler {
 public:
  PatchTiler(std::span<const Id> triangles, const std::vector<double>& coords,
             const Tetrahedralization& tz, const TetSkeleton& skeleton)
      : tris_(triangles),
        coords_(coords),
        tz_(tz),
        skeleton_(skeleton),
        mark_(coords.size() / 3, 0) {
    // Tets at each point (CSR).
    const std::size_t np = coords.size() / 3;
    first_.assign(np + 1, 0);
    for (const Id v : tz.tets) ++first_[static_cast<std::size_t>(v) + 1];
    for (std::size_t v = 0; v < np; ++v) first_[v + 1] += first_[v];
    at_.resize(tz.tets.size());
    std::vector<std::size_t> fill(first_.begin(), first_.end() - 1);
    for (std::size_t k = 0; k < tz.tets.size(); ++k)
      at_[fill[static_cast<std::size_t>(tz.tets[k])]++] = static_cast<Id>(k / 4);
  }

  /// The patch `members` (triangle indices, with `inside(t)` telling membership): true and the
  /// new triangles in *out when tz's faces on its plane tile it.
  template <class Inside>
  bool tile(const std::vector<Id>& members, const std::vector<Id>& neighbour, Inside inside,
            std::vector<Tri>* out) {
    ++stamp_;
    const Tri seed = tri(members.front());
    // Projection: drop the axis of the largest normal component (exactly coplanar points keep
    // their orientations under it).
    double n[3];
    const double* a = p(seed[0]);
    const double* b = p(seed[1]);
    const double* c = p(seed[2]);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      n[i] = (b[j] - a[j]) * (c[k] - a[k]) - (b[k] - a[k]) * (c[j] - a[j]);
    }
    axis_ = std::fabs(n[0]) >= std::fabs(n[1]) && std::fabs(n[0]) >= std::fabs(n[2]) ? 0
            : std::fabs(n[1]) >= std::fabs(n[2])                                     ? 1
                                                                                     : 2;
    const int side = sign(orient(seed[0], seed[1], seed[2]));
    if (side == 0) return false;
    double area = 0.0;
    std::vector<std::pair<std::uint64_t, std::pair<Id, Id>>> outline;  // key, directed (a, b)
    std::vector<Id> points;
    for (const Id t : members) {
      const Tri v = tri(t);
      const double o = orient(v[0], v[1], v[2]);
      if (sign(o) != side) return false;
      area += std::fabs(o);
      for (int j = 0; j < 3; ++j) {
        if (mark_[static_cast<std::size_t>(v[j])] != stamp_) {
          mark_[static_cast<std::size_t>(v[j])] = stamp_;
          points.push_back(v[j]);
        }
        // Edge j joins v[j] and v[j + 1]; neighbour[3 t + j] is the triangle across it.
        if (!inside(neighbour[3 * static_cast<std::size_t>(t) + j])) {
          const Id x = v[j], y = v[(j + 1) % 3];
          if (!skeleton_.has_edge(x, y)) return false;
          outline.push_back({edge_key(x, y), {x, y}});
        }
      }
    }
    std::sort(outline.begin(), outline.end());
    // The faces of tz with three patch points (on the plane), each once.
    std::vector<Tri> faces;
    for (const Id v : points)
      for (std::size_t k = first_[static_cast<std::size_t>(v)];
           k < first_[static_cast<std::size_t>(v) + 1]; ++k) {
        const Id* w = &tz_.tets[4 * static_cast<std::size_t>(at_[k])];
        for (int i = 0; i < 4; ++i) {
          const Tri f = {w[(i + 1) % 4], w[(i + 2) % 4], w[(i + 3) % 4]};
          if (marked(f[0]) && marked(f[1]) && marked(f[2])) faces.push_back(sorted3(f));
        }
      }
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    std::vector<std::pair<std::uint64_t, Id>> by_edge;
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (int j = 0; j < 3; ++j)
        by_edge.push_back({edge_key(faces[f][j], faces[f][(j + 1) % 3]), static_cast<Id>(f)});
    std::sort(by_edge.begin(), by_edge.end());
    const auto faces_on = [&](std::uint64_t key) {
      return std::equal_range(by_edge.begin(), by_edge.end(), std::pair<std::uint64_t, Id>{key, -1},
                              [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    const auto third = [&](Id f, std::uint64_t key) {
      for (const Id v : faces[static_cast<std::size_t>(f)])
        if (v != static_cast<Id>(key >> 32) && v != static_cast<Id>(key & 0xffffffffu)) return v;
      return kNoId;
    };
    // Seeds: on each outline edge (a, b), the face on the patch's side; then across the inner
    // edges, exactly one face each (none: a tet edge pierces the patch; more: not a tiling).
    std::vector<std::uint8_t> in(faces.size(), 0);
    std::vector<Id> stack;
    for (const auto& [key, ab] : outline) {
      int found = 0;
      for (auto [it, end] = faces_on(key); it != end; ++it)
        if (sign(orient(ab.first, ab.second, third(it->second, key))) == side) {
          ++found;
          if (!in[static_cast<std::size_t>(it->second)]) {
            in[static_cast<std::size_t>(it->second)] = 1;
            stack.push_back(it->second);
          }
        }
      if (found != 1) return false;
    }
    const auto is_outline = [&](std::uint64_t key) {
      return std::binary_search(outline.begin(), outline.end(),
                                std::pair<std::uint64_t, std::pair<Id, Id>>{key, {-1, -1}},
                                [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    while (!stack.empty()) {
      const Id f = stack.back();
      stack.pop_back();
      const Tri& v = faces[static_cast<std::size_t>(f)];
      for (int j = 0; j < 3; ++j) {
        const std::uint64_t key = edge_key(v[j], v[(j + 1) % 3]);
        if (is_outline(key)) continue;
        Id other = kNoId;
        int count = 0;
        for (auto [it, end] = faces_on(key); it != end; ++it)
          if (it->second != f) other = it->second, ++count;
        if (count != 1) return false;
        if (!in[static_cast<std::size_t>(other)]) {
          in[static_cast<std::size_t>(other)] = 1;
          stack.push_back(other);
        }
      }
    }
    // Oriented like the patch, covering its area.
    out->clear();
    double covered = 0.0;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!in[f]) continue;
      Tri t = faces[f];
      const double o = orient(t[0], t[1], t[2]);
      if (sign(o) == 0) return false;
      if (sign(o) != side) std::swap(t[1], t[2]);
      covered += std::fabs(o);
      out->push_back(t);
    }
    return std::fabs(covered - area) <= 1e-9 * area;
  }

 private:
  const double* p(Id v) const { return coords_.data() + 3 * static_cast<std::size_t>(v); }
  Tri tri(Id t) const {
    const std::size_t k = 3 * static_cast<std::size_t>(t);
    return {tris_[k], tris_[k + 1], tris_[k + 2]};
  }
  bool marked(Id v) const { return v >= 0 && mark_[static_cast<std::size_t>(v)] == stamp_; }
  /// Exact orientation of (a, b, c) in the projection.
  double orient(Id a, Id b, Id c) const {
    const int i = (axis_ + 1) % 3, j = (axis_ + 2) % 3;
    const double pa[2] = {p(a)[i], p(a)[j]}, pb[2] = {p(b)[i], p(b)[j]}, pc[2] = {p(c)[i], p(c)[j]};
    return orient2d(pa, pb, pc);
  }

  std::span<const Id> tris_;
  const std::vector<double>& coords_;
  const Tetrahedralization& tz_;
  const TetSkeleton& skeleton_;
  std::vector<std::uint32_t> mark_;
  std::uint32_t stamp_ = 0;
  std::vector<std::size_t> first_;
  std::vector<Id> at_;
  int axis_ = 2;
};

}  // namespace

TetSkeleton::TetSkeleton(const Tetrahedralization& tz) {
  edges.reserve(6 * tz.num_tets());
  faces.reserve(4 * tz.num_tets());
  for (std::size_t t = 0; t < tz.num_tets(); ++t) {
    const Id* v = &tz.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) edges.push_back(edge_key(v[i], v[j]));
      faces.push_back(sorted3({v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4]}));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
}

bool TetSkeleton::has_edge(Id a, Id b) const {
  return std::binary_search(edges.begin(), edges.end(), edge_key(a, b));
}

bool TetSkeleton::has_face(const std::array<Id, 3>& t) const {
  return std::binary_search(faces.begin(), faces.end(), sorted3(t));
}

PatchTriangulation retriangulate_planar_patches(std::span<const Id> triangles,
                                                std::span<const int> refs,
                                                std::span<const int> tags,
                                                const std::vector<double>& coords,
                                                const Tetrahedralization& tz,
                                                const TetSkeleton& skeleton, bool retriangulate) {
  const std::size_t nt = triangles.size() / 3;
  PatchTriangulation out;
  // Input edges with their triangles, and the counts of what tz misses.
  std::vector<std::pair<std::uint64_t, Id>> edges;
  edges.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const Tri v = {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
    for (int j = 0; j < 3; ++j)
      edges.push_back({edge_key(v[j], v[(j + 1) % 3]), static_cast<Id>(t)});
    if (!skeleton.has_face(v)) ++out.missing_faces;
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t i = 0; i < edges.size(); ++i)
    if ((i == 0 || edges[i].first != edges[i - 1].first) &&
        !skeleton.has_edge(static_cast<Id>(edges[i].first >> 32),
                           static_cast<Id>(edges[i].first & 0xffffffffu)))
      ++out.missing_edges;
  const auto copy_input = [&] {
    out.triangles.assign(triangles.begin(), triangles.end());
    out.refs.assign(refs.begin(), refs.end());
    out.tags.assign(tags.begin(), tags.end());
  };
  if (out.missing_faces == 0 || !retriangulate) {
    copy_input();
    return out;
  }
  // The triangle across each edge on two triangles; none across an edge where regions meet
  // (three or more triangles: the patch's outline, never re-triangulated).
  std::vector<Id> neighbour(3 * nt, kNoId);
  for (std::size_t t = 0; t < nt; ++t)
    for (int j = 0; j < 3; ++j) {
      const std::uint64_t key = edge_key(triangles[3 * t + j], triangles[3 * t + (j + 1) % 3]);
      auto it = std::lower_bound(edges.begin(), edges.end(), std::pair<std::uint64_t, Id>{key, -1});
      if (it + 1 == edges.end() || (it + 1)->first != key ||
          (it + 2 != edges.end() && (it + 2)->first == key))
        continue;
      neighbour[3 * t + j] = it->second != static_cast<Id>(t) ? it->second : (it + 1)->second;
    }
  const auto point = [&](Id v) { return coords.data() + 3 * static_cast<std::size_t>(v); };
  // Patches by flooding across edges: same ref and tag, every vertex on the seed's plane.
  std::vector<Id> patch(nt, kNoId);
  std::vector<std::uint8_t> keep(nt, 1);
  std::vector<Tri> added_tris, tiles;
  std::vector<int> added_refs, added_tags;
  PatchTiler tiler(triangles, coords, tz, skeleton);
  Id patches = 0;
  for (std::size_t s = 0; s < nt; ++s) {
    if (patch[s] != kNoId) continue;
    const Id id = patches++;
    const Id* seed = &triangles[3 * s];
    std::vector<Id> members = {static_cast<Id>(s)};
    patch[s] = id;
    for (std::size_t k = 0; k < members.size(); ++k)
      for (int j = 0; j < 3; ++j) {
        const Id w = neighbour[3 * static_cast<std::size_t>(members[k]) + j];
        const auto uw = static_cast<std::size_t>(w);
        if (w == kNoId || patch[uw] != kNoId || refs[uw] != refs[s] || tags[uw] != tags[s])
          continue;
        bool coplanar = true;
        for (int i = 0; i < 3 && coplanar; ++i)
          coplanar = detail::orient3d_sign(point(seed[0]), point(seed[1]), point(seed[2]),
                                           point(triangles[3 * uw + i])) == 0;
        if (!coplanar) continue;
        patch[uw] = id;
        members.push_back(w);
      }
    if (members.size() < 2) continue;
    const bool missing = std::any_of(members.begin(), members.end(), [&](Id t) {
      const std::size_t k = 3 * static_cast<std::size_t>(t);
      return !skeleton.has_face({triangles[k], triangles[k + 1], triangles[k + 2]});
    });
    if (!missing) continue;
    const auto inside = [&](Id t) {
      return t != kNoId && patch[static_cast<std::size_t>(t)] == id;
    };
    if (!tiler.tile(members, neighbour, inside, &tiles)) continue;
    ++out.patches;
    out.replaced += members.size();
    for (const Id t : members) keep[static_cast<std::size_t>(t)] = 0;
    for (const Tri& t : tiles) {
      added_tris.push_back(t);
      added_refs.push_back(refs[s]);
      added_tags.push_back(tags[s]);
    }
  }
  if (out.patches == 0) {
    copy_input();
    return out;
  }
  for (std::size_t t = 0; t < nt; ++t) {
    if (!keep[t]) continue;
    out.triangles.insert(out.triangles.end(),
                         triangles.begin() + static_cast<std::ptrdiff_t>(3 * t),
                         triangles.begin() + static_cast<std::ptrdiff_t>(3 * t + 3));
    out.refs.push_back(refs[t]);
    out.tags.push_back(tags[t]);
  }
  for (std::size_t k = 0; k < added_tris.size(); ++k) {
    out.triangles.insert(out.triangles.end(), added_tris[k].begin(), added_tris[k].end());
    out.refs.push_back(added_refs[k]);
    out.tags.push_back(added_tags[k]);
  }
  return out;
}

}  // namespace riemesh
