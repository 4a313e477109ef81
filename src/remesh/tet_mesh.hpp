#pragma once
// The mutable tetrahedral mesh the 3D remesher works on: flat arrays with free lists, the
// neighbour across each face, and the listed boundary faces (Mesh::triangles) kept as refs on
// tetrahedron faces.
//
// Conventions (as in mesh/adjacency.hpp): tet t has vertices tv[4t..4t+3] with positive volume;
// its face i is opposite vertex i, oriented outward as kTetFace[i]. A face slot is 4t + i.
// tadj[4t + i] is the slot of the same face seen from the neighbour, or kNoId on the domain
// boundary. fbdy[slot] != 0 marks a listed face (every domain-boundary face is listed; unlisted
// input boundary faces get ref 0) and face_ref(slot) is its ref: one byte per face (memory,
// issue #7), the index + 1 of the ref in a small table of the distinct refs, or kRefOverflow
// for a ref beyond the table's 254 entries, kept in a map by slot. Dead tets have
// tv[4t] == kNoId, dead vertices vtet == kNoId.
//
// Every change of the tets goes through replace_cavity(): a set of tets is replaced by new ones
// that must fill exactly the same region (checked on the faces), which is how the operators
// stay conforming.
#include <algorithm>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// What the boundary rules allow a vertex to do (BOOK.md §7, boundary operators).
enum class VertexKind : std::uint8_t {
  kInterior,  ///< in no listed face: moves and goes freely
  kPlanar,    ///< on one planar boundary patch (plane ref vplane[2v]): moves in it
  kRidge,     ///< on the line where two planar patches meet (refs vplane[2v], vplane[2v+1]),
              ///< or on a straight line of the input's Edges inside the planar patch
              ///< vplane[2v] = vplane[2v+1] (TetMesh::line_ref)
  kFixed,     ///< corner, required, on an interface (or a curved patch with --nosurf): kept
  kSurface,   ///< on a curved patch (ref vplane[2v]): stays on its reconstruction (boundary3d.hpp)
  kCurve,     ///< on a feature line of curved patches (refs vplane[2v..]): stays on that line
};

class Boundary3d;

struct TetMesh {
  // Vertices.
  std::vector<Vec3> xyz;
  std::vector<SymMat3> metric;
  std::vector<SymMat3> log_metric;  // log_spd(metric[v]) once a metric is not diagonal, else
                                    // empty (vertex_logs.hpp; set_metric keeps it in step)
  std::vector<std::int32_t> vref;
  std::vector<std::uint8_t> vtag;
  std::vector<VertexKind> vkind;
  std::vector<std::int32_t> vplane;  // 2 per vertex: the boundary refs of a planar/ridge vertex
  std::vector<Id> vtet;              // one live tet around the vertex; kNoId when dead

  // Tetrahedra.
  std::vector<Id> tv;    // 4 per tet
  std::vector<Id> tadj;  // 4 per tet: slot of the neighbour's copy of the face, or kNoId
  std::vector<std::int32_t> tref;
  std::vector<std::uint8_t> fbdy;  // 4 per tet: 0 unlisted, else the ref code (see above)

  // Refs of the listed faces: fbdy[slot] - 1 indexes ref_table; kRefOverflow: ref_overflow.
  static constexpr std::uint8_t kRefOverflow = 255;
  std::vector<std::int32_t> ref_table;
  std::map<Id, std::int32_t> ref_overflow;

  std::vector<Id> free_tets, free_verts;

  /// The input's Edges on listed faces (feature lines: ridges, ref changes, lines drawn inside
  /// a patch), by line_key, with their refs. A split edge leaves its halves here, a collapse
  /// moves `from`'s lines to `to` (split_edge, collapse_edge), so that every output edge on an
  /// input edge keeps that edge's ref (to_mesh), as the surface remesher's feature edges do.
  std::unordered_map<std::uint64_t, std::int32_t> line_ref;
  static std::uint64_t line_key(Id a, Id b) {
    const auto lo = static_cast<std::uint64_t>(std::min(a, b));
    const auto hi = static_cast<std::uint64_t>(std::max(a, b));
    return (hi << 32) | lo;
  }
  bool on_line(Id a, Id b) const { return !line_ref.empty() && line_ref.count(line_key(a, b)); }

