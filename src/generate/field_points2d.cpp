#include "generate/field_points2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "generate/cdt2d.hpp"
#include "generate/filtered_predicates2d.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/hilbert.hpp"

namespace riemesh {

namespace {

using detail::incircle_sign;
using detail::orient2d_sign;

double metric_length(const SymMat2& m, double dx, double dy) {
  return std::sqrt(m.c[0] * dx * dx + 2.0 * m.c[1] * dx * dy + m.c[2] * dy * dy);
}

/// > 0 when p lies strictly inside the circumcircle of the counter-clockwise a, b, c measured in
/// the metric m (its circumellipse): the in-circle determinant of the points mapped by L, LᵀL =
/// m, which is det L times the one with each point's lift |q − p|² replaced by (q − p)ᵀ m (q − p)
/// (BOOK.md §4, anisotropic Delaunay kernel). Double precision: it chooses the cavity, whose
/// validity (star-shaped from p) is checked exactly afterwards.
double metric_incircle(const double* a, const double* b, const double* c, const double* p,
                       const SymMat2& m) {
  const auto lift = [&](double x, double y) {
    return m.c[0] * x * x + 2.0 * m.c[1] * x * y + m.c[2] * y * y;
  };
  const double ax = a[0] - p[0], ay = a[1] - p[1], bx = b[0] - p[0], by = b[1] - p[1];
  const double cx = c[0] - p[0], cy = c[1] - p[1];
  return lift(ax, ay) * (bx * cy - cx * by) + lift(bx, by) * (cx * ay - ax * cy) +
         lift(cx, cy) * (ax * by - bx * ay);
}

/// An edge whose ends' metric lengths differ by more than this is steep: its candidates are
/// placed along the metric interpolated on it (Refiner::steep_candidates).
constexpr double kSteepRatio = 16.0;

/// The largest ratio of the metric lengths at the ends of a piece of a steep edge, and the
/// deepest bisection (pieces of 2⁻³⁰ of the edge).
constexpr double kPieceRatio = 1.1;
constexpr int kMaxPieceDepth = 30;

struct Candidate {
  double x, y;
  SymMat2 metric;
  Id hint;  // a triangle near the point
};

/// A triangulated domain with half-edge adjacency (kNoId outside), locked half-edges (boundary and
/// interface edges) and constrained Bowyer–Watson insertion.
class Refiner {
 public:
  Refiner(const Mesh& m, std::vector<SymMat2>& metrics) : metrics_(metrics) {
    xy_ = m.coords;
    tri_ = m.triangles;
    tref_ = m.tri_ref;
    tref_.resize(m.num_triangles(), 0);
    nbr_.assign(tri_.size(), kNoId);
    locked_.assign(tri_.size(), 0);
    // Twins from the mesh layer's neighbours (the triangle across the edge opposite vertex s,
    // in which the twin is the slot of the vertex off that edge); Edges found around their
    // first vertex.
    const Adjacency adj = build_face_adjacency(tri_, 3, xy_.size() / 2);
    for (std::size_t h = 0; h < tri_.size(); ++h) {
      const Id n = adj.elem2elem[h];
      if (n == kNoId) continue;
      const Id a = from(static_cast<Id>(h)), b = to(static_cast<Id>(h));
      for (int j = 0; j < 3; ++j)
        if (tri_[3 * n + j] != a && tri_[3 * n + j] != b) nbr_[h] = 3 * n + j;
    }
    for (std::size_t e = 0; e < m.num_edges(); ++e) {
      const Id a = m.edges[2 * e], b = m.edges[2 * e + 1];
      for (const Id t : ball(adj, a))
        for (int s = 0; s < 3; ++s) {
          const Id h = 3 * t + s;
          if ((from(h) == a && to(h) == b) || (from(h) == b && to(h) == a)) locked_[h] = 1;
        }
    }
    mark_.assign(num_triangles(), 0);
    fan_.assign(xy_.size() / 2, kNoId);
  }

