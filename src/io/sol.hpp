#pragma once
// Medit solution files: ASCII .sol and binary .solb (libMeshb SolAtVertices, code 62, and the
// per-element SolAtTriangles, 64, and SolAtTetrahedra, 66, of P0 fields). One section holds
// several fields, interleaved per vertex (or element); types 1 = scalar,
// 2 = vector (dim values), 3 = symmetric tensor (m11 m12 m22 / m11 m12 m22 m13 m23 m33, the
// SymMat order, so values are copied as they are).
#include <cstddef>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

/// Where the values of a solution file live: one value set per vertex (P1 fields) or per element
/// (P0 fields: SolAtTriangles, SolAtTetrahedra).
enum class SolLocation { kVertices, kTriangles, kTetrahedra };

/// The libMeshb keyword name of a location ("SolAtVertices", ...).
const char* sol_keyword(SolLocation location);

/// The fields of a file and where they live.
struct SolData {
  SolLocation location = SolLocation::kVertices;
  std::vector<Field> fields;
};

struct SolWriteOptions {
  /// The section written: SolAtVertices (default), SolAtTriangles or SolAtTetrahedra.
  SolLocation location = SolLocation::kVertices;
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

/// Reads the fields of a file at whichever location it holds: its first SolAtVertices,
/// SolAtTriangles or SolAtTetrahedra section decides, and later sections of other locations are
/// ignored. Counts are checked against the mesh's vertices, triangles or tetrahedra. Throws
/// InputError as read_sol does, or when the file has no solution section.
SolData read_sol_any(const std::string& path, const Mesh& mesh);

/// Writes fields (all on the same vertices, or elements with options.location) as one section,
/// atomically.
void write_sol(const std::string& path, const std::vector<Field>& fields, int dim,
               const SolWriteOptions& options = {});

}  // namespace riemesh
