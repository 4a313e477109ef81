// Curved boundaries of the 3D remesher (boundary3d.hpp).
#include "remesh/boundary3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "core/error.hpp"
#include "metric/intersection.hpp"
#include "remesh/plane_fit.hpp"
#include "remesh/surface_metric.hpp"

namespace riemesh {
namespace {

constexpr double kTurn = 0.5235987755982988;     // 30°: largest turn of a wide boundary triangle
constexpr double kCheckMargin = 0.95;            // the checks use 0.95 hausd (as surface_ops)
/// Placed points are at most this × hausd from the input polyhedron: the reconstruction is
/// followed up to the Hausdorff bound that the checks then enforce.
constexpr double kLift = 0.9;
/// A same-ref boundary edge between two feature-line vertices is on the line when its midpoint
/// is closer than this × its length to the reconstructed line.
constexpr double kOnLine = 0.25;
/// Sizes on curved patches are computed for this fraction of hausd (as surface_adapt.cpp).
constexpr double kCentroidFactor = 0.75;

/// A new boundary triangle below this quality (in the operation's metric) is refused unless an
/// old one was worse (bad boundary triangles make every tet on them bad, and no volume operator
/// repairs them). Measured in Euclidean terms before 2026-12-06, the floor refused the stretched
/// boundary triangles a strongly anisotropic metric oblique to the surface asks for (a 1:100
/// metric on a cube whose faces share one ref: edges of metric length 6 left unsplit, then
/// 228 k tets, 54% in band, slivers; 40 k tets, 93% with six planar refs).
constexpr double kTriangleFloor = 0.1;

/// Mean-ratio quality 4√3 A / Σ l² of a triangle (1 equilateral) in the metric m: lengths
/// √(eᵀ M e), area ½ √det of the Gram matrix of two edges in M. For an isotropic m, the
/// Euclidean quality.
double tri_quality(const Tri3& t, const SymMat3& m) {
  const Vec3 e0 = t[1] - t[0], e1 = t[2] - t[0], e2 = t[2] - t[1];
  const double g00 = quadratic(m, e0), g11 = quadratic(m, e1);
  const double g01 = 0.5 * (g00 + g11 - quadratic(m, e2));  // e0ᵀ M e1
  const double l2 = g00 + g11 + quadratic(m, e2);
  const double det = g00 * g11 - g01 * g01;
  return l2 > 0.0 && det > 0.0 ? 3.4641016151377544 * std::sqrt(det) / l2 : 0.0;
}

Vec3 unit_normal(const Tri3& t) {
  const Vec3 n = cross(t[1] - t[0], t[2] - t[0]);
  const double l = norm(n);
  return l > 0.0 ? (1.0 / l) * n : Vec3{};
}

/// Smallest height of a triangle: twice its area over its longest edge.
double width(const Tri3& t) {
  const double l = std::max({norm(t[1] - t[0]), norm(t[2] - t[1]), norm(t[0] - t[2])});
  return l > 0.0 ? norm(cross(t[1] - t[0], t[2] - t[0])) / l : 0.0;
}

/// Whether an operation turns a boundary triangle's normal by at most 30° more than the
/// surface leaves undetermined: a triangle within h of the surface and of width w may lean by
/// atan(h / w) across it (a thin triangle along a curved direction, as a metric oblique to the
/// surface asks for, leans far from the surface's normal, and the next one the other way).
bool normal_turn_ok(const Tri3& before, const Tri3& after, double h) {
  const double c = std::clamp(dot(unit_normal(before), unit_normal(after)), -1.0, 1.0);
  const double w = std::min(width(before), width(after));
  const double slack = w > 0.0 ? std::atan(h / w) : 1.5707963267948966;
  return std::acos(c) <= kTurn + slack;
}

FeatureOptions feature_options(const Adapt3dOptions& o) {
  FeatureOptions f;
  f.angle_deg = o.angle_deg;
  f.detect_angle = o.detect_angles;
  return f;
}

Vec3 point_of(const Mesh& m, Id v) {
  const std::size_t i = 3 * static_cast<std::size_t>(v);
  return Vec3{{m.coords[i], m.coords[i + 1], m.coords[i + 2]}};
}

}  // namespace

Boundary3d::Boundary3d(const TetMesh& m, std::vector<std::int32_t> curved_refs,
                       const Adapt3dOptions& options)
    : curved_refs_(std::move(curved_refs)), surf_id_(m.vertex_capacity(), kNoId),
      hausd_(options.hausd) {
  std::sort(curved_refs_.begin(), curved_refs_.end());
  Mesh s;
  s.dim = 3;
  std::vector<SymMat3> metric;
  for (std::size_t slot = 0; slot < m.fbdy.size(); ++slot) {
    const Id t = static_cast<Id>(slot / 4);
    if (!m.fbdy[slot] || !m.tet_alive(t) || !m.face_side_listed(slot) || !curved(m.face_ref(slot)))
      continue;
    const int i = static_cast<int>(slot % 4);
    for (int k = 0; k < 3; ++k) {
      const Id v = m.tv[4 * t + kTetFace[i][k]];
      Id& sid = surf_id_[v];
      if (sid == kNoId) {
        sid = static_cast<Id>(metric.size());
        s.coords.insert(s.coords.end(), {m.xyz[v][0], m.xyz[v][1], m.xyz[v][2]});
        s.vert_ref.push_back(m.vref[v]);
        s.vert_tag.push_back(m.vtag[v]);
        metric.push_back(m.metric[v]);
      }
      s.triangles.push_back(sid);
    }
    s.tri_ref.push_back(m.face_ref(slot));
  }
  // The input's Edges on the curved patches are feature lines too (a line drawn inside a patch:
  // its vertices kCurve, its edges split on it; m.line_ref keeps their refs).
  std::vector<std::uint64_t> lines;
  for (const auto& [key, ref] : m.line_ref) lines.push_back(key);
  std::sort(lines.begin(), lines.end());  // (the map's order is no order)
  for (const std::uint64_t key : lines) {
    const Id a = surf_id_[key & 0xffffffffu], b = surf_id_[key >> 32];
    if (a == kNoId || b == kNoId) continue;
    s.edges.insert(s.edges.end(), {a, b});
    s.edge_ref.push_back(m.line_ref.at(key));
    s.edge_tag.push_back(kTagNone);
  }
  geo_ = std::make_unique<SurfaceProjection>(s, feature_options(options), std::move(metric),
                                             kLift * hausd_);
  tag_ = geo_->features().vert_tag;  // the kinds: the input's features
  if (!options.geometry) return;
  geo_ = geometry_projection(*options.geometry, options);
  // The input's curved boundary must lie on the geometry (a previous run's output, within
  // hausd): another surface was accepted, and every operation near it then refused, leaving the
  // boundary as given without a word.
  Vec3 lo = point_of(s, 0), hi = lo;
  for (std::size_t v = 0; v < s.num_vertices(); ++v)
    for (int k = 0; k < 3; ++k)
      lo[k] = std::min(lo[k], s.coords[3 * v + k]), hi[k] = std::max(hi[k], s.coords[3 * v + k]);
  // (Ten times hausd: a loop may tighten --hausd from one run to the next.)
  const double tolerance = std::max(10.0 * hausd_, 1e-9 * norm(hi - lo));
  for (std::size_t v = 0; v < s.num_vertices(); ++v) {
    const Vec3 p = point_of(s, static_cast<Id>(v));
    const double d = geo_->distance(p);
    if (!(d <= tolerance)) {
      char msg[240];
      std::snprintf(
          msg, sizeof msg,
          "--geometry: the input's boundary point (%g, %g, %g) is %.3g from the "
          "geometry's surface, more than 10 times --hausd (%g): not the surface the input "
          "was meshed from",
          p[0], p[1], p[2], d, hausd_);
      throw InputError(msg);
    }
  }
}

std::unique_ptr<SurfaceProjection> Boundary3d::geometry_projection(const Mesh& g,
                                                                   const Adapt3dOptions& options) const {
  Mesh s;
  s.dim = 3;
  std::vector<Id> sid(g.num_vertices(), kNoId);
  std::string refs;
  for (std::size_t t = 0; t < g.num_triangles(); ++t) {
    if (!curved(g.tri_ref[t])) continue;
    for (int k = 0; k < 3; ++k) {
      const Id v = g.triangles[3 * t + static_cast<std::size_t>(k)];
      if (sid[v] == kNoId) {
        sid[v] = static_cast<Id>(s.num_vertices());
        s.coords.insert(s.coords.end(), {g.coords[3 * v], g.coords[3 * v + 1], g.coords[3 * v + 2]});
        s.vert_ref.push_back(g.vert_ref.empty() ? 0 : g.vert_ref[v]);
        s.vert_tag.push_back(g.vert_tag.empty() ? 0 : g.vert_tag[v]);
      }
      s.triangles.push_back(sid[v]);
    }
    s.tri_ref.push_back(g.tri_ref[t]);
  }
  for (std::size_t e = 0; e < g.num_edges(); ++e) {  // its lines on those patches (as above)
    const Id a = sid[g.edges[2 * e]], b = sid[g.edges[2 * e + 1]];
    if (a == kNoId || b == kNoId) continue;
    s.edges.insert(s.edges.end(), {a, b});
    s.edge_ref.push_back(e < g.edge_ref.size() ? g.edge_ref[e] : 0);
    s.edge_tag.push_back(kTagNone);
  }
  if (s.triangles.empty()) {
    for (const std::int32_t r : curved_refs_) refs += (refs.empty() ? "" : ", ") + std::to_string(r);
    throw InputError("the geometry mesh has no triangle with the ref of a curved boundary "
                     "patch of this mesh (" + refs + ")");
  }
  // The metric the projection interpolates at placed points is not used here (place() keeps
  // the point only).
  std::vector<SymMat3> metric(s.num_vertices(), SymMat3::identity());
  return std::make_unique<SurfaceProjection>(s, feature_options(options), std::move(metric),
                                             kLift * hausd_);
}

bool Boundary3d::curved(std::int32_t ref) const {
  return std::binary_search(curved_refs_.begin(), curved_refs_.end(), ref);
}

VertexKind Boundary3d::kind(Id v) const {
  const Id sid = static_cast<std::size_t>(v) < surf_id_.size() ? surf_id_[v] : kNoId;
  if (sid == kNoId) return VertexKind::kFixed;
  const std::uint8_t tag = tag_[static_cast<std::size_t>(sid)];
  if (tag & (kTagCorner | kTagRequired)) return VertexKind::kFixed;
  return (tag & kTagRidge) ? VertexKind::kCurve : VertexKind::kSurface;
}

bool Boundary3d::feature_edge(const TetMesh& m, Id a, Id b, std::int32_t r0,
                              std::int32_t r1) const {
  if (r0 != r1) return true;
  for (const Id v : {a, b}) {
    const VertexKind k = m.vkind[v];
    if (k == VertexKind::kCurve) continue;
    // A fixed vertex of the input counts when it is on a feature line (a corner).
    const Id sid = static_cast<std::size_t>(v) < surf_id_.size() ? surf_id_[v] : kNoId;
    if (k != VertexKind::kFixed || sid == kNoId ||
        !(tag_[static_cast<std::size_t>(sid)] & (kTagRidge | kTagCorner)))
      return false;
  }
  const Vec3 mid = 0.5 * (m.xyz[a] + m.xyz[b]);
  const Vec3 q = geo_->on_feature(mid, kNoId).point;
  return norm(q - mid) < kOnLine * norm(m.xyz[b] - m.xyz[a]);
}

Vec3 Boundary3d::place(VertexKind kind, const Vec3& p) const {
  if (kind == VertexKind::kCurve) return geo_->on_feature(p, kNoId).point;
  return geo_->on_surface(p, kNoId).point;
}

bool Boundary3d::chord_instead(const Vec3& placed) const {
  return geo_->distance(placed) >= 0.8 * kLift * hausd_;
}

bool Boundary3d::accepts(const std::vector<Tri3>& old_t, const std::vector<Tri3>& kept,
                         const std::vector<Tri3>& new_t, const SymMat3& metric) const {
  double old_worst = 1.0, new_worst = 1.0;
  for (const Tri3& t : old_t) old_worst = std::min(old_worst, tri_quality(t, metric));
  for (std::size_t i = 0; i < new_t.size(); ++i) {
    if (!normal_turn_ok(kept[i], new_t[i], kCheckMargin * hausd_)) return false;
    new_worst = std::min(new_worst, tri_quality(new_t[i], metric));
  }
  if (new_worst < kTriangleFloor && new_worst < old_worst) return false;
  const double h = kCheckMargin * hausd_;
  return new_triangles_close(*geo_, h, new_t, kNoId) && keeps_input_close(*geo_, h, old_t, new_t);
}

bool curved_boundary_ok(const TetMesh& m, std::span<const Id> ball, Id v, Id to, const Vec3& p) {
  if (!m.surface) return true;
  thread_local std::vector<Tri3> old_t, kept, new_t;
  old_t.clear(), kept.clear(), new_t.clear();
  const Vec3 target = to == kNoId ? p : m.xyz[to];
  for (const Id t : ball)
    for (int i = 0; i < 4; ++i) {
      const std::size_t s = 4 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i);
      if (!m.fbdy[s] || !m.face_side_listed(s) || !m.surface->curved(m.face_ref(s))) continue;
      Id f[3];
      for (int k = 0; k < 3; ++k) f[k] = m.tv[4 * t + kTetFace[i][k]];
      if (f[0] != v && f[1] != v && f[2] != v) continue;
      Tri3 o{m.xyz[f[0]], m.xyz[f[1]], m.xyz[f[2]]};
      old_t.push_back(o);
      if (to != kNoId && (f[0] == to || f[1] == to || f[2] == to)) continue;
      Tri3 n = o;
      for (int k = 0; k < 3; ++k)
        if (f[k] == v) n[static_cast<std::size_t>(k)] = target;
      kept.push_back(o), new_t.push_back(n);
    }
  return m.surface->accepts(old_t, kept, new_t, m.metric[v]);
}

