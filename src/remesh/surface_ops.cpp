// The passes of the surface remesher: split, collapse, swap, smooth (surface_adapt.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>

#include "mesh/distance.hpp"
#include "remesh/surface_adapt_detail.hpp"
#include "remesh/surface_cover.hpp"
#include "remesh/surface_hausdorff.hpp"

namespace riemesh::surface_detail {
namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr double kCosTurn = 0.8660254037844387;  // cos 30°: largest turn of a triangle's normal
constexpr double kTinyEdge =
    0.25;  // edges below this may collapse into worse triangles (try_collapse)
/// Smoothing leaves a vertex alone when the worst triangle of its ball is at least this good.
constexpr double kSmoothEnough = 0.9;

std::size_t us(Id i) { return static_cast<std::size_t>(i); }

/// The neighbours of v (the other vertices of its ball), sorted, unique, into n (scratch reused
/// by the caller: the passes ask for thousands of balls).
void neighbours(const State& s, std::span<const Id> ball_v, Id v, std::vector<Id>& n) {
  n.clear();
  for (Id t : ball_v)
    for (int i = 0; i < 3; ++i)
      if (s.tri[3 * us(t) + i] != v) n.push_back(s.tri[3 * us(t) + i]);
  if (n.size() > 32) {
    std::sort(n.begin(), n.end());
  } else {  // a ball's dozen ids: insertion sort
    for (std::size_t i = 1; i < n.size(); ++i) {
      const Id x = n[i];
      std::size_t j = i;
      for (; j > 0 && x < n[j - 1]; --j) n[j] = n[j - 1];
      n[j] = x;
    }
  }
  n.erase(std::unique(n.begin(), n.end()), n.end());
}

/// Triangle t's corners with vertex `from` at position `p` (the others at their place).
void corners(const State& s, Id t, Id from, const Vec3& p, Vec3 (&c)[3]) {
  for (int i = 0; i < 3; ++i) {
    const Id v = s.tri[3 * us(t) + i];
    c[i] = v == from ? p : s.x[us(v)];
  }
}

/// Distance from p to triangle abc.
double to_triangle(const Vec3& p, const Vec3 (&c)[3]) {
  return norm(p - closest_point_on_triangle(p, c[0], c[1], c[2]));
}

/// The B -> A check of surface_hausdorff.hpp at kCheckMargin × hausd. The lattice points of every
/// triangle of the mesh passed it (or lie on the input, at the start): those of the edges of the
/// old triangles old_t are not checked again.
bool new_triangles_close(const State& s, const std::vector<Tri3>& new_t, Id hint,
                         const std::vector<Tri3>& old_t) {
  return riemesh::new_triangles_close(*s.geo, kCheckMargin * s.opt->hausd, new_t, hint, &old_t);
}

/// The metric of triangle t: the mean of its vertex metrics, vertex `moved` (if any) taking `mm`.
SymMat3 tri_metric(const State& s, Id t, Id moved = kNoId, const SymMat3* mm = nullptr) {
  SymMat3 sum = SymMat3::zero();
  for (int i = 0; i < 3; ++i) {
    const Id v = s.tri[3 * us(t) + i];
    sum += (v == moved && mm) ? *mm : s.m[us(v)];
  }
  return (1.0 / 3.0) * sum;
}

/// Local position i of the edge p -> q in triangle t (tri[i] = p, tri[i+1] = q), or -1.
int directed(const State& s, Id t, Id p, Id q) {
  for (int i = 0; i < 3; ++i)
    if (s.tri[3 * us(t) + i] == p && s.tri[3 * us(t) + (i + 1) % 3] == q) return i;
  return -1;
}

}  // namespace

Vec3 tri_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  const double l = norm(n);
  return l > 0.0 ? n / l : Vec3::zero();
}

double quality(const SymMat3& m, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, e3 = c - b;
  const double g11 = quadratic(m, e1), g22 = quadratic(m, e2), g12 = bilinear(m, e1, e2);
  const double area = 0.5 * std::sqrt(std::max(0.0, g11 * g22 - g12 * g12));
  const double l2 = g11 + g22 + quadratic(m, e3);
  return l2 > 0.0 ? 4.0 * std::sqrt(3.0) * area / l2 : 0.0;
}

double quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double area = 0.5 * norm(cross(b - a, c - a));
  const double l2 = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
  return l2 > 0.0 ? 4.0 * std::sqrt(3.0) * area / l2 : 0.0;
}

Topology build_topology(const State& s) {
  // What build_edge_adjacency gives (balls, edges sorted by (a, b), elem2edge; the passes never
  // cross faces), built for triangles alone in fewer steps: the half-edges bucketed by their
  // smaller vertex, each bucket sorted by the larger one then by half-edge (a few entries).
  Topology t;
  Adjacency& adj = t.adj;
  const std::size_t nv = s.num_vertices(), nt = s.num_triangles();
  adj.verts_per_simplex = 3;
  adj.num_vertices = nv;
  adj.vert2elem_offsets.assign(nv + 1, 0);
  for (Id v : s.tri) ++adj.vert2elem_offsets[us(v) + 1];
  for (std::size_t v = 0; v < nv; ++v) adj.vert2elem_offsets[v + 1] += adj.vert2elem_offsets[v];
  adj.vert2elem.resize(s.tri.size());
  std::vector<Id> fill(adj.vert2elem_offsets.begin(), adj.vert2elem_offsets.end() - 1);
  for (std::size_t k = 0; k < s.tri.size(); ++k)
    adj.vert2elem[us(fill[us(s.tri[k])]++)] = static_cast<Id>(k / 3);
  // Half-edge h = 3 t + j (local edge j = kTriEdge[j]) as (larger vertex << 32 | h), in the
  // bucket of its smaller vertex.
  std::vector<Id> start(nv + 1, 0);
  for (std::size_t tr = 0; tr < nt; ++tr)
    for (int j = 0; j < 3; ++j) {
      const Id p = s.tri[3 * tr + kTriEdge[j][0]], q = s.tri[3 * tr + kTriEdge[j][1]];
      if (p != q) ++start[us(std::min(p, q)) + 1];
    }
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::uint64_t> half(us(start[nv]));
  std::copy(start.begin(), start.end() - 1, fill.begin());
  for (std::size_t tr = 0; tr < nt; ++tr)
    for (int j = 0; j < 3; ++j) {
      const Id p = s.tri[3 * tr + kTriEdge[j][0]], q = s.tri[3 * tr + kTriEdge[j][1]];
      if (p == q) continue;
      half[us(fill[us(std::min(p, q))]++)] = (static_cast<std::uint64_t>(std::max(p, q)) << 32) |
                                             (3 * tr + static_cast<std::size_t>(j));
    }
  std::size_t ne = 0;
  for (std::size_t a = 0; a < nv; ++a) {
    std::uint64_t* const b = half.data() + start[a];
    std::uint64_t* const e = half.data() + start[a + 1];
    for (std::uint64_t* i = b + 1; i < e; ++i) {  // insertion sort: a handful of entries
      const std::uint64_t x = *i;
      std::uint64_t* j = i;
      for (; j > b && x < *(j - 1); --j) *j = *(j - 1);
      *j = x;
    }
    for (std::uint64_t* i = b; i < e; ++i) ne += i == b || (*(i - 1) >> 32) != (*i >> 32);
  }
  adj.elem2edge.assign(3 * nt, kNoId);
  adj.edges.resize(2 * ne);
  t.edge_count.assign(ne, 0);
  t.edge_tris.assign(2 * ne, kNoId);
  std::size_t found = 0;  // edges so far: the current one is found - 1
  for (std::size_t a = 0; a < nv; ++a)
    for (std::size_t k = us(start[a]); k < us(start[a + 1]); ++k) {
      const std::uint64_t x = half[k];
      if (k == us(start[a]) || (half[k - 1] >> 32) != (x >> 32)) {  // a new edge (a, x >> 32)
        adj.edges[2 * found] = static_cast<Id>(a);
        adj.edges[2 * found + 1] = static_cast<Id>(x >> 32);
        ++found;
      }
      const std::size_t edge = found - 1, h = static_cast<std::size_t>(x & 0xffffffffu);
      adj.elem2edge[h] = static_cast<Id>(edge);
      int& count = t.edge_count[edge];
      if (count < 2) t.edge_tris[2 * edge + us(count)] = static_cast<Id>(h / 3);
      ++count;
    }
  return t;
}

