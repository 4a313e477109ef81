// Vertex relocation: accepted when the ball's worst quality improves.
#include <algorithm>

#include "remesh/boundary3d.hpp"
#include "remesh/ops3d.hpp"

namespace riemesh {

Outcome move_vertex(TetMesh& m, Id v, const Vec3& p, const SymMat3& metric) {
  thread_local std::vector<Id> ball;
  if (m.vkind[v] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  collect_ball(m, v, ball);
  double old_worst = 1.0;
  for (const Id t : ball) old_worst = std::min(old_worst, tet_quality(m, t));
  const Vec3 old_p = m.xyz[v];
  const SymMat3 old_m = m.metric[v];
  m.xyz[v] = p, m.metric[v] = metric;
  double worst = 1.0;
  for (const Id t : ball) {
    worst = std::min(worst, tet_quality(m, t));
    if (!(worst > 0.0)) break;
  }
  if (worst > old_worst) {
    if (!on_curved_boundary(m.vkind[v])) return Outcome::kApplied;
    m.xyz[v] = old_p;  // the boundary checks compare the old and new positions
    const bool ok = curved_boundary_ok(m, ball, v, kNoId, p);
    if (ok) m.xyz[v] = p;
    else m.metric[v] = old_m;
    return ok ? Outcome::kApplied : Outcome::kRejectedGeometry;
  }
  m.xyz[v] = old_p, m.metric[v] = old_m;
  return worst > 0.0 ? Outcome::kRejectedQuality : Outcome::kRejectedGeometry;
}

}  // namespace riemesh