  /// The curved boundary that kSurface and kCurve vertices stay on (not owned; null when the
  /// boundary has no curved patch or is kept).
  const Boundary3d* surface = nullptr;

  // Scratch marks for ball and shell walks (stamp per tet); not part of the mesh's state.
  mutable std::vector<std::uint32_t> mark;
  mutable std::uint32_t stamp = 0;
  // Cache of each live tet's quality (ops3d.hpp cached_quality), NaN when unknown: cleared for
  // the tets replace_cavity creates and by the vertex moves that are kept (move_vertex). Code
  // that changes a vertex's position or metric any other way must clear it (quality.clear()).
  mutable std::vector<double> quality;
  // Scratch of the driver's edge enumeration (6 entries per tet), kept across its calls so that
  // the pass does not allocate, fault in and zero it each time.
  mutable std::vector<std::uint32_t> edge_scratch;

  // Per vertex, the value of `clock` when a replaced cavity last held it, old or new (0: never):
  // a driver that keeps data about a vertex's neighbours (adapt3d.cpp) advances the clock when it
  // takes them and trusts them while the vertex is untouched since.
  std::vector<std::uint32_t> vtouch;
  // Per vertex, the value of `clock` when it last moved (move_vertex; 0: never).
  std::vector<std::uint32_t> vmoved;
  std::uint32_t clock = 0;
  /// Whether vertex v was held by no cavity replaced since the clock read `since`.
  bool untouched_since(Id v, std::uint32_t since) const {
    return static_cast<std::size_t>(v) >= vtouch.size() || vtouch[v] < since;
  }

  /// Whether vertex v has not moved since the clock read `since`.
  bool unmoved_since(Id v, std::uint32_t since) const {
    return static_cast<std::size_t>(v) >= vmoved.size() || vmoved[v] < since;
  }

  /// Sets vertex v's metric and its logarithm.
  void set_metric(Id v, const SymMat3& m);

  std::size_t vertex_capacity() const { return xyz.size(); }
  std::size_t tet_capacity() const { return tref.size(); }
  bool tet_alive(Id t) const { return tv[4 * t] != kNoId; }
  bool vert_alive(Id v) const { return vtet[v] != kNoId; }
  std::size_t num_live_tets() const { return tet_capacity() - free_tets.size(); }
  std::size_t num_live_vertices() const { return vertex_capacity() - free_verts.size(); }

  /// The ref of the listed face at `slot` (fbdy[slot] != 0).
  std::int32_t face_ref(std::size_t slot) const {
    const std::uint8_t c = fbdy[slot];
    return c == kRefOverflow ? ref_overflow.at(static_cast<Id>(slot)) : ref_table[c - 1];
  }
  /// Whether slot s is the side a listed face is taken from when it is taken once: an outer
  /// face, or an interface face seen from the region of lower tet ref (from the lower slot
  /// between tets of one ref), so that an interface's faces are oriented alike (out of that
  /// region) in reconstructions and output files.
  bool face_side_listed(std::size_t s) const {
    const Id r = tadj[s];
    if (r == kNoId) return true;
    const std::int32_t here = tref[s / 4], there = tref[static_cast<std::size_t>(r) / 4];
    return here != there ? here < there : static_cast<Id>(s) < r;
  }
  /// The code of a listed face of ref `ref` (table entry added when new and room is left).
  std::uint8_t ref_code(std::int32_t ref);
  /// Sets the face at `slot`: unlisted (code 0), or listed with `code` (ref_code) and, for
  /// kRefOverflow, the ref.
  void set_face(std::size_t slot, std::uint8_t code, std::int32_t ref = 0);

  Id add_vertex(const Vec3& p, const SymMat3& m);
  void kill_vertex(Id v);
};

/// Signed volume of tet (a, b, c, d): positive when positively oriented.
inline double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return dot(b - a, cross(c - a, d - a)) / 6.0;
}

