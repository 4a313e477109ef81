// Vertex relocation: accepted when the ball's worst quality improves.
#include <algorithm>
#include <cmath>

#include "remesh/ops3d.hpp"

namespace riemesh {

Outcome move_vertex(TetMesh& m, Id v, const Vec3& p, const SymMat3& metric, double* ball_worst) {
  thread_local std::vector<Id> ball;
  if (m.vkind[v] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  collect_ball(m, v, ball);
  double old_worst = 1.0;
  if (ball_worst && !std::isnan(*ball_worst)) {
    old_worst = *ball_worst;
  } else {
    for (const Id t : ball) old_worst = std::min(old_worst, tet_quality(m, t));
    if (ball_worst) *ball_worst = old_worst;
  }
  const Vec3 old_p = m.xyz[v];
  const SymMat3 old_m = m.metric[v];
  m.xyz[v] = p, m.metric[v] = metric;
  double worst = 1.0;
  for (const Id t : ball) {
    worst = std::min(worst, tet_quality(m, t));
    if (!(worst > 0.0)) break;
  }
  if (worst > old_worst) {
    if (ball_worst) *ball_worst = std::min(worst, 1.0);
    return Outcome::kApplied;
  }
  m.xyz[v] = old_p, m.metric[v] = old_m;
  return worst > 0.0 ? Outcome::kRejectedQuality : Outcome::kRejectedGeometry;
}

}  // namespace riemesh
