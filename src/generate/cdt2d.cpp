#include "generate/cdt2d.hpp"

#include <algorithm>
#include <cstdio>
#include <deque>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "core/predicates.hpp"

namespace riemesh {

namespace {

std::string place(double x, double y) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g)", x, y);
  return buf;
}

/// Flips and queries on a Triangulation2d, with a triangle per vertex kept up to date.
class Flipper {
 public:
  explicit Flipper(Triangulation2d& t) : t_(t), vert_tri_(t.xy.size() / 2, kNoId) {
    for (std::size_t k = 0; k < t.tri.size(); ++k) vert_tri_[t.tri[k]] = static_cast<Id>(k / 3);
  }

  const double* pt(Id v) const { return &t_.xy[2 * static_cast<std::size_t>(v)]; }
  Id vertex(Id tri, int slot) const { return t_.tri[3 * tri + slot]; }

  /// A half-edge of the edge {a, b}, or kNoId if it is not an edge. Turns around a (an input
  /// point: inside the super-triangle, so its triangles form a closed fan).
  Id find_edge(Id a, Id b) const {
    const Id start = vert_tri_[a];
    Id tri = start;
    do {
      const int k = slot_of(tri, a);
      if (vertex(tri, (k + 1) % 3) == b) return 3 * tri + (k + 2) % 3;
      if (vertex(tri, (k + 2) % 3) == b) return 3 * tri + (k + 1) % 3;
      tri = t_.nbr[3 * tri + (k + 1) % 3] / 3;  // counter-clockwise around a
    } while (tri != start);
    return kNoId;
  }

  /// The triangle (a, c, d) around a whose interior angle at a contains the direction of b,
  /// as the half-edge opposite a. Throws if a vertex c lies on the open segment ab.
  template <class OnVertex>
  Id first_crossing(Id a, Id b, OnVertex&& on_vertex) const {
    const Id start = vert_tri_[a];
    Id tri = start;
    do {
      const int k = slot_of(tri, a);
      const Id c = vertex(tri, (k + 1) % 3), d = vertex(tri, (k + 2) % 3);
      const double oc = orient2d(pt(a), pt(c), pt(b));
      if (oc == 0 && !t_.is_super(c) && same_direction(a, c, b)) on_vertex(c);
      if (oc > 0 && orient2d(pt(a), pt(d), pt(b)) < 0) return 3 * tri + k;
      tri = t_.nbr[3 * tri + (k + 1) % 3] / 3;
    } while (tri != start);
    RIEMESH_CHECK(false);  // the fan around a covers every direction
    return kNoId;
  }

  /// Flips the edge of half-edge h (its quadrilateral must be strictly convex). With t = (p, a,
  /// b) and u = (q, b, a) the triangles become (p, a, q) and (q, b, p).
  void flip(Id h) {
    const Id tri = h / 3, u = t_.nbr[h] / 3;
    const int i = h % 3, j = t_.nbr[h] % 3;
    const Id p = vertex(tri, i), a = vertex(tri, (i + 1) % 3), b = vertex(tri, (i + 2) % 3);
    const Id q = vertex(u, j);
    const Id n_bp = t_.nbr[3 * tri + (i + 1) % 3], n_pa = t_.nbr[3 * tri + (i + 2) % 3];
    const Id n_aq = t_.nbr[3 * u + (j + 1) % 3], n_qb = t_.nbr[3 * u + (j + 2) % 3];
    set(tri, p, a, q, n_aq, 3 * u + 1, n_pa);
    set(u, q, b, p, n_bp, 3 * tri + 1, n_qb);
    vert_tri_[p] = vert_tri_[a] = tri;
    vert_tri_[q] = vert_tri_[b] = u;
  }

  /// True when the quadrilateral of h's edge is strictly convex (the flip is valid).
  bool flippable(Id h) const {
    if (t_.nbr[h] == kNoId) return false;
    const Id tri = h / 3, u = t_.nbr[h] / 3;
    const int i = h % 3, j = t_.nbr[h] % 3;
    const Id p = vertex(tri, i), q = vertex(u, j);
    const Id a = vertex(tri, (i + 1) % 3), b = vertex(tri, (i + 2) % 3);
    const double oa = orient2d(pt(p), pt(q), pt(a)), ob = orient2d(pt(p), pt(q), pt(b));
    return (oa > 0 && ob < 0) || (oa < 0 && ob > 0);
  }

