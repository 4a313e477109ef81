// Edge swap (flip): the diagonal of the quadrilateral formed by two triangles is exchanged when
// the worse of the two triangles gets better.
#include <algorithm>

#include "remesh/ops2d.hpp"

namespace riemesh {
namespace {

struct EdgeData {
  Id adj;
  std::int32_t curve, ref;
  std::uint8_t tag;
};

EdgeData save(const TriMesh& m, Id slot) {
  return {m.tadj[slot], m.ecurve[slot], m.eref[slot], m.etag[slot]};
}

void restore(TriMesh& m, Id slot, const EdgeData& d) {
  link(m, slot, d.adj);
  m.ecurve[slot] = d.curve;
  m.eref[slot] = d.ref;
  m.etag[slot] = d.tag;
}

}  // namespace

Outcome swap_edge(TriMesh& m, Id slot, double min_gain) {
  const Id r = m.tadj[slot];
  if (r == kNoId || m.is_feature(slot)) return Outcome::kRejectedTopology;
  const Id t = slot / 3, u = r / 3;
  const int i = slot % 3, j = r % 3;
  // t = (c, a, b) with the edge a -> b; u = (d, b, a).
  const Id c = m.tv[3 * t + i], a = m.tv[3 * t + (i + 1) % 3], b = m.tv[3 * t + (i + 2) % 3];
  const Id d = m.tv[3 * u + j];
  if (c == d) return Outcome::kRejectedTopology;
  // No check that the diagonal c-d exists elsewhere: both new triangles must be positive, so the
  // quadrilateral is strictly convex and c-d crosses a-b; in a valid planar triangulation no
  // other edge can cross a-b.
  const Vec2 &pa = m.xy[a], &pb = m.xy[b], &pc = m.xy[c], &pd = m.xy[d];
  const double scale = std::abs(signed_area(pc, pa, pb)) + std::abs(signed_area(pd, pb, pa));
  if (!(signed_area(pc, pa, pd) > 1e-9 * scale && signed_area(pd, pb, pc) > 1e-9 * scale))
    return Outcome::kRejectedGeometry;
  // Accepted when min(q1, q2) > before + min_gain; most edges of a settled mesh already fail
  // on q1, so q2 is computed only when q1 passes (the same decision, NaNs included).
  const double before = std::min(tri_quality(m, c, a, b), tri_quality(m, d, b, a));
  const double q1 = tri_quality(m, c, a, d);
  if (!(q1 > before + min_gain)) return Outcome::kRejectedQuality;
  const double after = std::min(q1, tri_quality(m, d, b, c));
  if (!(after > before + min_gain)) return Outcome::kRejectedQuality;

  // Outer edges: t's b -> c and c -> a, u's a -> d and d -> b.
  const EdgeData bc = save(m, 3 * t + (i + 1) % 3), ca = save(m, 3 * t + (i + 2) % 3);
  const EdgeData ad = save(m, 3 * u + (j + 1) % 3), db = save(m, 3 * u + (j + 2) % 3);
  // t becomes (c, a, d): edges 0 a->d, 1 d->c, 2 c->a; u becomes (d, b, c): 0 b->c, 1 c->d, 2 d->b.
  m.tv[3 * t] = c, m.tv[3 * t + 1] = a, m.tv[3 * t + 2] = d;
  m.tv[3 * u] = d, m.tv[3 * u + 1] = b, m.tv[3 * u + 2] = c;
  restore(m, 3 * t, ad);
  restore(m, 3 * t + 2, ca);
  restore(m, 3 * u, bc);
  restore(m, 3 * u + 2, db);
  restore(m, 3 * t + 1, {3 * u + 1, kNoCurve, 0, kTagNone});
  m.ecurve[3 * u + 1] = kNoCurve, m.eref[3 * u + 1] = 0, m.etag[3 * u + 1] = kTagNone;
  m.vtri[a] = t, m.vtri[c] = t, m.vtri[b] = u, m.vtri[d] = u;
  return Outcome::kApplied;
}

int swap_around(TriMesh& m, Id v, double min_gain, double below, int max_tries,
                std::vector<Id>& touched) {
  thread_local Ball ball;             // scratch reused across calls; never shared between threads
  thread_local std::vector<Id> todo;  // triangles of v's ball whose link edge is to be tried
  collect_ball(m, v, ball);
  todo.assign(ball.tris.begin(), ball.tris.end());
  int flips = 0;
  for (int tries = 0; !todo.empty() && tries < max_tries; ++tries) {
    const Id t = todo.back();
    todo.pop_back();
    const int i = vertex_index(m, t, v);
    const Id slot = 3 * t + i;  // the edge opposite v
    if (i < 0 || m.tadj[slot] == kNoId) continue;
    if (!(tri_quality(m, t) < below)) continue;
    const Id r = m.tadj[slot];
    const Id a = m.tv[3 * t + (i + 1) % 3], b = m.tv[3 * t + (i + 2) % 3], d = m.tv[r];
    if (swap_edge(m, slot, min_gain) != Outcome::kApplied) continue;
    ++flips;
    touched.insert(touched.end(), {a, b, d});
    // Both triangles of the quadrilateral now hold v, each with a new link edge (a-d, d-b).
    todo.push_back(t);
    todo.push_back(r / 3);
  }
  return flips;
}

}  // namespace riemesh
