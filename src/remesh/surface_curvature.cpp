#include "remesh/surface_curvature.hpp"

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

/// Collects the fit points of sector `sec` of vertex v (see the header): 1-ring, or 2-ring
/// without crossing features. `stamp`/`tstamp` are per-vertex/per-triangle marks equal to
/// `mark` when visited; `tris` and `queue` are scratch.
struct Gather {
  std::vector<Id> vstamp, tstamp, ring1stamp;
  std::vector<Id> tris, queue;
  Id mark = 0;
};

void gather_points(const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& f,
                   const SurfaceSectors& s, Id v, Id sec, Gather& g, std::vector<Vec3>& pts) {
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
  if (static_cast<int>(pts.size()) >= kMinRingPoints) return;
  // 2-ring: walk across smooth edges from the sector, keeping triangles that touch the 1-ring.
  for (std::size_t head = 0; head < g.queue.size(); ++head) {
    const auto ut = static_cast<std::size_t>(g.queue[head]);
    for (int j = 0; j < 3; ++j) {
      if (f.edge_feature[static_cast<std::size_t>(adj.elem2edge[3 * ut + j])]) continue;
      const Id nb = adj.elem2elem[3 * ut + j];
      if (nb == kNoId || g.tstamp[static_cast<std::size_t>(nb)] == g.mark) continue;
      const Id* tri = &mesh.triangles[3 * static_cast<std::size_t>(nb)];
      bool touches = false;
      for (int i = 0; i < 3; ++i) touches |= g.ring1stamp[static_cast<std::size_t>(tri[i])] == g.mark;
      if (!touches) continue;
      g.tstamp[static_cast<std::size_t>(nb)] = g.mark;
      g.queue.push_back(nb);
      for (int i = 0; i < 3; ++i) add_vertex(tri[i]);
    }
  }
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
