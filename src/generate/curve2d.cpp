#include "generate/curve2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace riemesh {

Curve2d Curve2d::segment(const Vec2& a, const Vec2& b) {
  Curve2d c;
  c.kind_ = Kind::kSegment;
  c.points_ = {a, b};
  return c;
}

Curve2d Curve2d::arc(const Vec2& start, const Vec2& centre, const Vec2& end) {
  Curve2d c;
  c.kind_ = Kind::kArc;
  c.points_ = {start, centre, end};
  const Vec2 u = start - centre, w = end - centre;
  c.radius_ = norm(u);
  c.angle0_ = std::atan2(u[1], u[0]);
  // The signed angle from u to w: the shorter way round; opposite ends (a half circle, within
  // 1e-9 of the radius) counter-clockwise, as Gmsh draws it.
  c.sweep_ =
      norm(u + w) <= 1e-9 * c.radius_ ? std::numbers::pi : std::atan2(cross(u, w), dot(u, w));
  return c;
}

Curve2d Curve2d::spline(std::vector<Vec2> points, bool closed) {
  RIEMESH_CHECK(points.size() >= 2);
  Curve2d c;
  c.kind_ = Kind::kSpline;
  c.points_ = std::move(points);
  c.closed_ = closed;
  return c;
}

Vec2 Curve2d::start() const { return points_.front(); }
Vec2 Curve2d::end() const { return points_.back(); }
int Curve2d::pieces() const {
  return kind_ == Kind::kSpline ? static_cast<int>(points_.size()) - 1 : 1;
}

CurveSample Curve2d::at(double t) const {
  switch (kind_) {
    case Kind::kSegment:
      return {points_[0] + t * (points_[1] - points_[0]), points_[1] - points_[0], Vec2{}};
    case Kind::kArc: {
      const double a = angle0_ + sweep_ * t, c = std::cos(a), s = std::sin(a);
      const double rs = radius_ * sweep_;
      return {points_[1] + radius_ * Vec2{{c, s}}, rs * Vec2{{-s, c}},
              -(rs * sweep_) * Vec2{{c, s}}};
    }
    case Kind::kSpline:
      break;
  }
  const int m = pieces();
  const int i = std::clamp(static_cast<int>(std::floor(t * m)), 0, m - 1);
  const double s = t * m - i;
  // Q0..Q3 = P(i−1)..P(i+2), the points beyond the ends mirrored (open) or wrapped (closed).
  const auto point = [&](int k) -> Vec2 {
    if (k >= 0 && k <= m) return points_[k];
    if (closed_) return points_[k < 0 ? k + m : k - m];
    return k < 0 ? 2.0 * points_[0] - points_[1] : 2.0 * points_[m] - points_[m - 1];
  };
  const Vec2 q0 = point(i - 1), q1 = point(i), q2 = point(i + 1), q3 = point(i + 2);
  const Vec2 c1 = q2 - q0, c2 = 2.0 * q0 - 5.0 * q1 + 4.0 * q2 - q3;
  const Vec2 c3 = 3.0 * (q1 - q2) + q3 - q0;
  const Vec2 p = q1 + 0.5 * (s * (c1 + s * (c2 + s * c3)));
  const Vec2 d1 = 0.5 * (c1 + s * (2.0 * c2 + 3.0 * s * c3));
  const Vec2 d2 = 0.5 * (2.0 * c2 + 6.0 * s * c3);
  return {p, static_cast<double>(m) * d1, static_cast<double>(m) * m * d2};
}

double chord_distance(const Curve2d& curve, double t0, double t1) {
  const Vec2 a = curve.at(t0).p, b = curve.at(t1).p, ab = b - a;
  const double l2 = dot(ab, ab);
  double worst = 0.0;
  for (int k = 1; k < 16; ++k) {
    const Vec2 q = curve.at(t0 + (t1 - t0) * k / 16.0).p;
    const double f = l2 > 0.0 ? std::clamp(dot(q - a, ab) / l2, 0.0, 1.0) : 0.0;
    worst = std::max(worst, norm(q - (a + f * ab)));
  }
  return worst;
}

namespace {

/// "the size along a curve is 0 ...": printed with %g (std::to_string printed 1e-300 as
/// 0.000000).
std::string size_error(double h) {
  char msg[160];
  std::snprintf(msg, sizeof msg,
                "the size along a curve is %g: sizes must be positive and finite (see the Points' "
                "lc and --hsiz)",
                h);
  return msg;
}

}  // namespace

std::vector<double> mesh_curve(const Curve2d& curve, const CurveSizing& sizing) {
  // The metric length density |γ'| / h on a fine uniform grid of t, then its running integral
  // (trapezoids).
  const int samples = 128 * curve.pieces();
  std::vector<double> ts(samples + 1), run(samples + 1, 0.0);
  double prev = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const double t = static_cast<double>(k) / samples;
    const CurveSample c = curve.at(t);
    const double speed = norm(c.d1);
    double h = sizing.size(t);
    if (!(h > 0.0) || !std::isfinite(h)) throw InputError(size_error(h));
    const double bend = std::abs(cross(c.d1, c.d2));  // |γ'|³ / ρ
    if (sizing.hausd > 0.0 && bend > 0.0)
      h = std::min(h, std::sqrt(8.0 * sizing.hausd * speed * speed * speed / bend));
    h = std::clamp(h, sizing.hmin, sizing.hmax);
    const double density = speed / h;
    ts[k] = t;
    if (k > 0) run[k] = run[k - 1] + 0.5 * (prev + density) / samples;
    prev = density;
  }
  const double length = run[samples];
  // A bound on the work (sizes far below the curve's length: a typing error in lc or --hmin).
  constexpr double kMostSegments = 1e7;
  const auto too_many = [&](double count) {
    if (!(count <= kMostSegments))
      throw InputError(
          "the curve would need " +
          (count < 1e18 ? std::to_string(static_cast<long long>(count)) : "over 1e18") +
          " segments at the sizes asked, more than 10000000");
  };
  too_many(length);
  long n = std::max<long>(sizing.min_segments, std::lround(length));
  n = std::max<long>(n, 1);
  std::vector<double> nodes;
  for (int attempt = 0;; ++attempt) {
    nodes.assign(1, 0.0);
    std::size_t k = 1;
    for (long j = 1; j < n; ++j) {
      const double target = length * static_cast<double>(j) / static_cast<double>(n);
      while (k < static_cast<std::size_t>(samples) && run[k] < target) ++k;
      const double span = run[k] - run[k - 1];
      const double f = span > 0.0 ? (target - run[k - 1]) / span : 0.0;
      nodes.push_back(ts[k - 1] + f * (ts[k] - ts[k - 1]));
    }
    nodes.push_back(1.0);
    bool close = true;
    if (sizing.hausd > 0.0)
      for (std::size_t i = 0; i + 1 < nodes.size() && close; ++i)
        close = chord_distance(curve, nodes[i], nodes[i + 1]) <= sizing.hausd;
    if (close || attempt == 64) break;
    n += std::max<long>(1, n / 32);
    too_many(static_cast<double>(n));
  }
  return nodes;
}

}  // namespace riemesh
