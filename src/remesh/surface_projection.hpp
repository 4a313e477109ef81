#pragma once
// The input surface as the geometry a surface remesher places its points on: the input mesh,
// its features, its smooth reconstruction (surface_reconstruction.hpp), trees for nearest-point
// queries on its triangles and on its feature edges, and a size per input vertex.
//
// Placing a point p: the nearest point f of the input (flat triangles, or feature edges for a
// point of a feature line) and its barycentric coordinates there give the point r of the smooth
// reconstruction at the same coordinates. The result is r, pulled back towards f so that it is at
// most `max_lift` from the input polyhedron: on a finely faceted input the reconstruction is
// followed; on a coarse one the output stays measurably close to the input (the distance that
// `riemesh distance` reports, and that mmgs does not bound; PEERS.md).
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/distance.hpp"
#include "mesh/mesh.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_features.hpp"
#include "remesh/surface_reconstruction.hpp"

namespace riemesh {

class SurfaceProjection {
 public:
  /// Analyses `input` (copied). `metric`: one metric per input vertex (interpolated linearly at
  /// placed points). `max_lift`: the largest distance between a placed point and the input
  /// polyhedron.
  SurfaceProjection(const Mesh& input, const FeatureOptions& features,
                    std::vector<SymMat3> metric, double max_lift);
  /// The metric computed from the analysis (mesh, adjacency, features, vertex curvatures) that
  /// the projection makes anyway: the curvature fits are done once for both.
  using MetricFromAnalysis = std::function<std::vector<SymMat3>(
      const Mesh&, const Adjacency&, const SurfaceFeatures&, const std::vector<VertexCurvature>&)>;
  SurfaceProjection(const Mesh& input, const FeatureOptions& features,
                    const MetricFromAnalysis& metric, double max_lift);
  SurfaceProjection(const SurfaceProjection&) = delete;
  SurfaceProjection& operator=(const SurfaceProjection&) = delete;

  struct Placed {
    Vec3 point{};
    SymMat3 metric{};
    Id hint = kNoId;  ///< input triangle (surface) or feature edge index (lines) found
  };
  /// The point of the surface for p; `hint` is a nearby input triangle or kNoId. `smooth`
  /// false: the nearest point of the input polyhedron itself (no reconstruction).
  Placed on_surface(const Vec3& p, Id hint, bool smooth = true) const;
  /// The point of the feature lines for p; `hint` is a nearby feature edge index or kNoId.
  Placed on_feature(const Vec3& p, Id hint, bool smooth = true) const;
  /// Whether p is within r of the input polyhedron (`hint` as TriangleTree::within). Walks
  /// from the hint across the input's edges toward p first (a few steps: consecutive questions
  /// come from nearby points), then asks the tree; the answer does not depend on the hint.
  bool within(const Vec3& p, double r, Id* hint) const;
  /// Distance from p to the input polyhedron.
  double distance(const Vec3& p, Id hint = kNoId) const { return tri_tree_.nearest(p, hint).distance; }

  /// The input's check points (the lattice of every input triangle, lattice_orders) inside the box
  /// [lo, hi], appended to `out` in a fixed order: the points an operator must keep within
  /// hausd of the output when they were within hausd before (surface_ops.cpp).
  void check_points(const Vec3& lo, const Vec3& hi, std::vector<Vec3>& out) const;
  /// All the check points into `pts` (replaced) and, if `owner`, for each an input triangle it
  /// lies on: the surface remesher starts from the input and follows which of its triangles
  /// answers for each point (surface_ops.cpp).
  void check_points_by_triangle(std::vector<Vec3>& pts, std::vector<Id>* owner) const;
  /// The lattice order of each input triangle's check points: 4, or a multiple of 4 up to 32
  /// where the triangle is long for its metric's in-plane sizes (spacing <= half the size).
  std::vector<int> lattice_orders() const;
  static constexpr int kCheckOrder = 4;  ///< the order of `riemesh distance`'s default lattice

  const Mesh& input() const { return mesh_; }
  const Adjacency& adjacency() const { return adj_; }
  const SurfaceFeatures& features() const { return features_; }
  const std::vector<SymMat3>& metrics() const { return metric_; }

 private:
  Vec3 lift(const Vec3& flat, const Vec3& smooth) const;

  Mesh mesh_;
  Adjacency adj_;
  SurfaceFeatures features_;
  SurfaceSectors sectors_;
  std::unique_ptr<SurfaceReconstruction> rec_;
  TriangleTree tri_tree_;
  std::vector<Id> line_edges_;  // 2 per feature edge (input vertex ids)
  std::unique_ptr<TriangleTree> line_tree_;
  std::vector<SymMat3> metric_;
  double max_lift_;
  // Uniform grid of the check points: cell (i, j, k) holds points
  // grid_points_[grid_offsets_[c] .. grid_offsets_[c + 1]), c = (k ny + j) nx + i. Built at the
  // first check_points (thread-safe): the surface remesher follows its points otherwise
  // (surface_ops.cpp) and never asks; the curved boundaries of the 3D remesher do.
  struct Grid {
    Vec3 lo{};
    double cell = 1.0;
    int nx = 1, ny = 1, nz = 1;
    std::vector<Id> offsets;
    std::vector<Vec3> points;
  };
  mutable Grid grid_;
  mutable std::once_flag grid_once_;
  void build_grid() const;
};

}  // namespace riemesh
