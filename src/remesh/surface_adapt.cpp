// The surface remesher's driver: sizes, state, cycles of passes, output (surface_adapt.hpp).
#include "remesh/surface_adapt.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "core/spd.hpp"
#include "mesh/distance.hpp"
#include "remesh/surface_adapt_detail.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_input.hpp"
#include "remesh/surface_metric.hpp"

namespace riemesh {
namespace {

constexpr double kSmallestScale = 1e-40, kLargestScale = 1e40;

using surface_detail::State;

/// The equilateral triangle whose edges have the chordal gap g on a sphere has its centroid
/// (4/3) g from the sphere (circumradius L/√3 instead of the half-chord L/2), so the sizes are
/// computed for 3/4 of hausd: the sampled distance then stays within hausd.
constexpr double kCentroidFactor = 0.75;

/// The most vertices a remeshed surface may need: sizes asking for more (a mistyped --hsiz or
/// --hausd) are refused before any point is added (a torus at --hausd 1e-9 reached 7 GB).
constexpr double kMostSurfaceVertices = 5e7;

/// Surfaces beyond 1e±40 are refused: the rotor scaled by 1e±60 gave 2,250 triangles instead of
/// 3,766 (the same at 1e±20 and 1e±40), by 1e±80 invalid outputs 6% of the diagonal away from
/// the input (products of lengths and metric values overflow or underflow).
void require_computable_scale(const Mesh& in) {
  const double diag = bounding_box_diagonal(in);
  if (diag >= kSmallestScale && diag <= kLargestScale) return;
  char msg[240];
  std::snprintf(msg, sizeof msg,
                "the surface's bounding-box diagonal is %.3g, outside [%g, %g] where riemesh "
                "computes sizes reliably: rescale its coordinates",
                diag, kSmallestScale, kLargestScale);
  throw InputError(msg);
}

/// Throws InputError when the unit mesh of the vertex metrics would need more than
/// kMostSurfaceVertices vertices: (2/√3) Σ area × the mean of the vertices' sqrt(λ1 λ2), their
/// two largest eigenvalues (an upper bound of the density in the tangent plane), naming the
/// finest size and its place.
void require_reachable_surface(const Mesh& in, const std::vector<SymMat3>& metrics) {
  // In units of the bounding box's diagonal (areas / L², densities · L²), so that no product
  // overflows within the accepted scales.
  const double unit = bounding_box_diagonal(in);
  std::vector<double> density(metrics.size());
  std::size_t finest = 0;
  for (std::size_t v = 0; v < metrics.size(); ++v) {
    const SymEigen<3> e = eigen((unit * unit) * metrics[v]);
    density[v] = std::sqrt(e.values[1] * e.values[2]);
    if (!(density[v] <= density[finest])) finest = v;
  }
  double total = 0.0;
  for (std::size_t t = 0; t < in.num_triangles(); ++t) {
    const Id* v = &in.triangles[3 * t];
    Vec3 p[3];
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c)
        p[k][c] =
            in.coords[3 * static_cast<std::size_t>(v[k]) + static_cast<std::size_t>(c)] / unit;
    const double area = 0.5 * norm(cross(p[1] - p[0], p[2] - p[0]));
    total += area * (density[v[0]] + density[v[1]] + density[v[2]]) / 3.0;
  }
  const double vertices = 1.1547005383792515 * total;
  if (vertices <= kMostSurfaceVertices) return;
  char msg[320];
  std::snprintf(
      msg, sizeof msg,
      "the sizes ask for about %.3g vertices on the surface, more than %g; finest size "
      "%.3g near (%g, %g, %g): ask for coarser sizes (a larger --hausd), or bound them with "
      "--hmin",
      vertices, kMostSurfaceVertices, unit / std::sqrt(density[finest]), in.coords[3 * finest],
      in.coords[3 * finest + 1], in.coords[3 * finest + 2]);
  throw InputError(msg);
}

/// Quality below which the last passes split a triangle's longest edge (the floor).
constexpr double kBadQuality = 0.3;

/// Largest number of consecutive split (or collapse) passes in one cycle.
constexpr int kInnerPasses = 8;

/// A user metric (a volume solver's, say) measured along the surface: the remesher measures
/// edges, all tangent to the surface, so only its restriction to the tangent plane matters (as in
/// mmgs); the full tensor's smallest size could be the one across the surface (a boundary layer:
/// sizes 0.3 along a sphere and 0.05 across it refined it 40 times: QA hunt 6 G7). The tangent
/// plane is the vertex's (its fitted normal); at a feature vertex, or without a fit, the planes of
/// its triangles (the finest size along any of them).
class AlongSurface {
 public:
  AlongSurface(const Mesh& in, const Adjacency& adj, const SurfaceFeatures& f,
               const std::vector<VertexCurvature>& c, bool needed)
      : adj_(adj), features_(f), curvature_(c) {
    if (needed) tri_normal_ = triangle_normals(in);
  }
  /// 1/h² of the finest size x asks along the surface at vertex v.
  double finest(std::size_t v, const SymMat3& x) const {
    if (const Vec3* n = normal(v)) return largest_in_plane(x, *n);
    double l = 0.0;
    for (const Id t : ball(adj_, static_cast<Id>(v)))
      if (const Vec3& n = tri_normal_[static_cast<std::size_t>(t)]; dot(n, n) > 0.0)
        l = std::max(l, largest_in_plane(x, n));
    return l > 0.0 ? l : eigen(x).values[2];  // no plane: the smallest principal size
  }
  /// x restricted to v's tangent plane, the finest size along it across (tangent_metric); x
  /// itself at a feature vertex (two planes or more) or without a fit.
  SymMat3 tangent(std::size_t v, const SymMat3& x) const {
    const Vec3* n = normal(v);
    return n ? tangent_metric(x, *n) : x;
  }