const Topology& topology(State& s) {
  if (!s.topo_valid) {
    s.topo = build_topology(s);
    s.topo_valid = true;
  }
  return s.topo;
}

std::size_t split_pass(State& s, double bad_quality) {
  const Topology& topo = topology(s);
  const std::size_t ne = topo.adj.num_edges();
  std::vector<std::pair<double, Id>> cand;
  if (bad_quality > 0.0) {
    // The longest edge in the metric of each triangle below bad_quality (the edge facing its
    // obtuse angle), when it is at least unit: a triangle that is bad for being too short one
    // way is made worse by more points (an isotropic input under an anisotropic metric whose
    // coarsening the Hausdorff bound stopped: 1,790 -> 5,636 triangles), not better.
    for (std::size_t t = 0; t < s.num_triangles(); ++t) {
      const Id* v = &s.tri[3 * t];
      if (quality(tri_metric(s, static_cast<Id>(t)), s.x[us(v[0])], s.x[us(v[1])], s.x[us(v[2])]) >=
          bad_quality)
        continue;
      int best = 0;
      double lbest = -1.0;
      for (int j = 0; j < 3; ++j) {
        const double l = s.size_length(v[kTriEdge[j][0]], v[kTriEdge[j][1]]);
        if (l > lbest) lbest = l, best = j;
      }
      if (!(lbest >= 1.0)) continue;
      const Id e = topo.adj.elem2edge[3 * t + best];
      if (topo.edge_count[us(e)] <= 2) cand.push_back({-lbest, e});
    }
    std::sort(cand.begin(), cand.end());
    cand.erase(std::unique(cand.begin(), cand.end()), cand.end());
  } else {
    for (std::size_t e = 0; e < ne; ++e) {
      const double l = s.size_length(topo.adj.edges[2 * e], topo.adj.edges[2 * e + 1]);
      if (l > kSqrt2 && topo.edge_count[e] <= 2) cand.push_back({-l, static_cast<Id>(e)});
    }
  }
  std::sort(cand.begin(), cand.end());
  std::vector<char> done(s.num_triangles(), 0);
  std::size_t count = 0;
  CoverScratch cover;
  std::vector<Id> new_ids;
  for (const auto& [neg, e] : cand) {
    const int nt = topo.edge_count[us(e)];
    const Id* et = &topo.edge_tris[2 * us(e)];
    if (done[us(et[0])] || (nt == 2 && done[us(et[1])])) continue;
    const Id a = topo.adj.edges[2 * us(e)], b = topo.adj.edges[2 * us(e) + 1];
    const bool feat = s.is_feature(a, b);
    const Vec3 mid = 0.5 * (s.x[us(a)] + s.x[us(b)]);
    // The point on the reconstruction when the halves stay within hausd of the input both ways;
    // else the nearest point of the input itself; else no split.
    SurfaceProjection::Placed p;
    bool ok = false;
    // The ids of the new triangles once applied (below): triangle t keeps the half with the
    // first corner of its directed edge, the other half is appended.
    new_ids.clear();
    for (int k = 0; k < nt; ++k) {
      const Id appended = static_cast<Id>(s.num_triangles()) + k;
      const bool a_first = directed(s, et[k], a, b) >= 0;
      new_ids.push_back(a_first ? appended : et[k]);  // a moved to the midpoint
      new_ids.push_back(a_first ? et[k] : appended);  // b moved
    }
    for (const bool smooth : {true, false}) {
      p = feat ? s.geo->on_feature(mid, s.line_hint[us(a)], smooth)
               : s.geo->on_surface(mid, s.surf_hint[us(a)], smooth);
      ok = true;
      std::vector<Tri3> old_t, new_t;
      for (int k = 0; k < nt && ok; ++k) {
        Vec3 c[3];
        corners(s, et[k], a, s.x[us(a)], c);
        const Vec3 n = tri_normal(c[0], c[1], c[2]);
        Vec3 c1[3], c2[3];
        corners(s, et[k], a, p.point, c1);
        corners(s, et[k], b, p.point, c2);
        // The two halves of each triangle keep its orientation.
        ok = dot(tri_normal(c1[0], c1[1], c1[2]), n) > 0.5 &&
             dot(tri_normal(c2[0], c2[1], c2[2]), n) > 0.5;
        old_t.push_back({c[0], c[1], c[2]});
        new_t.push_back({c1[0], c1[1], c1[2]});
        new_t.push_back({c2[0], c2[1], c2[2]});
      }
      ok = ok && new_triangles_close(s, new_t, s.surf_hint[us(a)], old_t) &&
           new_triangles_cover(s, std::span<const Id>(et, us(nt)), new_t, new_ids, cover);
      if (ok) break;
    }
    if (!ok) continue;
    s.touch(std::span<const Id>(et, us(nt)));
    const Id m = s.add_vertex(p.point, p.metric, feat ? kTagRidge : kTagNone,
                              feat ? s.surf_hint[us(a)] : p.hint, feat ? p.hint : s.line_hint[us(a)]);
    for (int k = 0; k < nt; ++k) {
      const Id t = et[k];
      done[us(t)] = 1;
      int i = directed(s, t, a, b);
      if (i < 0) i = directed(s, t, b, a);
      const Id pv = s.tri[3 * us(t) + i], qv = s.tri[3 * us(t) + (i + 1) % 3];
      const Id rv = s.tri[3 * us(t) + (i + 2) % 3];
      s.tri[3 * us(t)] = pv;
      s.tri[3 * us(t) + 1] = m;
      s.tri[3 * us(t) + 2] = rv;
      s.tri.insert(s.tri.end(), {m, qv, rv});
      s.tref.push_back(s.tref[us(t)]);
    }
    hand_over(s, std::span<const Id>(et, us(nt)), new_ids, cover);
    if (feat) {
      const std::uint64_t key = edge_key(a, b);
      const std::int32_t ref = s.feature[key];
      const std::uint8_t tag = s.feature_tag[key];
      s.feature.erase(key);
      s.feature_tag.erase(key);
      for (Id x : {a, b}) {
        s.feature[edge_key(x, m)] = ref;
        s.feature_tag[edge_key(x, m)] = tag;
      }
    }
    ++count;
  }
  if (count > 0) s.topo_valid = false;
  return count;
}