  std::size_t num_triangles() const { return tri_.size() / 3; }
  Id from(Id h) const { return tri_[3 * (h / 3) + (h % 3 + 1) % 3]; }
  Id to(Id h) const { return tri_[3 * (h / 3) + (h % 3 + 2) % 3]; }
  const double* pt(Id v) const { return &xy_[2 * static_cast<std::size_t>(v)]; }

  /// Candidates at unit metric spacing on the edges longer than √2 (each edge once). The length
  /// is the mean of the ends' metric lengths, the points at equal steps; on a steep edge (its
  /// ends' lengths more than kSteepRatio apart) it is the length in the metric interpolated
  /// along it, the points at unit steps of that length (steep_candidates).
  std::vector<Candidate> candidates(InterpScheme scheme) const {
    std::vector<Candidate> out;
    std::vector<std::array<double, 2>> nodes;
    for (std::size_t h = 0; h < tri_.size(); ++h) {
      const Id g = nbr_[h];
      if (locked_[h] || (g != kNoId && g < static_cast<Id>(h))) continue;
      const Id a = from(static_cast<Id>(h)), b = to(static_cast<Id>(h));
      const double dx = pt(b)[0] - pt(a)[0], dy = pt(b)[1] - pt(a)[1];
      const double la = metric_length(metrics_[a], dx, dy), lb = metric_length(metrics_[b], dx, dy);
      if (std::max(la, lb) > kSteepRatio * std::min(la, lb)) {
        steep_candidates(scheme, static_cast<Id>(h), la, lb, nodes, out);
        continue;
      }
      const double len = 0.5 * (la + lb);
      if (!(len > std::sqrt(2.0))) continue;
      const int n = std::max(2, static_cast<int>(std::lround(len)));
      for (int k = 1; k < n; ++k) {
        const double t = static_cast<double>(k) / n;
        out.push_back({pt(a)[0] + t * dx, pt(a)[1] + t * dy,
                       interpolate<2>(scheme, metrics_[a], metrics_[b], t), static_cast<Id>(h / 3)});
      }
    }
    return out;
  }

  /// Inserts the candidate unless it is too close to the mesh; returns whether it was inserted.
  bool insert(const Candidate& c) {
    const double p[2] = {c.x, c.y};
    const Id t = locate(p, last_ != kNoId ? last_ : c.hint);
    if (t == kNoId) return false;
    last_ = t;  // the next candidate is near (Hilbert order), inserted or not
    // The cavity in the candidate's metric (anisotropic Delaunay), unless it is isotropic (the
    // Euclidean test decides the same, exactly); a metric cavity that p does not see whole
    // (the mesh is not Delaunay in that metric) gives way to the Euclidean one.
    // t's vertices and locked edges are on the border of any cavity grown from it: a candidate
    // too close to them (the test below) is refused before the cavity is searched, with the
    // same answer (between a fine and a coarse boundary, cavities of hundreds of needles).
    for (int s = 0; s < 3; ++s) {
      const Id v = tri_[3 * t + s], h = 3 * t + s;
      if (metric_length(c.metric, pt(v)[0] - p[0], pt(v)[1] - p[1]) < std::sqrt(0.5)) return false;
      if (locked_[h] && distance_to_edge(c.metric, p, from(h), to(h)) < 0.5) return false;
    }
    const bool isotropic = c.metric.c[1] == 0.0 && c.metric.c[0] == c.metric.c[2];
    if (!find_cavity(t, p, isotropic ? nullptr : &c.metric)) return false;
    if (!star_shaped(p) && (isotropic || !find_cavity(t, p, nullptr) || !star_shaped(p)))
      return false;  // not star-shaped (possible in a constrained triangulation): keep out
    for (const Border& b : border_) {
      if (metric_length(c.metric, pt(b.a)[0] - p[0], pt(b.a)[1] - p[1]) < std::sqrt(0.5)) return false;
      if (b.locked && distance_to_edge(c.metric, p, b.a, b.b) < 0.5) return false;
    }
    const Id v = static_cast<Id>(xy_.size() / 2);
    xy_.insert(xy_.end(), {p[0], p[1]});
    metrics_.push_back(c.metric);
    fan_.push_back(kNoId);
    fill_cavity(v);
    return true;
  }

