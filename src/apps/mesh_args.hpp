#pragma once
// Inputs shared by the mesh commands (check, stats, convert, render): a mesh file read by its
// extension and a metric field read from a .sol/.solb file and validated against the mesh.
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::cli {

/// Reads a .mesh, .meshb or .msh file (InputError naming the file otherwise).
Mesh load_mesh(const std::string& path);

/// Reads the single symmetric-tensor field of a .sol/.solb file for `mesh`: one SPD tensor per
/// vertex, packed in the .sol order; or, without one, sizes h (one scalar per vertex) as the
/// isotropic metric I/h² (read_metric_file). InputError naming the file (and the first bad
/// vertex, 1-based) for a wrong count, another kind of field, or a tensor that is not SPD.
std::vector<double> load_metric(const std::string& path, const Mesh& mesh);

/// The --hausd of a run on `domain` when none was given: default_hausd (0.01, raised to the
/// smallest allowed on domains over 1e7 across), with a note on stderr when raised and `note`.
double defaulted_hausd(const Mesh& domain, bool note);

/// Throws InputError naming the file when the mesh's arrays cannot be measured (sizes, ids out
/// of range, non-finite coordinates): statistics and pictures need that much; `riemesh check`
/// says more.
void require_measurable(const Mesh& mesh, const std::string& path);

/// Runs f() and returns its result; an InputError from it that does not start with `path` is
/// thrown again with "path: " in front, so that what the library finds deep inside a mesh (a
/// clockwise triangle, no elements) names the file it is about.
template <class F>
decltype(auto) naming_file(const std::string& path, F&& f) {
  try {
    return f();
  } catch (const InputError& e) {
    if (std::string_view(e.what()).starts_with(path)) throw;
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace riemesh::cli
