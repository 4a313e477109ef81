#include "generate/geometry2d.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "generate/curve2d.hpp"
#include "generate/mesh2d.hpp"
#include "remesh/prepare_metrics.hpp"  // kMostVertices2d

namespace riemesh {

namespace {

std::string line_of(std::size_t line) { return "line " + std::to_string(line) + ": "; }

/// Twice the signed area of a closed polygon (counter-clockwise positive).
double twice_area(const std::vector<Vec2>& ring) {
  double a = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) a += cross(ring[i], ring[(i + 1) % ring.size()]);
  return a;
}

/// Whether p is inside the closed polygon (crossing number; p on no edge).
bool inside(const std::vector<Vec2>& ring, const Vec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 &a = ring[i], &b = ring[j];
    if ((a[1] > p[1]) != (b[1] > p[1]) &&
        p[0] < a[0] + (p[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
      in = !in;
  }
  return in;
}

/// The geometry with its ids indexed, and the curves meshed on demand (each once).
class BoundaryBuilder {
 public:
  BoundaryBuilder(const Geometry2d& g, const GeometryMeshOptions& o) : g_(g) {
    for (std::size_t i = 0; i < g.points.size(); ++i) point_[g.points[i].id] = i;
    for (std::size_t i = 0; i < g.curves.size(); ++i) curve_[g.curves[i].id] = i;
    for (std::size_t i = 0; i < g.loops.size(); ++i) loop_[g.loops[i].id] = i;
    for (const GeoPhysical& p : g.physical_curves)
      for (const int id : p.ids) curve_ref_.emplace(id, p.tag);  // the first group wins
    for (const GeoPhysical& p : g.physical_surfaces)
      for (const int id : p.ids) surface_ref_.emplace(id, p.tag);
    // An entity in no group takes its id, unless a group's tag is that id: then a ref above
    // every tag and id (two squares, one in Physical Surface(1), the other surface 1 in none,
    // were both ref 1, one region for the user: QA hunt 5 F6).
    const auto apart = [](const auto& entities, std::map<int, int>& refs,
                          const std::vector<GeoPhysical>& groups) {
      std::set<int> tags;
      int next = 0;
      for (const GeoPhysical& p : groups) tags.insert(p.tag), next = std::max(next, p.tag);
      for (const auto& e : entities) next = std::max(next, e.id);
      for (const auto& e : entities)
        if (!refs.count(e.id) && tags.count(e.id) && next < INT_MAX) refs.emplace(e.id, ++next);
    };
    apart(g.curves, curve_ref_, g.physical_curves);
    apart(g.surfaces, surface_ref_, g.physical_surfaces);
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    for (std::size_t i = 0; i < g.points.size(); ++i) {
      const double xy[2] = {g.points[i].x, g.points[i].y};
      for (int c = 0; c < 2; ++c) {
        lo[c] = i == 0 ? xy[c] : std::min(lo[c], xy[c]);
        hi[c] = i == 0 ? xy[c] : std::max(hi[c], xy[c]);
      }
    }
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(diagonal > 0.0)) throw InputError("the geometry's points all lie at one place");
    if (!std::isfinite(diagonal))
      throw InputError(
          "the geometry's points lie too far apart for double precision (their box "
          "has no finite diagonal)");
    size_ = o.hsiz > 0.0 ? o.hsiz : diagonal / 25.0;
    hsiz_ = o.hsiz > 0.0;
    sizing_.hausd = o.hausd > 0.0 ? o.hausd : 1e-3 * diagonal;
    sizing_.hmin = o.hmin > 0.0 ? o.hmin : 1e-6 * diagonal;
    if (o.hmax > 0.0) sizing_.hmax = o.hmax;
    out_.domain.dim = 2;
  }

  /// Start and end point ids of a curve.
  std::pair<int, int> ends(const GeoCurve& c) const {
    return {c.points.front(), c.kind == GeoCurveKind::kCircle ? c.points[2] : c.points.back()};
  }
  const GeoCurve& curve(int id) const { return g_.curves[curve_.at(id)]; }
  const GeoLoop& loop(int id) const { return g_.loops[loop_.at(id)]; }
  int curve_ref(int id) const {
    const auto it = curve_ref_.find(id);
    return it == curve_ref_.end() ? id : it->second;
  }
  int surface_ref(int id) const {
    const auto it = surface_ref_.find(id);
    return it == surface_ref_.end() ? id : it->second;
  }

  /// The curve's shape on t in [0, 1].
  Curve2d shape(const GeoCurve& c) const {
    const auto at = [&](std::size_t k) {
      const GeoPoint& p = g_.points[point_.at(c.points[k])];
      return Vec2{{p.x, p.y}};
    };
    if (c.kind == GeoCurveKind::kCircle) return Curve2d::arc(at(0), at(1), at(2));
    if (c.kind == GeoCurveKind::kSpline) {
      std::vector<Vec2> through;
      for (std::size_t k = 0; k < c.points.size(); ++k) through.push_back(at(k));
      const auto [first, last] = ends(c);
      return Curve2d::spline(std::move(through), first == last);
    }
    return Curve2d::segment(at(0), at(1));
  }

  /// The sizes asked at the curve's start and end (linear in between): --hsiz; else the lc of
  /// its end points (one given: that one, as Gmsh); else the default.
  std::pair<double, double> end_sizes(const GeoCurve& c) const {
    if (!sized_by_points(c)) return {size_, size_};
    const auto [first, last] = ends(c);
    const double la = g_.points[point_.at(first)].lc, lb = g_.points[point_.at(last)].lc;
    return {la > 0.0 ? la : lb, lb > 0.0 ? lb : la};
  }
  bool sized_by_points(const GeoCurve& c) const {
    const auto [first, last] = ends(c);
    return !hsiz_ && (g_.points[point_.at(first)].lc > 0.0 || g_.points[point_.at(last)].lc > 0.0);
  }

  /// Refuses a surface whose sizes ask for more than kMostVertices2d vertices before any curve
  /// is meshed (a mistyped lc or --hsiz would otherwise first mesh millions of boundary nodes).
  /// A lower bound on the count: no size inside exceeds 1.5 h, h the largest size asked on the
  /// surface's curves clamped to [hmin, hmax] (a curve's segments are at most 1.5 times its
  /// sizes, the sizes inside interpolate the boundary's, gradation only shrinks them), and
  /// a unit equilateral triangle covers √3/4 h², two per vertex: (2/√3) area / (1.5 h)²,
  /// with half the area of the loops sampled 16 times per curve piece (chords).
  void require_reachable_size(const GeoSurface& s) const {
    double largest = 0.0, twice = 0.0;
    for (std::size_t k = 0; k < s.loops.size(); ++k) {
      std::vector<Vec2> ring;
      for (const int signed_id : loop(s.loops[k]).curves) {
        const GeoCurve& c = curve(std::abs(signed_id));
        const auto [a, b] = end_sizes(c);
        largest = std::max({largest, a, b});
        const Curve2d shape = this->shape(c);
        const int n = 16 * shape.pieces();
        for (int i = 0; i < n; ++i) {
          const double t = static_cast<double>(signed_id > 0 ? i : n - i) / n;
          ring.push_back(shape.at(t).p);
        }
      }
      const double a = std::abs(twice_area(ring));
      twice += k == 0 ? a : -a;
    }
    const double h = std::min(std::max(largest, sizing_.hmin), sizing_.hmax);
    const double area = 0.5 * std::max(0.0, 0.5 * twice);
    const double vertices = 2.0 / std::sqrt(3.0) * area / (2.25 * h * h);
    if (vertices > kMostVertices2d) {
      char msg[256];
      std::snprintf(msg, sizeof msg,
                    "Plane Surface %d: its sizes (at most %g) ask for more than %g vertices "
                    "over its area (about %g); see --hsiz, --hmin and the points' lc",
                    s.id, h, kMostVertices2d, 0.5 * twice);
      throw InputError(line_of(s.line) + msg);
    }
  }

  /// The mesh vertex of a geometry point (a corner), made at its first use.
  Id vertex(int point_id) {
    const auto [it, fresh] = vertex_.emplace(point_id, kNoId);
    if (fresh) {
      const GeoPoint& p = g_.points[point_.at(point_id)];
      it->second = add_vertex(Vec2{{p.x, p.y}}, kTagCorner);
    }
    return it->second;
  }

  /// The vertices of a curve's mesh from its start to its end.
  const std::vector<Id>& nodes(int id) {
    const auto found = nodes_.find(id);
    if (found != nodes_.end()) return found->second;
    const GeoCurve& c = curve(id);
    const auto [first, last] = ends(c);
    const Curve2d shape = this->shape(c);
    CurveSizing sizing = sizing_;
    if (c.kind == GeoCurveKind::kCircle) sizing.min_segments = 2;
    if (c.kind == GeoCurveKind::kSpline) sizing.min_segments = first == last ? 3 : 2;
    const std::pair<double, double> ends_size = end_sizes(c);
    const double a = ends_size.first, b = ends_size.second;  // (clang 14: no binding captures)
    sizing.size = [a, b](double t) { return a + t * (b - a); };
    if (sized_by_points(c)) ++out_.sized_by_points;
    std::vector<double> ts;
    try {
      ts = mesh_curve(shape, sizing);
    } catch (const InputError& e) {
      throw InputError(line_of(c.line) + "curve " + std::to_string(id) + ": " + e.what());
    }
    std::vector<Id> ids{vertex(first)};
    for (std::size_t k = 1; k + 1 < ts.size(); ++k) ids.push_back(add_vertex(shape.at(ts[k]).p, 0));
    ids.push_back(vertex(last));
    ++out_.curves;
    return nodes_.emplace(id, std::move(ids)).first->second;
  }

  Vec2 xy(Id v) const {
    return Vec2{{out_.domain.coords[2 * static_cast<std::size_t>(v)],
                 out_.domain.coords[2 * static_cast<std::size_t>(v) + 1]}};
  }
  void add_edge(Id a, Id b, int ref) {
    out_.domain.edges.insert(out_.domain.edges.end(), {a, b});
    out_.domain.edge_ref.push_back(ref);
    out_.domain.edge_tag.push_back(kTagNone);
  }

  GeometryBoundary& result() { return out_; }
  double size() const { return size_; }
  double hausd() const { return sizing_.hausd; }

 private:
  Id add_vertex(const Vec2& p, std::uint8_t tag) {
    Mesh& m = out_.domain;
    m.coords.insert(m.coords.end(), {p[0], p[1]});
    m.vert_ref.push_back(0);
    m.vert_tag.push_back(tag);
    return static_cast<Id>(m.num_vertices() - 1);
  }

  const Geometry2d& g_;
  std::map<int, std::size_t> point_, curve_, loop_;
  std::map<int, int> curve_ref_, surface_ref_;
  std::map<int, Id> vertex_;
  std::map<int, std::vector<Id>> nodes_;
  CurveSizing sizing_;
  double size_ = 0.0;
  bool hsiz_ = false;
  GeometryBoundary out_;
};

}  // namespace

void GeometryMeshOptions::validate() const {
  const std::pair<const char*, double> values[] = {
      {"--hsiz", hsiz}, {"--hausd", hausd}, {"--hmin", hmin}, {"--hmax", hmax}};
  for (const auto& [name, v] : values)
    if (!(v >= 0.0) || !std::isfinite(v))
      throw InputError(std::string(name) + " must be a positive number, got " + std::to_string(v));
  if (hmin > 0.0 && hmax > 0.0 && hmin > hmax)
    throw InputError("--hmin (" + std::to_string(hmin) + ") is larger than --hmax (" +
                     std::to_string(hmax) + ")");
}

GeometryBoundary mesh_geometry_boundary(const Geometry2d& geometry,
                                        const GeometryMeshOptions& options) {
  options.validate();
  if (geometry.surfaces.empty())
    throw InputError(
        "no Plane Surface: nothing to mesh (add e.g. 'Plane Surface(1) = {1};' "
        "over a Curve Loop)");
  BoundaryBuilder b(geometry, options);
  for (const GeoSurface& s : geometry.surfaces) b.require_reachable_size(s);
  // Which surface has each curve on its left, in each direction: two surfaces on the same side
  // of a curve overlap (mesh_domain2d would merge them silently).
  std::map<std::pair<int, bool>, int> left_of;
  for (const GeoSurface& s : geometry.surfaces) {
    SurfacePolygons polygons;
    polygons.ref = b.surface_ref(s.id);
    polygons.id = s.id;
    for (std::size_t k = 0; k < s.loops.size(); ++k) {
      const GeoLoop& loop = b.loop(s.loops[k]);
      const std::string where = line_of(loop.line) + "Curve Loop " + std::to_string(loop.id);
      // The loop's vertices in its order (each curve's last node is the next one's first) and,
      // for the edge from ring[i] to ring[i + 1], the ref of its curve.
      std::vector<Id> ring;
      std::vector<int> refs;
      int first_point = 0, at_point = 0;
      for (std::size_t i = 0; i < loop.curves.size(); ++i) {
        const int signed_id = loop.curves[i], id = std::abs(signed_id);
        auto [from, to] = b.ends(b.curve(id));
        if (signed_id < 0) std::swap(from, to);
        if (i == 0)
          first_point = from;
        else if (from != at_point)
          throw InputError(where + ": curve " + std::to_string(signed_id) + " starts at point " +
                           std::to_string(from) + ", not at point " + std::to_string(at_point) +
                           " where the curve before it ends");
        at_point = to;
        std::vector<Id> nodes = b.nodes(id);
        if (signed_id < 0) std::reverse(nodes.begin(), nodes.end());
        ring.insert(ring.end(), nodes.begin(), nodes.end() - 1);
        refs.insert(refs.end(), nodes.size() - 1, b.curve_ref(id));
      }
      if (at_point != first_point)
        throw InputError(where + " is not closed: it ends at point " + std::to_string(at_point) +
                         ", not at point " + std::to_string(first_point) + " where it starts");
      std::vector<Vec2> xy;
      for (const Id v : ring) xy.push_back(b.xy(v));
      const double area = twice_area(xy);
      if (ring.size() < 3 || !(std::abs(area) > 0.0)) throw InputError(where + " encloses no area");
      // Outer loops counter-clockwise, holes clockwise (the domain on the left of each edge).
      const bool flip = (area > 0.0) != (k == 0);
      for (const int signed_id : loop.curves) {
        const int id = std::abs(signed_id);
        const auto [it, fresh] = left_of.emplace(std::pair{id, (signed_id > 0) != flip}, s.id);
        if (fresh) continue;
        const std::string surface = line_of(s.line) + "Plane Surface " + std::to_string(s.id);
        if (it->second == s.id)
          throw InputError(surface + " uses curve " + std::to_string(id) + " twice on one side");
        throw InputError(surface + " overlaps Plane Surface " + std::to_string(it->second) +
                         ": both lie on the same side of curve " + std::to_string(id));
      }
      if (flip) {
        std::reverse(ring.begin() + 1, ring.end());
        std::reverse(refs.begin(), refs.end());
        std::reverse(xy.begin() + 1, xy.end());
      }
      // Outside when most of its nodes are (one node tested, a hole touching its outer loop at
      // that node was called outside; crossing loops are caught by the domain's checks).
      std::size_t out_nodes = 0;
      if (k > 0)
        for (const Vec2& p : xy) out_nodes += !inside(polygons.loops.front(), p);
      if (k > 0 && 2 * out_nodes > xy.size())
        throw InputError(line_of(s.line) + "Plane Surface " + std::to_string(s.id) + ": hole " +
                         "Curve Loop " + std::to_string(loop.id) +
                         " lies outside its outer Curve Loop " + std::to_string(s.loops[0]));
      for (std::size_t i = 0; i < ring.size(); ++i)
        b.add_edge(ring[i], ring[(i + 1) % ring.size()], refs[i]);
      polygons.loops.push_back(std::move(xy));
    }
    b.result().surfaces.push_back(std::move(polygons));
  }
  GeometryBoundary& out = b.result();
  out.size = b.size();
  out.hausd = b.hausd();
  return std::move(out);
}

void assign_surface_refs(const GeometryBoundary& boundary, Mesh& mesh) {
  // The triangles of each region, then up to kSamples of them spread over it: a region is
  // decided by the surfaces holding most of their centroids (one centroid near a curved
  // boundary could fall outside the polygon of the curve's nodes).
  constexpr std::size_t kSamples = 16;
  std::map<int, std::vector<std::size_t>> of_region;
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t) of_region[mesh.tri_ref[t]].push_back(t);
  std::map<int, int> ref_of_region;
  for (const auto& [region, tris] : of_region) {
    std::map<std::vector<std::size_t>, std::size_t> votes;  // surfaces holding a centroid
    Vec2 where{};
    const std::size_t step = std::max<std::size_t>(1, tris.size() / kSamples);
    for (std::size_t k = 0; k < tris.size(); k += step) {
      const std::size_t t = tris[k];
      Vec2 c{};
      for (int i = 0; i < 3; ++i)
        for (int d = 0; d < 2; ++d)
          c[d] += mesh.coords[2 * static_cast<std::size_t>(mesh.triangles[3 * t + i]) + d] / 3.0;
      if (k == 0) where = c;
      std::vector<std::size_t> holding;
      for (std::size_t s = 0; s < boundary.surfaces.size(); ++s) {
        const SurfacePolygons& sp = boundary.surfaces[s];
        bool in = inside(sp.loops.front(), c);
        for (std::size_t h = 1; h < sp.loops.size() && in; ++h) in = !inside(sp.loops[h], c);
        if (in) holding.push_back(s);
      }
      ++votes[holding];
    }
    const auto best =
        std::max_element(votes.begin(), votes.end(),
                         [](const auto& x, const auto& y) { return x.second < y.second; });
    const std::vector<std::size_t>& holding = best->first;
    char near[80];
    std::snprintf(near, sizeof near, "near (%g, %g)", where[0], where[1]);
    if (holding.empty())
      throw InputError(std::string("the region ") + near +
                       " lies in no Plane Surface: a hole inside a hole, or a hole loop that "
                       "crosses or shares a curve with its outer loop");
    if (holding.size() > 1)
      throw InputError("Plane Surface " + std::to_string(boundary.surfaces[holding[0]].id) +
                       " and Plane Surface " + std::to_string(boundary.surfaces[holding[1]].id) +
                       " overlap " + near + " (a surface inside another must be one of its holes)");
    ref_of_region[region] = boundary.surfaces[holding[0]].ref;
  }
  for (auto& r : mesh.tri_ref) r = ref_of_region.at(r);
}

void keep_point_corners(const GeometryBoundary& boundary, Mesh& mesh) {
  const Mesh& d = boundary.domain;
  std::set<std::pair<double, double>> points;  // the geometry's points, kept exactly
  for (std::size_t v = 0; v < d.num_vertices(); ++v)
    if (d.vert_tag[v] & kTagCorner) points.emplace(d.coords[2 * v], d.coords[2 * v + 1]);
  for (std::size_t v = 0; v < mesh.num_vertices() && v < mesh.vert_tag.size(); ++v)
    if ((mesh.vert_tag[v] & kTagCorner) &&
        !points.count({mesh.coords[2 * v], mesh.coords[2 * v + 1]}))
      mesh.vert_tag[v] = static_cast<std::uint8_t>(mesh.vert_tag[v] & ~kTagCorner);
}

}  // namespace riemesh