bool curved_split_ok(const TetMesh& m, std::span<const Id> shell, Id a, Id b, const Vec3& p) {
  if (!m.surface) return true;
  thread_local std::vector<Tri3> old_t, kept, new_t;
  old_t.clear(), kept.clear(), new_t.clear();
  for (const Id t : shell)
    for (int i = 0; i < 4; ++i) {
      const std::size_t s = 4 * static_cast<std::size_t>(t) + static_cast<std::size_t>(i);
      const Id opp = m.tv[s];
      if (opp == a || opp == b || !m.fbdy[s] || !m.face_side_listed(s) ||
          !m.surface->curved(m.face_ref(s)))
        continue;
      Id f[3];
      for (int k = 0; k < 3; ++k) f[k] = m.tv[4 * t + kTetFace[i][k]];
      const Tri3 o{m.xyz[f[0]], m.xyz[f[1]], m.xyz[f[2]]};
      old_t.push_back(o);
      for (const Id end : {a, b}) {
        Tri3 n = o;
        for (int k = 0; k < 3; ++k)
          if (f[k] == end) n[static_cast<std::size_t>(k)] = p;
        kept.push_back(o), new_t.push_back(n);
      }
    }
  return m.surface->accepts(old_t, kept, new_t, 0.5 * (m.metric[a] + m.metric[b]));
}