 private:
  const Vec3* normal(std::size_t v) const {
    const VertexCurvature& c = curvature_[v];
    const bool feature = features_.vert_tag[v] & (kTagRidge | kTagCorner);
    return !feature && c.fitted && dot(c.geometry.normal, c.geometry.normal) > 0.0
               ? &c.geometry.normal
               : nullptr;
  }
  const Adjacency& adj_;
  const SurfaceFeatures& features_;
  const std::vector<VertexCurvature>& curvature_;
  std::vector<Vec3> tri_normal_;
};

/// The sizes --hsiz and the user metric ask for, clipped to [--hmin, --hmax] as 2D and 3D clip
/// theirs (prepare_metrics), with the same notes: --hsiz folded into the geometric metric's hmax
/// (raised to --hmin when below), the user metric's sizes below --hmin clipped after the
/// intersection and the gradation (which only shrinks sizes). Before 2026-12-07 a --hsiz below
/// --hmin silently lowered --hmin to it (QA hunt 6 G4: --hsiz 0.05 --hmin 0.1 gave the 13,248
/// triangles of --hsiz 0.05 alone).
std::vector<SymMat3> vertex_metrics(const Mesh& input, const Adjacency& adj,
                                    const SurfaceFeatures& features,
                                    const std::vector<VertexCurvature>& curvature,
                                    const SurfaceAdaptOptions& o, std::vector<std::string>& notes) {
  SurfaceMetricOptions m;
  m.hausd = kCentroidFactor * o.hausd;
  m.hmin = o.hmin;
  m.hmax = o.hmax;
  if (o.hsiz > 0.0) {
    m.hmax = m.hmax > 0.0 ? std::min(m.hmax, o.hsiz) : o.hsiz;
    if (o.hmax > 0.0 && o.hsiz > o.hmax)
      notes.push_back("sizes above --hmax " + format_g(o.hmax) + " clipped at " +
                      std::to_string(input.num_vertices()) + " vertices (--hsiz " +
                      format_g(o.hsiz) + ")");
  }
  const bool hsiz_below = o.hmin > 0.0 && o.hsiz > 0.0 && o.hsiz < o.hmin;
  if (hsiz_below) m.hmax = o.hmin;
  m.hgrad = o.hgrad;
  m.gradation_measures = false;  // not reported
  m.anisotropic = o.anisotropic;
  m.beta_fraction = o.beta_fraction;
  m.user_metric = &o.metric;
  std::vector<SymMat3> metric = geometric_surface_metric(input, adj, features, curvature, m);
  const AlongSurface along(input, adj, features, curvature, !o.metric.empty());
  if (o.hmin > 0.0) {
    const double hi = 1.0 / (o.hmin * o.hmin);
    std::size_t below = 0, first = 0;
    for (std::size_t v = 0; v < metric.size(); ++v) {
      const bool asks = hsiz_below || (!o.metric.empty() && along.finest(v, o.metric[v]) > hi);
      if (asks && below++ == 0) first = v;
      metric[v] = project_spd(metric[v], 0.0, hi);
    }
    if (below > 0)
      notes.push_back("the metric asks for sizes below --hmin " + format_g(o.hmin) + " at " +
                      std::to_string(below) + " vertices, e.g. near (" +
                      format_g(input.coords[3 * first]) + ", " +
                      format_g(input.coords[3 * first + 1]) + ", " +
                      format_g(input.coords[3 * first + 2]) + "): clipped to --hmin");
  }
  if (!o.metric.empty()) {  // measured along the surface (QA hunt 6 G7)
    for (std::size_t v = 0; v < metric.size(); ++v)
      metric[v] = o.anisotropic ? along.tangent(v, metric[v])
                                : SymMat3::diagonal(along.finest(v, metric[v]));
  } else if (!o.anisotropic) {  // isotropic: the smallest principal size in every direction
    for (SymMat3& x : metric) x = SymMat3::diagonal(eigen(x).values[2]);
  }
  return metric;
}

State initial_state(const Mesh& input, const SurfaceProjection& geo) {
  State s;
  const std::size_t nv = input.num_vertices();
  const Adjacency& adj = geo.adjacency();
  const SurfaceFeatures& f = geo.features();
  for (std::size_t v = 0; v < nv; ++v) {
    const Vec3 p{{input.coords[3 * v], input.coords[3 * v + 1], input.coords[3 * v + 2]}};
    const auto b = ball(adj, static_cast<Id>(v));
    s.add_vertex(p, geo.metrics()[v], f.vert_tag[v] & (kTagCorner | kTagRidge),
                 b.empty() ? kNoId : b[0], kNoId);
  }
  s.tri = input.triangles;
  s.tref = input.tri_ref.size() == input.num_triangles() ? input.tri_ref
                                                         : std::vector<std::int32_t>(input.num_triangles(), 0);
  // Feature edges with the ref of the listed edge when there is one.
  for (std::size_t e = 0; e < adj.num_edges(); ++e)
    if (f.edge_feature[e]) {
      const auto key = surface_detail::edge_key(adj.edges[2 * e], adj.edges[2 * e + 1]);
      s.feature[key] = 0;
      s.feature_tag[key] = (f.edge_feature[e] & kFeatureAngle) ? kTagRidge : kTagNone;
    }
  for (std::size_t e = 0; e < input.num_edges(); ++e) {
    const auto key = surface_detail::edge_key(input.edges[2 * e], input.edges[2 * e + 1]);
    if (s.feature.count(key) && input.edge_ref.size() == input.num_edges())
      s.feature[key] = input.edge_ref[e];
  }
  s.compact();  // drops vertices of no triangle
  return s;
}

Mesh output_mesh(const State& s) {
  Mesh m;
  m.dim = 3;
  for (const Vec3& p : s.x) m.coords.insert(m.coords.end(), {p[0], p[1], p[2]});
  m.vert_ref.assign(s.num_vertices(), 0);
  m.vert_tag.resize(s.num_vertices());
  for (std::size_t v = 0; v < s.num_vertices(); ++v) m.vert_tag[v] = s.tag[v] & kTagCorner;
  m.triangles = s.tri;
  m.tri_ref = s.tref;
  m.tri_tag.assign(s.num_triangles(), kTagNone);
  std::vector<std::uint64_t> keys;
  for (const auto& kv : s.feature) keys.push_back(kv.first);
  std::sort(keys.begin(), keys.end());  // deterministic order
  for (std::uint64_t k : keys) {
    m.edges.insert(m.edges.end(), {static_cast<Id>(k & 0xffffffffu), static_cast<Id>(k >> 32)});
    m.edge_ref.push_back(s.feature.at(k));
    m.edge_tag.push_back(s.feature_tag.at(k));
  }
  return m;
}

}  // namespace

