#pragma once
// Mesh files by extension, for the CLI (`riemesh convert`) and for users who do not care about
// the format: .mesh / .meshb (Medit), .msh (Gmsh 4.1 written; 4.1 and 2.2 read), .vtu (VTK,
// write only). Medit files carry no fields (see io/sol.hpp); .msh and .vtu files carry them.
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

enum class MeshFormat { kMedit, kMeditBinary, kGmsh, kVtu };

/// The format named by the extension of path (case-sensitive, as the Medit functions); throws
/// InputError naming the path for any other extension.
MeshFormat mesh_format(const std::string& path);

struct MeshWriteOptions {
  /// Write .msh files in binary.
  bool gmsh_binary = false;
  /// fsync the file before renaming it into place.
  bool sync = false;
};

/// Reads a .mesh, .meshb or .msh file. Throws InputError for a .vtu file (not read) or another
/// extension, and for malformed input.
/// `unknown_keywords`, when given, receives the unknown keywords of an ASCII Medit file
/// (MeditReadOptions::unknown_keywords).
Mesh read_mesh(const std::string& path, std::vector<std::string>* unknown_keywords = nullptr);

/// Writes a .mesh, .meshb, .msh or .vtu file, atomically.
void write_mesh(const Mesh& mesh, const std::string& path, const MeshWriteOptions& options = {});

}  // namespace riemesh