 private:
  int slot_of(Id tri, Id v) const {
    return vertex(tri, 0) == v ? 0 : vertex(tri, 1) == v ? 1 : 2;
  }
  bool same_direction(Id a, Id c, Id b) const {
    const double* pa = pt(a);
    return (pt(c)[0] - pa[0]) * (pt(b)[0] - pa[0]) + (pt(c)[1] - pa[1]) * (pt(b)[1] - pa[1]) > 0;
  }
  void set(Id tri, Id v0, Id v1, Id v2, Id n0, Id n1, Id n2) {
    Id* v = &t_.tri[3 * tri];
    v[0] = v0, v[1] = v1, v[2] = v2;
    const Id n[3] = {n0, n1, n2};
    for (int s = 0; s < 3; ++s) {
      t_.nbr[3 * tri + s] = n[s];
      if (n[s] != kNoId) t_.nbr[n[s]] = 3 * tri + s;
    }
  }

  Triangulation2d& t_;
  std::vector<Id> vert_tri_;
};

struct Recovery {
  Triangulation2d& t;
  Flipper f;
  std::span<const Id> edges;
  std::unordered_map<std::uint64_t, Id> constraint;  // recovered edges so far
  std::vector<Id> touched;  // the triangles of every flip (a triangle keeps its id when flipped)

  std::string edge_name(Id e) const {
    std::string s = "boundary edge ";
    s += std::to_string(e + 1);
    s += " ";
    s += place(f.pt(edges[2 * e])[0], f.pt(edges[2 * e])[1]);
    s += "-";
    s += place(f.pt(edges[2 * e + 1])[0], f.pt(edges[2 * e + 1])[1]);
    return s;
  }

  [[noreturn]] void vertex_on_edge(Id v, Id e) const {
    std::string msg = "vertex ";
    msg += std::to_string(v + 1);
    msg += " ";
    msg += place(f.pt(v)[0], f.pt(v)[1]);
    msg += " lies on ";
    msg += edge_name(e);
    throw InputError(msg);
  }

  /// The edges crossed by the segment of constraint e, from its first vertex to its second.
  std::vector<std::uint64_t> crossed_edges(Id e) const {
    const Id a = edges[2 * e], b = edges[2 * e + 1];
    std::vector<std::uint64_t> out;
    Id h = f.first_crossing(a, b, [&](Id v) { vertex_on_edge(v, e); });
    // h: edge (c, d) with c right of a→b and d left of it, in a triangle on a's side.
    Id c = f.vertex(h / 3, (h % 3 + 1) % 3), d = f.vertex(h / 3, (h % 3 + 2) % 3);
    for (;;) {
      const auto hit = constraint.find(edge_key(c, d));
      if (hit != constraint.end()) crossing(e, hit->second);
      out.push_back(edge_key(c, d));
      const Id g = t.nbr[h];
      const Id u = g / 3, e_opp = f.vertex(u, g % 3);
      if (e_opp == b) return out;
      const double o = orient2d(f.pt(a), f.pt(b), f.pt(e_opp));
      if (o == 0) vertex_on_edge(e_opp, e);
      // u = (e_opp, d, c): leave through (c, e_opp) if e_opp is left of a→b, else (e_opp, d).
      if (o > 0) {
        h = 3 * u + (g % 3 + 1) % 3;  // opposite d: edge (c, e_opp)
        d = e_opp;
      } else {
        h = 3 * u + (g % 3 + 2) % 3;  // opposite c: edge (e_opp, d)
        c = e_opp;
      }
    }
  }

  [[noreturn]] void crossing(Id e, Id other) const {
    // The crossing point, for the message (floating point is enough here).
    const double* a = f.pt(edges[2 * e]);
    const double* b = f.pt(edges[2 * e + 1]);
    const double* c = f.pt(edges[2 * other]);
    const double* d = f.pt(edges[2 * other + 1]);
    const double oc = orient2d(a, b, c), od = orient2d(a, b, d);
    const double s = oc / (oc - od);
    std::string msg = edge_name(e);
    msg += " and ";
    msg += edge_name(other);
    msg += " cross near ";
    msg += place(c[0] + s * (d[0] - c[0]), c[1] + s * (d[1] - c[1]));
    throw InputError(msg);
  }

