#pragma once
// Medit solution files: ASCII .sol and binary .solb (libMeshb SolAtVertices, code 62). One
// SolAtVertices section holds several fields, interleaved per vertex; types 1 = scalar,
// 2 = vector (dim values), 3 = symmetric tensor (m11 m12 m22 / m11 m12 m22 m13 m23 m33, the
// SymMat order, so values are copied as they are).
#include <cstddef>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

struct SolWriteOptions {
  /// .solb file version (1 to 4, see MeditWriteOptions); 0 picks 2.
  int binary_version = 0;
  bool sync = false;
};

/// Reads the per-vertex fields of a .sol/.solb file (chosen by the extension) for a mesh with
/// num_vertices vertices in dimension dim. Fields are named "sol0", "sol1", ..., or "metric"
/// when the file holds a single tensor field. Throws InputError on malformed input, a vertex
/// count that differs from num_vertices, or a vector/tensor field of another dimension.
std::vector<Field> read_sol(const std::string& path, std::size_t num_vertices, int dim);
/// Same, for the vertices and dimension of `mesh`.
std::vector<Field> read_sol(const std::string& path, const Mesh& mesh);

/// Writes fields (all on the same vertices) as one SolAtVertices section, atomically.
void write_sol(const std::string& path, const std::vector<Field>& fields, int dim,
               const SolWriteOptions& options = {});

}  // namespace riemesh
