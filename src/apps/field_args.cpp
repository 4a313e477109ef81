#include "apps/field_args.hpp"

#include <limits>

#include "apps/parse.hpp"
#include "core/error.hpp"

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

}  // namespace riemesh::cli