  void recover(Id e) {
    const Id a = edges[2 * e], b = edges[2 * e + 1];
    if (f.find_edge(a, b) == kNoId) {
      std::deque<std::uint64_t> queue;
      for (const std::uint64_t k : crossed_edges(e)) queue.push_back(k);
      std::size_t guard = 0;
      const std::size_t limit = 100 * (queue.size() + 10) * (queue.size() + 10);
      while (!queue.empty()) {
        RIEMESH_CHECK(++guard < limit);
        const std::uint64_t k = queue.front();
        queue.pop_front();
        const Id h = f.find_edge(static_cast<Id>(k & 0xffffffffu), static_cast<Id>(k >> 32));
        if (!f.flippable(h)) {
          queue.push_back(k);
          continue;
        }
        touched.push_back(h / 3);
        touched.push_back(t.nbr[h] / 3);
        f.flip(h);
        // h's triangle is now (p, a, q): the new edge is (p, q).
        const Id p = f.vertex(h / 3, 0), q = f.vertex(h / 3, 2);
        const double op = orient2d(f.pt(a), f.pt(b), f.pt(p));
        const double oq = orient2d(f.pt(a), f.pt(b), f.pt(q));
        if ((op > 0 && oq < 0) || (op < 0 && oq > 0)) queue.push_back(edge_key(p, q));
      }
      RIEMESH_CHECK(f.find_edge(a, b) != kNoId);
    }
    constraint.emplace(edge_key(a, b), e);
  }

  /// Lawson's flips: every edge that is not a constraint becomes locally Delaunay. Only the
  /// edges of the triangles the recovery flipped can have stopped being so: the others keep
  /// both their triangles from the Delaunay triangulation.
  void make_delaunay() {
    std::vector<Id> stack;
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    for (const Id tri : touched)
      for (int s = 0; s < 3; ++s)
        if (t.nbr[3 * tri + s] != kNoId) stack.push_back(3 * tri + s);
    while (!stack.empty()) {
      const Id h = stack.back();
      stack.pop_back();
      const Id g = t.nbr[h];
      if (g == kNoId) continue;
      const Id tri = h / 3, u = g / 3;
      const Id a = f.vertex(tri, (h % 3 + 1) % 3), b = f.vertex(tri, (h % 3 + 2) % 3);
      if (constraint.count(edge_key(a, b))) continue;
      const double in = incircle(f.pt(f.vertex(tri, 0)), f.pt(f.vertex(tri, 1)),
                                 f.pt(f.vertex(tri, 2)), f.pt(f.vertex(u, g % 3)));
      if (!(in > 0)) continue;
      f.flip(h);  // strictly convex: the opposite vertex is strictly inside the circle
      stack.insert(stack.end(), {3 * tri, 3 * tri + 2, 3 * u, 3 * u + 2});
    }
  }
};

}  // namespace

std::vector<Id> recover_edges(Triangulation2d& t, std::span<const Id> edges) {
  Recovery r{t, Flipper(t), edges, {}, {}};
  const Id ne = static_cast<Id>(edges.size() / 2);
  for (Id e = 0; e < ne; ++e) {
    RIEMESH_CHECK(edges[2 * e] != edges[2 * e + 1]);
    RIEMESH_CHECK(!t.is_super(edges[2 * e]) && !t.is_super(edges[2 * e + 1]));
    r.recover(e);
  }
  r.make_delaunay();
  std::vector<Id> out = huge_vector<Id>(t.tri.size(), kNoId);
  for (const auto& [key, e] : r.constraint) {  // both half-edges of each constraint
    const Id h = r.f.find_edge(edges[2 * e], edges[2 * e + 1]);
    RIEMESH_CHECK(h != kNoId);
    out[h] = e;
    if (t.nbr[h] != kNoId) out[t.nbr[h]] = e;
  }
  return out;
}

}  // namespace riemesh
