#include "generate/regenerate2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "generate/mesh2d.hpp"
#include "mesh/adjacency.hpp"
#include "metric/metric.hpp"
#include "remesh/background.hpp"
#include "remesh/boundary_curves.hpp"
#include "remesh/prepare_metrics.hpp"

namespace riemesh {

namespace {

/// The input's feature curves as a domain for mesh_domain2d: the vertices on them (input order,
/// refs and tags kept, curve corners tagged kTagCorner) and one edge per feature edge, turned so
/// that its triangle is on its left when it has one (both sides: an interface, as listed).
/// Empty when the curves do not make a domain mesh_domain2d takes the same way (a feature edge
/// with no triangle, a curve that ends at a vertex of no other feature edge).
struct CurveDomain {
  Mesh boundary;
  bool usable = false;
};

CurveDomain curve_domain(const Mesh& in, const BoundaryCurves& curves) {
  const std::size_t nf = curves.edges.size(), nv = in.num_vertices();
  // Per feature edge: triangles on its sides, and the direction with a triangle on its left.
  std::vector<int> sides(nf, 0);
  std::vector<Id> from(nf, kNoId);
  for (std::size_t t = 0; t < in.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id a = in.triangles[3 * t + i], b = in.triangles[3 * t + (i + 1) % 3];
      const Id f = curves.find_feature_edge(a, b);
      if (f == kNoId) continue;
      ++sides[f];
      from[f] = a;
    }
  std::vector<int> degree(nv, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    if (sides[f] == 0) return {};
    ++degree[curves.edges[f].v0], ++degree[curves.edges[f].v1];
  }
  CurveDomain out;
  Mesh& b = out.boundary;
  b.dim = 2;
  std::vector<Id> id(nv, kNoId);
  for (std::size_t v = 0; v < nv; ++v) {
    if (degree[v] == 0) {
      if (v < in.vert_tag.size() && (in.vert_tag[v] & kTagRequired)) return {};
      continue;
    }
    if (degree[v] == 1) return {};
    id[v] = static_cast<Id>(b.num_vertices());
    b.coords.insert(b.coords.end(), {in.coords[2 * v], in.coords[2 * v + 1]});
    b.vert_ref.push_back(v < in.vert_ref.size() ? in.vert_ref[v] : 0);
    std::uint8_t tag = v < in.vert_tag.size() ? in.vert_tag[v] : std::uint8_t{kTagNone};
    if (curves.corner[v]) tag |= kTagCorner;
    b.vert_tag.push_back(tag);
  }
  // Two curve vertices at one place (the lips of a crack, a pinch given twice) would be merged
  // by the domain's triangulation: the crack would close.
  std::vector<std::pair<double, double>> places;
  places.reserve(b.num_vertices());
  for (std::size_t v = 0; v < b.num_vertices(); ++v)
    places.emplace_back(b.coords[2 * v], b.coords[2 * v + 1]);
  std::sort(places.begin(), places.end());
  if (std::adjacent_find(places.begin(), places.end()) != places.end()) return {};
  for (std::size_t f = 0; f < nf; ++f) {
    const FeatureEdge& fe = curves.edges[f];
    const Id a = sides[f] == 1 ? from[f] : fe.v0, c = a == fe.v0 ? fe.v1 : fe.v0;
    b.edges.insert(b.edges.end(), {id[a], id[c]});
    b.edge_ref.push_back(fe.ref);
    const auto e = static_cast<std::size_t>(fe.input_edge);
    b.edge_tag.push_back(fe.input_edge != kNoId && e < in.edge_tag.size() ? in.edge_tag[e]
                                                                          : std::uint8_t{kTagNone});
  }
  out.usable = true;
  return out;
}

/// The conditions of regeneration_applies that need no metric: options and tags.
bool allowed(const Mesh& in, std::span<const SymMat2> metrics, const Adapt2dOptions& o) {
  if (in.dim != 2 || in.num_triangles() == 0 || metrics.size() != in.num_vertices()) return false;
  if (!o.insert || !o.swap || !o.move) return false;
  for (const std::uint8_t tag : in.tri_tag)
    if (tag & kTagRequired) return false;
  return same_metric<2>(metrics).has_value();
}

/// The triangles the constant metric m asks for over the mesh: (4/√3) ∫ sqrt(det m).
double unit_triangles(const Mesh& in, const SymMat2& m) {
  double area = 0.0;
  for (std::size_t t = 0; t < in.num_triangles(); ++t) {
    const double* p = &in.coords[2 * static_cast<std::size_t>(in.triangles[3 * t])];
    const double* q = &in.coords[2 * static_cast<std::size_t>(in.triangles[3 * t + 1])];
    const double* r = &in.coords[2 * static_cast<std::size_t>(in.triangles[3 * t + 2])];
    area += 0.5 * ((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]));
  }
  return 4.0 / std::sqrt(3.0) * area * std::sqrt(det(m));
}

/// The metric after adapt2d's clipping to [hmin, hmax] (its notes go to `report`).
SymMat2 prepared_metric(const Mesh& in, std::span<const SymMat2> metrics, const Adapt2dOptions& o,
                        Adapt2dReport& report) {
  Adapt2dOptions no_gradation = o;  // a constant field has nothing to grade
  no_gradation.hgrad = 0.0;
  return prepare_metrics<2>(in, Adjacency{}, metrics, no_gradation, report).front();
}

/// Each region's triangles (refs 1, 2, ... from mesh_domain2d) take the input's triangle ref at
/// the centre of one of them, preferably one with no vertex on an edge (a boundary vertex on a
/// curved reconstruction may lie just outside the input's triangles).
void restore_region_refs(const Mesh& in, const SymMat2& m, int regions, Mesh& out) {
  std::vector<std::uint8_t> on_edge(out.num_vertices(), 0);
  for (const Id v : out.edges) on_edge[v] = 1;
  std::vector<Id> pick(static_cast<std::size_t>(regions) + 1, kNoId);
  std::vector<std::uint8_t> inner(pick.size(), 0);
  for (std::size_t t = 0; t < out.num_triangles(); ++t) {
    const auto r = static_cast<std::size_t>(out.tri_ref[t]);
    if (r >= pick.size() || inner[r]) continue;
    const Id* v = &out.triangles[3 * t];
    const bool deep = !on_edge[v[0]] && !on_edge[v[1]] && !on_edge[v[2]];
    if (pick[r] == kNoId || deep) pick[r] = static_cast<Id>(t), inner[r] = deep;
  }
  std::vector<double> packed(3 * in.num_vertices());
  for (std::size_t v = 0; v < in.num_vertices(); ++v) std::copy_n(m.c, 3, &packed[3 * v]);
  const BackgroundMesh<2> background(in, packed);
  std::vector<std::int32_t> ref(pick.size(), 0);
  for (std::size_t r = 1; r < pick.size(); ++r) {
    if (pick[r] == kNoId) continue;
    Vec2 c{{0.0, 0.0}};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 2; ++k)
        c[k] += out.coords[2 * static_cast<std::size_t>(out.triangles[3 * pick[r] + i]) + k] / 3.0;
    ref[r] = in.tri_ref[static_cast<std::size_t>(background.locate(c).simplex)];
  }
  for (auto& r : out.tri_ref) r = ref[static_cast<std::size_t>(r)];
}

