// Vertex relocation: accepted when the ball's worst quality improves.
#include <algorithm>

#include "remesh/ops3d.hpp"

namespace riemesh {

Outcome move_vertex(TetMesh& m, Id v, const Vec3& p, const SymMat3& metric, MoveCache* cache) {
  thread_local MoveCache local;
  if (m.vkind[v] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  MoveCache& c = cache ? *cache : local;
  if (!cache || c.v != v) {
    collect_ball(m, v, c.ball);
    c.worst = 1.0;
    for (const Id t : c.ball) c.worst = std::min(c.worst, tet_quality(m, t));
    c.v = cache ? v : kNoId;
  }
  const std::vector<Id>& ball = c.ball;
  const double old_worst = c.worst;
  const Vec3 old_p = m.xyz[v];
  const SymMat3 old_m = m.metric[v];
  m.xyz[v] = p, m.metric[v] = metric;
  double worst = 1.0;
  for (const Id t : ball) {
    worst = std::min(worst, tet_quality(m, t));
    if (!(worst > 0.0)) break;
  }
  if (worst > old_worst) {
    c.worst = worst;  // the ball's tets are the same, v moved
    return Outcome::kApplied;
  }
  m.xyz[v] = old_p, m.metric[v] = old_m;
  return worst > 0.0 ? Outcome::kRejectedQuality : Outcome::kRejectedGeometry;
}

}  // namespace riemesh