namespace {

/// Exact balls while a collapse pass changes triangles: the pass's topology, whose balls keep
/// their triangle ids (a collapse v -> w renames v in its triangles and kills the edge's two),
/// minus the triangles that no longer hold the vertex, plus those it gained (a target w gains
/// the triangles of v). Collapses can thus follow one another in a pass without a rebuild.
class PassBalls {
 public:
  PassBalls(const State& s, const Topology& t)
      : topo_(&t), gained_(s.num_vertices()), dead_(s.num_vertices(), 0) {}
  /// Triangle t took vertex v in this pass.
  void gain(Id v, Id t) { gained_[us(v)].push_back(t); }
  /// Vertex v was collapsed away: no triangle holds it any more.
  void kill(Id v) { dead_[us(v)] = 1; }
  bool dead(Id v) const { return dead_[us(v)] != 0; }
  /// The triangles holding v now, into out.
  void ball_of(const State& s, Id v, std::vector<Id>& out) const {
    out.clear();
    auto holds = [&s, v](Id t) {  // a dead triangle holds kNoId only
      const Id* x = &s.tri[3 * us(t)];
      return x[0] == v || x[1] == v || x[2] == v;
    };
    for (Id t : ball(topo_->adj, v))
      if (holds(t)) out.push_back(t);
    for (Id t : gained_[us(v)])
      if (holds(t)) out.push_back(t);
  }

