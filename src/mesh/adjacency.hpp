#pragma once
// Topology of a simplex array (triangles: 3 ids each, tetrahedra: 4 ids each): neighbours across
// faces, vertex -> element incidence (CSR), the unique edge list, and ball / shell queries.
//
// Local numbering (shared by the whole library):
//   face i of a simplex is the face opposite its local vertex i;
//   kTriEdge[i]  : edge i of a triangle = face i, vertices ordered counter-clockwise;
//   kTetFace[i]  : face i of a tetrahedron, ordered so that its normal points outward when the
//                  tetrahedron is positively oriented;
//   kTetEdge[j]  : the 6 edges of a tetrahedron, (0,1) (0,2) (0,3) (1,2) (1,3) (2,3).
#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace riemesh {

inline constexpr int kTriEdge[3][2] = {{1, 2}, {2, 0}, {0, 1}};
inline constexpr int kTetFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
inline constexpr int kTetEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// Adjacency of a simplex array, built once by build_adjacency and read by queries.
struct Adjacency {
  int verts_per_simplex = 0;  // 3 (triangles) or 4 (tetrahedra)
  std::size_t num_vertices = 0;

  /// elem2elem[k*e + i]: the element across face i of element e; kNoId on the boundary and on
  /// non-manifold faces (those are listed in nonmanifold_faces).
  std::vector<Id> elem2elem;
  /// Faces shared by more than two elements, as element * verts_per_simplex + local face, sorted.
  std::vector<Id> nonmanifold_faces;

  /// Elements around each vertex (CSR): vert2elem[vert2elem_offsets[v] .. offsets[v+1]),
  /// in increasing element id.
  std::vector<Id> vert2elem_offsets;  // num_vertices + 1
  std::vector<Id> vert2elem;

  /// Unique edges as pairs (a, b) with a < b, sorted lexicographically.
  std::vector<Id> edges;
  /// elem2edge[n*e + j]: the edge id of local edge j of element e, with n = 3 (triangles, edge j
  /// = kTriEdge[j]) or 6 (tetrahedra, edge j = kTetEdge[j]).
  std::vector<Id> elem2edge;

  std::size_t num_elements() const {
    return verts_per_simplex ? elem2elem.size() / verts_per_simplex : 0;
  }
  std::size_t num_edges() const { return edges.size() / 2; }
  int edges_per_simplex() const { return verts_per_simplex == 4 ? 6 : 3; }
};

/// Builds the adjacency of `simplices` (verts_per_simplex = 3 or 4 ids each, all ids in
/// [0, num_vertices)). O(n) counting sorts plus small per-vertex sorts; deterministic.
/// Throws InputError for a bad size or an id out of range.
Adjacency build_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                          std::size_t num_vertices);

/// As build_adjacency without the edges (edges and elem2edge empty): the neighbours and the
/// vertex balls only, about half the memory, for callers that need no edge ids.
Adjacency build_face_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                               std::size_t num_vertices);

/// As build_adjacency without the neighbours (elem2elem and nonmanifold_faces empty, so
/// num_elements() is 0): the vertex balls and the edges only, for callers that rebuild their
/// topology often and never walk across faces (the surface remesher's passes).
Adjacency build_edge_adjacency(const std::vector<Id>& simplices, int verts_per_simplex,
                               std::size_t num_vertices);
/// Adds the edges (edges and elem2edge, as build_adjacency gives them) to an adjacency built
/// without them (build_face_adjacency) of the same simplices.
void add_edges(Adjacency& adj, const std::vector<Id>& simplices);

/// The elements of the mesh's main simplex array (tets of a volume, triangles otherwise).
Adjacency build_adjacency(const Mesh& mesh);

/// The elements around vertex v, in increasing id.
inline std::span<const Id> ball(const Adjacency& adj, Id v) {
  const auto b = static_cast<std::size_t>(adj.vert2elem_offsets[v]);
  const auto e = static_cast<std::size_t>(adj.vert2elem_offsets[v + 1]);
  return std::span<const Id>(adj.vert2elem).subspan(b, e - b);
}

/// Local index of vertex v in a simplex of n vertices, or -1.
inline int local_index(const Id* simplex, int n, Id v) {
  for (int i = 0; i < n; ++i)
    if (simplex[i] == v) return i;
  return -1;
}

/// The id of edge (a, b) (either order) in adj.edges by binary search, or kNoId.
Id find_edge(const Adjacency& adj, Id a, Id b);

/// The elements around an edge.
struct Shell {
  std::vector<Id> elements;
  bool closed = false;   // the walk came back to its start (an interior edge)
  bool ordered = false;  // consecutive elements share a face (false if the shell is non-manifold)
};

/// Elements containing the edge (a, b). For tetrahedra they are ordered by walking through
/// neighbours: an open shell (boundary edge) starts at an element with a boundary face on the
/// edge; a closed one starts at its smallest element id. For triangles: the 1 or 2 triangles.
Shell shell(const Adjacency& adj, const std::vector<Id>& simplices, Id a, Id b);

}  // namespace riemesh
