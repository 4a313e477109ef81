#pragma once
// Internals shared by the Medit readers and writers (ASCII and binary, mesh and sol): keyword
// codes, the assembler that validates ids and turns keyword lists into tags, error formatting.
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "io/medit.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {
class AtomicFile;
}

namespace riemesh::medit_detail {

// The format-specific readers and writers behind read_medit / write_medit.
Mesh read_medit_ascii(const std::string& path, std::string_view text,
                      const MeditReadOptions& options);
Mesh read_medit_binary(const std::string& path, std::string_view bytes,
                       const MeditReadOptions& options);
void write_medit_ascii(const Mesh& mesh, AtomicFile& file, const MeditWriteOptions& options);
void write_medit_binary(const Mesh& mesh, AtomicFile& file, const MeditWriteOptions& options);
/// read_sol on bytes already in memory (the fuzz targets call it): `path` picks .sol or .solb
/// by its extension and names the file in messages.
std::vector<Field> read_sol_bytes(const std::string& path, std::string_view bytes,
                                  std::size_t num_vertices, int dim);
/// Throws InputError unless the path ends with .sol or .solb.
void check_sol_name(const std::string& path);

// libMeshb keyword codes: enum GmfKwdCod in sources/libmeshb7.h of LoicMarechal/libMeshb
// (v7.62), counted from GmfReserved1 = 0. Entry layouts from GmfKwdFmt in libmeshb7.c.
enum Code : int {
  kVersionFormatted = 1,  // ASCII only
  kDimension = 3,         // no count; one int
  kVertices = 4,          // "dri": dim reals, ref
  kEdges = 5,             // "iii"
  kTriangles = 6,         // "iiii"
  kTetrahedra = 8,        // "iiiii"
  kCorners = 13,          // "i" (vertex)
  kRidges = 14,           // "i" (edge)
  kRequiredVertices = 15,
  kRequiredEdges = 16,
  kRequiredTriangles = 17,
  kNormalAtVertices = 20,   // "ii" (vertex, normal)
  kEnd = 54,                // no count, no data
  kTangents = 59,           // "dr"
  kNormals = 60,            // "dr"
  kTangentAtVertices = 61,  // "ii" (vertex, tangent)
  kSolAtVertices = 62,      // count, #types, types, then reals
  kSolAtTriangles = 64,     // same layout, one value set per triangle
  kSolAtTetrahedra = 66,    // same layout, one value set per tetrahedron
};

/// Code of a keyword name (ASCII, case-insensitive) among those Riemesh reads; 0 if other.
int keyword_code(std::string_view name);
/// Canonical libMeshb name of a code Riemesh reads.
const char* keyword_name(int code);
/// Integers per entry of libMeshb element keywords Riemesh skips (Quadrilaterals, Prisms, ...);
/// -1 if the keyword is not one of them.
int skipped_keyword_ints(std::string_view name);
/// The name of the skipped element keyword of that code and its integers per entry; nullptr
/// (ints unchanged) if the code is not one of them.
const char* skipped_keyword(int code, int& ints);
/// True for the keywords of libMeshb and of FreeFem/BAMG's dialect that Riemesh skips knowingly
/// (Identifier, Geometry, VertexOnGeometricEdge, ...).
bool known_skipped_keyword(std::string_view name);
/// False for the skipped keywords that list no elements (RequiredQuadrilaterals).
bool holds_elements(std::string_view name);
/// "N elements of a kind riemesh does not read (...)": why a skipped element section is refused
/// (elements dropped without a word made a quad or P2 mesh read as empty and valid, and a mixed
/// one convert with a hole).
std::string unread_elements(std::size_t n);

/// A short printable form of a token for error messages.
std::string quote(std::string_view token);

/// Throws InputError("<where>: <keyword>: <what>"); `where` is "file:line" or "file: byte N".
[[noreturn]] void fail(const std::string& where, std::string_view keyword, const std::string& what);

/// What an id column refers to.
enum class Bound : std::uint8_t { kVertex, kEdge, kTriangle, kNormal, kTangent };

/// Location ("file:line" or "file: byte N") of column `column` of entry `entry` of a section.
using Locator = std::function<std::string(std::size_t entry, int column)>;

/// A section of ids read from a file (0-based, unchecked), checked once all sections are read,
/// since libMeshb files may list sections in any order.
struct IdBlock {
  int code = 0;
  std::vector<Id>* ids = nullptr;
  std::size_t begin = 0;  // first id of the section in *ids
  std::size_t end = 0;
  int stride = 1;                 // ids per entry in *ids
  std::array<Bound, 4> bounds{};  // per column
  Locator locate;
};

/// Collects what the readers parse and turns it into a valid Mesh.
struct MeshAssembler {
  Mesh mesh;
  std::vector<Id> corners, required_vertices, ridges, required_edges, required_triangles;
  std::vector<IdBlock> blocks;

  /// The list a tag keyword (Corners, Ridges, Required*) fills.
  std::vector<Id>& tag_list(int code);
  /// Records ids[begin..] (just appended) as coming from one section with this layout.
  void add_block(int code, std::vector<Id>& ids, std::size_t begin, int stride,
                 std::array<Bound, 4> bounds, Locator locate);
  /// Checks every id, builds the tag arrays, applies planar_as_2d.
  Mesh finish(const MeditReadOptions& options);
};

/// True (and converts to dim 2) if mesh is a 3D mesh lying in z = 0 without tetrahedra,
/// normals or tangents, whose triangles are all counter-clockwise or all clockwise (then turned
/// over, its edges too: Gmsh's meshes of clockwise loops).
bool make_planar(Mesh& mesh);

// ---- writing -------------------------------------------------------------------------------

/// Checks array sizes and ids of a mesh about to be written; throws Error naming the path.
void check_writable(const Mesh& mesh, const std::string& path);
/// Ids of the entities whose tag has `bit`, increasing.
std::vector<Id> tagged(const std::vector<std::uint8_t>& tags, std::uint8_t bit);
/// Triangles as they go to the file: counter-clockwise for a planar mesh if ccw is set.
std::vector<Id> output_triangles(const Mesh& mesh, bool ccw);
/// refs[i], or 0 if the ref array is empty.
inline std::int32_t ref_at(const std::vector<std::int32_t>& refs, std::size_t i) {
  return refs.empty() ? 0 : refs[i];
}
/// True if the path ends with the suffix (case-sensitive).
bool ends_with(const std::string& path, std::string_view suffix);

}  // namespace riemesh::medit_detail