 private:
  const Topology* topo_;
  std::vector<std::vector<Id>> gained_;
  std::vector<char> dead_;
};

/// Scratch vectors of try_collapse, reused from edge to edge (thousands of tries per pass).
struct CollapseScratch {
  std::vector<Id> bv, bw, nv, new_ids;
  std::vector<Tri3> old_t, new_t;
  CoverScratch cover;
  std::vector<std::uint32_t> mark;  // per vertex: the stamp of the last ball that met it
  std::uint32_t stamp = 0;
};

/// Tries to collapse v into w (see surface_adapt.hpp); applies it and returns true when allowed.
bool try_collapse(State& s, PassBalls& balls, Id v, Id w, CollapseScratch& scratch) {
  if (balls.dead(v) || balls.dead(w)) return false;  // the edge went with an earlier collapse
  if (s.tag[us(v)] & (kTagCorner | kTagRequired)) return false;
  const bool feat = s.is_feature(v, w);
  if ((s.tag[us(v)] & kTagRidge) && !feat) return false;
  std::vector<Id>&bv = scratch.bv, &bw = scratch.bw;
  balls.ball_of(s, v, bv);
  int nt = 0;  // triangles of the edge
  for (Id t : bv)
    nt += s.tri[3 * us(t)] == w || s.tri[3 * us(t) + 1] == w || s.tri[3 * us(t) + 2] == w;
  if (nt < 1 || nt > 2 || (nt == 1 && !feat)) return false;
  balls.ball_of(s, w, bw);
  // Link condition: the common neighbours of v and w are the apexes of the edge's triangles
  // (v's neighbours stamped, w's counted among them).
  std::vector<Id>& nv = scratch.nv;
  std::vector<std::uint32_t>& mark = scratch.mark;
  const std::uint32_t sv = ++scratch.stamp, sw = ++scratch.stamp;
  nv.clear();
  for (Id t : bv)
    for (int i = 0; i < 3; ++i) {
      const Id x = s.tri[3 * us(t) + i];
      if (x != v && mark[us(x)] != sv) {
        mark[us(x)] = sv;
        nv.push_back(x);
      }
    }
  int common = 0;
  for (Id t : bw)
    for (int i = 0; i < 3; ++i) {
      const Id x = s.tri[3 * us(t) + i];
      if (x == w || mark[us(x)] == sw) continue;
      common += mark[us(x)] == sv;
      mark[us(x)] = sw;
    }
  if (common != nt) return false;
  // New edges not too long.
  for (Id x : nv)
    if (x != w && s.size_length(w, x) > kSqrt2) return false;
  // A new triangle may not fall below min(0.3, the worst old one): the old ones measured only
  // when a new one is below 0.3. Edges far below unit length (a stretched input, cells 1:6 an
  // order of magnitude finer than the metric asks) may make a triangle up to 2x worse, as in 2D
  // (adapt2d.cpp): each collapse there gives a slightly worse triangle on the way to coarse ones.
  const double relative_floor = s.size_length(v, w) < kTinyEdge ? 0.5 : 1.0;
  double qmin_old = -1.0;
  auto worst_old = [&] {
    if (qmin_old < 0.0) {
      qmin_old = 1.0;
      for (Id t : bv) {
        Vec3 c[3];
        corners(s, t, v, s.x[us(v)], c);
        qmin_old = std::min(qmin_old, quality(tri_metric(s, t), c[0], c[1], c[2]));
      }
    }
    return qmin_old;
  };
  const double hausd = kCheckMargin * s.opt->hausd;
  double gap = std::numeric_limits<double>::infinity();
  std::vector<Tri3>&old_t = scratch.old_t, &new_t = scratch.new_t;
  std::vector<Id>& new_ids = scratch.new_ids;
  old_t.clear();
  new_t.clear();
  new_ids.clear();
  for (Id t : bv) {
    bool has_w = false;
    for (int i = 0; i < 3; ++i) has_w |= s.tri[3 * us(t) + i] == w;
    Vec3 c[3], n[3];
    corners(s, t, v, s.x[us(v)], c);
    old_t.push_back({c[0], c[1], c[2]});
    if (has_w) continue;  // removed
    corners(s, t, v, s.x[us(w)], n);
    new_t.push_back({n[0], n[1], n[2]});
    new_ids.push_back(t);
    const Vec3 n_old = tri_normal(c[0], c[1], c[2]), n_new = tri_normal(n[0], n[1], n[2]);
    if (dot(n_old, n_new) < kCosTurn) return false;
    const double q = quality(tri_metric(s, t, v, &s.m[us(w)]), n[0], n[1], n[2]);
    if (q < 0.3 && q < relative_floor * worst_old()) return false;
    gap = std::min(gap, to_triangle(s.x[us(v)], n));
  }
  if (gap > hausd || !new_triangles_close(s, new_t, s.surf_hint[us(v)], old_t) ||
      !new_triangles_cover(s, bv, new_t, new_ids, scratch.cover))
    return false;
  // Apply.
  s.touch(bv);
  for (Id t : bv) {
    bool has_w = false;
    for (int i = 0; i < 3; ++i) has_w |= s.tri[3 * us(t) + i] == w;
    for (int i = 0; i < 3; ++i) {
      Id& x = s.tri[3 * us(t) + i];
      if (has_w) x = kNoId;
      else if (x == v) x = w;
    }
  }
  for (Id x : nv) {
    const std::uint64_t key = edge_key(v, x);
    const auto it = s.feature.find(key);
    if (it == s.feature.end()) continue;
    if (x != w) {
      s.feature[edge_key(w, x)] = it->second;
      s.feature_tag[edge_key(w, x)] = s.feature_tag[key];
    }
    s.feature.erase(key);
    s.feature_tag.erase(key);
  }
  hand_over(s, bv, new_ids, scratch.cover);
  for (Id t : new_ids) balls.gain(w, t);
  balls.kill(v);
  return true;
}

}  // namespace

