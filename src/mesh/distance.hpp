#pragma once
// Distances between triangle surfaces in 3D: exact point–triangle distance, an AABB tree for
// nearest-triangle queries, and the sampled one-sided and two-sided Hausdorff distances used to
// measure how far a remeshed surface strays from its input (issue #6).
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "core/vec.hpp"
#include "mesh/mesh.hpp"

namespace riemesh {

/// The point of triangle abc closest to p: its projection on the plane when that is inside the
/// edge lines, else the closest point of the edges facing p; rounded relative to p's distance to
/// the vertices, also for needle triangles (aspect 1e6). Degenerate triangles are handled (the
/// closest point of the segment or point they reduce to).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Triangle abc prepared for many "is p within r of it?" questions: the plane and the three
/// edge lines in the plane reject most far points and answer for points above the inside without
/// the exact closest point, which is computed only in the band around the edges.
struct TriangleProbe {
  Vec3 a{}, b{}, c{};
  Vec3 n{};          ///< unit normal (zero when degenerate)
  Vec3 inward[3]{};  ///< unit in-plane normals of the edges ab, bc, ca, toward the inside
  bool flat = false;  ///< non-degenerate: n and inward are unit vectors

  TriangleProbe() = default;
  TriangleProbe(const Vec3& pa, const Vec3& pb, const Vec3& pc);
  /// Whether dist(p, abc) <= r (r2 = r²), exact up to rounding. Inline: the Hausdorff checks
  /// of the surface remesher ask it millions of times.
  bool within(const Vec3& p, double r, double r2) const {
    if (flat) {
      const Vec3 pa = p - a;
      if (std::abs(dot(pa, n)) > r) return false;
      // Signed distances to the edge lines: all >= 0, the projection is inside and the distance
      // is the plane's; one below -r, the point is farther than r.
      const double s0 = dot(pa, inward[0]), s1 = dot(p - b, inward[1]), s2 = dot(p - c, inward[2]);
      if (s0 < -r || s1 < -r || s2 < -r) return false;
      if (s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0) return true;
    }
    const Vec3 d = p - closest(p);
    return dot(d, d) <= r2;
  }
  /// closest_point_on_triangle(p, a, b, c), with the normals computed once.
  Vec3 closest(const Vec3& p) const;
};

/// Bounding-volume hierarchy (axis-aligned boxes, median splits) over the triangles of a mesh,
/// for nearest-point queries in O(log n) on typical surfaces.
class TriangleTree {
 public:
  /// Builds the tree over mesh.triangles (dim 3; tets ignored). Throws InputError for a mesh
  /// that is not 3D or has no triangle.
  explicit TriangleTree(const Mesh& mesh);

  struct Nearest {
    double distance = std::numeric_limits<double>::infinity();
    Id triangle = kNoId;
    Vec3 point{};  ///< the closest point on that triangle
  };

  /// The nearest point of the surface to p. `hint`: a triangle likely to be close (e.g. the
  /// answer for a nearby query), tried first to prune the search; kNoId for none.
  Nearest nearest(const Vec3& p, Id hint = kNoId) const;
  /// Whether some triangle is within distance r of p (stops at the first one found; `hint` is
  /// tried first and, when not kNoId, receives the triangle found). Cheaper than nearest.
  bool within(const Vec3& p, double r, Id* hint = nullptr) const;
  std::size_t num_triangles() const { return tri_.size(); }
  /// Triangle t (an index of the mesh's triangles) prepared for within() questions.
  const TriangleProbe& probe(Id t) const { return tri_[static_cast<std::size_t>(t)]; }
  /// The triangles whose bounding boxes overlap the box [lo, hi], appended to `out`.
  void overlapping(const Vec3& lo, const Vec3& hi, std::vector<Id>& out) const;

 private:
  struct Node {
    double lo[3], hi[3];
    int first = 0, count = 0;  // leaf: triangles order_[first .. first+count); inner: count = 0
    int left = -1, right = -1;
  };
  int build(int first, int count, std::vector<double>& centroid);
  void consider(const Vec3& p, Id t, Nearest& best) const;

  std::vector<TriangleProbe> tri_;  // per triangle: corners and the within() tests
  std::vector<Id> order_;  // triangle ids, grouped by leaf
  std::vector<Node> nodes_;
};

struct DistanceOptions {
  /// Lattice order per triangle: the points of barycentric coordinates (i/n, j/n), i + j <= n,
  /// i.e. the vertices, n − 1 points per edge and the interior points ((n+1)(n+2)/2 in all).
  int samples = 4;
  /// If > 0, a triangle whose longest edge exceeds n·spacing uses a finer lattice,
  /// order ceil(longest / spacing): sampling at least that dense whatever the triangle size.
  double spacing = 0.0;
  /// Throws InputError for samples < 1 or a negative / non-finite spacing.
  void validate() const;
};

/// Distance from the samples of one surface to another.
struct OneSidedDistance {
  double max = 0.0;   ///< largest sampled distance
  double mean = 0.0;  ///< area-weighted mean of the sampled distances
  Vec3 where{};       ///< the sample where the largest distance was found
  std::size_t samples = 0;
};

struct HausdorffDistance {
  OneSidedDistance a_to_b, b_to_a;
  /// The two-sided (symmetric) Hausdorff distance: max of the two one-sided figures.
  double two_sided() const { return a_to_b.max > b_to_a.max ? a_to_b.max : b_to_a.max; }
};

/// Sampled one-sided distance from the triangles of `from` to the surface in `to`.
OneSidedDistance one_sided_distance(const Mesh& from, const TriangleTree& to,
                                    const DistanceOptions& options);

/// Both one-sided distances between the triangles of a and b (two trees, two passes).
HausdorffDistance hausdorff_distance(const Mesh& a, const Mesh& b, const DistanceOptions& options);

/// Length of the diagonal of the bounding box of the vertices (0 for an empty mesh).
double bounding_box_diagonal(const Mesh& mesh);

}  // namespace riemesh
