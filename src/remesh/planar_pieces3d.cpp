#include "remesh/planar_pieces3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "mesh/adjacency.hpp"
#include "remesh/plane_fit.hpp"

namespace riemesh {
namespace {

struct Face {
  std::size_t slot = 0;
  std::int32_t ref = 0;
  std::array<Id, 3> v{};
  Vec3 n{};
  bool outer = false;
};

Id find_root(std::vector<Id>& parent, Id f) {
  while (parent[f] != f) f = parent[f] = parent[parent[f]];
  return f;
}

/// How much faces f and g (sharing an edge) turn: the cosine of the angle of their outward
/// normals (outer faces) or of their planes (an interface face is seen from either side).
double turn_cosine(const Face& f, const Face& g) {
  const double c = dot(f.n, g.n);
  return f.outer && g.outer ? c : std::abs(c);
}

}  // namespace

std::map<std::int32_t, std::int32_t> split_planar_pieces(TetMesh& m, double angle_deg,
                                                         double diagonal) {
  std::vector<Face> faces;
  std::int32_t highest = std::numeric_limits<std::int32_t>::min();
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    const Id t = static_cast<Id>(s / 4);
    if (!m.fbdy[s] || !m.tet_alive(t)) continue;
    const Id r = m.tadj[s];
    if (r != kNoId && r < static_cast<Id>(s)) continue;  // an interface face once
    const int i = static_cast<int>(s % 4);
    Face f;
    f.slot = s;
    f.ref = m.face_ref(s);
    for (int k = 0; k < 3; ++k) f.v[k] = m.tv[4 * t + kTetFace[i][k]];
    const Vec3 &a = m.xyz[f.v[0]], &b = m.xyz[f.v[1]], &c = m.xyz[f.v[2]];
    f.n = normalize(cross(b - a, c - a));
    f.outer = r == kNoId;
    highest = std::max(highest, f.ref);
    faces.push_back(f);
  }
  // The faces on each edge; faces of one ref joined where they are coplanar.
  struct EdgeFace {
    Id a, b, face;
    bool operator<(const EdgeFace& o) const {
      return a != o.a ? a < o.a : b != o.b ? b < o.b : face < o.face;
    }
  };
  std::vector<EdgeFace> edges;
  edges.reserve(3 * faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Id p = faces[f].v[k], q = faces[f].v[(k + 1) % 3];
      edges.push_back({std::min(p, q), std::max(p, q), static_cast<Id>(f)});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<Id> parent(faces.size());
  std::iota(parent.begin(), parent.end(), Id{0});
  constexpr double kCoplanar = 1.0 - kPlaneNormal;
  const auto each_pair_on_an_edge = [&](auto&& act) {
    for (std::size_t i = 0; i < edges.size();) {
      std::size_t j = i;
      while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) ++j;
      for (std::size_t x = i; x < j; ++x)
        for (std::size_t y = x + 1; y < j; ++y) {
          const Face &f = faces[edges[x].face], &g = faces[edges[y].face];
          if (f.ref == g.ref) act(edges[x].face, edges[y].face, f, g);
        }
      i = j;
    }
  };
  each_pair_on_an_edge([&](Id x, Id y, const Face& f, const Face& g) {
    if (turn_cosine(f, g) > kCoplanar) parent[find_root(parent, x)] = find_root(parent, y);
  });
  // Refs with two pieces or more (several[ref] true), whose pieces meet at sharp edges only.
  std::map<std::int32_t, Id> first_root;
  std::map<std::int32_t, bool> several;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Id root = find_root(parent, static_cast<Id>(f));
    const auto [it, fresh] = first_root.try_emplace(faces[f].ref, root);
    if (!fresh && it->second != root) several[faces[f].ref] = true;
  }
  const double sharp = std::cos(angle_deg * M_PI / 180.0);
  each_pair_on_an_edge([&](Id x, Id y, const Face& f, const Face& g) {
    if (find_root(parent, x) != find_root(parent, y) && turn_cosine(f, g) >= sharp)
      several[f.ref] = false;  // a smooth edge between two pieces: a curved patch
  });
  // Each piece planar.
  std::map<Id, std::vector<Tri3>> piece_faces;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto it = several.find(faces[f].ref);
    if (it == several.end() || !it->second) continue;
    const Face& x = faces[f];
    piece_faces[find_root(parent, static_cast<Id>(f))].push_back(
        Tri3{m.xyz[x.v[0]], m.xyz[x.v[1]], m.xyz[x.v[2]]});
  }
  for (const auto& [root, tris] : piece_faces)
    if (!is_planar(fit_plane(tris), diagonal)) several[faces[root].ref] = false;
  // Fresh refs for the pieces after each ref's first, in the order of their first face: above
  // every face ref, or below them all when the refs reach INT32_MAX (a wall ref of 2147483647
  // kept every interface meeting it), none when neither has room.
  std::int64_t needed = 0;
  std::map<Id, bool> counted;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto it = several.find(faces[f].ref);
    const Id root = find_root(parent, static_cast<Id>(f));
    if (it != several.end() && it->second && first_root.at(faces[f].ref) != root &&
        counted.try_emplace(root, true).second)
      ++needed;
  }
  std::int32_t lowest = std::numeric_limits<std::int32_t>::max();
  for (const Face& f : faces) lowest = std::min(lowest, f.ref);
  constexpr std::int64_t kTop = std::numeric_limits<std::int32_t>::max();
  constexpr std::int64_t kBottom = std::numeric_limits<std::int32_t>::min();
  std::int64_t next = static_cast<std::int64_t>(highest) + 1;
  if (next + needed - 1 > kTop) next = static_cast<std::int64_t>(lowest) - needed;
  std::map<std::int32_t, std::int32_t> pieces;
  if (needed == 0 || next < kBottom) return pieces;
  std::map<Id, std::int32_t> piece_ref;  // root -> ref
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto it = several.find(faces[f].ref);
    if (it == several.end() || !it->second) continue;
    const Id root = find_root(parent, static_cast<Id>(f));
    auto [pr, fresh] = piece_ref.try_emplace(root, faces[f].ref);
    if (fresh && first_root.at(faces[f].ref) != root) {
      pr->second = static_cast<std::int32_t>(next++);
      pieces[pr->second] = faces[f].ref;
    }
    if (pr->second == faces[f].ref) continue;
    const std::uint8_t code = m.ref_code(pr->second);
    m.set_face(faces[f].slot, code, pr->second);
    if (const Id r = m.tadj[faces[f].slot]; r != kNoId)
      m.set_face(static_cast<std::size_t>(r), code, pr->second);
  }
  return pieces;
}

void restore_piece_refs(TetMesh& m, const std::map<std::int32_t, std::int32_t>& pieces) {
  if (pieces.empty()) return;
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    if (!m.fbdy[s] || !m.tet_alive(static_cast<Id>(s / 4))) continue;
    const auto it = pieces.find(m.face_ref(s));
    if (it != pieces.end()) m.set_face(s, m.ref_code(it->second), it->second);
  }
}

}  // namespace riemesh
