#include "remesh/surface_metric.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "mesh/distance.hpp"
#include "metric/geometric.hpp"
#include "metric/intersection.hpp"

namespace riemesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

Vec3 vertex_at(const Mesh& mesh, Id v) {
  const double* p = &mesh.coords[3 * static_cast<std::size_t>(v)];
  return {{p[0], p[1], p[2]}};
}

/// Chord length on a circle of radius ρ whose gap to the arc is hausd: 2 sqrt(hausd(2ρ − hausd)),
/// 2ρ when hausd >= ρ (the chord cannot deviate by more than ρ from a half circle).
double chord_for_gap(double rho, double hausd) {
  if (std::isinf(rho)) return kInf;
  return hausd >= rho ? 2.0 * rho : 2.0 * std::sqrt(hausd * (2.0 * rho - hausd));
}

/// The metric of one vertex from its curvature (before the feature line).
SymMat3 vertex_metric(const SurfaceGeometry& g, const SurfaceMetricOptions& o, double hmin,
                      double hmax) {
  if (std::isinf(g.rho1)) return SymMat3::diagonal(1.0 / (hmax * hmax));
  GeometricTolerance tol;
  tol.kind = GeometricTolerance::kRelativeGap;
  tol.value = std::min(1.0, o.hausd / g.rho1);
  if (!o.anisotropic) return surface_metric_isotropic(g, tol, hmin, hmax);
  return surface_metric_anisotropic(g, tol, hmin, hmax, o.beta_fraction);
}

/// Smallest and largest principal sizes of a metric.
void principal_sizes(const SymMat3& m, double& smallest, double& largest) {
  const SymEigen<3> e = eigen(m);
  smallest = std::min(smallest, 1.0 / std::sqrt(e.values[2]));
  largest = std::max(largest, 1.0 / std::sqrt(e.values[0]));
}

}  // namespace

void SurfaceMetricOptions::validate() const {
  // Named by the options of `riemesh metric geometric` and `adapt`, with the value (they said
  // "hmin must be <= hmax", and a negative --hgrad passed as "no gradation").
  if (!(hausd > 0.0) || !std::isfinite(hausd))
    throw InputError("--hausd must be a distance > 0, got " + format_g(hausd));
  if (hmin > 0.0 && hmax > 0.0 && hmin > hmax)
    throw InputError("--hmin " + format_g(hmin) + " is larger than --hmax " + format_g(hmax));
  if (!std::isfinite(hmin) || !std::isfinite(hmax) || hmin < 0.0 || hmax < 0.0)
    throw InputError("--hmin and --hmax must be finite sizes >= 0 (0: the default), got " +
                     format_g(hmin) + " and " + format_g(hmax));
  if (!(hgrad == 0.0 || (hgrad > 1.0 && std::isfinite(hgrad))))
    throw InputError("--hgrad must be 0 (off) or a ratio > 1, got " + format_g(hgrad));
  if (!(beta_fraction >= 0.0 && beta_fraction <= 1.0))
    throw InputError("--beta must be in [0, 1], got " + format_g(beta_fraction));
}

namespace {

/// The block [p q; q r] of m in an orthonormal basis (t1, t2) of the plane normal to n.
struct InPlane {
  Vec3 t1, t2;
  double p, q, r;
  InPlane(const SymMat3& m, const Vec3& n) {
    detail::orthonormal_complement(n, 1.0 / norm(n), t1, t2);
    p = quadratic(m, t1), q = bilinear(m, t1, t2), r = quadratic(m, t2);
  }
  double largest() const { return 0.5 * (p + r) + std::hypot(0.5 * (p - r), q); }
};

}  // namespace

double largest_in_plane(const SymMat3& m, const Vec3& n) { return InPlane(m, n).largest(); }

SymMat3 tangent_metric(const SymMat3& m, const Vec3& n) {
  const InPlane b(m, n);
  SymMat3 s{};
  s.at(0, 0) = b.p, s.at(0, 1) = b.q, s.at(1, 1) = b.r, s.at(2, 2) = b.largest();
  return congruence(Mat3::from_columns({b.t1, b.t2, (1.0 / norm(n)) * n}), s);
}

