#pragma once
// VTK XML UnstructuredGrid (.vtu) output for ParaView and VTK-based tools: raw appended binary
// data (UInt64 block headers, native byte order, declared in the file).
//
// Cells: the tetrahedra, then the triangles, then the edges (boundary and feature entities of
// lower dimension included, so that refs can be seen), with the CellData arrays "ref" (Int32)
// and "dim" (UInt8: 3 tetrahedron, 2 triangle, 1 edge) to select them (ParaView: Threshold on
// "dim"). Points always have 3 components (z = 0 for a planar mesh). PointData: "ref" (the
// vertex refs, Int32) and one Float64 array per mesh field: scalars, vectors as 3 components,
// symmetric tensors as 6 components in VTK's order XX YY ZZ XY YZ XZ (converted from the SymMat
// order m11 m12 m22 m13 m23 m33; 2D tensors padded with zeros).
#include <string>

#include "mesh/mesh.hpp"

namespace riemesh {

struct VtuWriteOptions {
  /// fsync the file before renaming it into place.
  bool sync = false;
};

/// Writes a .vtu file through a temporary file renamed into place.
void write_vtu(const Mesh& mesh, const std::string& path, const VtuWriteOptions& options = {});

}  // namespace riemesh
