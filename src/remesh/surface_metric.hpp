#pragma once
// The geometric metric of a triangulated surface: per-vertex 3x3 sizes that keep the chordal gap
// between the surface and its remeshed version below an absolute tolerance `hausd`
// (BOOK.md §1 "Geometric metrics (curves and surfaces)").
//
// At a vertex with principal radii ρ1 <= ρ2 (surface_curvature.hpp), the relative gap is
// ε = hausd/ρ1 (capped at 1), so that the isotropic size is
//   h = α ρ1 = 2 sqrt(hausd (2ρ1 − hausd))  (≈ sqrt(8 hausd ρ1) when hausd << ρ1);
// the anisotropic metric keeps that size along w1 and takes βρ2, β = 2 sqrt(ε'(2 − ε')),
// ε' = hausd/ρ2 (the same absolute gap) along w2 (surface_metric_anisotropic with the fraction
// `beta_fraction` of the way from α to β). A vertex on a feature line also follows the line's
// own curvature (circle through the vertex and its two feature neighbours): h_c = α_c ρ_c along
// the line's tangent (isotropically in the isotropic mode). Flat places get hmax. Sizes are
// clipped to [hmin, hmax], intersected with the user metric if any, then graded along the surface
// edges (metric/gradation.hpp).
#include <vector>

#include "core/symmat.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/mesh.hpp"
#include "metric/gradation.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_features.hpp"

namespace riemesh {

struct SurfaceMetricOptions {
  double hausd = 0.01;  ///< maximal chordal gap (absolute, in mesh units)
  double hmin = 0.0;    ///< smallest size; <= 0: hausd (a smaller size cannot be needed)
  double hmax = 0.0;    ///< largest size; <= 0: the bounding-box diagonal
  bool anisotropic = false;
  double beta_fraction = 1.0;  ///< in [0, 1]: 0 isotropic, 1 the full anisotropic β (BOOK §1)
  double hgrad = 1.3;          ///< H-shock gradation threshold (> 1); 0: no gradation
  /// The gradation's H-shock before and after in the report (two sweeps over the edges).
  bool gradation_measures = true;
  /// A user (e.g. physical) metric per vertex, intersected with the geometric one before the
  /// gradation so that the result stays geometric (BOOK.md §1); null or empty: none. Not owned.
  const std::vector<SymMat3>* user_metric = nullptr;
  /// Throws InputError, naming the option and the value, for hausd <= 0, hmin > hmax (both
  /// given), a negative or infinite hmin or hmax, hgrad neither 0 nor > 1, or beta_fraction
  /// outside [0, 1].
  void validate() const;
};

struct SurfaceMetricReport {
  double hmin = 0.0, hmax = 0.0;  ///< the bounds used (after the defaults)
  double smallest = 0.0, largest = 0.0;  ///< smallest and largest principal size after gradation
  GradationReport gradation;
};

/// The largest eigenvalue of m restricted to the plane normal to n (nonzero, any length): 1/h²
/// of the finest size m asks along that plane.
double largest_in_plane(const SymMat3& m, const Vec3& n);

/// m restricted to the plane normal to n (nonzero), with across it the finest size along it (as
/// the anisotropic geometric metric, surface_metric_anisotropic): the lengths of vectors in the
/// plane are m's, what m asks along n (a volume's boundary layer) is dropped.
SymMat3 tangent_metric(const SymMat3& m, const Vec3& n);

/// Size bound by the curvature of a feature line at `v` between its neighbours `a` and `b`:
/// 2 sqrt(hausd (2ρ − hausd)) with ρ the radius of the circle through a, v, b (inf if straight).
double feature_line_size(const Vec3& a, const Vec3& v, const Vec3& b, double hausd);

/// The geometric metric at every vertex (packed SymMat3), graded along the edges of `adj`.
std::vector<SymMat3> geometric_surface_metric(const Mesh& mesh, const Adjacency& adj,
                                              const SurfaceFeatures& features,
                                              const std::vector<VertexCurvature>& curvature,
                                              const SurfaceMetricOptions& options,
                                              SurfaceMetricReport* report = nullptr);

/// Convenience: adjacency, features (default FeatureOptions unless given), sectors, curvatures
/// and the metric in one call.
std::vector<SymMat3> geometric_surface_metric(const Mesh& mesh,
                                              const SurfaceMetricOptions& options,
                                              const FeatureOptions& feature_options = {},
                                              SurfaceMetricReport* report = nullptr);

}  // namespace riemesh