std::size_t collapse_pass(State& s) {
  const Topology& topo = topology(s);
  std::vector<std::pair<double, Id>> cand;
  for (std::size_t e = 0; e < topo.adj.num_edges(); ++e) {
    const double l = s.size_length(topo.adj.edges[2 * e], topo.adj.edges[2 * e + 1]);
    if (l < 1.0 / kSqrt2) cand.push_back({l, static_cast<Id>(e)});
  }
  std::sort(cand.begin(), cand.end());
  PassBalls balls(s, topo);
  std::size_t count = 0;
  CollapseScratch scratch;
  scratch.mark.assign(s.num_vertices(), 0);
  for (const auto& [l, e] : cand) {
    const Id a = topo.adj.edges[2 * us(e)], b = topo.adj.edges[2 * us(e) + 1];
    if (try_collapse(s, balls, a, b, scratch) || try_collapse(s, balls, b, a, scratch)) ++count;
  }
  s.compact();  // renumbers nothing when nothing was collapsed: the topology stays valid
  if (count > 0) s.topo_valid = false;
  return count;
}

std::size_t swap_pass(State& s) {
  const Topology& topo = topology(s);
  std::vector<char> dirty(s.num_triangles(), 0);
  std::size_t count = 0;
  const double hausd = kCheckMargin * s.opt->hausd;
  CoverScratch cover;
  for (std::size_t e = 0; e < topo.adj.num_edges(); ++e) {
    if (topo.edge_count[e] != 2) continue;
    const Id a = topo.adj.edges[2 * e], b = topo.adj.edges[2 * e + 1];
    if (s.is_feature(a, b)) continue;
    Id t1 = topo.edge_tris[2 * e], t2 = topo.edge_tris[2 * e + 1];
    if (dirty[us(t1)] || dirty[us(t2)]) continue;
    int i1 = directed(s, t1, a, b);
    if (i1 < 0) {
      std::swap(t1, t2);
      i1 = directed(s, t1, a, b);
    }
    const int i2 = directed(s, t2, b, a);
    if (i1 < 0 || i2 < 0) continue;  // inconsistent orientation: leave alone
    const Id c = s.tri[3 * us(t1) + (i1 + 2) % 3], d = s.tri[3 * us(t2) + (i2 + 2) % 3];
    if (c == d || find_edge(topo.adj, c, d) != kNoId) continue;
    const Vec3 &pa = s.x[us(a)], &pb = s.x[us(b)], &pc = s.x[us(c)], &pd = s.x[us(d)];
    const SymMat3 &ma = s.m[us(a)], &mb = s.m[us(b)], &mc = s.m[us(c)], &md = s.m[us(d)];
    const double q_old = std::min(quality((1.0 / 3.0) * (ma + mb + mc), pa, pb, pc),
                                  quality((1.0 / 3.0) * (mb + ma + md), pb, pa, pd));
    const double q_new = std::min(quality((1.0 / 3.0) * (ma + md + mc), pa, pd, pc),
                                  quality((1.0 / 3.0) * (md + mb + mc), pd, pb, pc));
    if (!(q_new > 1.05 * q_old)) continue;
    const Vec3 n1 = tri_normal(pa, pb, pc), n2 = tri_normal(pb, pa, pd);
    const Vec3 m1 = tri_normal(pa, pd, pc), m2 = tri_normal(pd, pb, pc);
    if (dot(m1, n1) < kCosTurn || dot(m1, n2) < kCosTurn || dot(m2, n1) < kCosTurn ||
        dot(m2, n2) < kCosTurn)
      continue;
    // Dihedral/Hausdorff check: the old edge stays near the new pair, the new edge near the input.
    const Vec3 mid_old = 0.5 * (pa + pb), mid_new = 0.5 * (pc + pd);
    const Vec3 f1[3] = {pa, pd, pc}, f2[3] = {pd, pb, pc};
    if (std::min(to_triangle(mid_old, f1), to_triangle(mid_old, f2)) > hausd) continue;
    Id hint = s.surf_hint[us(c)];
    if (!s.geo->within(mid_new, hausd, &hint)) continue;
    const std::vector<Tri3> new_t = {Tri3{pa, pd, pc}, Tri3{pd, pb, pc}};
    const Id ids[2] = {t1, t2};  // before and after: t1 becomes a d c, t2 d b c
    const std::vector<Tri3> old_t = {Tri3{pa, pb, pc}, Tri3{pb, pa, pd}};
    if (!new_triangles_close(s, new_t, s.surf_hint[us(c)], old_t) ||
        !new_triangles_cover(s, ids, new_t, ids, cover))
      continue;
    s.touch(ids);
    s.tri[3 * us(t1)] = a;
    s.tri[3 * us(t1) + 1] = d;
    s.tri[3 * us(t1) + 2] = c;
    s.tri[3 * us(t2)] = d;
    s.tri[3 * us(t2) + 1] = b;
    s.tri[3 * us(t2) + 2] = c;
    hand_over(s, ids, ids, cover);
    dirty[us(t1)] = dirty[us(t2)] = 1;
    ++count;
  }
  if (count > 0) s.topo_valid = false;
  return count;
}

