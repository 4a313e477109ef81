// Vertex relocation: accepted when the ball's worst quality improves.
#include <algorithm>
#include <limits>

#include "remesh/ops3d.hpp"

namespace riemesh {

Outcome move_vertex(TetMesh& m, Id v, const Vec3& p, const SymMat3& metric, MoveCache* cache) {
  thread_local MoveCache local;
  if (m.vkind[v] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  MoveCache& c = cache ? *cache : local;
  if (!cache || c.v != v) {
    collect_ball(m, v, c.ball);
    c.worst = 1.0;
    for (const Id t : c.ball) c.worst = std::min(c.worst, cached_quality(m, t));
    c.v = cache ? v : kNoId;
  }
  const std::vector<Id>& ball = c.ball;
  const double old_worst = c.worst;
  const Vec3 old_p = m.xyz[v];
  const SymMat3 old_m = m.metric[v];
  m.xyz[v] = p, m.metric[v] = metric;
  double worst = 1.0;
  std::size_t k = 0;
  for (; k < ball.size(); ++k) {
    worst = std::min(worst, tet_quality(m, ball[k]));
    if (!(worst > old_worst)) break;  // refused: the rest only tells geometry from quality
  }
  if (worst > old_worst) {
    c.worst = worst;  // the ball's tets are the same, v moved
    for (const Id t : ball)
      if (static_cast<std::size_t>(t) < m.quality.size())
        m.quality[t] = std::numeric_limits<double>::quiet_NaN();
    return Outcome::kApplied;
  }
  bool valid = worst > 0.0;
  for (++k; k < ball.size() && valid; ++k) {
    const Id* tv = &m.tv[4 * ball[k]];
    valid = above_volume_floor(m.xyz[tv[0]], m.xyz[tv[1]], m.xyz[tv[2]], m.xyz[tv[3]]);
  }
  m.xyz[v] = old_p, m.metric[v] = old_m;
  return valid ? Outcome::kRejectedQuality : Outcome::kRejectedGeometry;
}

}  // namespace riemesh
