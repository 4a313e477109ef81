// `riemesh metric hessian ...` (a metric from a solution field: recovered Hessian, L∞ or Lp
// metric, clipping, gradation) and `riemesh metric combine ...` (intersection of metric files).
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/field_args.hpp"
#include "apps/mesh_args.hpp"
#include "apps/parse.hpp"
#include "core/error.hpp"
#include "io/sol.hpp"
#include "mesh/adjacency.hpp"
#include "metric/gradation.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/recovery.hpp"

namespace riemesh::cli {
namespace {

struct HessianArgs {
  std::string mesh, sol, field, recovery = "lsq", norm = "2", output;
  double hgrad = 0.0;
  bool json = false;
  HessianMetricOptions opt;
};

struct CombineArgs {
  std::vector<std::string> inputs;
  std::string mesh, output;
  double hgrad = 0.0;
  bool json = false;
};

/// 2 for a planar triangle mesh, 3 for a tetrahedral volume; InputError otherwise.
int metric_dim(const Mesh& mesh, const std::string& path) {
  if (!mesh.tets.empty()) return 3;
  if (mesh.dim == 2 && !mesh.triangles.empty()) return 2;
  throw InputError(path + ": metrics are built on planar triangle meshes and tetrahedral volumes");
}

/// "inf" (or "infinity") for the L∞ norm, else a number.
/// Gradation as riemesh adapt does it (physical-space growth, Alauzet 2010), when hgrad > 0.
void require_hgrad(double hgrad) {
  if (hgrad != 0.0 && !(hgrad > 1.0)) throw InputError("--hgrad must be 0 (off) or a ratio > 1");
}

template <int D>
void grade(const Mesh& mesh, std::vector<SymMat<D>>& metrics, double hgrad) {
  if (hgrad == 0.0) return;
  GradationOptions g;
  g.mode = GradationMode::kGrowthPhysical;
  g.threshold = hgrad;
  gradate<D>(mesh.coords, build_adjacency(mesh).edges, std::span<SymMat<D>>(metrics), g);
}

template <int D>
void write_metric(const std::string& path, const std::vector<SymMat<D>>& metrics) {
  Field f{"metric", FieldKind::kSymTensor, {}};
  f.values.reserve(metrics.size() * SymMat<D>::kSize);
  for (const SymMat<D>& m : metrics) f.values.insert(f.values.end(), m.c, m.c + SymMat<D>::kSize);
  write_sol(path, {f}, D);
}

void print_report(const MetricReport& r, int dim, bool json) {
  const char* elements = dim == 2 ? "triangles" : "tetrahedra";
  if (json)
    std::printf("{\"complexity\": %.17g, \"predicted_vertices\": %.17g, \"predicted_elements\": %.17g}\n",
                r.complexity, r.predicted_vertices, r.predicted_elements);
  else
    std::printf("complexity         : %.6g\npredicted vertices : %.0f\npredicted %-9s: %.0f\n",
                r.complexity, r.predicted_vertices, elements, r.predicted_elements);
}

template <int D>
void run_hessian(const HessianArgs& a, const Mesh& mesh, const Field& u) {
  const RecoveryMethod method = parse_recovery_method(a.recovery);
  const std::vector<SymMat<D>> h = recover_hessian<D>(mesh, u.values, method);
  std::vector<SymMat<D>> m = hessian_metric<D>(mesh, h, a.opt);
  grade<D>(mesh, m, a.hgrad);
  write_metric<D>(a.output, m);
  print_report(metric_report<D>(mesh, m), D, a.json);
}

void hessian(HessianArgs& a) {
  if (a.output.empty()) throw InputError("no output file: give -o M.sol");
  a.opt.norm = parse_norm(a.norm);
  a.opt.validate();
  require_hgrad(a.hgrad);
  parse_recovery_method(a.recovery);
  const Mesh mesh = load_mesh(a.mesh);
  require_measurable(mesh, a.mesh);
  const int dim = metric_dim(mesh, a.mesh);
  const std::vector<Field> fields = read_sol(a.sol, mesh);
  const Field& u = select_field(fields, a.field, a.sol);
  dim == 2 ? run_hessian<2>(a, mesh, u) : run_hessian<3>(a, mesh, u);
}

template <int D>
void run_combine(const CombineArgs& a, const Mesh& mesh) {
  std::vector<std::vector<SymMat<D>>> fields;
  for (const std::string& path : a.inputs) {
    const std::vector<double> c = load_metric(path, mesh);
    std::vector<SymMat<D>>& f = fields.emplace_back(mesh.num_vertices());
    for (std::size_t v = 0; v < f.size(); ++v)
      for (int k = 0; k < SymMat<D>::kSize; ++k) f[v].c[k] = c[SymMat<D>::kSize * v + k];
  }
  std::vector<SymMat<D>> m = combine_metrics<D>(fields);
  grade<D>(mesh, m, a.hgrad);
  write_metric<D>(a.output, m);
  print_report(metric_report<D>(mesh, m), D, a.json);
}

void combine(const CombineArgs& a) {
  if (a.output.empty()) throw InputError("no output file: give -o M.sol");
  require_hgrad(a.hgrad);
  const Mesh mesh = load_mesh(a.mesh);
  require_measurable(mesh, a.mesh);
  const int dim = metric_dim(mesh, a.mesh);
  dim == 2 ? run_combine<2>(a, mesh) : run_combine<3>(a, mesh);
}

void register_hessian(CLI::App& metric) {
  auto a = std::make_shared<HessianArgs>();
  auto* cmd = metric.add_subcommand(
      "hessian",
      "Metric from a scalar field: Hessian recovery, then the Lp-optimal metric for a complexity "
      "N or the L∞ metric for a tolerance E (BOOK.md §2), clipped and graded");
  cmd->add_option("mesh", a->mesh, "Mesh (.mesh, .meshb, .msh): triangles (2D) or tetrahedra")->required();
  cmd->add_option("field", a->sol, "Vertex fields (.sol/.solb)")->required();
  cmd->add_option("-o,--output", a->output, "Output metric (.sol/.solb)");
  cmd->add_option("--field", a->field, "Scalar field by name (sol0, sol1, ...) or 0-based index; default: the first scalar field");
  cmd->add_option("--recovery", a->recovery, "Hessian recovery: lsq (least squares), l2 (double L2 projection), green")
      ->capture_default_str();
  cmd->add_option("--norm", a->norm, "Norm p of the Lp metric: 1, 2, ... or inf")->capture_default_str();
  cmd->add_option("--complexity", a->opt.complexity, "Target complexity N (about the vertex count in 2D)");
  cmd->add_option("--tolerance", a->opt.tolerance, "L∞ interpolation error E (with --norm inf): M = c_d |H| / E");
  cmd->add_option("--hmin", a->opt.hmin, "Smallest size");
  cmd->add_option("--hmax", a->opt.hmax, "Largest size");
  cmd->add_option("--aniso-max", a->opt.aniso_max, "Largest anisotropy ratio h_max / h_min");
  cmd->add_option("--hgrad", a->hgrad, "Gradation: growth ratio between neighbours (0: off)")->capture_default_str();
  cmd->add_flag("--json", a->json, "Print one JSON object (complexity, predicted_vertices, predicted_elements)");
  cmd->callback([a] { hessian(*a); });
}

void register_combine(CLI::App& metric) {
  auto a = std::make_shared<CombineArgs>();
  auto* cmd = metric.add_subcommand(
      "combine", "Intersect metric fields on the same mesh (several fields or time samples)");
  cmd->add_option("metrics", a->inputs, "Metric files A.sol B.sol ...")->required();
  cmd->add_option("--mesh", a->mesh, "The mesh the metrics live on")->required();
  cmd->add_option("-o,--output", a->output, "Output metric (.sol/.solb)");
  cmd->add_option("--hgrad", a->hgrad, "Gradation of the result (0: off)")->capture_default_str();
  cmd->add_flag("--json", a->json, "Print one JSON object (complexity, predicted_vertices, predicted_elements)");
  cmd->callback([a] { combine(*a); });
}

}  // namespace

void register_metric_hessian(CLI::App& metric) {
  register_hessian(metric);
  register_combine(metric);
}

}  // namespace riemesh::cli