std::size_t smooth_pass(State& s) {
  const Topology& topo = topology(s);  // moves change no triangle: stays valid
  std::size_t count = 0;
  std::vector<Id> nb;  // scratch reused from vertex to vertex
  std::vector<Tri3> old_t, new_t;
  CoverScratch cover;
  // Quality of each triangle, computed when first needed and forgotten when a corner moves
  // (-1: unknown): every triangle is in three balls.
  std::vector<double> tq(s.num_triangles(), -1.0);
  for (std::size_t vi = 0; vi < s.num_vertices(); ++vi) {
    const auto v = static_cast<Id>(vi);
    if (s.tag[vi] & (kTagCorner | kTagRequired)) continue;
    const auto bv = ball(topo.adj, v);
    if (bv.empty()) continue;
    // Balls whose worst triangle is already good have little to gain (and each try costs a
    // projection and the Hausdorff checks).
    double q_ball = 1.0;
    for (Id t : bv) {
      if (tq[us(t)] < 0.0) {
        Vec3 c[3];
        corners(s, t, v, s.x[vi], c);
        tq[us(t)] = quality(tri_metric(s, t), c[0], c[1], c[2]);
      }
      q_ball = std::min(q_ball, tq[us(t)]);
    }
    if (q_ball >= kSmoothEnough) continue;
    if (s.smooth_failed[vi] != 0 && s.changed[vi] <= s.smooth_failed[vi]) continue;  // same ball
    neighbours(s, ball(topo.adj, v), v, nb);
    SurfaceProjection::Placed p;
    if (s.tag[vi] & kTagRidge) {
      Id line[2];
      int k = 0;
      for (Id x : nb)
        if (s.is_feature(v, x) && k < 3) line[std::min(k++, 1)] = x;
      if (k != 2) continue;
      p = s.geo->on_feature(0.5 * (s.x[us(line[0])] + s.x[us(line[1])]), s.line_hint[vi]);
    } else {
      Vec3 mean = Vec3::zero();
      for (Id x : nb) mean += s.x[us(x)];
      p = s.geo->on_surface(mean / static_cast<double>(nb.size()), s.surf_hint[vi]);
    }
    const double q_old = q_ball;
    double q_new = 1.0;
    bool ok = true;
    old_t.clear();
    new_t.clear();
    for (Id t : bv) {
      Vec3 c[3], n[3];
      corners(s, t, v, s.x[vi], c);
      corners(s, t, v, p.point, n);
      old_t.push_back({c[0], c[1], c[2]});
      new_t.push_back({n[0], n[1], n[2]});
      q_new = std::min(q_new, quality(tri_metric(s, t, v, &p.metric), n[0], n[1], n[2]));
      if (dot(tri_normal(c[0], c[1], c[2]), tri_normal(n[0], n[1], n[2])) < kCosTurn) ok = false;
      if (!ok) break;
    }
    // A real gain only: marginal moves would oscillate from pass to pass, each paying the checks.
    if (!ok || !(q_new > 1.02 * q_old) || !new_triangles_close(s, new_t, p.hint, old_t) ||
        !new_triangles_cover(s, bv, new_t, bv, cover)) {
      s.smooth_failed[vi] = s.ops;
      continue;
    }
    s.touch(bv);
    hand_over(s, bv, bv, cover);  // same triangles, moved
    s.x[vi] = p.point;
    s.m[vi] = p.metric;
    for (Id t : bv) tq[us(t)] = -1.0;
    if (s.tag[vi] & kTagRidge) s.line_hint[vi] = p.hint;
    else s.surf_hint[vi] = p.hint;
    ++count;
  }
  return count;
}

