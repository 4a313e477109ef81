#include "remesh/prepare_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "core/huge_pages.hpp"
#include "core/spd.hpp"
#include "mesh/check.hpp"
#include "metric/gradation.hpp"
#include "metric/metric.hpp"
#include "remesh/simplex_geometry.hpp"

namespace riemesh {
namespace {

// Unit-mesh vertex count per unit of complexity: (2/√3) in 2D, √2 in 3D (regular simplices).
template <int D>
constexpr double kVerticesPerComplexity = D == 2 ? 1.1547005383792515 : 1.4142135623730951;

}  // namespace

template <int D>
void require_reachable_complexity(const Mesh& in, std::span<const SymMat<D>> m, double max_vertices,
                                  ComplexityBound bound) {
  // Only the order of magnitude matters here: each element's measure times the arithmetic
  // (log-Euclidean) or geometric (linear sizes) mean of its vertices' sqrt(det M), one root
  // per vertex.
  const bool geometric = bound == ComplexityBound::kLinearSizes;
  const std::vector<Id>& elems = D == 2 ? in.triangles : in.tets;
  std::vector<double> density(m.size());
  for (std::size_t v = 0; v < m.size(); ++v)
    density[v] = geometric ? 0.5 * std::log(det(m[v])) : std::sqrt(det(m[v]));
  double total = 0.0;
  for (std::size_t e = 0; e + D < elems.size(); e += D + 1) {
    Vec<D> p[D + 1];
    double mean = 0.0;
    for (int i = 0; i <= D; ++i) {
      const Id v = elems[e + i];
      for (int k = 0; k < D; ++k) p[i][k] = in.coords[D * v + k];
      mean += density[v] / (D + 1);
    }
    total += std::abs(simplex_measure(p)) * (geometric ? std::exp(mean) : mean);
  }
  const double vertices = kVerticesPerComplexity<D> * total;
  const double ids = static_cast<double>(std::numeric_limits<Id>::max());
  if (vertices <= std::min(max_vertices, ids)) return;
  std::size_t finest = 0;
  for (std::size_t v = 1; v < m.size(); ++v)
    if (!(det(m[v]) <= det(m[finest]))) finest = v;
  std::string where = "(";
  for (int i = 0; i < D; ++i) where += (i > 0 ? ", " : "") + format_g(in.coords[D * finest + i]);
  // Its size from the determinant, or (overflowing: --hsiz 1e-100) the largest eigenvalue.
  const double d = det(m[finest]);
  const double size =
      std::isfinite(d) ? std::pow(d, -0.5 / D) : 1.0 / std::sqrt(eigen(m[finest]).values[D - 1]);
  throw InputError(
      "the metric asks for " +
      (std::isfinite(vertices) ? "about " + format_g(vertices)
                               : std::string("an unbounded number of")) +
      " vertices, more than " +
      (max_vertices < ids ? format_g(max_vertices) : std::string("the 2^31 - 1 ids hold")) +
      "; finest size " + (size > 0.0 ? format_g(size) : std::string("~0 (determinant overflows)")) +
      " near " + where + "): ask for coarser sizes, or bound them with --hmin");
}

template void require_reachable_complexity<2>(const Mesh&, std::span<const SymMat2>, double,
                                              ComplexityBound);
template void require_reachable_complexity<3>(const Mesh&, std::span<const SymMat3>, double,
                                              ComplexityBound);

template <int D>
std::vector<SymMat<D>> prepare_metrics(const Mesh& in, const Adjacency& adj,
                                       std::span<const SymMat<D>> metrics, const Adapt2dOptions& o,
                                       Adapt2dReport& report) {
  if (metrics.size() != in.num_vertices())
    throw InputError("the metric has " + std::to_string(metrics.size()) + " values but the mesh " +
                     std::to_string(in.num_vertices()) + " vertices");
  std::vector<SymMat<D>> out;
  reserve_huge(out, metrics.size());
  out.assign(metrics.begin(), metrics.end());
  const double lo = std::isfinite(o.hmax) ? 1.0 / (o.hmax * o.hmax) : 0.0;
  const double hi = o.hmin > 0.0 ? 1.0 / (o.hmin * o.hmin) : std::numeric_limits<double>::max();
  std::size_t below_hmin = 0, above_hmax = 0, first_below = 0;
  for (std::size_t v = 0; v < out.size(); ++v) {
    // The vertex's name only for the error (building it cost more than the test).
    if (!is_spd(out[v])) require_metric(out[v], "vertex " + std::to_string(v + 1));
    if (lo > 0.0 || hi < std::numeric_limits<double>::max()) {
      const SymEigen<D> e = eigen(out[v]);
      if (e.values[D - 1] > hi && below_hmin++ == 0) first_below = v;
      above_hmax += e.values[0] < lo ? 1 : 0;
      out[v] = project_spd(out[v], lo, hi);
    }
  }
  if (below_hmin > 0) {
    std::string note = "the metric asks for sizes below --hmin " + format_g(o.hmin) + " at ";
    note += std::to_string(below_hmin);
    note += " vertices, e.g. near (";
    for (int i = 0; i < D; ++i) {
      if (i > 0) note += ", ";
      note += format_g(in.coords[D * first_below + i]);
    }
    note += "): clipped to --hmin";
    report.notes.push_back(note);
  }
  if (above_hmax > 0)
    report.notes.push_back("sizes above --hmax " + format_g(o.hmax) + " clipped at " +
                           std::to_string(above_hmax) + " vertices");
  require_reachable_complexity<D>(in, out, D == 2 ? kMostVertices2d : kMostVertices3d);
  if (o.hgrad > 0.0) {
    GradationOptions g;
    g.mode = GradationMode::kGrowthPhysical;
    g.threshold = o.hgrad;
    const GradationReport r = gradate<D>(in.coords, adj.edges, std::span<SymMat<D>>(out), g);
    report.gradation_before = r.measure_before;
    report.gradation_after = r.measure_after;
    // Gradation only shrinks sizes: --hmin again after it (it left 0.00991 for --hmin 0.01).
    if (hi < std::numeric_limits<double>::max())
      for (SymMat<D>& m : out) m = project_spd(m, 0.0, hi);
  }
  return out;
}

template <int D>
void require_valid_input(const Mesh& in, std::span<const SymMat<D>> metrics) {
  const std::vector<Id>& elems = D == 2 ? in.triangles : in.tets;
  const char* name = D == 2 ? "triangle " : "tetrahedron ";
  const std::size_t nv = in.num_vertices();
  for (std::size_t e = 0; e + D < elems.size(); e += D + 1) {
    Vec<D> p[D + 1];
    for (int i = 0; i <= D; ++i) {
      const Id v = elems[e + i];
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw InputError(name + std::to_string(e / (D + 1) + 1) + ": vertex id out of range");
      for (int k = 0; k < D; ++k) p[i][k] = in.coords[D * v + k];
    }
    // In 3D a volume rounded to zero or below is decided by the exact orientation: a flat
    // sliver of a Delaunay tetrahedralisation (between nearly cospherical points) is valid, and
    // the remesher's sliver sweeps remove it.
    if (!(simplex_measure<D>(p) > 0.0) && !(D == 3 && simplex::exact_orientation(p) > 0.0))
      throw InputError(name + std::to_string(e / (D + 1) + 1) +
                       (D == 2 ? " is clockwise or degenerate"
                               : " has a negative or zero volume (3D remeshing needs positive tets)"));
  }
  // An edge listed twice with different refs kept one of them without a word (2D; the 3D
  // context refuses it where it reads the edges, as `riemesh mesh` does in 2D).
  if (D == 2 && in.edge_ref.size() == in.num_edges()) {
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    keys.reserve(in.num_edges());
    for (std::size_t e = 0; e < in.num_edges(); ++e) {
      const auto a = static_cast<std::uint32_t>(std::min(in.edges[2 * e], in.edges[2 * e + 1]));
      const auto b = static_cast<std::uint32_t>(std::max(in.edges[2 * e], in.edges[2 * e + 1]));
      keys.push_back({(std::uint64_t{a} << 32) | b, e});
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t k = 1; k < keys.size(); ++k) {
      const std::size_t e0 = keys[k - 1].second, e1 = keys[k].second;
      if (keys[k].first != keys[k - 1].first || in.edge_ref[e0] == in.edge_ref[e1]) continue;
      refuse_edge_refs("edge", e0, e1, in.edge_ref[e0], in.edge_ref[e1]);
    }
  }
  // The name only for the error: building it for every vertex cost more than the test.
  for (std::size_t v = 0; v < metrics.size(); ++v)
    if (!is_spd(metrics[v]) || !std::isfinite(det(metrics[v])))
      require_metric(metrics[v], "vertex " + std::to_string(v + 1));
}

void require_unfolded(const Mesh& in, const Adjacency& adj) {
  // Edges on three triangles or more (a triangle listed twice, whose copies then "fold" across
  // a side) are named as such when the remesher reads the triangles.
  if (!adj.nonmanifold_faces.empty()) return;
  const std::vector<PlanarFold> folds = planar_folds(in.coords, in.triangles, adj, 1);
  if (folds.empty()) return;
  const Id* t = &in.triangles[3 * folds[0].triangle];
  const auto x = [&](int k, int c) {
    return in.coords[2 * static_cast<std::size_t>(t[kTriEdge[folds[0].edge][k]]) + c];
  };
  char msg[240];
  std::snprintf(msg, sizeof msg,
                "the mesh folds over itself at (%g, %g): two counter-clockwise triangles lie on "
                "the same side of their common edge there (riemesh check: overlapping elements)",
                0.5 * (x(0, 0) + x(1, 0)), 0.5 * (x(0, 1) + x(1, 1)));
  throw InputError(msg);
}

void refuse_edge_refs(const char* what, std::size_t e0, std::size_t e1, std::int32_t r0,
                      std::int32_t r1) {
  char msg[240];
  std::snprintf(msg, sizeof msg,
                "%ss %zu and %zu join the same vertices with different refs (%d and %d): an edge "
                "has one ref",
                what, e0 + 1, e1 + 1, r0, r1);
  throw InputError(msg);
}

template void require_valid_input<2>(const Mesh&, std::span<const SymMat2>);
template void require_valid_input<3>(const Mesh&, std::span<const SymMat3>);
template std::vector<SymMat2> prepare_metrics<2>(const Mesh&, const Adjacency&,
                                                 std::span<const SymMat2>, const Adapt2dOptions&,
                                                 Adapt2dReport&);
template std::vector<SymMat3> prepare_metrics<3>(const Mesh&, const Adjacency&,
                                                 std::span<const SymMat3>, const Adapt2dOptions&,
                                                 Adapt2dReport&);

}  // namespace riemesh