  /// Room for `more` vertices (each adds 2 triangles): one reallocation per round instead of a
  /// doubling and a copy of every array as they grow.
  void reserve(std::size_t more) {
    const std::size_t nv = xy_.size() / 2 + more, nt = num_triangles() + 2 * more;
    xy_.reserve(2 * nv);
    metrics_.reserve(nv);
    fan_.reserve(nv);
    tri_.reserve(3 * nt);
    nbr_.reserve(3 * nt);
    locked_.reserve(3 * nt);
    tref_.reserve(nt);
    mark_.reserve(nt);
  }

  /// Moves the triangulation into m (the refiner is left empty).
  void write(Mesh& m) {
    m.coords = std::move(xy_);
    m.vert_ref.resize(m.num_vertices(), 0);
    m.vert_tag.resize(m.num_vertices(), kTagNone);
    m.triangles = std::move(tri_);
    m.tri_ref = std::move(tref_);
    m.tri_tag.assign(m.num_triangles(), kTagNone);
  }

 private:
  /// The candidates of the steep half-edge h (its ends' metric lengths la, lb): the edge's
  /// length in the metric interpolated along it, by bisection of the parameter until the lengths
  /// at the ends of each piece are within kPieceRatio (trapezoids on the pieces), and the points
  /// at equal steps of that length, n = round(length) pieces as on the other edges. The mean of
  /// the ends' lengths counts an edge from a fine boundary (size h) to a coarse one as d / 2h
  /// long, where the interpolated sizes make it log(ratio)-like: a circle of N edges inside a
  /// square of 4 gave N²/8 candidates at equal steps, every one too close to the circle or the
  /// corner in its own metric (hunt 5, F3: 1.9 M for N = 3000, 26 s).
  void steep_candidates(InterpScheme scheme, Id h, double la, double lb,
                        std::vector<std::array<double, 2>>& nodes,
                        std::vector<Candidate>& out) const {
    const Id a = from(h), b = to(h);
    const double dx = pt(b)[0] - pt(a)[0], dy = pt(b)[1] - pt(a)[1];
    const auto length = [&](double t) {
      return metric_length(interpolate<2>(scheme, metrics_[a], metrics_[b], t), dx, dy);
    };
    nodes.assign(1, {0.0, la});  // (t, metric length of the edge at t), t increasing
    // Depth-first bisection; the stack holds the right ends still to reach.
    std::array<std::array<double, 2>, kMaxPieceDepth + 1> stack;
    int top = 0;
    stack[0] = {1.0, lb};
    while (top >= 0) {
      const std::array<double, 2> lo = nodes.back(), hi = stack[top];
      const double big = std::max(lo[1], hi[1]), small = std::min(lo[1], hi[1]);
      if (top < kMaxPieceDepth && big > kPieceRatio * small) {
        const double t = 0.5 * (lo[0] + hi[0]);
        stack[++top] = {t, length(t)};
      } else {
        nodes.push_back(hi);
        --top;
      }
    }
    std::vector<double> sum(nodes.size(), 0.0);
    for (std::size_t k = 1; k < nodes.size(); ++k)
      sum[k] = sum[k - 1] + (nodes[k][0] - nodes[k - 1][0]) * 0.5 * (nodes[k][1] + nodes[k - 1][1]);
    const double len = sum.back();
    if (!(len > std::sqrt(2.0)) || !std::isfinite(len)) return;
    const int n = std::max(2, static_cast<int>(std::lround(len)));
    std::size_t piece = 1;
    for (int k = 1; k < n; ++k) {
      const double s = len * k / n;
      while (piece + 1 < nodes.size() && sum[piece] < s) ++piece;
      const double w = sum[piece] > sum[piece - 1]
                           ? std::clamp((s - sum[piece - 1]) / (sum[piece] - sum[piece - 1]), 0.0, 1.0)
                           : 0.0;
      const double t = nodes[piece - 1][0] + w * (nodes[piece][0] - nodes[piece - 1][0]);
      out.push_back({pt(a)[0] + t * dx, pt(a)[1] + t * dy,
                     interpolate<2>(scheme, metrics_[a], metrics_[b], t), static_cast<Id>(h / 3)});
    }
  }

