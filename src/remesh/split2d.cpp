// Edge split: the triangle(s) on each side of the edge are cut in two at the new vertex.
#include <algorithm>

#include "remesh/ops2d.hpp"

namespace riemesh {
namespace {

/// Copies the feature data of edge slot `from` to slot `to`.
void copy_edge_data(TriMesh& m, Id from, Id to) {
  m.ecurve[to] = m.ecurve[from];
  m.eref[to] = m.eref[from];
  m.etag[to] = m.etag[from];
}

void clear_edge_data(TriMesh& m, Id slot) {
  m.ecurve[slot] = kNoCurve;
  m.eref[slot] = 0;
  m.etag[slot] = kTagNone;
}

/// Cuts triangle t (edge i from a to b, apex c) at vertex n: t keeps (c, a, n) in place and a new
/// triangle (c, n, b) takes over the edge b -> c. Returns the new triangle. Links inside the pair
/// are made here; the two halves of the split edge are linked by the caller.
Id cut_triangle(TriMesh& m, Id t, int i, Id n) {
  const Id c = m.tv[3 * t + i], b = m.tv[3 * t + (i + 2) % 3];
  const Id old_bc = 3 * t + (i + 1) % 3;  // edge b -> c
  const Id outer = m.tadj[old_bc];
  const Id t1 = m.add_triangle(c, n, b, m.tref[t]);  // edges: 0 n->b, 1 b->c, 2 c->n
  copy_edge_data(m, 3 * t + i, 3 * t1);
  copy_edge_data(m, old_bc, 3 * t1 + 1);
  link(m, 3 * t1 + 1, outer);
  m.tv[3 * t + (i + 2) % 3] = n;  // t becomes (c, a, n); its edge (i+1) is now n -> c
  clear_edge_data(m, old_bc);
  link(m, old_bc, 3 * t1 + 2);
  m.vtri[b] = t1;
  m.vtri[c] = t;
  m.vtri[n] = t;
  return t1;
}

bool side_ok(const TriMesh& m, Id t, int i, const NewVertex& nv, double min_quality) {
  const Id c = m.tv[3 * t + i], a = m.tv[3 * t + (i + 1) % 3], b = m.tv[3 * t + (i + 2) % 3];
  const Vec2 &pa = m.xy[a], &pb = m.xy[b], &pc = m.xy[c];
  // Relative area test: each half must keep a fair share of the original triangle's area scale.
  const double ref = std::abs(signed_area(pa, pb, pc)) * 1e-9;
  if (!(signed_area(pc, pa, nv.p) > ref && signed_area(pc, nv.p, pb) > ref) ||
      !fair_area(pc, pa, nv.p) || !fair_area(pc, nv.p, pb))
    return false;
  if (min_quality <= 0.0) return true;
  // Only the halves on a boundary or interface edge of t (c -> a, b -> c), and below the floor
  // only as poor as t (a poor triangle is still refined).
  const bool on_ca = m.is_feature(3 * t + (i + 2) % 3), on_bc = m.is_feature(3 * t + (i + 1) % 3);
  if (!on_ca && !on_bc) return true;
  min_quality = std::min(min_quality, tri_quality(m, t));
  if (on_ca) {
    const SymMat2 m1 = tri_metric(m.metric[c], log_of(m.log_metric, c), m.metric[a],
                                  log_of(m.log_metric, a), nv.metric, nullptr);
    if (!(quality_in(m1, pc, pa, nv.p) >= min_quality)) return false;
  }
  if (on_bc) {
    const SymMat2 m2 = tri_metric(m.metric[c], log_of(m.log_metric, c), nv.metric, nullptr,
                                  m.metric[b], log_of(m.log_metric, b));
    if (!(quality_in(m2, pc, nv.p, pb) >= min_quality)) return false;
  }
  return true;
}

}  // namespace

Outcome split_edge(TriMesh& m, Id slot, const NewVertex& nv, double min_quality, Id* created) {
  const Id t = slot / 3, r = m.tadj[slot];
  const int i = slot % 3;
  if (m.etag[slot] & kTagRequired) return Outcome::kRejectedTopology;
  if (!side_ok(m, t, i, nv, -1.0) || (r != kNoId && !side_ok(m, r / 3, r % 3, nv, -1.0)))
    return Outcome::kRejectedGeometry;
  if (min_quality > 0.0 &&
      (!side_ok(m, t, i, nv, min_quality) || (r != kNoId && !side_ok(m, r / 3, r % 3, nv, min_quality))))
    return Outcome::kRejectedQuality;
  const Id n = m.add_vertex(nv.p, nv.metric);
  m.vcurve[n] = nv.curve;
  m.vparam[n] = nv.param;
  if (nv.curve != kNoCurve) {
    m.vtag[n] = kTagRidge;
    m.vref[n] = m.eref[slot];
  }
  const Id t1 = cut_triangle(m, t, i, n);  // t: a -> n at slot; t1: n -> b at 3*t1
  if (r != kNoId) {
    const Id u = r / 3;
    const int j = r % 3;
    const Id u1 = cut_triangle(m, u, j, n);  // u: b -> n at r; u1: n -> a at 3*u1
    link(m, slot, 3 * u1);
    link(m, 3 * t1, r);
  }
  *created = n;
  return Outcome::kApplied;
}

}  // namespace riemesh
