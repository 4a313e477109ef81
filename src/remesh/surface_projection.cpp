#include "remesh/surface_projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_metric.hpp"

namespace riemesh {
namespace {

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

/// Barycentric coordinates (u, v) of q (a point of triangle abc) on b and c.
Vec2 barycentric(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, d = q - a;
  const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
  const double det = d11 * d22 - d12 * d12;
  if (!(det > 0.0)) return {{0.0, 0.0}};
  const double r1 = dot(d, e1), r2 = dot(d, e2);
  double u = (d22 * r1 - d12 * r2) / det, v = (d11 * r2 - d12 * r1) / det;
  u = std::clamp(u, 0.0, 1.0);
  v = std::clamp(v, 0.0, 1.0 - u);
  return {{u, v}};
}

/// The feature edges of the input as degenerate triangles (a, b, b), for a TriangleTree.
Mesh line_mesh(const Mesh& mesh, const std::vector<Id>& line_edges) {
  Mesh m;
  m.dim = 3;
  m.coords = mesh.coords;
  for (std::size_t e = 0; 2 * e < line_edges.size(); ++e)
    m.triangles.insert(m.triangles.end(), {line_edges[2 * e], line_edges[2 * e + 1],
                                           line_edges[2 * e + 1]});
  return m;
}

}  // namespace

SurfaceProjection::SurfaceProjection(const Mesh& input, const FeatureOptions& features,
                                     std::vector<SymMat3> metric, double max_lift)
    : SurfaceProjection(
          input, features,
          [&metric](const Mesh&, const Adjacency&, const SurfaceFeatures&,
                    const std::vector<VertexCurvature>&) { return std::move(metric); },
          max_lift) {}

SurfaceProjection::SurfaceProjection(const Mesh& input, const FeatureOptions& features,
                                     const MetricFromAnalysis& metric, double max_lift)
    : mesh_(input),
      adj_(build_adjacency(mesh_)),
      features_(detect_features(mesh_, adj_, features)),
      sectors_(surface_sectors(mesh_, adj_, features_)),
      tri_tree_(mesh_),
      max_lift_(max_lift) {
  const std::vector<VertexCurvature> fits = sector_curvatures(mesh_, adj_, features_, sectors_);
  metric_ = metric(mesh_, adj_, features_, vertex_curvatures(mesh_.num_vertices(), sectors_, fits));
  if (metric_.size() != mesh_.num_vertices())
    throw InputError("SurfaceProjection: one metric per input vertex expected");
  sectors_.normal = fitted_sector_normals(sectors_, fits);
  rec_ = std::make_unique<SurfaceReconstruction>(mesh_, adj_, features_, sectors_);
  for (std::size_t e = 0; e < adj_.num_edges(); ++e)
    if (features_.edge_feature[e])
      line_edges_.insert(line_edges_.end(), {adj_.edges[2 * e], adj_.edges[2 * e + 1]});
  if (!line_edges_.empty())
    line_tree_ = std::make_unique<TriangleTree>(line_mesh(mesh_, line_edges_));
}

namespace {

/// The smallest size of metric m in the plane of the triangle (a, b, c): 1 / sqrt of the largest
/// eigenvalue of its restriction to the plane (the 3D remesher's boundary metrics are fine
/// across the surface, which the lattice on it has nothing to do with).
double in_plane_size(const SymMat3& m, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = cross(b - a, c - a);
  if (!(norm(n) > 0.0)) return std::numeric_limits<double>::infinity();
  const double largest = largest_in_plane(m, n);
  return largest > 0.0 ? 1.0 / std::sqrt(largest) : std::numeric_limits<double>::infinity();
}

}  // namespace

std::vector<int> SurfaceProjection::lattice_orders() const {
  // Per triangle: 4 k, k the smallest integer with spacing (longest edge / 4 k) at most half the
  // smallest in-plane size of its vertices' metrics, up to 8 (order 32). An input triangle much
  // larger than the output's (a coarse input refined) was checked at 4 points a side only, and a
  // denser sampling found input points 1.23 hausd from the output (the rotor at 0.05%).
  std::vector<int> order(mesh_.num_triangles(), kCheckOrder);
  if (metric_.size() != mesh_.num_vertices()) return order;
  for (std::size_t t = 0; t < mesh_.num_triangles(); ++t) {
    const Vec3 a = vertex_at(mesh_, mesh_.triangles[3 * t]);
    const Vec3 b = vertex_at(mesh_, mesh_.triangles[3 * t + 1]);
    const Vec3 c = vertex_at(mesh_, mesh_.triangles[3 * t + 2]);
    const double longest = std::max({norm(b - a), norm(c - b), norm(a - c)});
    double size = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k)
      size = std::min(
          size,
          in_plane_size(metric_[static_cast<std::size_t>(mesh_.triangles[3 * t + k])], a, b, c));
    const double ratio = longest / (0.5 * kCheckOrder * size);
    const int k = ratio > 1.0 ? static_cast<int>(std::min(std::ceil(ratio), 8.0)) : 1;
    order[t] = kCheckOrder * k;
  }
  return order;
}