double feature_line_size(const Vec3& a, const Vec3& v, const Vec3& b, double hausd) {
  // Circumradius of (a, v, b): |va| |vb| |ab| / (2 |va × vb|).
  const Vec3 va = a - v, vb = b - v;
  const double twice_area = norm(cross(va, vb));
  const double la = norm(va), lb = norm(vb);
  if (!(twice_area > 1e-12 * la * lb)) return kInf;  // straight (or a repeated point)
  return chord_for_gap(la * lb * norm(b - a) / (2.0 * twice_area), hausd);
}

std::vector<SymMat3> geometric_surface_metric(const Mesh& mesh, const Adjacency& adj,
                                              const SurfaceFeatures& features,
                                              const std::vector<VertexCurvature>& curvature,
                                              const SurfaceMetricOptions& options,
                                              SurfaceMetricReport* report) {
  options.validate();
  const std::size_t nv = mesh.num_vertices();
  if (curvature.size() != nv || features.vert_tag.size() != nv)
    throw InputError("geometric_surface_metric: curvature or features not built from this mesh");
  const double hmax = options.hmax > 0.0 ? options.hmax : bounding_box_diagonal(mesh);
  const double hmin = options.hmin > 0.0 ? options.hmin : std::min(options.hausd, hmax);
  if (!(hmax > 0.0)) throw InputError("geometric_surface_metric: the surface has no extent");
  const std::vector<Id> line = feature_neighbours(adj, features);
  std::vector<SymMat3> m(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    m[v] = vertex_metric(curvature[v].geometry, options, hmin, hmax);
    if (features.feature_degree[v] != 2 || (features.vert_tag[v] & kTagCorner)) continue;
    const Vec3 a = vertex_at(mesh, line[2 * v]), p = vertex_at(mesh, static_cast<Id>(v));
    const Vec3 b = vertex_at(mesh, line[2 * v + 1]);
    const double hc = std::clamp(feature_line_size(a, p, b, options.hausd), hmin, hmax);
    if (hc >= hmax) continue;
    if (!options.anisotropic) {
      m[v] = intersect(m[v], SymMat3::diagonal(1.0 / (hc * hc)));
    } else {
      // Size hc along the line's tangent, nothing imposed across it.
      const Vec3 t = normalize(b - a);
      const SymMat3 mc =
          SymMat3::diagonal(1.0 / (hmax * hmax)) + (1.0 / (hc * hc) - 1.0 / (hmax * hmax)) * outer(t);
      m[v] = intersect(m[v], mc);
    }
  }
  if (options.user_metric && !options.user_metric->empty()) {
    if (options.user_metric->size() != nv)
      throw InputError("geometric_surface_metric: the user metric needs one tensor per vertex");
    for (std::size_t v = 0; v < nv; ++v) m[v] = intersect(m[v], (*options.user_metric)[v]);
  }
  SurfaceMetricReport r;
  r.hmin = hmin;
  r.hmax = hmax;
  if (options.hgrad > 0.0) {
    GradationOptions g;
    g.mode = GradationMode::kHShock;
    g.threshold = options.hgrad;
    g.measure = options.gradation_measures;
    // An isotropic field (no user tensor) stays isotropic through the H-shock gradation: its
    // scalar form (one size per vertex, no eigen-decompositions) gives the same sizes.
    g.anisotropic = options.anisotropic || (options.user_metric && !options.user_metric->empty());
    r.gradation = gradate<3>(std::span<const double>(mesh.coords),
                             std::span<const int32_t>(adj.edges), std::span<SymMat3>(m), g);
  }
  r.smallest = kInf;
  r.largest = 0.0;
  for (const SymMat3& x : m) principal_sizes(x, r.smallest, r.largest);
  if (report) *report = r;
  return m;
}

std::vector<SymMat3> geometric_surface_metric(const Mesh& mesh,
                                              const SurfaceMetricOptions& options,
                                              const FeatureOptions& feature_options,
                                              SurfaceMetricReport* report) {
  const Adjacency adj = build_adjacency(mesh);
  const SurfaceFeatures f = detect_features(mesh, adj, feature_options);
  const SurfaceSectors s = surface_sectors(mesh, adj, f);
  return geometric_surface_metric(mesh, adj, f, vertex_curvatures(mesh, adj, f, s), options,
                                  report);
}

}  // namespace riemesh
