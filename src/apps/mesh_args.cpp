#include "apps/mesh_args.hpp"

#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "apps/field_args.hpp"
#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "io/sol.hpp"
#include "mesh/check.hpp"
#include "metric/mesh_quality.hpp"
#include "remesh/adapt2d.hpp"

namespace riemesh::cli {

Mesh load_mesh(const std::string& path) {
  std::vector<std::string> unknown;
  Mesh mesh = read_mesh(path, &unknown);
  // A misspelt keyword (`Triangle`) dropped its section without a word: named here (the
  // FreeFem/BAMG and libMeshb keywords riemesh skips knowingly are not).
  if (!unknown.empty()) {
    std::string list;
    for (std::size_t k = 0; k < unknown.size() && k < 3; ++k) list += (k ? ", " : "") + unknown[k];
    if (unknown.size() > 3) list += ", ...";
    std::fprintf(stderr, "riemesh: note: %s: %zu unknown keyword%s skipped with %s data: %s\n",
                 path.c_str(), unknown.size(), unknown.size() > 1 ? "s" : "",
                 unknown.size() > 1 ? "their" : "its", list.c_str());
  }
  return mesh;
}

std::vector<double> load_metric(const std::string& path, const Mesh& mesh) {
  std::vector<Field> fields = read_sol(path, mesh);
  const Field* metric = nullptr;
  for (const Field& f : fields)
    if (f.kind == FieldKind::kSymTensor) {
      if (metric) throw InputError(path + ": holds several tensor fields, expected one metric");
      metric = &f;
    }
  if (!metric) {
    // Sizes, one per vertex, are the isotropic metric I/h², as adapt --metric reads them (they
    // were refused: "no symmetric tensor field").
    std::vector<double> out;
    const auto flatten = [&out](const auto& tensors) {
      for (const auto& m : tensors) out.insert(out.end(), std::begin(m.c), std::end(m.c));
    };
    if (mesh.dim == 2)
      flatten(metric_from_fields<2>(fields, path, mesh.num_vertices()));
    else
      flatten(metric_from_fields<3>(fields, path, mesh.num_vertices()));
    return out;
  }
  try {
    validate_metric_field(mesh, metric->values);
  } catch (const InputError& e) {
    std::string msg = path;
    msg += ": ";
    msg += e.what();
    throw InputError(msg);
  }
  return metric->values;
}

double defaulted_hausd(const Mesh& domain, bool note) {
  const double hausd = default_hausd(domain);
  if (note && hausd > Adapt2dOptions{}.hausd)
    std::fprintf(stderr,
                 "riemesh: note: --hausd not given: the default %g is below %g of the domain's "
                 "bounding-box diagonal, raised to %g\n",
                 Adapt2dOptions{}.hausd, kSmallestHausd, hausd);
  return hausd;
}

void require_measurable(const Mesh& mesh, const std::string& path) {
  const CheckReport r = check_mesh(mesh);
  for (CheckCategory c : {CheckCategory::kArraySize, CheckCategory::kIdOutOfRange,
                          CheckCategory::kNonFiniteCoordinate})
    if (r.count(c) > 0) {
      std::string msg = path;
      msg += ": ";
      msg += to_string(c);
      msg += " (see riemesh check)";
      throw InputError(msg);
    }
}

}  // namespace riemesh::cli