void intersect_curvature_sizes(const Mesh& volume, std::vector<SymMat3>& metrics,
                               const Adapt3dOptions& options) {
  const std::size_t nv = volume.num_vertices(), nt = volume.num_triangles();
  if (metrics.size() != nv || nt == 0) return;
  Vec3 lo = point_of(volume, 0), hi = lo;
  for (std::size_t v = 0; v < nv; ++v) {
    const Vec3 p = point_of(volume, static_cast<Id>(v));
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  }
  // The planar listed patches (as Remesh3dContext finds them, plane_fit.hpp).
  auto ref_of = [&](std::size_t t) { return volume.tri_ref.size() == nt ? volume.tri_ref[t] : 0; };
  std::map<std::int32_t, std::vector<Tri3>> faces;
  for (std::size_t t = 0; t < nt; ++t)
    faces[ref_of(t)].push_back(Tri3{point_of(volume, volume.triangles[3 * t]),
                                    point_of(volume, volume.triangles[3 * t + 1]),
                                    point_of(volume, volume.triangles[3 * t + 2])});
  std::map<std::int32_t, bool> planar;
  for (const auto& [ref, f] : faces) planar[ref] = is_planar(fit_plane(f), norm(hi - lo));
  Mesh s;
  s.dim = 3;
  std::vector<Id> sid(nv, kNoId), vid;
  for (std::size_t t = 0; t < nt; ++t) {
    if (planar[ref_of(t)]) continue;
    for (int k = 0; k < 3; ++k) {
      const Id v = volume.triangles[3 * t + k];
      if (sid[v] == kNoId) {
        sid[v] = static_cast<Id>(vid.size());
        vid.push_back(v);
        const Vec3 p = point_of(volume, v);
        s.coords.insert(s.coords.end(), {p[0], p[1], p[2]});
        s.vert_ref.push_back(0);
        s.vert_tag.push_back(volume.vert_tag.size() == nv ? volume.vert_tag[v] : std::uint8_t{kTagNone});
      }
      s.triangles.push_back(sid[v]);
    }
    s.tri_ref.push_back(ref_of(t));
  }
  if (vid.empty()) return;
  if (!(options.hausd > 0.0))
    throw InputError("--hausd must be > 0 for a volume with curved boundary patches");
  SurfaceMetricOptions so;
  so.hausd = kCentroidFactor * options.hausd;
  so.hmin = options.hmin;
  so.hmax = std::isfinite(options.hmax) && options.hmax > 0.0 ? options.hmax : norm(hi - lo);
  if (so.hmin > so.hmax) so.hmin = so.hmax;
  so.anisotropic = true;
  so.hgrad = 0.0;  // graded with the volume metric afterwards (prepare_metrics)
  const std::vector<SymMat3> g = geometric_surface_metric(s, so, feature_options(options));
  for (std::size_t i = 0; i < vid.size(); ++i)
    metrics[static_cast<std::size_t>(vid[i])] =
        intersect(metrics[static_cast<std::size_t>(vid[i])], g[i]);
}

}  // namespace riemesh
