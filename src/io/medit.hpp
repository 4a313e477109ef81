#pragma once
// Medit mesh files (the libMeshb "Gamma Mesh Format" that MMG, Feflo.a, FreeFem and Gmsh use):
// ASCII .mesh and binary .meshb. Ids are 0-based in Mesh and 1-based in the files.
//
// Read: Vertices, Edges, Triangles, Tetrahedra, Corners, Ridges, RequiredVertices,
// RequiredEdges, RequiredTriangles, Normals, NormalAtVertices, Tangents, TangentAtVertices;
// every other keyword is skipped. Sections given twice are appended (meshio writes one section
// per cell block). Malformed input throws InputError with one line: file, keyword, and line
// (ASCII) or byte offset (binary).
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

struct MeditReadOptions {
  /// Read a `Dimension 3` file whose z are all 0 and that has no tetrahedra, normals or tangents
  /// as a planar mesh (dim 2): Gmsh writes 2D meshes that way.
  bool planar_as_2d = true;
  /// When given (ASCII files), receives "NAME (line N)" for each keyword skipped that is neither
  /// read nor known from libMeshb or FreeFem/BAMG: a misspelt `Triangle` dropped its section
  /// without a word (QA hunt 5 F8).
  std::vector<std::string>* unknown_keywords = nullptr;
};

struct MeditWriteOptions {
  /// .meshb file version: 1 (32-bit reals), 2 (64-bit reals), 3 (64-bit positions),
  /// 4 (64-bit ints). 0 picks 2, or 4 if a count or id does not fit in 32 bits.
  int binary_version = 0;
  /// Write the triangles of a planar mesh counter-clockwise (FreeFem rejects clockwise ones).
  bool ccw_2d = true;
  /// fsync the file before renaming it into place.
  bool sync = false;
};

/// Reads a .mesh (ASCII) or .meshb (binary) file, chosen by the extension.
Mesh read_medit(const std::string& path, const MeditReadOptions& options = {});

/// Writes a .mesh (ASCII, shortest round-trip reals) or .meshb file, chosen by the extension,
/// through a temporary file renamed into place. Fields are not written (see io/sol.hpp).
void write_medit(const Mesh& mesh, const std::string& path, const MeditWriteOptions& options = {});

}  // namespace riemesh
