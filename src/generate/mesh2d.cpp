#include "generate/mesh2d.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "metric/metric.hpp"
#include "remesh/prepare_metrics.hpp"

namespace riemesh {

namespace {

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

}  // namespace

void Mesh2dOptions::validate() const {
  if (hsiz < 0.0 || !std::isfinite(hsiz)) throw InputError("hsiz must be a positive size");
  if (hsiz > 0.0 && !metric.empty()) throw InputError("a metric and hsiz contradict: give one");
  if (holes.size() % 2 != 0) throw InputError("hole points need two coordinates each");
  adapt.validate();
}

Mesh2dResult mesh_domain2d(const Mesh& boundary, const Mesh2dOptions& options,
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
  Domain2d domain = triangulate_domain2d(boundary, options.holes);
  Mesh& start = domain.mesh;
  if (start.num_edges() == 0 || start.num_vertices() == 0)
    throw InputError("the domain has no boundary edge left to mesh");
  // Every input vertex left lies on a boundary edge unless it was an isolated point inside.
  std::vector<SymMat2> metrics;
  if (!options.metric.empty()) {
    for (const Id v : domain.input_vertex) metrics.push_back(options.metric[v]);
  } else if (options.hsiz > 0.0) {
    metrics.assign(start.num_vertices(), isotropic_metric<2>(options.hsiz));
  } else {
    metrics = boundary_sizes(start);
  }
  // A size far too small for the domain (a mistyped --hsiz or lc) is refused before any point
  // is added instead of exhausting the memory: at most 1e8 vertices (about 2e8 triangles).
  require_reachable_complexity<2>(start, metrics, kMostVertices2d);
  // Field points on the boundary-only triangulation, before any tag meant for adapt2d.
  const FieldPointStats field_points = insert_field_points2d(start, metrics, options.adapt.interp);
  bool given_required = false;
  for (const auto tag : start.edge_tag) given_required |= (tag & kTagRequired) != 0;
  for (const auto tag : start.vert_tag) given_required |= (tag & kTagRequired) != 0;
  if (options.keep_boundary) {
    for (auto& tag : start.edge_tag) tag |= kTagRequired;
    for (std::size_t e = 0; e < start.num_edges(); ++e)
      for (int i = 0; i < 2; ++i) start.vert_tag[start.edges[2 * e + i]] |= kTagRequired;
  }
  Adapt2dResult adapted = adapt2d(start, metrics, options.adapt, on_pass);
  Mesh2dResult out;
  out.mesh = std::move(adapted.mesh);
  if (!given_required) {  // the tags added above were for adapt2d only
    for (auto& tag : out.mesh.edge_tag) tag &= static_cast<std::uint8_t>(~kTagRequired);
    for (auto& tag : out.mesh.vert_tag) tag &= static_cast<std::uint8_t>(~kTagRequired);
  }
  out.metrics = std::move(adapted.metrics);
  out.report = std::move(adapted.report);
  out.field_points = field_points;
  out.regions = domain.regions;
  out.holes = domain.holes;
  return out;
}

}  // namespace riemesh
