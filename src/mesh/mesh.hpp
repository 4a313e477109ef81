#pragma once
// The mesh: flat arrays (struct of arrays), 0-based 32-bit ids. One type for the three kinds of
// mesh Riemesh handles: planar triangles (dim 2), surface triangles in 3D (dim 3, no tetrahedra)
// and tetrahedral volumes (dim 3). DESIGN.md "Data model".
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace riemesh {

using Id = std::int32_t;
constexpr Id kNoId = -1;

/// Tags of vertices and edges (bit flags, combinable). Corners and required entities never move;
/// ridges are feature lines of a surface (or the boundary curves of a 2D domain).
enum Tag : std::uint8_t {
  kTagNone = 0,
  kTagCorner = 1,
  kTagRidge = 2,
  kTagRequired = 4,
};

/// What a per-vertex field holds, with the Medit .sol type codes.
enum class FieldKind : int { kScalar = 1, kVector = 2, kSymTensor = 3 };

/// Number of doubles per vertex of a field kind in dimension dim.
constexpr int field_components(FieldKind kind, int dim) {
  return kind == FieldKind::kScalar ? 1 : kind == FieldKind::kVector ? dim : dim * (dim + 1) / 2;
}

/// A named per-vertex field. Symmetric tensors are packed in the SymMat order (= .sol order).
struct Field {
  std::string name;
  FieldKind kind = FieldKind::kScalar;
  std::vector<double> values;  // num_vertices * field_components(kind, dim)
};

enum class MeshKind { kEmpty, kPlanar, kSurface, kVolume };

struct Mesh {
  int dim = 3;  // spatial dimension of coordinates: 2 or 3

  // Vertices.
  std::vector<double> coords;         // dim per vertex
  std::vector<std::int32_t> vert_ref;  // one per vertex
  std::vector<std::uint8_t> vert_tag;  // Tag bits per vertex

  // Boundary edges (2D boundary, surface ridges and feature lines).
  std::vector<Id> edges;  // 2 per edge
  std::vector<std::int32_t> edge_ref;
  std::vector<std::uint8_t> edge_tag;  // kTagRidge, kTagRequired

  // Triangles (2D elements, surface elements, or boundary faces of a volume).
  std::vector<Id> triangles;  // 3 per triangle
  std::vector<std::int32_t> tri_ref;
  std::vector<std::uint8_t> tri_tag;  // kTagRequired

  // Tetrahedra.
  std::vector<Id> tets;  // 4 per tetrahedron
  std::vector<std::int32_t> tet_ref;

  // Normals and tangents given at vertices by the file (Medit Normals/NormalAtVertices,
  // Tangents/TangentAtVertices), kept so that they round-trip.
  std::vector<double> normals;           // 3 per normal
  std::vector<Id> normal_at_vertex;      // pairs (vertex, normal)
  std::vector<double> tangents;          // 3 per tangent
  std::vector<Id> tangent_at_vertex;     // pairs (vertex, tangent)

  std::vector<Field> fields;  // per-vertex fields by name

  std::size_t num_vertices() const { return dim > 0 ? coords.size() / dim : 0; }
  std::size_t num_edges() const { return edges.size() / 2; }
  std::size_t num_triangles() const { return triangles.size() / 3; }
  std::size_t num_tets() const { return tets.size() / 4; }

  MeshKind kind() const {
    if (!tets.empty()) return MeshKind::kVolume;
    if (triangles.empty()) return MeshKind::kEmpty;
    return dim == 2 ? MeshKind::kPlanar : MeshKind::kSurface;
  }
};

}  // namespace riemesh