  struct Border {
    Id a, b, outside;
    std::uint8_t locked;
  };

  /// Visibility walk; on leaving the domain or after too many steps (the triangulation is only
  /// constrained Delaunay), a scan of all triangles. kNoId if p is in no triangle.
  Id locate(const double* p, Id t) {
    const std::size_t limit = 64 + 4 * static_cast<std::size_t>(std::sqrt(double(num_triangles())));
    for (std::size_t step = 0; step < limit; ++step) {
      int cross = -1;
      for (int k = 0; k < 3 && cross < 0; ++k) {
        const int e = (k + static_cast<int>(step % 3)) % 3;
        if (orient2d_sign(pt(tri_[3 * t + (e + 1) % 3]), pt(tri_[3 * t + (e + 2) % 3]), p) < 0)
          cross = e;
      }
      if (cross < 0) return t;
      const Id g = nbr_[3 * t + cross];
      if (g == kNoId) break;
      t = g / 3;
    }
    for (std::size_t k = 0; k < num_triangles(); ++k) {
      const Id* v = &tri_[3 * k];
      if (orient2d_sign(pt(v[0]), pt(v[1]), p) >= 0 && orient2d_sign(pt(v[1]), pt(v[2]), p) >= 0 &&
          orient2d_sign(pt(v[2]), pt(v[0]), p) >= 0)
        return static_cast<Id>(k);
    }
    return kNoId;
  }

  /// Whether p sees every edge of the cavity's border from inside (exact).
  bool star_shaped(const double* p) const {
    for (const Border& b : border_)
      if (!(orient2d_sign(pt(b.a), pt(b.b), p) > 0)) return false;
    return true;
  }

  /// The triangles reachable from t without crossing a locked edge whose circumcircle contains
  /// p strictly (with `metric`: whose circumcircle in that metric, metric_incircle). False if p
  /// is on a vertex or a locked edge of t.
  bool find_cavity(Id t, const double* p, const SymMat2* metric) {
    const auto conflict = [&](const Id* v) {
      return metric ? metric_incircle(pt(v[0]), pt(v[1]), pt(v[2]), p, *metric) > 0.0
                    : incircle_sign(pt(v[0]), pt(v[1]), pt(v[2]), p) > 0;
    };
    ++stamp_;
    const std::int64_t in = 2 * stamp_, out = in + 1;
    cavity_.clear();
    border_.clear();
    for (int s = 0; s < 3; ++s) {
      const Id h = 3 * t + s;
      if (locked_[h] && orient2d_sign(pt(from(h)), pt(to(h)), p) == 0) return false;
    }
    if (!conflict(&tri_[3 * t])) return false;
    cavity_.push_back(t);
    mark_[t] = in;
    for (std::size_t k = 0; k < cavity_.size(); ++k) {
      const Id c = cavity_[k];
      for (int s = 0; s < 3; ++s) {
        const Id h = 3 * c + s, g = nbr_[h];
        if (g != kNoId && !locked_[h]) {
          const Id n = g / 3;
          if (mark_[n] == in) continue;
          if (mark_[n] != out) {
            if (conflict(&tri_[3 * n])) {
              mark_[n] = in;
              cavity_.push_back(n);
              continue;
            }
            mark_[n] = out;
          }
        }
        border_.push_back({from(h), to(h), g, locked_[h]});
      }
    }
    return true;
  }

