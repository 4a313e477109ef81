#include "apps/field_args.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "apps/parse.hpp"
#include "core/error.hpp"
#include "io/sol.hpp"
#include "metric/metric.hpp"

namespace riemesh::cli {

double parse_norm(const std::string& text) {
  if (text == "inf" || text == "infinity" || text == "Inf") return std::numeric_limits<double>::infinity();
  const std::vector<double> v = parse_numbers(text, "--norm '" + text + "'");
  if (v.size() != 1) throw InputError("--norm '" + text + "': expected one number or inf");
  return v[0];
}

const Field& select_field(const std::vector<Field>& fields, const std::string& choice,
                          const std::string& path) {
  std::string names;
  for (const Field& f : fields) names += (names.empty() ? "" : ", ") + f.name;
  const Field* found = nullptr;
  for (std::size_t i = 0; i < fields.size() && !found; ++i)
    if (choice.empty() ? fields[i].kind == FieldKind::kScalar
                       : fields[i].name == choice || std::to_string(i) == choice)
      found = &fields[i];
  if (!found && choice.empty()) throw InputError(path + ": holds no scalar field (fields: " + names + ")");
  if (!found) throw InputError(path + ": no field '" + choice + "' (fields: " + names + ")");
  if (found->kind != FieldKind::kScalar)
    throw InputError(path + ": field '" + found->name + "' is not a scalar field");
  return *found;
}

template <int D>
std::vector<SymMat<D>> read_metric_file(const std::string& path, const Mesh& mesh) {
  return metric_from_fields<D>(read_sol(path, mesh), path, mesh.num_vertices());
}

template <int D>
std::vector<SymMat<D>> metric_from_fields(const std::vector<Field>& fields, const std::string& path,
                                          std::size_t nv) {
  constexpr int kSize = SymMat<D>::kSize;
  // A file of several fields: the first metric was taken without a word (a scalar before a
  // tensor, or the other way round).
  int metrics = 0;
  for (const Field& f : fields)
    metrics += f.kind == FieldKind::kSymTensor || f.kind == FieldKind::kScalar;
  if (metrics > 1)
    throw InputError(path + ": " + std::to_string(metrics) +
                     " scalar or tensor fields in SolAtVertices; a metric file holds one (sizes "
                     "or tensors)");
  for (const Field& f : fields) {
    std::vector<SymMat<D>> out(nv);
    if (f.kind == FieldKind::kSymTensor) {
      for (std::size_t v = 0; v < nv; ++v) {
        for (int k = 0; k < kSize; ++k) out[v].c[k] = f.values[kSize * v + k];
        require_metric(out[v], path + ": vertex " + std::to_string(v + 1));
      }
      return out;
    }
    if (f.kind == FieldKind::kScalar) {
      for (std::size_t v = 0; v < nv; ++v) {
        const double h = f.values[v];
        if (!(h > 0.0) || !std::isfinite(h))
          throw InputError(path + ": size at vertex " + std::to_string(v + 1) +
                           " is not a positive number");
        out[v] = isotropic_metric<D>(h);
        // 1e-300 made an infinite tensor, blamed on the mesh file as "NaN or infinite". (The
        // message only for a size whose tensor or determinant leaves the doubles.)
        const double d = det(out[v]);
        if (std::isfinite(d) && d >= std::numeric_limits<double>::min()) continue;
        char what[96];
        std::snprintf(what, sizeof what, ": size %g at vertex %zu", h, v + 1);
        if (!std::isfinite(out[v](0, 0)))
          throw InputError(path + what + " is too small to compute with (1/size² overflows)");
        require_metric(out[v], path + what);
      }
      return out;
    }
  }
  throw InputError(path + ": no scalar or symmetric tensor field in SolAtVertices");
}

template std::vector<SymMat2> read_metric_file<2>(const std::string&, const Mesh&);
template std::vector<SymMat3> read_metric_file<3>(const std::string&, const Mesh&);
template std::vector<SymMat2> metric_from_fields<2>(const std::vector<Field>&, const std::string&,
                                                    std::size_t);
template std::vector<SymMat3> metric_from_fields<3>(const std::vector<Field>&, const std::string&,
                                                    std::size_t);

}  // namespace riemesh::cli