/// Local index of v in tet t (0..3), or -1.
inline int tet_index(const TetMesh& m, Id t, Id v) {
  for (int i = 0; i < 4; ++i)
    if (m.tv[4 * t + i] == v) return i;
  return -1;
}

/// The tets around vertex v (walk through the faces that hold v), in walk order.
void collect_ball(const TetMesh& m, Id v, std::vector<Id>& out);
/// The vertices other than v of the tets in `ball` (v's ball), sorted, without repeats.
void ball_neighbours(const TetMesh& m, Id v, std::span<const Id> ball, std::vector<Id>& out);

/// A tet holding edge (a, b), searched in a's ball (stopping at the first), or kNoId when a
/// and b are not joined.
Id find_edge_tet(const TetMesh& m, Id a, Id b);

/// The tets around edge (a, b), turning around it from `hint` when that tet holds the edge
/// (else from find_edge_tet); empty when a and b are not joined.
void collect_shell(const TetMesh& m, Id a, Id b, std::vector<Id>& out, Id hint = kNoId);

/// A tet to create in replace_cavity.
struct NewTet {
  Id v[4];
  std::int32_t ref;
};

/// "New vertex x stands for old vertex y" on the cavity's boundary faces: a new face that is
/// an old boundary face with y replaced by x inherits that face's ref (a split boundary face,
/// or a boundary face dragged by a collapse). An old boundary face holding both x and y
/// vanishes (a collapsed boundary edge).
struct Substitution {
  Id x, y;
};

/// Replaces the tets `cavity` by `tets` when the new tets fill exactly the cavity: each new
/// face is shared by two new tets with opposite orientations, or is a face of the cavity's
/// boundary (directly, or through a substitution for listed domain-boundary faces), and every
/// boundary face of the cavity is covered. Geometry is the caller's job (it checks volumes).
/// Returns false, changing nothing, when the faces do not match. On success `created` (when
/// given) receives the new tet ids and vtet of their vertices is updated.
bool replace_cavity(TetMesh& m, std::span<const Id> cavity, std::span<const NewTet> tets,
                    std::span<const Substitution> subst, std::vector<Id>* created = nullptr);

/// Renumbers the vertices from `first` on along the Hilbert curve, dropping the dead ones (ids
/// below `first` are kept: data kept per input vertex stays valid), then the tets by their
/// smallest vertex id (stably; dead ones dropped); adjacency, back-pointers, face refs, the
/// per-vertex clocks, the quality cache and the free lists follow (as renumber_tail for the
/// TriMesh: splits append far from the neighbours, and this restores the locality). Returns the
/// old -> new vertex ids, and the tets' in *tet_old2new when given (kNoId: dropped).
std::vector<Id> renumber_tail(TetMesh& m, Id first, std::vector<Id>* tet_old2new = nullptr);

/// Structural and geometric invariants (tests, debugging): symmetric adjacency with opposite
/// orientations, boundary faces listed, listed data equal on both sides, live vertex
/// back-pointers, positive volumes. Empty when all hold, otherwise the first violation.
std::string check_tet_mesh(const TetMesh& m);

/// Builds the TetMesh of a volume mesh: its tetrahedra (positively oriented, else InputError),
/// their neighbours, the listed faces from mesh.triangles (refs), the Edges that are edges of
/// listed triangles (line_ref; others are dropped), vertex refs and tags; vertex kinds all
/// kFixed until the caller classifies them. `metrics` gives one metric per vertex.
TetMesh build_tet_mesh(const Mesh& mesh, std::span<const SymMat3> metrics);

/// Back to a compacted Mesh: live vertices in id order, tets, the listed faces as triangles
/// with their refs, and Edges: the lines of m.line_ref with their refs, and the other boundary
/// edges between listed outer faces of different refs (ridges the input did not list: ref 0),
/// tagged kTagRidge, in increasing (a, b). `metrics`, when given, receives the metric of each
/// output vertex.
Mesh to_mesh(const TetMesh& m, std::vector<SymMat3>* metrics = nullptr);

}  // namespace riemesh
