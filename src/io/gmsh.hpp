#pragma once
// Gmsh .msh files: read MSH 4.1 and 2.2 (ASCII and binary), write MSH 4.1 (ASCII or binary).
// Format: gmsh.info/doc/texinfo/gmsh.html "MSH file format" (and "Legacy formats" for 2.2).
//
// Elements kept: 15 (point) -> corner tag and vertex ref, 1 (2-node line) -> edge,
// 2 (3-node triangle), 4 (4-node tetrahedron). Other element types (quadrangles, prisms,
// high-order elements) are skipped and counted in GmshReadInfo.
//
// References and tags: the ref of an element is the first physical tag of its entity if the
// entity has one, else the entity's (elementary) tag. In 2.2 files, the first element tag is the
// physical tag and 0 means "none" (the elementary tag is used then). The writer turns each
// distinct ref of each element dimension into one entity and one physical group, both tagged by
// the ref (an entity tag must be positive: refs <= 0 get an unused positive entity tag and keep
// the ref as their physical tag), so refs round-trip through Riemesh, meshio and gmsh.
//
// Nodes keep the order of the file (tags may be sparse and unordered; ids are 0-based in
// order of appearance). A file with every z = 0 and no tetrahedra reads as a planar mesh.
// Vertex refs other than those of corners, ridge/required tags and normals are not stored in
// .msh files. Fields go to $NodeData: scalars (1 component), vectors (3, z = 0 in 2D) and
// symmetric tensors (9, the full 3x3 matrix, row by row, zero-padded in 2D).
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

struct GmshReadOptions {
  /// Read a mesh whose z are all 0 and that has no tetrahedra as a planar mesh (dim 2).
  bool planar_as_2d = true;
};

/// What a read left out, for the caller to report.
struct GmshReadInfo {
  double version = 0;  // 2.2 or 4.1
  bool binary = false;
  /// (Gmsh element type, count) of the elements skipped, by increasing type.
  std::vector<std::pair<int, std::size_t>> skipped_elements;
};

struct GmshWriteOptions {
  bool binary = false;
  /// Write the mesh fields as $NodeData sections.
  bool fields = true;
  /// fsync the file before renaming it into place.
  bool sync = false;
};

/// Reads a .msh file (4.1 or 2.2, ASCII or binary). Malformed input throws InputError naming
/// the file and the line (ASCII) or byte offset (binary).
Mesh read_gmsh(const std::string& path, const GmshReadOptions& options = {},
               GmshReadInfo* info = nullptr);

/// Same, on the bytes of a file already in memory; `name` names it in messages.
Mesh read_gmsh_bytes(const std::string& name, std::string_view bytes,
                     const GmshReadOptions& options = {}, GmshReadInfo* info = nullptr);

/// Writes a MSH 4.1 file through a temporary file renamed into place.
void write_gmsh(const Mesh& mesh, const std::string& path, const GmshWriteOptions& options = {});

}  // namespace riemesh