void SurfaceProjection::check_points_by_triangle(std::vector<Vec3>& pts,
                                                 std::vector<Id>* owner) const {
  // The lattice of order n on every input triangle (vertices, n - 1 points per edge, the
  // interior points), each point once; n is a multiple of 4 (lattice_orders), so that the
  // points `riemesh distance` samples on the input by default (order 4) are among them and the
  // A -> B check of the operators (surface_ops.cpp) bounds what it measures. An edge takes the
  // larger order of its triangles. Owner: an input triangle the point lies on (a vertex's
  // first, an edge's first by id).
  const std::vector<int> order = lattice_orders();
  std::vector<int> edge_order(adj_.num_edges(), kCheckOrder);
  for (std::size_t k = 0; k < adj_.elem2edge.size(); ++k) {
    int& n = edge_order[static_cast<std::size_t>(adj_.elem2edge[k])];
    n = std::max(n, order[k / 3]);
  }
  std::size_t count = mesh_.num_vertices();
  for (const int n : edge_order) count += static_cast<std::size_t>(n - 1);
  for (const int n : order) count += static_cast<std::size_t>((n - 1) * (n - 2) / 2);
  pts.clear();
  pts.reserve(count);
  if (owner) {
    owner->clear();
    owner->reserve(count);
  }
  for (std::size_t v = 0; v < mesh_.num_vertices(); ++v) {
    const auto b = ball(adj_, static_cast<Id>(v));
    if (b.empty()) continue;
    pts.push_back(vertex_at(mesh_, static_cast<Id>(v)));
    if (owner) owner->push_back(b[0]);
  }
  std::vector<Id> edge_owner;
  if (owner) {
    edge_owner.assign(adj_.num_edges(), kNoId);
    for (std::size_t k = adj_.elem2edge.size(); k-- > 0;)
      edge_owner[static_cast<std::size_t>(adj_.elem2edge[k])] = static_cast<Id>(k / 3);
  }
  for (std::size_t e = 0; e < adj_.num_edges(); ++e) {
    const Vec3 a = vertex_at(mesh_, adj_.edges[2 * e]), b = vertex_at(mesh_, adj_.edges[2 * e + 1]);
    const int n = edge_order[e];
    for (int i = 1; i < n; ++i) {
      pts.push_back(a + (static_cast<double>(i) / n) * (b - a));
      if (owner) owner->push_back(edge_owner[e]);
    }
  }
  for (std::size_t t = 0; t < mesh_.num_triangles(); ++t) {
    const Vec3 a = vertex_at(mesh_, mesh_.triangles[3 * t]);
    const Vec3 b = vertex_at(mesh_, mesh_.triangles[3 * t + 1]);
    const Vec3 c = vertex_at(mesh_, mesh_.triangles[3 * t + 2]);
    const int n = order[t];
    for (int i = 1; i < n; ++i)
      for (int j = 1; i + j < n; ++j) {
        pts.push_back(a + (static_cast<double>(i) / n) * (b - a) + (static_cast<double>(j) / n) * (c - a));
        if (owner) owner->push_back(static_cast<Id>(t));
      }
  }
}

