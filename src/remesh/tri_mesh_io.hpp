#pragma once
// Conversion between the static Mesh (files, library API) and the remesher's TriMesh.
#include <span>
#include <vector>

#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"
#include "remesh/tri_mesh.hpp"

namespace riemesh {

/// A feature (boundary or interface) edge of the input, with its curve and ref.
struct TriFeature {
  Id a, b;
  std::int32_t curve, ref;
  std::uint8_t tag;  // kTagRequired for a required edge
};

/// Per-vertex feature data: the curve a (non-corner) boundary vertex lies on, and its parameter.
struct VertexCurve {
  std::int32_t curve = kNoCurve;
  double param = 0.0;
};

/// Builds a TriMesh from a 2D triangle mesh, one metric per vertex, the feature edges (every
/// boundary edge of the triangulation must be among them) and the vertices' curve data.
/// Vertex tags and refs are taken from the mesh. Throws InputError for a clockwise or degenerate
/// triangle, a non-manifold edge or a boundary edge that is not a feature.
/// `adjacency`, when given, is build_adjacency(mesh.triangles, 3, nv) (saves rebuilding it).
TriMesh build_tri_mesh(const Mesh& mesh, std::span<const SymMat2> metrics,
                       std::span<const TriFeature> features,
                       std::span<const VertexCurve> vertex_curves,
                       const Adjacency* adjacency = nullptr);

/// The live part of a TriMesh as a compact Mesh (dim 2): vertices with refs and tags
/// (corners, required), triangles with refs, feature edges once each as Edges with their refs.
/// When `metrics` is given it receives the vertex metrics in the output numbering.
Mesh to_mesh(const TriMesh& m, std::vector<SymMat2>* metrics = nullptr);

}  // namespace riemesh