  void fill_cavity(Id v) {
    const std::int32_t ref = tref_[cavity_[0]];
    created_.clear();
    for (std::size_t k = 0; k < border_.size(); ++k) {
      Id t;
      if (k < cavity_.size()) {
        t = cavity_[k];
      } else {
        t = static_cast<Id>(num_triangles());
        tri_.resize(tri_.size() + 3);
        nbr_.resize(nbr_.size() + 3);
        locked_.resize(locked_.size() + 3);
        tref_.push_back(ref);
        mark_.push_back(0);
      }
      const Border& b = border_[k];
      tri_[3 * t] = v, tri_[3 * t + 1] = b.a, tri_[3 * t + 2] = b.b;
      nbr_[3 * t] = b.outside;
      if (b.outside != kNoId) nbr_[b.outside] = 3 * t;
      locked_[3 * t] = b.locked, locked_[3 * t + 1] = locked_[3 * t + 2] = 0;
      tref_[t] = ref;
      fan_[b.a] = t;
      created_.push_back(t);
    }
    for (const Id t : created_) {
      const Id s = fan_[tri_[3 * t + 2]];
      nbr_[3 * t + 1] = 3 * s + 2;
      nbr_[3 * s + 2] = 3 * t + 1;
    }
    last_ = created_.back();
  }

  /// The distance in metric m from p to the segment ab (closest point in the metric).
  double distance_to_edge(const SymMat2& m, const double* p, Id a, Id b) const {
    const double ux = pt(b)[0] - pt(a)[0], uy = pt(b)[1] - pt(a)[1];
    const double wx = p[0] - pt(a)[0], wy = p[1] - pt(a)[1];
    const double uu = m.c[0] * ux * ux + 2 * m.c[1] * ux * uy + m.c[2] * uy * uy;
    const double uw = m.c[0] * ux * wx + m.c[1] * (ux * wy + uy * wx) + m.c[2] * uy * wy;
    const double s = uu > 0 ? std::clamp(uw / uu, 0.0, 1.0) : 0.0;
    return metric_length(m, wx - s * ux, wy - s * uy);
  }