void SurfaceProjection::build_grid() const {
  std::vector<Vec3> pts;
  check_points_by_triangle(pts, nullptr);
  Vec3 lo = pts[0], hi = pts[0];
  for (const Vec3& p : pts)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], p[c]);
      hi[c] = std::max(hi[c], p[c]);
    }
  // About 4 points per occupied cell of a surface: cell ~ 2 sqrt(area / points).
  double area = 0.0;
  for (std::size_t t = 0; t < mesh_.num_triangles(); ++t) {
    const Vec3 a = vertex_at(mesh_, mesh_.triangles[3 * t]);
    area += 0.5 * norm(cross(vertex_at(mesh_, mesh_.triangles[3 * t + 1]) - a,
                             vertex_at(mesh_, mesh_.triangles[3 * t + 2]) - a));
  }
  const double ext = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300});
  grid_.cell = std::max(2.0 * std::sqrt(area / static_cast<double>(pts.size())), ext / 256.0);
  grid_.lo = lo;
  grid_.nx = static_cast<int>((hi[0] - lo[0]) / grid_.cell) + 1;
  grid_.ny = static_cast<int>((hi[1] - lo[1]) / grid_.cell) + 1;
  grid_.nz = static_cast<int>((hi[2] - lo[2]) / grid_.cell) + 1;
  const std::size_t ncell = static_cast<std::size_t>(grid_.nx) * grid_.ny * grid_.nz;
  auto cell_of = [&](const Vec3& p) {
    const int i = std::min(grid_.nx - 1, static_cast<int>((p[0] - lo[0]) / grid_.cell));
    const int j = std::min(grid_.ny - 1, static_cast<int>((p[1] - lo[1]) / grid_.cell));
    const int k = std::min(grid_.nz - 1, static_cast<int>((p[2] - lo[2]) / grid_.cell));
    return (static_cast<std::size_t>(k) * grid_.ny + j) * grid_.nx + i;
  };
  grid_.offsets.assign(ncell + 1, 0);
  for (const Vec3& p : pts) ++grid_.offsets[cell_of(p) + 1];
  for (std::size_t c = 0; c < ncell; ++c) grid_.offsets[c + 1] += grid_.offsets[c];
  grid_.points.resize(pts.size());
  std::vector<Id> fill(grid_.offsets.begin(), grid_.offsets.end() - 1);
  for (const Vec3& p : pts) grid_.points[static_cast<std::size_t>(fill[cell_of(p)]++)] = p;
}

void SurfaceProjection::check_points(const Vec3& lo, const Vec3& hi, std::vector<Vec3>& out) const {
  std::call_once(grid_once_, [this] { build_grid(); });
  int a[3], b[3];
  const int n[3] = {grid_.nx, grid_.ny, grid_.nz};
  for (int c = 0; c < 3; ++c) {
    a[c] =
        std::clamp(static_cast<int>(std::floor((lo[c] - grid_.lo[c]) / grid_.cell)), 0, n[c] - 1);
    b[c] =
        std::clamp(static_cast<int>(std::floor((hi[c] - grid_.lo[c]) / grid_.cell)), 0, n[c] - 1);
    if (hi[c] < grid_.lo[c] || lo[c] > grid_.lo[c] + n[c] * grid_.cell) return;
  }
  // The cells i = a[0] .. b[0] of a row (j, k) hold consecutive points: one range per row (most
  // cells of a box around a piece of surface are empty).
  for (int k = a[2]; k <= b[2]; ++k)
    for (int j = a[1]; j <= b[1]; ++j) {
      const std::size_t row = (static_cast<std::size_t>(k) * grid_.ny + j) * grid_.nx;
      const Id end = grid_.offsets[row + b[0] + 1];
      for (Id q = grid_.offsets[row + a[0]]; q < end; ++q) {
        const Vec3& p = grid_.points[static_cast<std::size_t>(q)];
        if (p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] &&
            p[2] <= hi[2])
          out.push_back(p);
      }
    }
}

