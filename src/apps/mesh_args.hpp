#pragma once
// Inputs shared by the mesh commands (check, stats, convert, render): a mesh file read by its
// extension and a metric field read from a .sol/.solb file and validated against the mesh.
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// Reads a .mesh, .meshb or .msh file (InputError naming the file otherwise).
Mesh load_mesh(const std::string& path);

/// Reads the single symmetric-tensor field of a .sol/.solb file for `mesh`: one SPD tensor per
/// vertex, packed in the .sol order. InputError naming the file (and the first bad vertex,
/// 1-based) for a wrong count, another kind of field, or a tensor that is not SPD.
std::vector<double> load_metric(const std::string& path, const Mesh& mesh);

/// Throws InputError naming the file when the mesh's arrays cannot be measured (sizes, ids out
/// of range, non-finite coordinates): statistics and pictures need that much; `riemesh check`
/// says more.
void require_measurable(const Mesh& mesh, const std::string& path);

}  // namespace riemesh::cli