void SurfaceAdaptOptions::validate() const {
  if (!(hausd > 0.0) || !std::isfinite(hausd)) throw InputError("hausd must be > 0");
  if (!(hsiz >= 0.0) || !std::isfinite(hsiz)) throw InputError("hsiz must be >= 0");
  if (hmin > 0.0 && hmax > 0.0 && hmin > hmax) {
    char msg[96];
    std::snprintf(msg, sizeof msg, "--hmin %g is larger than --hmax %g", hmin, hmax);
    throw InputError(msg);
  }
  if (max_cycles < 0) throw InputError("the number of cycles must be >= 0");
  if (!(beta_fraction >= 0.0 && beta_fraction <= 1.0))
    throw InputError("beta fraction must be in [0, 1]");
  for (const SymMat3& m : metric)
    if (!(det(m) > 0.0) || !(m.c[0] > 0.0) || !is_finite(m))
      throw InputError("surface metric: a tensor is not positive definite");
  features.validate();
}

double triangle_quality(const double* a, const double* b, const double* c) {
  return surface_detail::quality({{a[0], a[1], a[2]}}, {{b[0], b[1], b[2]}}, {{c[0], c[1], c[2]}});
}

namespace {

/// A triangle listed twice (same three vertices) made zero-area triangles in the output.
void require_no_duplicate_triangles(const Mesh& m) {
  std::vector<std::array<Id, 4>> keys(m.num_triangles());
  for (std::size_t t = 0; t < keys.size(); ++t) {
    std::array<Id, 3> v{m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]};
    std::sort(v.begin(), v.end());
    keys[t] = {v[0], v[1], v[2], static_cast<Id>(t)};
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (std::equal(keys[i].begin(), keys[i].begin() + 3, keys[i - 1].begin()))
      throw InputError("triangles " + std::to_string(keys[i - 1][3] + 1) + " and " +
                       std::to_string(keys[i][3] + 1) + " have the same vertices (" +
                       std::to_string(keys[i][0] + 1) + ", " + std::to_string(keys[i][1] + 1) +
                       ", " + std::to_string(keys[i][2] + 1) + ")");
}

}  // namespace

