#pragma once
// Planar parametric curves and their meshing to a size along them (issue #8, BOOK.md §3: curve
// meshing). A curve is a segment, a circular arc or a cubic Catmull-Rom spline through points, on
// t in [0, 1]. It is cut into n = round(L) segments of equal length L / n in the metric of the
// sizes h(t) — L = ∫ |γ'(t)| / h(t) dt — where h is the size asked (a function of t), limited by
// the curve's geometric size sqrt(8 ρ hausd) (ρ the radius of curvature: a chord of length h on a
// circle of radius ρ lies within h² / (8 ρ) of it) and clamped to [hmin, hmax]; every chord is
// then checked against the curve and n raised until each lies within hausd of it.
#include <functional>
#include <limits>
#include <vector>

#include "core/vec.hpp"

namespace riemesh {

/// Position and first two derivatives of a curve at a parameter.
struct CurveSample {
  Vec2 p, d1, d2;
};

class Curve2d {
 public:
  /// The segment from a to b.
  static Curve2d segment(const Vec2& a, const Vec2& b);
  /// The circular arc from `start` to `end` around `centre`, the shorter way (Gmsh's Circle; a
  /// half circle counter-clockwise, as Gmsh); the radius is |start − centre| (the caller checks
  /// |end − centre| agrees).
  static Curve2d arc(const Vec2& start, const Vec2& centre, const Vec2& end);
  /// The uniform Catmull-Rom spline through the points (at least 2): piece i runs from point i to
  /// point i + 1 on t in [i / m, (i + 1) / m], m pieces. Open: the end tangents from the points
  /// mirrored across the ends (2 p0 − p1, ...). Closed (`closed`, the last point equal to the
  /// first): periodic, smooth at the join.
  static Curve2d spline(std::vector<Vec2> points, bool closed);

  CurveSample at(double t) const;
  /// Exactly the end points given (not evaluated).
  Vec2 start() const;
  Vec2 end() const;
  /// Pieces with their own polynomial (1 for segments and arcs).
  int pieces() const;

 private:
  enum class Kind { kSegment, kArc, kSpline };
  Kind kind_ = Kind::kSegment;
  std::vector<Vec2> points_;  // segment: a, b; arc: start, centre, end; spline: control points
  double radius_ = 0.0, angle0_ = 0.0, sweep_ = 0.0;  // arc
  bool closed_ = false;
};

struct CurveSizing {
  std::function<double(double t)> size;  ///< size asked at parameter t (> 0)
  double hausd = 0.0;                    ///< chord-to-curve distance limit (0: none)
  double hmin = 0.0;
  double hmax = std::numeric_limits<double>::infinity();
  int min_segments = 1;  ///< e.g. 3 for a closed curve alone in its loop
};

/// The parameters 0 = t_0 < t_1 < ... < t_n = 1 of the curve's nodes: n = max(min_segments,
/// round(L)) segments of equal length in the metric of the sizes, n raised (at most 64 times, by
/// 1 or n / 32) until every chord is within hausd of the curve (16 samples per chord). Throws
/// InputError when a size is not positive and finite, or when the curve would need more than
/// 10^7 segments.
std::vector<double> mesh_curve(const Curve2d& curve, const CurveSizing& sizing);

/// The largest distance from the curve between parameters t0 and t1 to their chord (16 samples).
double chord_distance(const Curve2d& curve, double t0, double t1);

}  // namespace riemesh