  std::vector<SymMat2>& metrics_;
  std::vector<double> xy_;
  std::vector<Id> tri_, nbr_;
  std::vector<std::uint8_t> locked_;
  std::vector<std::int32_t> tref_;
  std::vector<std::int64_t> mark_;
  std::vector<Id> fan_, cavity_, created_;
  std::vector<Border> border_;
  std::int64_t stamp_ = 0;
  Id last_ = kNoId;
};

}  // namespace

namespace {

/// The rounds of field points over the whole mesh.
FieldPointStats refine_whole(Mesh& mesh, std::vector<SymMat2>& metrics, InterpScheme scheme,
                             int max_rounds) {
  FieldPointStats stats;
  Refiner r(mesh, metrics);
  for (int round = 0; round < max_rounds; ++round) {
    std::vector<Candidate> cands = r.candidates(scheme);
    if (cands.empty()) break;
    std::vector<double> xy;
    xy.reserve(2 * cands.size());
    for (const Candidate& c : cands) xy.insert(xy.end(), {c.x, c.y});
    std::size_t added = 0;
    r.reserve(cands.size());
    for (const Id k : hilbert_order(xy, 2)) {
      if (r.insert(cands[k])) ++added;
      else ++stats.rejected;
    }
    stats.inserted += added;
    stats.rounds = round + 1;
    if (added == 0) break;
  }
  r.write(mesh);
  return stats;
}

/// Per triangle: 1 when one of its edges is longer than √2 in the mean of its ends' metrics
/// (Refiner::candidates' test, locked edges included); their count.
std::vector<std::uint8_t> long_edge_triangles(const Mesh& m, const std::vector<SymMat2>& metrics,
                                              std::size_t* count) {
  std::vector<std::uint8_t> out(m.num_triangles(), 0);
  *count = 0;
  for (std::size_t h = 0; h < m.triangles.size(); ++h) {
    const auto a = static_cast<std::size_t>(m.triangles[h]);
    const auto b = static_cast<std::size_t>(m.triangles[h % 3 == 2 ? h - 2 : h + 1]);
    const double dx = m.coords[2 * b] - m.coords[2 * a],
                 dy = m.coords[2 * b + 1] - m.coords[2 * a + 1];
    const double len =
        0.5 * (metric_length(metrics[a], dx, dy) + metric_length(metrics[b], dx, dy));
    if (len > std::sqrt(2.0) && !out[h / 3]) out[h / 3] = 1, ++*count;
  }
  return out;
}

/// Adds to `in` the triangles sharing a vertex with it, `rings` times.
void grow_by_vertex_rings(const Mesh& m, std::vector<std::uint8_t>& in, int rings) {
  std::vector<std::uint8_t> touched(m.num_vertices(), 0);
  for (int r = 0; r < rings; ++r) {
    for (std::size_t t = 0; t < in.size(); ++t)
      if (in[t])
        for (int i = 0; i < 3; ++i) touched[m.triangles[3 * t + i]] = 1;
    for (std::size_t t = 0; t < in.size(); ++t)
      if (touched[m.triangles[3 * t]] || touched[m.triangles[3 * t + 1]] ||
          touched[m.triangles[3 * t + 2]])
        in[t] = 1;
  }
}

/// The rounds on the triangles of `region` alone, their outer edges and the mesh's Edges among
/// them locked (no point on them, no cavity across them), spliced back: the field points of a
/// mesh with few long edges (a unit lattice and its boundary band) without setting up the whole
/// mesh. Region triangles keep their slots in order (the others are not moved); more are appended.
FieldPointStats refine_near(Mesh& mesh, std::vector<SymMat2>& metrics, InterpScheme scheme,
                            int max_rounds, const std::vector<std::uint8_t>& region) {
  const std::size_t nv = mesh.num_vertices();
  Mesh sub;
  sub.dim = 2;
  std::vector<SymMat2> sub_metrics;
  std::vector<Id> local(nv, kNoId), global, slots;
  for (std::size_t t = 0; t < region.size(); ++t) {
    if (!region[t]) continue;
    slots.push_back(static_cast<Id>(t));
    for (int i = 0; i < 3; ++i) {
      const Id v = mesh.triangles[3 * t + i];
      if (local[v] == kNoId) {
        local[v] = static_cast<Id>(global.size());
        global.push_back(v);
        sub.coords.insert(sub.coords.end(), {mesh.coords[2 * v], mesh.coords[2 * v + 1]});
        sub.vert_ref.push_back(mesh.vert_ref[v]);
        sub.vert_tag.push_back(mesh.vert_tag[v]);
        sub_metrics.push_back(metrics[v]);
      }
      sub.triangles.push_back(local[v]);
    }
    sub.tri_ref.push_back(mesh.tri_ref[t]);
  }
  // Edges of one region triangle (its border, or the domain's boundary; the mesh layer's
  // neighbours) and the mesh's Edges between region vertices: locked.
  const Adjacency adj = build_face_adjacency(sub.triangles, 3, sub.num_vertices());
  for (std::size_t h = 0; h < sub.triangles.size(); ++h)
    if (adj.elem2elem[h] == kNoId) {
      const Id* tri = &sub.triangles[h - h % 3];
      sub.edges.insert(sub.edges.end(), {tri[kTriEdge[h % 3][0]], tri[kTriEdge[h % 3][1]]});
    }
  for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
    const Id a = local[mesh.edges[2 * e]], b = local[mesh.edges[2 * e + 1]];
    if (a != kNoId && b != kNoId) sub.edges.insert(sub.edges.end(), {a, b});
  }
  sub.edge_ref.assign(sub.num_edges(), 0);
  sub.edge_tag.assign(sub.num_edges(), kTagNone);
  const FieldPointStats stats = refine_whole(sub, sub_metrics, scheme, max_rounds);
  // Splice: the new vertices after the mesh's, the region's triangles in their slots, then more.
  const std::size_t n0 = global.size();
  const auto id = [&](Id v) {
    return static_cast<std::size_t>(v) < n0 ? global[v] : static_cast<Id>(nv + (v - n0));
  };
  // (Exact room: appending to full arrays would double them.)
  const std::size_t more = sub.num_vertices() - n0;
  const std::size_t extra = sub.num_triangles() - std::min(sub.num_triangles(), slots.size());
  mesh.coords.reserve(mesh.coords.size() + 2 * more);
  mesh.vert_ref.reserve(mesh.vert_ref.size() + more);
  mesh.vert_tag.reserve(mesh.vert_tag.size() + more);
  metrics.reserve(metrics.size() + more);
  mesh.triangles.reserve(mesh.triangles.size() + 3 * extra);
  mesh.tri_ref.reserve(mesh.tri_ref.size() + extra);
  for (std::size_t v = n0; v < sub.num_vertices(); ++v) {
    mesh.coords.insert(mesh.coords.end(), {sub.coords[2 * v], sub.coords[2 * v + 1]});
    mesh.vert_ref.push_back(sub.vert_ref[v]);
    mesh.vert_tag.push_back(sub.vert_tag[v]);
    metrics.push_back(sub_metrics[v]);
  }
  for (std::size_t t = 0; t < sub.num_triangles(); ++t) {
    const Id tri[3] = {id(sub.triangles[3 * t]), id(sub.triangles[3 * t + 1]),
                       id(sub.triangles[3 * t + 2])};
    if (t < slots.size()) {
      std::copy_n(tri, 3, &mesh.triangles[3 * static_cast<std::size_t>(slots[t])]);
      mesh.tri_ref[static_cast<std::size_t>(slots[t])] = sub.tri_ref[t];
    } else {
      mesh.triangles.insert(mesh.triangles.end(), tri, tri + 3);
      mesh.tri_ref.push_back(sub.tri_ref[t]);
    }
  }
  mesh.tri_tag.assign(mesh.num_triangles(), kTagNone);
  return stats;
}

/// Vertex rings around the triangles with a long edge that refine_near takes: cavities of unit
/// meshes stay within a ring or two.
constexpr int kNearRings = 3;

}  // namespace

FieldPointStats insert_field_points2d(Mesh& mesh, std::vector<SymMat2>& metrics,
                                      InterpScheme scheme, int max_rounds) {
  RIEMESH_CHECK(mesh.dim == 2 && metrics.size() == mesh.num_vertices());
  // Refiner::write's sizes, whatever the path.
  mesh.vert_ref.resize(mesh.num_vertices(), 0);
  mesh.vert_tag.resize(mesh.num_vertices(), kTagNone);
  mesh.tri_ref.resize(mesh.num_triangles(), 0);
  std::size_t seeds = 0;
  std::vector<std::uint8_t> near = long_edge_triangles(mesh, metrics, &seeds);
  if (seeds == 0) {  // (a unit lattice)
    mesh.tri_tag.assign(mesh.num_triangles(), kTagNone);
    return {};
  }
  // Long edges in a small part of the mesh (the band between a unit lattice and the boundary):
  // the rounds around them only.
  if (seeds * 16 < mesh.num_triangles()) {
    grow_by_vertex_rings(mesh, near, kNearRings);
    return refine_near(mesh, metrics, scheme, max_rounds, near);
  }
  return refine_whole(mesh, metrics, scheme, max_rounds);
}

}  // namespace riemesh
