#include "remesh/plane_fit.hpp"

#include <algorithm>
#include <cmath>

namespace riemesh {

PlaneFit fit_plane(std::span<const Tri3> faces) {
  PlaneFit f;
  if (faces.empty()) return f;
  const auto normal = [](const Tri3& t) { return cross(t[1] - t[0], t[2] - t[0]); };
  const Vec3 first = normalize(normal(faces[0]));
  Vec3 sum{};
  for (const Tri3& t : faces) {
    Vec3 n = normal(t);
    if (dot(n, first) < 0.0) n = -1.0 * n;
    const double length = norm(n);
    if (length > 0.0 && dot(n, first) < (1.0 - kPlaneNormal) * length) f.aligned = false;
    sum = sum + n;  // (area-weighted: |n| is twice the area)
  }
  f.n = norm(sum) > 0.0 ? normalize(sum) : first;
  double area = 0.0, offset = 0.0;
  for (const Tri3& t : faces) {
    const double a = norm(normal(t));
    area += a;
    offset += a * dot(f.n, (1.0 / 3.0) * (t[0] + t[1] + t[2]));
  }
  f.d = area > 0.0 ? offset / area : dot(f.n, faces[0][0]);
  for (const Tri3& t : faces)
    for (const Vec3& p : t) f.deviation = std::max(f.deviation, std::abs(dot(f.n, p) - f.d));
  return f;
}

}  // namespace riemesh