void State::compact() {
  std::vector<Id> new_id(x.size(), kNoId);
  std::vector<Id> t2;
  std::vector<std::int32_t> r2;
  std::vector<Id> h2;  // cover_head of the kept triangles (a dead one answers for no point)
  Id next = 0;
  for (std::size_t t = 0; t < num_triangles(); ++t) {
    if (tri[3 * t] == kNoId) continue;
    if (!cover_head.empty()) h2.push_back(cover_head[t]);
    for (int i = 0; i < 3; ++i) {
      const Id v = tri[3 * t + i];
      if (new_id[us(v)] == kNoId) new_id[us(v)] = next++;
    }
    t2.insert(t2.end(), {tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]});
    r2.push_back(tref[t]);
  }
  // Keep the old relative order of vertices (new_id above follows triangle order): renumber
  // by increasing old id for determinism and locality.
  next = 0;
  for (std::size_t v = 0; v < x.size(); ++v)
    if (new_id[v] != kNoId) new_id[v] = next++;
  std::vector<Vec3> x2(us(next));
  std::vector<SymMat3> m2(us(next));
  std::vector<std::uint8_t> tag2(us(next));
  std::vector<Id> sh2(us(next)), lh2(us(next));
  std::vector<std::uint32_t> ch2(us(next)), sf2(us(next));
  for (std::size_t v = 0; v < x.size(); ++v) {
    const Id n = new_id[v];
    if (n == kNoId) continue;
    x2[us(n)] = x[v];
    m2[us(n)] = m[v];
    tag2[us(n)] = tag[v];
    sh2[us(n)] = surf_hint[v];
    lh2[us(n)] = line_hint[v];
    ch2[us(n)] = changed[v];
    sf2[us(n)] = smooth_failed[v];
  }
  for (Id& v : t2) v = new_id[us(v)];
  std::unordered_map<std::uint64_t, std::int32_t> f2;
  std::unordered_map<std::uint64_t, std::uint8_t> ft2;
  for (const auto& [key, ref] : feature) {
    const auto a = static_cast<Id>(key & 0xffffffffu), b = static_cast<Id>(key >> 32);
    if (new_id[us(a)] == kNoId || new_id[us(b)] == kNoId) continue;
    f2[edge_key(new_id[us(a)], new_id[us(b)])] = ref;
    ft2[edge_key(new_id[us(a)], new_id[us(b)])] = feature_tag[key];
  }
  x.swap(x2);
  m.swap(m2);
  tag.swap(tag2);
  surf_hint.swap(sh2);
  line_hint.swap(lh2);
  changed.swap(ch2);
  smooth_failed.swap(sf2);
  tri.swap(t2);
  tref.swap(r2);
  if (!cover_head.empty()) cover_head.swap(h2);
  feature.swap(f2);
  feature_tag.swap(ft2);
}

}  // namespace riemesh::surface_detail
