#include "generate/mesh2d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "generate/lattice2d.hpp"
#include "mesh/distance.hpp"
#include "metric/metric.hpp"
#include "remesh/boundary_curves.hpp"
#include "remesh/prepare_metrics.hpp"

namespace riemesh {

namespace {

/// The mesh without its triangles: the curves of its Edges alone (build_boundary_curves reads
/// the triangles' sides too).
Mesh edges_only(const Mesh& m) {
  Mesh out;
  out.dim = m.dim;
  out.coords = m.coords, out.vert_ref = m.vert_ref, out.vert_tag = m.vert_tag;
  out.edges = m.edges, out.edge_ref = m.edge_ref, out.edge_tag = m.edge_tag;
  return out;
}

BoundaryCurves edge_curves(const Mesh& edges, const Adapt2dOptions& options) {
  return build_boundary_curves(edges, {options.angle_deg, options.detect_angles});
}

/// The mean length of the boundary edges at each vertex, as an isotropic metric.
std::vector<SymMat2> boundary_sizes(const Mesh& m) {
  const std::size_t nv = m.num_vertices();
  std::vector<double> sum(nv, 0.0);
  std::vector<int> count(nv, 0);
  for (std::size_t e = 0; e < m.num_edges(); ++e) {
    const Id a = m.edges[2 * e], b = m.edges[2 * e + 1];
    const double l = std::hypot(m.coords[2 * b] - m.coords[2 * a], m.coords[2 * b + 1] - m.coords[2 * a + 1]);
    sum[a] += l, sum[b] += l;
    ++count[a], ++count[b];
  }
  // Points inside the domain that are on no edge take the mean of all boundary edges.
  double all = 0.0;
  for (std::size_t v = 0; v < nv; ++v) all += sum[v];
  const double mean = all / (2.0 * static_cast<double>(m.num_edges()));
  std::vector<SymMat2> out(nv);
  for (std::size_t v = 0; v < nv; ++v)
    out[v] = isotropic_metric<2>(count[v] > 0 ? sum[v] / count[v] : mean);
  return out;
}

/// The boundary with its edges cut to unit length in the size field before it is triangulated
/// (when the boundary is to be remeshed): each edge (not required) into n = round(L) pieces,
/// L its metric length (the mean of its ends'), the new vertices at equal arc lengths on the
/// boundary curve's smooth reconstruction — the one adapt2d then places its boundary vertices on
/// (remesh/boundary_curves.hpp, corners by `angle`) — each with the metric of its ends
/// interpolated (`metrics`, one per vertex, is extended). An edge listed twice (an interface
/// given in both directions) gets the same vertices. The field points then start from a boundary
/// at the sizes asked: on a long coarse boundary they kept 1/2 away from edges that adapt2d cut
/// into hundreds of pieces afterwards, leaving needles it could not repair (a 1:100 metric on
/// the square given by 4 edges a side: 72.8% of the edges in band, 99.2% with the cut).
Mesh split_boundary(const Mesh& boundary, std::vector<SymMat2>& metrics,
                    const Adapt2dOptions& options) {
  Mesh out = edges_only(boundary);
  const BoundaryCurves curves = edge_curves(out, options);
  out.edges.clear(), out.edge_ref.clear(), out.edge_tag.clear();
  out.vert_ref.resize(out.num_vertices(), 0);
  out.vert_tag.resize(out.num_vertices(), kTagNone);
  // The corners of the given boundary stay corners: between the shorter chords on the smooth
  // reconstruction, adapt2d's angle test could no longer see a corner whose turn is near `angle`.
  for (std::size_t v = 0; v < out.num_vertices(); ++v)
    if (curves.corner[v]) out.vert_tag[v] |= kTagCorner;
  std::map<Id, std::vector<Id>> inside;  // feature edge -> its new vertices, curve order
  const auto xy = [&](Id v) {
    return Vec2{{out.coords[2 * static_cast<std::size_t>(v)],
                 out.coords[2 * static_cast<std::size_t>(v) + 1]}};
  };
  for (std::size_t e = 0; e < boundary.num_edges(); ++e) {
    const Id a = boundary.edges[2 * e], b = boundary.edges[2 * e + 1];
    const std::int32_t ref = boundary.edge_ref[e];
    const std::uint8_t tag =
        e < boundary.edge_tag.size() ? boundary.edge_tag[e] : static_cast<std::uint8_t>(kTagNone);
    const Id f = curves.input_edge2feature[e];
    const FeatureEdge& fe = curves.edges[static_cast<std::size_t>(f)];
    const BoundaryCurve& c = curves.curves[static_cast<std::size_t>(fe.curve)];
    const bool forward = c.vertices[static_cast<std::size_t>(fe.index)] == a;
    auto [it, fresh] = inside.emplace(f, std::vector<Id>{});
    if (fresh && !(tag & kTagRequired) && a != b) {
      const Vec2 d = xy(b) - xy(a);
      const double length =
          0.5 * (std::sqrt(quadratic(metrics[a], d)) + std::sqrt(quadratic(metrics[b], d)));
      const long n = std::isfinite(length) ? std::lround(std::min(length, 1e7)) : 1;
      const double s0 = static_cast<double>(fe.index), s1 = s0 + 1.0;
      const Id from = c.vertices[static_cast<std::size_t>(fe.index)];
      const Id to = c.vertices[static_cast<std::size_t>(fe.index) + 1];
      for (long i = 1; i < n; ++i) {
        const double t = static_cast<double>(i) / static_cast<double>(n);
        const Vec2 p = point(c, param_at_fraction(c, s0, s1, t));
        it->second.push_back(static_cast<Id>(out.num_vertices()));
        out.coords.insert(out.coords.end(), {p[0], p[1]});
        out.vert_ref.push_back(0);
        out.vert_tag.push_back(kTagNone);
        metrics.push_back(interpolate<2>(options.interp, metrics[from], metrics[to], t));
      }
    }
    std::vector<Id> chain{a};
    if (forward)
      chain.insert(chain.end(), it->second.begin(), it->second.end());
    else
      chain.insert(chain.end(), it->second.rbegin(), it->second.rend());
    chain.push_back(b);
    for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
      out.edges.insert(out.edges.end(), {chain[k], chain[k + 1]});
      out.edge_ref.push_back(ref);
      out.edge_tag.push_back(tag);
    }
  }
  return out;
}

/// Lattice points closer than this to the boundary (in the metric) are left out: the first row
/// kept is 0.43–1.30 away from a boundary edge at unit spacing (1/2 to 1.37 with 1/2), centred
/// on the √3/2 of a unit equilateral triangle.
constexpr double kLatticeClearance = 0.43;

/// The largest move of a lattice point's image before it is triangulated (with_lattice).
constexpr double kLatticeJitter = 1e-7;

/// Sorts the triangles of m by their smallest vertex (refs follow; tags are all none here): the
/// triangles of the Hilbert-ordered insertion then follow the vertex numbering, which the
/// optimiser's sweeps visit in order (a 2.3 M-triangle lattice mesh: its set-up and first pass
/// 3.4 s in insertion order, 2.0 s so).
void sort_triangles_by_vertex(Mesh& m) {
  const std::size_t nt = m.num_triangles(), nv = m.num_vertices();
  const auto low = [&](std::size_t t) {
    return static_cast<std::size_t>(
        std::min({m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]}));
  };
  std::vector<std::size_t> start = huge_vector<std::size_t>(nv + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) ++start[low(t) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<Id> tri = huge_vector<Id>(3 * nt);
  std::vector<std::int32_t> ref = huge_vector<std::int32_t>(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const std::size_t k = start[low(t)]++;
    std::copy_n(&m.triangles[3 * t], 3, &tri[3 * k]);
    ref[k] = m.tri_ref[t];
  }
  m.triangles.swap(tri);
  m.tri_ref.swap(ref);
}

/// `bare` (the triangulation of `boundary`'s Edges alone) again with the lattice points of the
/// constant metric m inside it (lattice2d.hpp), triangulated in m's unit space so that they make
/// unit equilateral triangles; `given` (the metric per vertex of `boundary`) is extended to them.
/// The vertices keep the lattice's row order; the coordinates are those of the points as given,
/// not mapped back and forth.
Domain2d with_lattice(const Mesh& boundary, Domain2d bare, const SymMat2 m,
                      std::span<const double> holes, bool no_holes, std::vector<SymMat2>& given,
                      std::size_t* count) {
  const std::vector<double> points = lattice_points2d(bare.mesh, m, kLatticeClearance);
  *count = points.size() / 2;
  if (points.empty()) return bare;
  const MetricMap2d map(m);
  Mesh unit;  // the boundary's Edges and vertices, and the points, in the unit space
  unit.dim = 2;
  const std::size_t n0 = boundary.num_vertices(), n = n0 + points.size() / 2;
  reserve_huge(unit.coords, 2 * n);
  unit.coords.resize(2 * n);
  for (std::size_t v = 0; v < n0; ++v) map.to_unit(&boundary.coords[2 * v], &unit.coords[2 * v]);
  // The lattice points' images are exact lattice points up to rounding, and the partial
  // triangulations along the insertion meet many cocircular ones (rectangles of the lattice),
  // each decided by the exact in-circle predicate: moved by a fixed pseudo-random amount below
  // kLatticeJitter (unit lengths), they no longer are (1.15 M points: 0.57 -> 0.26 s in
  // delaunay2d). The finished triangulation has no such ties away from the boundary, so it is the
  // lattice's, and the points keep their exact coordinates (below).
  for (std::size_t v = n0; v < n; ++v) {
    double* u = &unit.coords[2 * v];
    map.to_unit(&points[2 * (v - n0)], u);
    const double k = static_cast<double>(v - n0);
    u[0] += kLatticeJitter *
            (2.0 * (k * 0.6180339887498949 - std::floor(k * 0.6180339887498949)) - 1.0);
    u[1] += kLatticeJitter *
            (2.0 * (k * 0.4142135623730950 - std::floor(k * 0.4142135623730950)) - 1.0);
  }
  unit.vert_ref = boundary.vert_ref, unit.vert_tag = boundary.vert_tag;
  unit.vert_ref.resize(n, 0), unit.vert_tag.resize(n, kTagNone);
  unit.edges = boundary.edges, unit.edge_ref = boundary.edge_ref, unit.edge_tag = boundary.edge_tag;
  std::vector<double> unit_holes(holes.size());
  for (std::size_t k = 0; 2 * k + 1 < holes.size(); ++k)
    map.to_unit(&holes[2 * k], &unit_holes[2 * k]);
  // Inserted along the Hilbert curve (the rows' order costs 3.4 times as many instructions:
  // each new row meets the long triangles from the last one to the far boundary).
  Domain2d d = triangulate_domain2d(unit, unit_holes, InsertionOrder::kHilbert, no_holes);
  for (std::size_t v = 0; v < d.mesh.num_vertices(); ++v) {
    const auto w = static_cast<std::size_t>(d.input_vertex[v]);
    const double* x = w < n0 ? &boundary.coords[2 * w] : &points[2 * (w - n0)];
    d.mesh.coords[2 * v] = x[0], d.mesh.coords[2 * v + 1] = x[1];
  }
  sort_triangles_by_vertex(d.mesh);
  given.resize(n, m);
  return d;
}

}  // namespace

