// Edge collapse: vertex `from` disappears into `to`; the one or two triangles on the edge go.
#include <algorithm>

#include "remesh/ops2d.hpp"

namespace riemesh {
namespace {

/// The vertices around v (the far ends of its edges), from its ball.
void ball_vertices(const TriMesh& m, const Ball& b, Id v, std::vector<Id>& out) {
  out.clear();
  for (const Id t : b.tris) {
    const int i = vertex_index(m, t, v);
    out.push_back(m.tv[3 * t + (i + 1) % 3]);
    out.push_back(m.tv[3 * t + (i + 2) % 3]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

/// The feature rules (no ball needed): frozen vertices stay, a curve vertex slides along its own
/// curve only, and a vertex off any curve keeps feature edges and the open boundary.
bool features_ok(const TriMesh& m, Id slot, Id from) {
  if (m.frozen(from)) return false;
  if (m.on_curve(from)) return m.ecurve[slot] == m.vcurve[from];
  return !m.is_feature(slot);
}

/// The link condition: the common neighbours of `from` and `to` are exactly the apexes of the
/// triangles on the edge, so the result stays a manifold mesh.
bool link_ok(const TriMesh& m, Id slot, Id from, Id to, const Ball& bfrom, const Ball& bto) {
  if (!m.on_curve(from) && !bfrom.closed) return false;  // boundary vertex off any curve: keep
  thread_local std::vector<Id> nf, nt, common;  // scratch, reused; never shared between threads
  ball_vertices(m, bfrom, from, nf);
  ball_vertices(m, bto, to, nt);
  common.clear();
  std::set_intersection(nf.begin(), nf.end(), nt.begin(), nt.end(), std::back_inserter(common));
  const std::size_t on_edge = m.tadj[slot] == kNoId ? 1 : 2;
  return common.size() == on_edge;
}

/// The new edges (to, x) for the vertices x of from's ball: none longer than lim.max_length.
/// The cheapest check, and on a converged mesh the one that refuses most candidates, so it runs
/// before the other ball, the link condition and the qualities.
bool lengths_ok(const TriMesh& m, const Ball& bfrom, Id from, Id to, const CollapseLimits& lim) {
  for (const Id t : bfrom.tris) {
    const int i = vertex_index(m, t, from);
    const Id a = m.tv[3 * t + (i + 1) % 3];  // each neighbour is the "a" of one triangle
    if (a != to && compare_edge_length(m, to, a, lim.max_length) > 0) return false;
  }
  if (!bfrom.closed) {  // the last neighbour of an open ball is only ever a "b"
    const Id t = bfrom.tris.back();
    const Id b = m.tv[3 * t + (vertex_index(m, t, from) + 2) % 3];
    if (b != to && compare_edge_length(m, to, b, lim.max_length) > 0) return false;
  }
  return true;
}

/// Geometry and quality of the triangles that keep `from` (now `to`).
/// A triangle may fall below lim.min_quality only when the ball was already worse (so collapses
/// can clean up a bad region without being blocked by it).
Outcome shape_check(const TriMesh& m, const Ball& bfrom, Id from, Id to,
                    const CollapseLimits& lim) {
  const Vec2& pt = m.xy[to];
  double old_min = 1.0;
  for (const Id t : bfrom.tris) old_min = std::min(old_min, tri_quality(m, t));
  const double floor = std::min(lim.min_quality, lim.relative_floor * old_min);
  for (const Id t : bfrom.tris) {
    const int i = vertex_index(m, t, from);
    const Id a = m.tv[3 * t + (i + 1) % 3], b = m.tv[3 * t + (i + 2) % 3];
    if (a == to || b == to) continue;  // removed with the edge
    const double old_area = signed_area(m.xy[from], m.xy[a], m.xy[b]);
    if (!(signed_area(pt, m.xy[a], m.xy[b]) > 1e-9 * old_area) || !fair_area(pt, m.xy[a], m.xy[b]))
      return Outcome::kRejectedGeometry;
    if (tri_quality(m, to, a, b) < floor) return Outcome::kRejectedQuality;
  }
  return Outcome::kApplied;
}

void set_edge_data(TriMesh& m, Id slot, std::int32_t curve, std::int32_t ref, std::uint8_t tag) {
  if (slot == kNoId) return;
  m.ecurve[slot] = curve;
  m.eref[slot] = ref;
  m.etag[slot] = tag;
}

/// A triangle on the collapsing edge: the slot of its edge (from, x), opposite `to`, and of its
/// edge (to, x), opposite `from`.
struct Side {
  Id t, slot_fx, slot_tx;
};

}  // namespace

bool collapse_too_long(const TriMesh& m, Id from, Id to, const CollapseLimits& lim) {
  thread_local Ball bfrom;  // scratch reused across calls; never shared between threads
  collect_ball(m, from, bfrom);
  return !lengths_ok(m, bfrom, from, to, lim);
}

Outcome collapse_edge(TriMesh& m, Id slot, Id from, Id to, const CollapseLimits& lim,
                      const Ball* from_ball) {
  thread_local Ball own, bto;  // scratch reused across calls; never shared between threads
  if (!features_ok(m, slot, from)) return Outcome::kRejectedTopology;
  if (from_ball == nullptr) {
    collect_ball(m, from, own);
    from_ball = &own;
  }
  const Ball& bfrom = *from_ball;
  if (!lengths_ok(m, bfrom, from, to, lim)) return Outcome::kRejectedQuality;
  collect_ball(m, to, bto);
  if (!link_ok(m, slot, from, to, bfrom, bto)) return Outcome::kRejectedTopology;

  Side sides[2];
  int nsides = 0;
  for (const Id s : {slot, m.tadj[slot]}) {
    if (s == kNoId) continue;
    const Id t = s / 3;
    const Side sd{t, 3 * t + vertex_index(m, t, to), 3 * t + vertex_index(m, t, from)};
    // Gluing must neither leave a dangling edge nor merge two feature edges into one.
    if (m.tadj[sd.slot_fx] == kNoId && m.tadj[sd.slot_tx] == kNoId)
      return Outcome::kRejectedTopology;
    if (m.is_feature(sd.slot_fx) && m.is_feature(sd.slot_tx)) return Outcome::kRejectedTopology;
    sides[nsides++] = sd;
  }
  const Outcome shape = shape_check(m, bfrom, from, to, lim);
  if (shape != Outcome::kApplied) return shape;

  // Glue the outer neighbours of each removed triangle; the merged edge keeps the feature data.
  Id survivor = kNoId;
  for (int k = 0; k < nsides; ++k) {
    const Side& sd = sides[k];
    const Id outer_f = m.tadj[sd.slot_fx], outer_t = m.tadj[sd.slot_tx];
    const Id keep = m.is_feature(sd.slot_fx) ? sd.slot_fx : sd.slot_tx;
    const std::int32_t curve = m.ecurve[keep], ref = m.eref[keep];
    const std::uint8_t tag = m.etag[keep];
    link(m, outer_f, outer_t);
    set_edge_data(m, outer_f, curve, ref, tag);
    set_edge_data(m, outer_t, curve, ref, tag);
    const Id any = outer_t != kNoId ? outer_t / 3 : outer_f / 3;
    const int ix = 3 - (sd.slot_fx % 3) - (sd.slot_tx % 3);  // local index of the apex x
    m.vtri[m.tv[3 * sd.t + ix]] = any;
    survivor = any;
  }
  for (const Id t : bfrom.tris) {
    const int i = vertex_index(m, t, from);
    if (t == sides[0].t || (nsides == 2 && t == sides[1].t)) continue;
    m.tv[3 * t + i] = to;
  }
  m.vtri[to] = survivor;
  for (int k = 0; k < nsides; ++k) m.kill_triangle(sides[k].t);
  m.kill_vertex(from);
  return Outcome::kApplied;
}

}  // namespace riemesh