bool SurfaceProjection::within(const Vec3& p, double r, Id* hint) const {
  // Steps of the walk before the tree takes over: a new triangle's lattice points are a
  // fraction of its edge apart, a few input triangles at most on a finely faceted input.
  constexpr int kMaxSteps = 6;
  const double r2 = r * r;
  Id t = hint ? *hint : kNoId, prev = kNoId;
  for (int step = 0; step < kMaxSteps && t != kNoId && static_cast<std::size_t>(t) < tri_tree_.num_triangles();
       ++step) {
    const TriangleProbe& tp = tri_tree_.probe(t);
    if (!tp.flat) {
      if (tp.within(p, r, r2)) {
        *hint = t;
        return true;
      }
      break;
    }
    // TriangleProbe::within, with the edge distances kept for the step.
    const Vec3 pa = p - tp.a;
    const bool near_plane = std::abs(dot(pa, tp.n)) <= r;
    const double s[3] = {dot(pa, tp.inward[0]), dot(p - tp.b, tp.inward[1]),
                         dot(p - tp.c, tp.inward[2])};
    if (near_plane && s[0] >= -r && s[1] >= -r && s[2] >= -r) {
      bool in = s[0] >= 0.0 && s[1] >= 0.0 && s[2] >= 0.0;
      if (!in) {
        const Vec3 d = p - tp.closest(p);
        in = dot(d, d) <= r2;
      }
      if (in) {
        *hint = t;
        return true;
      }
    }
    // Across the edge whose line p is farthest outside of: edges ab, bc, ca are the faces
    // opposite c, a, b (adjacency.hpp numbering).
    int e = 0;
    for (int k = 1; k < 3; ++k)
      if (s[k] < s[e]) e = k;
    if (s[e] >= 0.0) break;  // above the inside but too far from the plane
    const Id next = adj_.elem2elem[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>((e + 2) % 3)];
    if (next == prev) break;
    prev = t;
    t = next;
  }
  return tri_tree_.within(p, r, hint);
}

Vec3 SurfaceProjection::lift(const Vec3& flat, const Vec3& smooth) const {
  const Vec3 d = smooth - flat;
  const double l = norm(d);
  return l <= max_lift_ ? smooth : flat + (max_lift_ / l) * d;
}

SurfaceProjection::Placed SurfaceProjection::on_surface(const Vec3& p, Id hint, bool smooth) const {
  const TriangleTree::Nearest q = tri_tree_.nearest(p, hint);
  const auto t = static_cast<std::size_t>(q.triangle);
  const Id* tri = &mesh_.triangles[3 * t];
  const Vec2 uv = barycentric(q.point, vertex_at(mesh_, tri[0]), vertex_at(mesh_, tri[1]),
                              vertex_at(mesh_, tri[2]));
  Placed out;
  out.point = smooth ? lift(q.point, rec_->point(q.triangle, uv[0], uv[1])) : q.point;
  out.metric = (1.0 - uv[0] - uv[1]) * metric_[static_cast<std::size_t>(tri[0])] +
               uv[0] * metric_[static_cast<std::size_t>(tri[1])] +
               uv[1] * metric_[static_cast<std::size_t>(tri[2])];
  out.hint = q.triangle;
  return out;
}

SurfaceProjection::Placed SurfaceProjection::on_feature(const Vec3& p, Id hint, bool smooth) const {
  if (!line_tree_) return on_surface(p, kNoId, smooth);
  const TriangleTree::Nearest q = line_tree_->nearest(p, hint);
  const auto e = static_cast<std::size_t>(q.triangle);
  const Id a = line_edges_[2 * e], b = line_edges_[2 * e + 1];
  const Vec3 pa = vertex_at(mesh_, a), pb = vertex_at(mesh_, b);
  const double l2 = dot(pb - pa, pb - pa);
  const double s = l2 > 0.0 ? std::clamp(dot(q.point - pa, pb - pa) / l2, 0.0, 1.0) : 0.0;
  Placed out;
  out.point = smooth ? lift(q.point, rec_->edge_point(a, b, s)) : q.point;
  out.metric = (1.0 - s) * metric_[static_cast<std::size_t>(a)] + s * metric_[static_cast<std::size_t>(b)];
  out.hint = q.triangle;
  return out;
}

}  // namespace riemesh