void Mesh2dOptions::validate() const {
  if (hsiz < 0.0 || !std::isfinite(hsiz)) throw InputError("hsiz must be a positive size");
  if (hsiz > 0.0 && !metric.empty()) throw InputError("a metric and hsiz contradict: give one");
  if (holes.size() % 2 != 0) throw InputError("hole points need two coordinates each");
  if (no_holes && !holes.empty()) throw InputError("hole points and no holes contradict");
  adapt.validate();
}

namespace {

/// The boundary kept as given is required for adapt2d, which makes every vertex of it a corner:
/// written so, they kept a later `adapt` from placing new boundary points on the curve (the NACA
/// far field: chords 59 times --hausd off the circle). Corners are those of the boundary's own
/// curves (turns above --angle, ref changes, junctions) and the input's Corners.
void keep_real_corners(const Mesh& boundary, const Adapt2dOptions& options, Mesh& out) {
  std::set<std::pair<double, double>> given;
  for (std::size_t v = 0; v < boundary.num_vertices(); ++v)
    if (v < boundary.vert_tag.size() && (boundary.vert_tag[v] & kTagCorner))
      given.insert({boundary.coords[2 * v], boundary.coords[2 * v + 1]});
  Mesh edges = edges_only(out);
  edges.vert_tag.assign(out.num_vertices(), kTagNone);  // (every kept vertex is a corner there)
  const BoundaryCurves curves = edge_curves(edges, options);
  for (std::size_t v = 0; v < out.num_vertices(); ++v) {
    if (!(out.vert_tag[v] & kTagCorner)) continue;
    if (!curves.corner[v] && !given.count({out.coords[2 * v], out.coords[2 * v + 1]}))
      out.vert_tag[v] &= static_cast<std::uint8_t>(~kTagCorner);
  }
}

/// --hausd alone: at each boundary vertex the smaller of its edges' mean length and the size
/// --hausd allows on its curves (as adapt2d tightens it, over √2), as an isotropic metric, so
/// that the inside follows the boundary as cut (the sizes of the coarse input edges inside left
/// fans of needles along a finely cut circle: quality mean 0.31, min 0.06).
std::vector<SymMat2> hausd_sizes(const Mesh& boundary, const Adapt2dOptions& options) {
  const Mesh edges = edges_only(boundary);
  const BoundaryCurves curves = edge_curves(edges, options);
  std::vector<SymMat2> out = boundary_sizes(edges);
  for (std::size_t v = 0; v < out.size(); ++v) {
    double h = 1.0 / std::sqrt(out[v](0, 0));
    for (const CurveVertex& cv : curves.curves_at(static_cast<Id>(v)))
      h = std::min(
          h, 0.7071067811865476 * hausd_size(curves.curves[static_cast<std::size_t>(cv.curve)],
                                             cv.param, options.hausd));
    out[v] = isotropic_metric<2>(std::max(h, options.hmin));
  }
  return out;
}

/// Sizes this many times the domain's bounding-box diagonal and more all give its coarsest mesh
/// (the boundary and --hausd decide it: the lake of Geneva, 40 across, has 176 vertices from
/// --hsiz 1e12 up, as at 1e80).
constexpr double kFarBeyondTheDomain = 1e10;

/// `hsiz`, clamped to kFarBeyondTheDomain times the domain before it is squared: --hsiz 1e100
/// made a metric of 1e-200 whose determinant underflows, and the lattice refused it as "not
/// positive definite", blaming the domain.
double reachable_size(const Mesh& boundary, double hsiz) {
  const double far = kFarBeyondTheDomain * bounding_box_diagonal(boundary);
  return far > 0.0 ? std::min(hsiz, far) : hsiz;
}

/// The boundary cut to the sizes crosses itself (mesh_domain2d_impl): the caller retries with
/// straight edges.
struct CutBoundaryCrosses : InputError {
  using InputError::InputError;
};

Mesh2dResult mesh_domain2d_impl(const Mesh& boundary, const Mesh2dOptions& options,
                                const PassCallback& on_pass) {
  options.validate();
  if (!options.metric.empty() && options.metric.size() != boundary.num_vertices()) {
    std::string msg = "the metric has ";
    msg += std::to_string(options.metric.size());
    msg += " values for ";
    msg += std::to_string(boundary.num_vertices());
    msg += " vertices";
    throw InputError(msg);
  }
  // A boundary to remesh to a size field is first cut to it (split_boundary).
  std::vector<SymMat2> given = options.metric;
  if (given.empty() && options.hsiz > 0.0)
    given.assign(boundary.num_vertices(),
                 isotropic_metric<2>(reachable_size(boundary, options.hsiz)));
  if (given.empty() && !options.keep_boundary && options.adapt.hausd > 0.0)
    given = hausd_sizes(boundary, options.adapt);
  // The boundary as given is checked first (open loops, crossing or zero-length edges, hole
  // points): cut first, two crossing edges would meet at a shared new vertex.
  Domain2d domain =
      triangulate_domain2d(boundary, options.holes, InsertionOrder::kBrio, options.no_holes);
  // Every input vertex left lies on a boundary edge unless it was an isolated point inside.
  const auto sizes = [&](const Domain2d& d) {
    std::vector<SymMat2> out;
    if (given.empty()) return boundary_sizes(d.mesh);
    reserve_huge(out, d.input_vertex.size());
    for (const Id v : d.input_vertex) out.push_back(given[v]);
    return out;
  };
  if (domain.mesh.num_edges() == 0 || domain.mesh.num_vertices() == 0)
    throw InputError("the domain has no boundary edge left to mesh");
  std::vector<SymMat2> metrics = sizes(domain);
  // A size far too small for the domain (a mistyped --hsiz or lc) is refused before any point
  // is added (and before the boundary is cut) instead of exhausting the memory: at most 1e8
  // vertices (about 2e8 triangles).
  require_reachable_complexity<2>(
      domain.mesh, metrics, kMostVertices2d,
      given.empty() ? ComplexityBound::kLinearSizes : ComplexityBound::kLogEuclidean);
  // A constant metric (--hsiz, or one tensor everywhere): its unit lattice fills the inside.
  const bool constant = same_metric<2>(given).has_value();
  std::size_t lattice_points = 0;
  const Mesh cut = !options.keep_boundary && !given.empty()
                       ? split_boundary(boundary, given, options.adapt)
                       : Mesh{};
  if (!cut.edges.empty()) {
    // The boundary as given passed the checks above: a defect now is the reconstruction's (a
    // smooth curve through a vertex that turns less than --angle, bulging across a sharp spike
    // next to it), in edges of the cut boundary the user never saw.
    try {
      domain = triangulate_domain2d(cut, options.holes, InsertionOrder::kBrio, options.no_holes);
    } catch (const InputError& e) {
      throw CutBoundaryCrosses(e.what());
    }
  }
  if (constant) {  // (the cut's metrics too: interpolating equal metrics is exact)
    const SymMat2 m = given.front();
    domain = with_lattice(cut.edges.empty() ? boundary : cut, std::move(domain), m, options.holes,
                          options.no_holes, given, &lattice_points);
  }
  if (!cut.edges.empty() || constant) metrics = sizes(domain);
  Mesh& start = domain.mesh;
  // Field points on the boundary-only triangulation, before any tag meant for adapt2d.
  const FieldPointStats field_points = insert_field_points2d(start, metrics, options.adapt.interp);
  // The required entities given, by place (adapt2d renumbers): the tags added below for a kept
  // boundary are taken off again, theirs kept (one RequiredVertices entry left every boundary
  // vertex and edge required and a corner in the output: QA hunt 5 F5).
  using Point = std::pair<double, double>;
  const auto point = [](const Mesh& m, Id v) {
    return Point{m.coords[2 * static_cast<std::size_t>(v)],
                 m.coords[2 * static_cast<std::size_t>(v) + 1]};
  };
  const auto edge_key = [&](const Mesh& m, std::size_t e) {
    const Point a = point(m, m.edges[2 * e]), b = point(m, m.edges[2 * e + 1]);
    return a < b ? std::pair{a, b} : std::pair{b, a};
  };
  std::set<Point> required_vertices;
  std::set<std::pair<Point, Point>> required_edges;
  for (std::size_t v = 0; v < start.vert_tag.size(); ++v)
    if (start.vert_tag[v] & kTagRequired)
      required_vertices.insert(point(start, static_cast<Id>(v)));
  for (std::size_t e = 0; e < start.edge_tag.size(); ++e)
    if (start.edge_tag[e] & kTagRequired) required_edges.insert(edge_key(start, e));
  if (options.keep_boundary) {
    for (auto& tag : start.edge_tag) tag |= kTagRequired;
    for (std::size_t e = 0; e < start.num_edges(); ++e)
      for (int i = 0; i < 2; ++i) start.vert_tag[start.edges[2 * e + i]] |= kTagRequired;
  }
  given = {};  // (the remesher copies what it needs: memory of large runs)
  Adapt2dResult adapted = adapt2d(std::move(start), std::move(metrics), options.adapt, on_pass);
  Mesh2dResult out;
  out.mesh = std::move(adapted.mesh);
  if (options.keep_boundary) {  // the tags added above were for adapt2d only
    Mesh& m = out.mesh;
    for (std::size_t e = 0; e < m.edge_tag.size(); ++e)
      if (!required_edges.count(edge_key(m, e)))
        m.edge_tag[e] &= static_cast<std::uint8_t>(~kTagRequired);
    for (std::size_t v = 0; v < m.vert_tag.size(); ++v)
      if (!required_vertices.count(point(m, static_cast<Id>(v))))
        m.vert_tag[v] &= static_cast<std::uint8_t>(~kTagRequired);
    keep_real_corners(boundary, options.adapt, m);
  }
  out.metrics = std::move(adapted.metrics);
  out.report = std::move(adapted.report);
  out.field_points = field_points;
  out.lattice_points = lattice_points;
  out.regions = domain.regions;
  out.holes = domain.holes;
  return out;
}

}  // namespace

Mesh2dResult mesh_domain2d(const Mesh& boundary, const Mesh2dOptions& options,
                           const PassCallback& on_pass) {
  try {
    return mesh_domain2d_impl(boundary, options, on_pass);
  } catch (const CutBoundaryCrosses& e) {
    // The smooth reconstruction through a vertex turning less than the corner angle bulged
    // across a sharp spike next to it (a star polygon at --hsiz 0.05 was refused, naming edges
    // of the cut boundary the user never saw): every turning vertex a corner, the boundary is
    // cut along its straight edges, which cannot cross (the boundary as given passed).
    Mesh2dOptions straight = options;
    straight.adapt.angle_deg = 0.0;
    straight.adapt.detect_angles = true;
    Mesh2dResult out = mesh_domain2d_impl(boundary, straight, on_pass);
    out.report.notes.push_back(
        std::string("the boundary's smooth reconstruction crossed itself (") + e.what() +
        "): it is kept straight between its vertices instead, every vertex a corner");
    return out;
  }
}

}  // namespace riemesh
