// Delaunay3d::flip_cocircular: edge flips between the two Delaunay diagonals of cocircular
// quads (delaunay3d.hpp).
#include <algorithm>

#include "generate/delaunay3d.hpp"
#include "generate/filtered_predicates3d.hpp"

namespace riemesh {

std::size_t Delaunay3d::flip_cocircular(const std::vector<std::array<Id, 4>>& quads) {
  if (quads.empty()) return 0;
  // The kernel's numbering of the points inserted, and a tetrahedron through each.
  const std::size_t n = coords_->size() / 3;
  std::vector<Id> local(n, kNoId);
  for (std::size_t k = 0; k < original_.size(); ++k)
    local[static_cast<std::size_t>(original_[k])] = static_cast<Id>(kStride * k);
  std::vector<std::uint32_t> vertex_tet(original_.size(), ~0u);
  for (std::uint32_t t = 0; t < tets_.size(); ++t) {
    const Id* v = tets_[t].v;
    if (v[0] == kDeleted) continue;
    for (int i = 0; i < 4; ++i)
      if (v[i] >= 0) vertex_tet[vertex_index(v[i])] = t;
  }
  std::size_t flipped = 0;
  for (const std::array<Id, 4>& q : quads) {
    Id l[4];
    bool known = true;
    for (int i = 0; i < 4; ++i) {
      known = known && q[i] >= 0 && static_cast<std::size_t>(q[i]) < n &&
              local[static_cast<std::size_t>(q[i])] != kNoId;
      l[i] = known ? local[static_cast<std::size_t>(q[i])] : kNoId;
    }
    if (known && flip_quad(l, vertex_tet)) ++flipped;
  }
  return flipped;
}

/// One quad {A, B, C, D} in the kernel's numbering (see flip_cocircular).
bool Delaunay3d::flip_quad(const Id (&q)[4], std::vector<std::uint32_t>& vertex_tet) {
  const Id A = q[0], B = q[1], C = q[2], D = q[3];
  const auto index = [&](std::uint32_t t, Id w) {
    const Id* v = tets_[t].v;
    return v[0] == w ? 0 : v[1] == w ? 1 : v[2] == w ? 2 : v[3] == w ? 3 : -1;
  };
  const auto across = [&](std::uint32_t t, int i) { return (tets_[t].n[i] & kCodeMask) >> 2; };
  // A tetrahedron through B and D: a search over the tetrahedra through B, given up (no flip)
  // past kMostBall of them (a vertex of a huge degree: the search is quadratic in it).
  constexpr std::size_t kMostBall = 256;
  const std::uint32_t start = vertex_tet[vertex_index(B)];
  if (start == ~0u || index(start, B) < 0) return false;
  std::vector<std::uint32_t> seen{start}, stack{start};
  std::uint32_t t0 = ~0u;
  while (!stack.empty() && t0 == ~0u && seen.size() <= kMostBall) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    if (index(t, D) >= 0) t0 = t;
    for (int i = 0; i < 4 && t0 == ~0u; ++i) {
      if (tets_[t].v[i] == B) continue;  // (the face opposite B is not through B)
      const std::uint32_t u = across(t, i);
      if (std::find(seen.begin(), seen.end(), u) != seen.end()) continue;
      seen.push_back(u);
      stack.push_back(u);
    }
  }
  if (t0 == ~0u) return false;
  // The ring around BD: T[k] holds B, D, P[k] and P[k + 1]; T[k + 1] is across from P[k].
  std::uint32_t T[4];
  Id P[5];
  int m = 0;
  for (int i = 0; i < 4; ++i) {
    const Id w = tets_[t0].v[i];
    if (w != B && w != D) P[m++] = w;
  }
  T[0] = t0;
  for (m = 1;; ++m) {
    const std::uint32_t u = across(T[m - 1], index(T[m - 1], P[m - 1]));
    if (u == t0) break;
    if (m == 4) return false;  // more than four around BD
    T[m] = u;
    for (int i = 0; i < 4; ++i) {
      const Id w = tets_[u].v[i];
      if (w != B && w != D && w != P[m]) P[m + 1] = w;
    }
  }
  if (m != 4) return false;
  int ia = 0;
  while (ia < 4 && P[ia] != A) ++ia;
  if (ia == 4 || P[(ia + 2) % 4] != C) return false;
  const Id X = P[(ia + 1) % 4], Y = P[(ia + 3) % 4];
  const std::uint32_t t1 = T[ia], t2 = T[(ia + 1) % 4], t4 = T[(ia + 2) % 4], t3 = T[(ia + 3) % 4];
  // A, B, C, D on one circle: C on the circumsphere of a finite tetrahedron through A, B, D.
  const std::uint32_t finite = X != kInfinite ? t1 : t3;
  const Id* w = tets_[finite].v;
  if (detail::insphere_sign(filter_, xyz(w[0]), xyz(w[1]), xyz(w[2]), xyz(w[3]), xyz(C)) != 0)
    return false;
  // The new tetrahedra: each old one with D replaced by C (through A) or B by A (through C).
  const auto positive = [&](std::uint32_t t, Id from, Id to) {
    Id v[4];
    std::copy(tets_[t].v, tets_[t].v + 4, v);
    // A ghost: its finite face is that of its partner across the plane of the quad, checked.
    if ((v[0] | v[1] | v[2] | v[3]) < 0) return true;
    std::replace(v, v + 4, from, to);
    return detail::orient3d_sign(filter_, xyz(v[0]), xyz(v[1]), xyz(v[2]), xyz(v[3])) > 0;
  };
  if (!positive(t1, D, C) || !positive(t2, B, A) || !positive(t3, D, C) || !positive(t4, B, A))
    return false;
  const int a1 = index(t1, A), b1 = index(t1, B), d1 = index(t1, D), x1 = index(t1, X);
  const int b2 = index(t2, B), c2 = index(t2, C), d2 = index(t2, D), x2 = index(t2, X);
  const int a3 = index(t3, A), b3 = index(t3, B), d3 = index(t3, D), y3 = index(t3, Y);
  const int b4 = index(t4, B), c4 = index(t4, C), d4 = index(t4, D), y4 = index(t4, Y);
  // The faces outside the ring (codes), before any is rewritten.
  const std::uint32_t e1b = tets_[t1].n[b1], e1d = tets_[t1].n[d1];
  const std::uint32_t e2b = tets_[t2].n[b2], e2d = tets_[t2].n[d2];
  const std::uint32_t e3b = tets_[t3].n[b3], e3d = tets_[t3].n[d3];
  const std::uint32_t e4b = tets_[t4].n[b4], e4d = tets_[t4].n[d4];
  tets_[t1].v[d1] = C;  // {A, B, C, X}
  tets_[t2].v[b2] = A;  // {A, C, D, X}
  tets_[t3].v[d3] = C;  // {A, B, C, Y}
  tets_[t4].v[b4] = A;  // {A, C, D, Y}
  const auto outer = [&](std::uint32_t t, int i, std::uint32_t e) {
    tets_[t].n[i] = e;
    tets_[e >> 2].n[e & 3] = 4 * t + static_cast<std::uint32_t>(i);
  };
  const auto inner = [&](std::uint32_t t, int i, std::uint32_t u, int j) {
    tets_[t].n[i] = 4 * u + static_cast<std::uint32_t>(j);
    tets_[u].n[j] = 4 * t + static_cast<std::uint32_t>(i);
  };
  // Opposite A, B, C (at D's index), X in {A, B, C, X}: (B, C, X), (A, C, X), (A, B, X), ABC.
  outer(t1, a1, e2d), inner(t1, b1, t2, d2), outer(t1, d1, e1d), inner(t1, x1, t3, y3);
  // Opposite A (at B's index), C, X in {A, C, D, X}: (C, D, X), (A, D, X), ACD.
  outer(t2, b2, e2b), outer(t2, c2, e1b), inner(t2, x2, t4, y4);
  // Opposite A, B, C (at D's index) in {A, B, C, Y}: (B, C, Y), (A, C, Y), (A, B, Y).
  outer(t3, a3, e4d), inner(t3, b3, t4, d4), outer(t3, d3, e3d);
  // Opposite A (at B's index), C in {A, C, D, Y}: (C, D, Y), (A, D, Y).
  outer(t4, b4, e4b), outer(t4, c4, e3b);
  vertex_tet[vertex_index(B)] = t1;
  vertex_tet[vertex_index(D)] = t2;
  return true;
}

}  // namespace riemesh
