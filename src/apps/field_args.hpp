#pragma once
// Arguments shared by the commands that take a solution field (metric hessian, adapt --field).
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// "--norm" value: a number, or inf / infinity for the L∞ metric.
double parse_norm(const std::string& text);

/// The scalar field chosen by --field: a name (sol0, sol1, ... as read_sol names them) or a
/// 0-based index; by default the first scalar field of the file. InputError naming `path`.
const Field& select_field(const std::vector<Field>& fields, const std::string& choice,
                          const std::string& path);

}  // namespace riemesh::cli
