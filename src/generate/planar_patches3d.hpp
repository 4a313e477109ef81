#pragma once
// Planar patches of a closed surface re-triangulated with the faces of a tetrahedralisation of
// its points (boundary recovery, generate/boundary_recovery3d.hpp). A planar face of a CAD model
// is often exported as a fan of thin triangles (a cylinder's caps fanned from one rim vertex, a
// box face cut into slivers): their edges are no Delaunay edges, and recovering them with
// Steiner points on the surface cascades (each split point encroaches the next thin triangle),
// past any sensible cap. The patch itself — exactly coplanar triangles of one ref joined by
// edges — can be triangulated any way with its own vertices: where the tetrahedralisation's
// faces on its plane tile it (a patch on the convex hull always; inside, when no tet edge
// pierces it), those faces replace its triangles. Vertices, outline, orientation and refs are
// kept; only the patch's inner edges change.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "generate/delaunay3d.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// The edges and faces of a tetrahedralisation, sorted, for membership tests (which surface
/// edges and triangles it holds).
struct TetSkeleton {
  std::vector<std::uint64_t> edges;      // (lo << 32) | hi
  std::vector<std::array<Id, 3>> faces;  // sorted vertex ids
  explicit TetSkeleton(const Tetrahedralization& tz);
  bool has_edge(Id a, Id b) const;
  bool has_face(const std::array<Id, 3>& t) const;
};

struct PatchTriangulation {
  std::vector<Id> triangles;  ///< 3 point ids each, oriented as the input's
  std::vector<int> refs, tags;
  std::size_t patches = 0;        ///< patches re-triangulated
  std::size_t replaced = 0;       ///< input triangles they held
  std::size_t missing_edges = 0;  ///< input edges that are no edge of the tetrahedralisation
  std::size_t missing_faces = 0;  ///< input triangles that are no face of it
};

/// The triangles (3 ids each into `coords`, 3 doubles per point; a closed, consistently oriented
/// surface) with each planar patch that holds a triangle missing from `tz` (a tetrahedralisation
/// of the points) replaced by the faces of `tz` tiling it, when they do; the other triangles as
/// given, in their order, the new ones after them. Patches: triangles of equal ref and tag, joined
/// by edges, whose vertices are exactly coplanar (exact orientation test). Deterministic.
/// `skeleton`: tz's edges and faces (the caller's, which boundary recovery reuses for its first
/// round). retriangulate false: the triangles as given, only the missing edges and faces counted.
PatchTriangulation retriangulate_planar_patches(
    std::span<const Id> triangles, std::span<const int> refs, std::span<const int> tags,
    const std::vector<double>& coords, const Tetrahedralization& tz, const TetSkeleton& skeleton,
    bool retriangulate = true);

}  // namespace riemesh
