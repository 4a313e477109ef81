#pragma once
// Analysis of a triangulated surface in 3D (a Mesh of kind kSurface): vertex normals, feature
// edges (ridges) and corners, and the "sectors" in which features cut the ball of a vertex
// (BOOK.md §1 "Discrete surfaces have no σ": normals at vertices, ridges and corners detected
// by dihedral angle). Pure functions of the mesh and its triangle adjacency.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// Why an edge of the surface is a feature (bit flags, combinable; 0 = smooth edge).
enum FeatureBits : std::uint8_t {
  kFeatureAngle = 1,        ///< dihedral angle between the two triangle normals > threshold
  kFeatureRefChange = 2,    ///< the two triangles have different refs (patch boundary)
  kFeatureGiven = 4,        ///< listed in the file's Edges (Ridges, RequiredEdges included)
  kFeatureOpen = 8,         ///< on one triangle only (open boundary)
  kFeatureNonManifold = 16  ///< on three triangles or more
};

struct FeatureOptions {
  /// Dihedral threshold in degrees (MMG's -ar, default 45): an edge whose two triangle normals
  /// make a larger angle is a ridge; a vertex where a feature line turns by more is a corner.
  double angle_deg = 45.0;
  /// false: no ridge detection by angle (MMG's -nr); given, ref, open and non-manifold
  /// features are still found.
  bool detect_angle = true;
  /// Throws InputError unless 0 < angle_deg < 180.
  void validate() const;
};

/// Features of a surface, indexed like the Adjacency's edge list and the mesh's vertices.
struct SurfaceFeatures {
  std::vector<std::uint8_t> edge_feature;  ///< FeatureBits per adjacency edge
  /// Tag bits per vertex: kTagRidge on a feature edge, kTagCorner where the vertex is fixed
  /// (given Corners, RequiredVertices, feature degree ≠ 2, or a feature line turning by more
  /// than the angle threshold), kTagRequired copied from the file.
  std::vector<std::uint8_t> vert_tag;
  std::vector<int> feature_degree;  ///< number of feature edges at each vertex
  std::size_t num_feature_edges = 0;
  std::size_t num_angle_edges = 0;  ///< edges with kFeatureAngle
  std::size_t num_corners = 0;
};

/// Unit normal of each triangle (right-hand rule on its vertex order); zero for a degenerate one.
std::vector<Vec3> triangle_normals(const Mesh& mesh);

/// Angle-weighted vertex normals (Thürmer and Wüthrich 1998): Σ θ_t n_t over the ball, normalised;
/// the angle weights make them independent of how the ball is triangulated. Zero for a vertex
/// of no (non-degenerate) triangle. Ignores features: see SurfaceSectors for ridge vertices.
std::vector<Vec3> vertex_normals(const Mesh& mesh, const Adjacency& adj);

/// Feature edges and corners. The dihedral angle of an edge is the angle between the normals of
/// its two triangles, with one normal flipped when they traverse the edge the same way (an
/// orientation conflict should not turn every edge into a ridge). Throws InputError unless the
/// mesh is a surface whose adjacency `adj` is built from its triangles.
SurfaceFeatures detect_features(const Mesh& mesh, const Adjacency& adj,
                                const FeatureOptions& options);

/// The first two feature neighbours of each vertex (2 per vertex, kNoId where fewer): for a
/// vertex inside a feature line (degree 2), its predecessor and successor on the line.
std::vector<Id> feature_neighbours(const Adjacency& adj, const SurfaceFeatures& features);

/// Sectors: the triangles of a vertex's ball linked through its non-feature edges. A smooth
/// vertex has one sector, a vertex inside a ridge two, a corner one per wedge. Each sector has
/// its own angle-weighted normal (one side of a ridge never sees the normal of the other).
struct SurfaceSectors {
  std::vector<Id> corner2sector;  ///< 3 per triangle: the sector of that triangle corner
  std::vector<Id> sector2vert;    ///< the vertex of each sector
  std::vector<Vec3> normal;       ///< unit normal of each sector
  std::size_t num_sectors() const { return sector2vert.size(); }
};

/// Splits every vertex ball into sectors along the feature edges and computes their normals.
SurfaceSectors surface_sectors(const Mesh& mesh, const Adjacency& adj,
                               const SurfaceFeatures& features);

}  // namespace riemesh
