#include "remesh/surface_curvature.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

#include "core/dense_solve.hpp"
#include "core/eigen.hpp"
#include "core/error.hpp"

namespace riemesh {
namespace {

constexpr int kUnknowns = 5;  // a b c d e of z = a x² + b xy + c y² + d x + e y
constexpr double kBalancedSpread = 1.0 / 9.0;          // second moments within 1:9 (extents 1:3)
constexpr double kBalanceCosine = 0.8660254037844386;  // cos 30°
constexpr std::size_t kMaxFitPoints = 200;
constexpr double kReach = 1.5;  // the balanced gather reaches 1.5x the farthest 1-ring point

SurfaceGeometry flat_geometry(const Vec3& n, const Vec3& t1, const Vec3& t2) {
  SurfaceGeometry g{};
  g.normal = n;
  g.w1 = t1;
  g.w2 = t2;
  g.k1 = g.k2 = 0.0;
  g.rho1 = g.rho2 = std::numeric_limits<double>::infinity();
  g.first_form = SymMat2::identity();
  g.second_form = SymMat2::zero();
  g.w1_uv = Vec2::unit(0);
  g.w2_uv = Vec2::unit(1);
  return g;
}

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

/// Scratch of the gathering of fit points (see the header): `vstamp`/`tstamp` are per-vertex/
/// per-triangle marks equal to `mark` when visited, `ring1stamp` marks the 1-ring's vertices;
/// `queue` holds the triangles taken.
struct Gather {
  std::vector<Id> vstamp, tstamp, ring1stamp;
  std::vector<Id> queue;
  Id mark = 0;
};

/// The vertices of the sector's triangles (its 1-ring); the triangles go to g.queue.
void gather_ring1(const Mesh& mesh, const Adjacency& adj, const SurfaceSectors& s, Id v, Id sec,
                  Gather& g, std::vector<Vec3>& pts) {
  ++g.mark;
  pts.clear();
  g.queue.clear();
  auto add_vertex = [&](Id w) {
    if (w == v || g.vstamp[static_cast<std::size_t>(w)] == g.mark) return;
    g.vstamp[static_cast<std::size_t>(w)] = g.mark;
    pts.push_back(vertex_at(mesh, w));
  };
  for (Id t : ball(adj, v)) {
    const auto ut = static_cast<std::size_t>(t);
    const int iv = local_index(&mesh.triangles[3 * ut], 3, v);
    if (s.corner2sector[3 * ut + iv] != sec) continue;
    g.tstamp[ut] = g.mark;
    g.queue.push_back(t);
    for (int i = 0; i < 3; ++i) {
      const Id w = mesh.triangles[3 * ut + i];
      g.ring1stamp[static_cast<std::size_t>(w)] = g.mark;
      add_vertex(w);
    }
  }
}

/// What a walk does with a triangle it reaches (walk_smooth).
enum class Step { kSkip, kTake, kDrop, kStop };

/// Breadth-first from the triangles in g.queue across smooth edges: visit(nb) for each triangle
/// not yet stamped, which answers kSkip (left unstamped: another path may take it), kTake
/// (stamped and queued), kDrop (stamped, not queued) or kStop (end of the walk).
template <class Visit>
void walk_smooth(const Adjacency& adj, const SurfaceFeatures& f, Gather& g, Visit visit) {
  for (std::size_t head = 0; head < g.queue.size(); ++head) {
    const auto ut = static_cast<std::size_t>(g.queue[head]);
    for (int j = 0; j < 3; ++j) {
      if (f.edge_feature[static_cast<std::size_t>(adj.elem2edge[3 * ut + j])]) continue;
      const Id nb = adj.elem2elem[3 * ut + j];
      if (nb == kNoId || g.tstamp[static_cast<std::size_t>(nb)] == g.mark) continue;
      const Step step = visit(nb);
      if (step == Step::kSkip) continue;
      g.tstamp[static_cast<std::size_t>(nb)] = g.mark;
      if (step == Step::kStop) return;
      if (step == Step::kTake) g.queue.push_back(nb);
    }
  }
}

/// The 2-ring: a walk across smooth edges from the sector, keeping triangles that touch the
/// 1-ring.
void gather_ring2(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& f, Id v, Gather& g,
                  std::vector<Vec3>& pts) {
  walk_smooth(adj, f, g, [&](Id nb) {
    const Id* tri = &mesh.triangles[3 * static_cast<std::size_t>(nb)];
    bool touches = false;
    for (int i = 0; i < 3; ++i) touches |= g.ring1stamp[static_cast<std::size_t>(tri[i])] == g.mark;
    if (!touches) return Step::kSkip;
    for (int i = 0; i < 3; ++i) {
      const Id w = tri[i];
      if (w == v || g.vstamp[static_cast<std::size_t>(w)] == g.mark) continue;
      g.vstamp[static_cast<std::size_t>(w)] = g.mark;
      pts.push_back(vertex_at(mesh, w));
    }
    return Step::kTake;
  });
}

/// Ratio of the smaller to the larger second moment of the points' offsets in the plane
/// orthogonal to n (1: spread evenly, 0: along a line).
struct TangentSpread {
  Vec3 t1, t2;
  double uu = 0.0, uv = 0.0, vv = 0.0;
  void add(const Vec3& d) {
    const double u = dot(d, t1), v = dot(d, t2);
    uu += u * u;
    uv += u * v;
    vv += v * v;
  }
  double ratio() const {
    const double half_trace = 0.5 * (uu + vv);
    const double r = std::hypot(0.5 * (uu - vv), uv);
    return half_trace > 0.0 ? (half_trace - r) / (half_trace + r) : 0.0;
  }
};

TangentSpread tangent_spread(const Vec3& p, const Vec3& n, const std::vector<Vec3>& pts) {
  TangentSpread spread;
  detail::orthonormal_complement(n, 1.0, spread.t1, spread.t2);
  for (const Vec3& q : pts) spread.add(q - p);
  return spread;
}

/// The 1-ring of stretched triangles spreads along one direction, and so does their 2-ring: the
/// quadric's term across it is then set by the points' tiny offsets that way and takes up the
/// model's residual along the other (a 10-sided prism in rows of height 0.01: curvature 570
/// instead of 1). Instead of the 2-ring, the gather goes on from the 1-ring across smooth edges,
/// within 1.5 times the distance of the farthest 1-ring point and over triangles whose normal is
/// within 30° of n, until the spread is even or kMaxFitPoints are taken.
void balance_points(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& f, Id v,
                    const Vec3& n, TangentSpread& spread, Gather& g, std::vector<Vec3>& pts) {
  const Vec3 p = vertex_at(mesh, v);
  double reach2 = 0.0;
  for (const Vec3& q : pts) reach2 = std::max(reach2, dot(q - p, q - p));
  reach2 *= kReach * kReach;
  walk_smooth(adj, f, g, [&](Id nb) {
    const Id* tri = &mesh.triangles[3 * static_cast<std::size_t>(nb)];
    const Vec3 a = vertex_at(mesh, tri[0]), b = vertex_at(mesh, tri[1]),
               c = vertex_at(mesh, tri[2]);
    const Vec3 tn = cross(b - a, c - a);
    if (!(std::abs(dot(tn, n)) >= kBalanceCosine * norm(tn))) return Step::kDrop;  // either side
    bool near = false;
    for (int i = 0; i < 3; ++i) {
      const Id w = tri[i];
      const Vec3 d = vertex_at(mesh, w) - p;
      if (dot(d, d) > reach2) continue;
      near = true;
      if (w == v || g.vstamp[static_cast<std::size_t>(w)] == g.mark) continue;
      g.vstamp[static_cast<std::size_t>(w)] = g.mark;
      pts.push_back(p + d);
      spread.add(d);
      if (spread.ratio() >= kBalancedSpread || pts.size() >= kMaxFitPoints) return Step::kStop;
    }
    return near ? Step::kTake : Step::kDrop;
  });
}

void gather_points(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& f,
                   const SurfaceSectors& s, Id v, Id sec, Gather& g, std::vector<Vec3>& pts) {
  gather_ring1(mesh, adj, s, v, sec, g, pts);
  const Vec3& n = s.normal[static_cast<std::size_t>(sec)];
  if (dot(n, n) > 0.0 && !pts.empty()) {
    TangentSpread spread = tangent_spread(vertex_at(mesh, v), n, pts);
    if (spread.ratio() < kBalancedSpread) {
      balance_points(mesh, adj, f, v, n, spread, g, pts);
      return;
    }
  }
  if (static_cast<int>(pts.size()) < kMinRingPoints) gather_ring2(mesh, adj, f, v, g, pts);
}

}  // namespace

VertexCurvature fit_quadric(const Vec3& p, const Vec3& n_in, const std::vector<Vec3>& q) {
  const bool has_normal = dot(n_in, n_in) > 0.0;  // zero for a sector of degenerate triangles
  const Vec3 n = has_normal ? n_in : Vec3::unit(2);
  Vec3 t1, t2;
  detail::orthonormal_complement(n, 1.0, t1, t2);
  VertexCurvature out;
  out.geometry = flat_geometry(n, t1, t2);
  out.points = static_cast<int>(q.size());
  if (!has_normal || static_cast<int>(q.size()) < kUnknowns) return out;
  double len = 0.0;
  for (const Vec3& x : q) len += norm(x - p);
  len /= static_cast<double>(q.size());
  if (!(len > 0.0)) return out;
  double a[kUnknowns][kUnknowns] = {}, r[kUnknowns] = {};
  for (const Vec3& x : q) {
    const Vec3 d = (x - p) / len;
    const double u = dot(d, t1), v = dot(d, t2), z = dot(d, n);
    const double phi[kUnknowns] = {u * u, u * v, v * v, u, v};
    for (int i = 0; i < kUnknowns; ++i) {
      for (int j = i; j < kUnknowns; ++j) a[i][j] += phi[i] * phi[j];
      r[i] += phi[i] * z;
    }
  }
  for (int i = 0; i < kUnknowns; ++i)  // symmetric: the same sums (a product commutes exactly)
    for (int j = 0; j < i; ++j) a[i][j] = a[j][i];
  if (!solve_dense(a, r)) return out;
  // Back to unscaled coordinates: z = len·z'(x/len, y/len) divides the quadratic terms by len.
  const double qa = r[0] / len, qb = r[1] / len, qc = r[2] / len, qd = r[3], qe = r[4];
  const SurfaceGeometry g = surface_geometry({{1.0, 0.0, qd}}, {{0.0, 1.0, qe}},
                                             {{0.0, 0.0, 2.0 * qa}}, {{0.0, 0.0, qb}},
                                             {{0.0, 0.0, 2.0 * qc}});
  auto to_space = [&](const Vec3& l) { return l[0] * t1 + l[1] * t2 + l[2] * n; };
  out.geometry = g;
  out.geometry.normal = to_space(g.normal);
  out.geometry.w1 = normalize(to_space(g.w1));
  out.geometry.w2 = normalize(to_space(g.w2));
  out.fitted = true;
  return out;
}

namespace {

Gather make_gather(const Mesh& mesh) {
  Gather g;
  g.vstamp.assign(mesh.num_vertices(), 0);
  g.ring1stamp.assign(mesh.num_vertices(), 0);
  g.tstamp.assign(mesh.num_triangles(), 0);
  return g;
}

void require_built(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& features,
                   const SurfaceSectors& sectors) {
  if (features.edge_feature.size() != adj.num_edges() ||
      sectors.corner2sector.size() != mesh.triangles.size())
    throw InputError("surface curvature: features or sectors not built from this mesh");
}

}  // namespace

std::vector<VertexCurvature> sector_curvatures(const Mesh& mesh, const Adjacency& adj,
                                               const SurfaceFeatures& features,
                                               const SurfaceSectors& sectors) {
  require_built(mesh, adj, features, sectors);
  std::vector<VertexCurvature> out(sectors.num_sectors());
  Gather g = make_gather(mesh);
  std::vector<Vec3> pts;
  for (std::size_t sec = 0; sec < sectors.num_sectors(); ++sec) {
    const Id v = sectors.sector2vert[sec];
    gather_points(mesh, adj, features, sectors, v, static_cast<Id>(sec), g, pts);
    out[sec] = fit_quadric(vertex_at(mesh, v), sectors.normal[sec], pts);
  }
  return out;
}

std::vector<Vec3> fitted_sector_normals(const SurfaceSectors& sectors,
                                        const std::vector<VertexCurvature>& fits) {
  std::vector<Vec3> n = sectors.normal;
  for (std::size_t sec = 0; sec < sectors.num_sectors(); ++sec)
    if (fits[sec].fitted) n[sec] = normalize(fits[sec].geometry.normal);
  return n;
}

std::vector<Vec3> fitted_sector_normals(const Mesh& mesh, const Adjacency& adj,
                                        const SurfaceFeatures& features,
                                        const SurfaceSectors& sectors) {
  return fitted_sector_normals(sectors, sector_curvatures(mesh, adj, features, sectors));
}

std::vector<VertexCurvature> vertex_curvatures(std::size_t num_vertices, const SurfaceSectors& sectors,
                                               const std::vector<VertexCurvature>& fits) {
  // Vertices of no triangle keep a flat frame (zero curvature, not fitted).
  VertexCurvature unused;
  unused.geometry = flat_geometry(Vec3::unit(2), Vec3::unit(0), Vec3::unit(1));
  std::vector<VertexCurvature> out(num_vertices, unused);
  std::size_t sec = 0;
  for (std::size_t v = 0; v < num_vertices; ++v) {
    bool first = true;
    // Sectors of a vertex are numbered consecutively (surface_sectors).
    for (; sec < sectors.num_sectors() && sectors.sector2vert[sec] == static_cast<Id>(v); ++sec) {
      const VertexCurvature& c = fits[sec];
      if (first || std::abs(c.geometry.k1) > std::abs(out[v].geometry.k1)) out[v] = c;
      first = false;
    }
  }
  return out;
}

std::vector<VertexCurvature> vertex_curvatures(const Mesh& mesh, const Adjacency& adj,
                                               const SurfaceFeatures& features,
                                               const SurfaceSectors& sectors) {
  return vertex_curvatures(mesh.num_vertices(), sectors,
                           sector_curvatures(mesh, adj, features, sectors));
}

}  // namespace riemesh
