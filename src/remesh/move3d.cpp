// Vertex relocation: accepted when the ball's worst quality improves (or stays above a floor).
#include <algorithm>
#include <limits>

#include "remesh/boundary3d.hpp"
#include "remesh/ops3d.hpp"

namespace riemesh {

void fill_move_cache(const TetMesh& m, Id v, MoveCache& c) {
  c.worst = 1.0, c.first = 0;
  for (std::size_t k = 0; k < c.ball.size(); ++k) {
    const double q = cached_quality(m, c.ball[k]);
    if (q < c.worst) c.worst = q, c.first = k;
  }
  c.v = v;
}

Outcome move_vertex(TetMesh& m, Id v, const Vec3& p, const SymMat3& metric, MoveCache* cache,
                    double floor) {
  thread_local MoveCache local;
  if (m.vkind[v] == VertexKind::kFixed) return Outcome::kRejectedTopology;
  MoveCache& c = cache ? *cache : local;
  if (!cache || c.v != v) {
    collect_ball(m, v, c.ball);
    fill_move_cache(m, v, c);
    if (!cache) c.v = kNoId;
  }
  // The ball's tets in the order: first, then the others.
  const std::size_t first = c.first < c.ball.size() ? c.first : 0;
  const auto at = [first](std::size_t k) { return k == 0 ? first : (k <= first ? k - 1 : k); };
  const std::vector<Id>& ball = c.ball;
  // Accepted above this: the old worst (capped at 1), or the floor when lower.
  const double bar = std::min(c.worst, floor);
  const Vec3 old_p = m.xyz[v];
  const SymMat3 old_m = m.metric[v];
  const bool had_logs = !m.log_metric.empty();
  const SymMat3 old_log = had_logs ? m.log_metric[v] : SymMat3{};
  m.xyz[v] = p, m.set_metric(v, metric);  // and its logarithm when kept (tet_metric needs it)
  const auto restore_metric = [&] {  // the trial may have started the logs: v's is then old_m's
    m.metric[v] = old_m;
    if (!m.log_metric.empty()) m.log_metric[v] = had_logs ? old_log : log_spd(old_m);
  };
  double worst = 1.0;
  std::size_t k = 0, worst_at = first;
  for (; k < ball.size(); ++k) {
    const double q = tet_quality(m, ball[at(k)]);
    if (q < worst) worst = q, worst_at = at(k);
    if (!(worst > bar)) break;  // refused: the rest only tells geometry from quality
  }
  c.first = worst_at;
  if (worst > bar) {
    if (on_curved_boundary(m.vkind[v])) {
      m.xyz[v] = old_p;  // the boundary checks compare the old and new positions
      const bool ok = curved_boundary_ok(m, ball, v, kNoId, p);
      if (!ok) {
        restore_metric();
        return Outcome::kRejectedGeometry;
      }
      m.xyz[v] = p;
    }
    c.worst = worst;  // the ball's tets are the same, v moved
    if (m.vmoved.size() <= static_cast<std::size_t>(v)) m.vmoved.resize(m.vertex_capacity(), 0);
    m.vmoved[v] = m.clock;
    for (const Id t : ball)
      if (static_cast<std::size_t>(t) < m.quality.size())
        m.quality[t] = std::numeric_limits<double>::quiet_NaN();
    return Outcome::kApplied;
  }
  bool valid = worst > 0.0;
  for (++k; k < ball.size() && valid && !c.any_refusal; ++k) {
    const Id* tv = &m.tv[4 * ball[at(k)]];
    valid = above_volume_floor(m.xyz[tv[0]], m.xyz[tv[1]], m.xyz[tv[2]], m.xyz[tv[3]]);
  }
  m.xyz[v] = old_p;
  restore_metric();
  return valid ? Outcome::kRejectedQuality : Outcome::kRejectedGeometry;
}

}  // namespace riemesh