/// What adapt_or_regenerate2d meshes afresh: the metric after clipping (its notes in `report`),
/// how many times the input's triangles it asks for, and the input's curves as a domain.
struct Regeneration {
  SymMat2 metric;
  double ratio = 0.0;
  Mesh boundary;
  Adapt2dReport report;
};

/// The regeneration, or nullopt when adapt2d's passes are to run (the conditions of
/// regeneration_applies). InputError as adapt2d for input it refuses (checked first).
std::optional<Regeneration> plan_regeneration(const Mesh& input, std::span<const SymMat2> metrics,
                                              const Adapt2dOptions& options) {
  if (!allowed(input, metrics, options)) return std::nullopt;
  require_valid_input<2>(input, metrics);  // adapt2d's errors, before anything else
  Regeneration plan;
  plan.metric = prepared_metric(input, metrics, options, plan.report);
  plan.ratio = unit_triangles(input, plan.metric) / static_cast<double>(input.num_triangles());
  if (plan.ratio < kRegenerateRatio) return std::nullopt;
  // (adapt2d's test; the mesh made afresh is many times the input: its adjacency costs little.)
  require_unfolded(input, build_face_adjacency(input.triangles, 3, input.num_vertices()));
  const BoundaryCurves curves =
      build_boundary_curves(input, {options.angle_deg, options.detect_angles});
  CurveDomain domain = curve_domain(input, curves);
  if (!domain.usable) return std::nullopt;
  plan.boundary = std::move(domain.boundary);
  return plan;
}

std::string regeneration_note(double ratio) {
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "the metric is the same everywhere and asks for %.3g times the input's triangles: "
                "the domain was meshed afresh from its boundary (the metric's unit lattice inside)",
                ratio);
  return buf;
}

}  // namespace

bool regeneration_applies(const Mesh& input, std::span<const SymMat2> metrics,
                          const Adapt2dOptions& options) {
  try {
    return plan_regeneration(input, metrics, options).has_value();
  } catch (const InputError&) {  // (adapt2d's errors: the input is not one to mesh afresh)
    return false;
  }
}

Adapt2dResult adapt_or_regenerate2d(const Mesh& input, std::span<const SymMat2> metrics,
                                    const Adapt2dOptions& options, const PassCallback& on_pass) {
  options.validate();
  std::optional<Regeneration> plan = plan_regeneration(input, metrics, options);
  if (!plan) return adapt2d(input, metrics, options, on_pass);
  const SymMat2 m = plan->metric;
  Mesh2dOptions mo;
  mo.metric.assign(plan->boundary.num_vertices(), m);
  mo.keep_boundary = false;
  mo.adapt = options;
  mo.adapt.hgrad = 0.0;
  Mesh2dResult meshed;
  try {
    meshed = mesh_domain2d(plan->boundary, mo, on_pass);
  } catch (const InputError&) {
    // The curves of a valid mesh that do not make a domain (e.g. crossing ones in a folded
    // mesh): the passes decide, and name the input's own places if it is at fault.
    return adapt2d(input, metrics, options, on_pass);
  }
  restore_region_refs(input, m, meshed.regions, meshed.mesh);
  Adapt2dResult out;
  out.mesh = std::move(meshed.mesh);
  out.metrics = std::move(meshed.metrics);
  out.report = std::move(meshed.report);
  // The clipping notes once (adapt2d clips the clipped metric again, to the same effect).
  const std::vector<std::string>& clipped = plan->report.notes;
  for (auto it = clipped.rbegin(); it != clipped.rend(); ++it)
    if (std::find(out.report.notes.begin(), out.report.notes.end(), *it) == out.report.notes.end())
      out.report.notes.insert(out.report.notes.begin(), *it);
  out.report.notes.push_back(regeneration_note(plan->ratio));
  return out;
}

}  // namespace riemesh
