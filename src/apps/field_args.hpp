#pragma once
// Arguments shared by the commands that take a solution field (metric hessian, adapt --field).
#include <cstddef>
#include <string>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// "--norm" value: a number, or inf / infinity for the L∞ metric.
double parse_norm(const std::string& text);

/// The scalar field chosen by --field: a name (sol0, sol1, ... as read_sol names them) or a
/// 0-based index; by default the first scalar field of the file. InputError naming `path`.
const Field& select_field(const std::vector<Field>& fields, const std::string& choice,
                          const std::string& path);

/// One metric per vertex of `mesh` from a .sol file: the first symmetric tensor field (the .sol
/// order) or scalar field (a size per vertex, as MMG accepts). InputError naming `path` and the
/// vertex for a non-SPD tensor or a non-positive size, or when the file has neither kind.
template <int D>
std::vector<SymMat<D>> read_metric_file(const std::string& path, const Mesh& mesh);

/// As read_metric_file, from the fields of a .sol file already read for a mesh of nv vertices.
template <int D>
std::vector<SymMat<D>> metric_from_fields(const std::vector<Field>& fields, const std::string& path,
                                          std::size_t nv);

}  // namespace riemesh::cli