Mesh adapt_surface(const Mesh& input, const SurfaceAdaptOptions& options,
                   SurfaceAdaptReport* report) {
  options.validate();
  if (input.kind() != MeshKind::kSurface)
    throw InputError("adapt_surface: need a surface mesh (3D triangles, no tetrahedra)");
  if (!options.metric.empty() && options.metric.size() != input.num_vertices())
    throw InputError("adapt_surface: the metric needs one tensor per input vertex");
  require_no_duplicate_triangles(input);
  require_adaptable_surface(input);
  require_computable_scale(input);
  // The metric from the projection's own analysis (features and curvature computed once).
  std::vector<std::string> notes;
  const SurfaceProjection geo(
      input, options.features,
      [&options, &notes](const Mesh& mesh, const Adjacency& adj, const SurfaceFeatures& f,
                         const std::vector<VertexCurvature>& curvature) {
        return vertex_metrics(mesh, adj, f, curvature, options, notes);
      },
      0.5 * options.hausd);
  require_reachable_surface(input, geo.metrics());
  State s = initial_state(input, geo);
  s.init_cover(geo);  // the state's triangles are the input's (compact keeps their order)
  s.geo = &geo;
  s.opt = &options;
  SurfaceAdaptReport r;
  r.notes = std::move(notes);
  r.input_corners = geo.features().num_corners;
  r.input_feature_edges = geo.features().num_feature_edges;
  auto report_cycle = [&](SurfaceCycle& c) {
    r.splits += c.splits, r.collapses += c.collapses, r.swaps += c.swaps, r.moves += c.moves;
    if (!options.on_cycle) return;
    c.triangles = s.num_triangles();
    c.vertices = s.num_vertices();
    options.on_cycle(c);
  };
  for (int cycle = 0; cycle < options.max_cycles; ++cycle) {
    const std::size_t nt = s.num_triangles();
    SurfaceCycle c;
    c.cycle = cycle + 1;
    if (options.insert) {
      // Splits, then collapses, each repeated while they change much (a pass only applies
      // independent operations): the cheap topological work before the swaps and moves.
      for (int k = 0; k < kInnerPasses; ++k) {
        const std::size_t sp = surface_detail::split_pass(s);
        c.splits += sp;
        if (sp < std::max<std::size_t>(1, s.num_triangles() / 100)) break;
      }
      for (int k = 0; k < kInnerPasses; ++k) {
        const std::size_t co = surface_detail::collapse_pass(s);
        c.collapses += co;
        if (co < std::max<std::size_t>(1, s.num_triangles() / 100)) break;
      }
    }
    if (options.swap) c.swaps = surface_detail::swap_pass(s);
    if (options.move) c.moves = surface_detail::smooth_pass(s);
    ++r.cycles;
    report_cycle(c);
    if (c.splits + c.collapses < std::max<std::size_t>(1, nt / 100) && cycle >= 2) break;
  }
  // Last touch: split the long edge of triangles still below quality 0.3 (the obtuse ones that
  // swaps and moves could not fix under the Hausdorff checks), then swap and move around them.
  SurfaceCycle last;
  for (int k = 0; k < 2 && options.insert; ++k) {
    const std::size_t sp = surface_detail::split_pass(s, kBadQuality);
    last.splits += sp;
    if (sp == 0) break;
    if (options.swap) last.swaps += surface_detail::swap_pass(s);
    if (options.move) last.moves += surface_detail::smooth_pass(s);
  }
  if (options.swap) last.swaps += surface_detail::swap_pass(s);
  if (options.move) last.moves += surface_detail::smooth_pass(s);
  report_cycle(last);
  Mesh out = output_mesh(s);
  r.q_min = 1.0;
  double sum = 0.0;
  for (std::size_t t = 0; t < out.num_triangles(); ++t) {
    const double q = triangle_quality(&out.coords[3 * static_cast<std::size_t>(out.triangles[3 * t])],
                                      &out.coords[3 * static_cast<std::size_t>(out.triangles[3 * t + 1])],
                                      &out.coords[3 * static_cast<std::size_t>(out.triangles[3 * t + 2])]);
    r.q_min = std::min(r.q_min, q);
    sum += q;
  }
  r.q_mean = out.num_triangles() ? sum / static_cast<double>(out.num_triangles()) : 0.0;
  if (report) *report = r;
  return out;
}

}  // namespace riemesh
