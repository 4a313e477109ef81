// Vertex relocation: accepted only when the ball stays valid and its worst quality holds.
#include <algorithm>

#include "remesh/ops2d.hpp"

namespace riemesh {

Outcome move_vertex(TriMesh& m, Id v, const Vec2& p, const SymMat2& metric, double param,
                    double floor, const Ball* ball, const double* worst) {
  if (m.frozen(v)) return Outcome::kRejectedTopology;
  thread_local Ball own;
  if (ball == nullptr) {
    collect_ball(m, v, own);
    ball = &own;
  }
  if (!ball->closed && !m.on_curve(v)) return Outcome::kRejectedTopology;
  double before = 2.0, after = 2.0;
  for (const Id t : ball->tris) {
    const int i = vertex_index(m, t, v);
    const Id a = m.tv[3 * t + (i + 1) % 3], b = m.tv[3 * t + (i + 2) % 3];
    const double old_area = signed_area(m.xy[v], m.xy[a], m.xy[b]);
    if (!(signed_area(p, m.xy[a], m.xy[b]) > 1e-6 * old_area) || !fair_area(p, m.xy[a], m.xy[b]))
      return Outcome::kRejectedGeometry;
    if (worst == nullptr) before = std::min(before, tri_quality(m, t));
    const SymMat2 mm = tri_metric(metric, nullptr, m.metric[a], log_of(m.log_metric, a),
                                  m.metric[b], log_of(m.log_metric, b));
    after = std::min(after, quality_in(mm, p, m.xy[a], m.xy[b]));
  }
  if (worst != nullptr) before = std::min(before, *worst);
  if (after < std::min(before, floor)) return Outcome::kRejectedQuality;
  m.xy[v] = p;
  m.metric[v] = metric;
  sync_log(m.metric, m.log_metric, v);
  m.vparam[v] = param;
  return Outcome::kApplied;
}

}  // namespace riemesh
