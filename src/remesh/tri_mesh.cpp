#include "remesh/tri_mesh.hpp"

#include <algorithm>
#include <string>

#include "remesh/renumber_tail.hpp"
#include "remesh/vertex_logs.hpp"

namespace riemesh {

Id TriMesh::add_vertex(const Vec2& p, const SymMat2& m) {
  Id v;
  if (!free_verts.empty()) {
    v = free_verts.back();
    free_verts.pop_back();
  } else {
    v = static_cast<Id>(xy.size());
    xy.emplace_back();
    metric.emplace_back();
    vref.emplace_back();
    vtag.emplace_back();
    vcurve.emplace_back();
    vparam.emplace_back();
    vtri.emplace_back();
  }
  xy[v] = p;
  metric[v] = m;
  sync_log(metric, log_metric, static_cast<std::size_t>(v));
  vref[v] = 0;
  vtag[v] = kTagNone;
  vcurve[v] = kNoCurve;
  vparam[v] = 0.0;
  vtri[v] = kNoId;
  return v;
}

Id TriMesh::add_triangle(Id a, Id b, Id c, std::int32_t ref) {
  Id t;
  if (!free_tris.empty()) {
    t = free_tris.back();
    free_tris.pop_back();
  } else {
    t = static_cast<Id>(tref.size());
    tref.emplace_back();
    tv.resize(tv.size() + 3);
    tadj.resize(tadj.size() + 3);
    ecurve.resize(ecurve.size() + 3);
    eref.resize(eref.size() + 3);
    etag.resize(etag.size() + 3);
  }
  const Id ids[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    tv[3 * t + i] = ids[i];
    tadj[3 * t + i] = kNoId;
    ecurve[3 * t + i] = kNoCurve;
    eref[3 * t + i] = 0;
    etag[3 * t + i] = kTagNone;
    vtri[ids[i]] = t;
  }
  tref[t] = ref;
  return t;
}

void TriMesh::kill_triangle(Id t) {
  for (int i = 0; i < 3; ++i) tv[3 * t + i] = kNoId;
  free_tris.push_back(t);
}

void TriMesh::kill_vertex(Id v) {
  vtri[v] = kNoId;
  free_verts.push_back(v);
}

void collect_ball(const TriMesh& m, Id v, Ball& out) {
  out.tris.clear();
  out.closed = true;
  // With v at local index i, triangle t spans the angle from P(i+1) to P(i+2) counter-clockwise:
  // its counter-clockwise neighbour around v is across edge (i+1)%3 (P(i+2) -> v), its clockwise
  // neighbour across edge (i+2)%3 (v -> P(i+1)). Collect counter-clockwise from vtri; only when
  // that hits the boundary, walk clockwise from vtri too and put those triangles first.
  const Id t0 = m.vtri[v];
  Id t = t0;
  do {
    out.tris.push_back(t);
    const Id across = m.tadj[3 * t + (vertex_index(m, t, v) + 1) % 3];
    if (across == kNoId) {
      out.closed = false;
      break;
    }
    t = across / 3;
  } while (t != t0);
  if (out.closed) return;
  const std::size_t ccw = out.tris.size();
  t = t0;
  for (;;) {
    const Id across = m.tadj[3 * t + (vertex_index(m, t, v) + 2) % 3];
    if (across == kNoId) break;
    t = across / 3;
    out.tris.push_back(t);
  }
  // Now [t0 .. ccw end) then the clockwise ones nearest first: rotate to clockwise-most first.
  std::reverse(out.tris.begin() + static_cast<std::ptrdiff_t>(ccw), out.tris.end());
  std::rotate(out.tris.begin(), out.tris.begin() + static_cast<std::ptrdiff_t>(ccw),
              out.tris.end());
}

Id find_edge_slot(const TriMesh& m, Id a, Id b) {
  // Turn around a counter-clockwise from vtri, then clockwise if the boundary stops the turn,
  // without building the ball.
  Id found = kNoId;
  auto test = [&](Id t) {
    const int i = vertex_index(m, t, a);
    if (m.tv[3 * t + (i + 1) % 3] == b) found = 3 * t + (i + 2) % 3;  // a -> b
    else if (m.tv[3 * t + (i + 2) % 3] == b) found = 3 * t + (i + 1) % 3;  // b -> a
    return i;
  };
  const Id t0 = m.vtri[a];
  Id t = t0;
  do {
    const int i = test(t);
    if (found != kNoId) return found;
    const Id across = m.tadj[3 * t + (i + 1) % 3];
    if (across == kNoId) break;
    t = across / 3;
    if (t == t0) return kNoId;
  } while (true);
  t = t0;
  for (;;) {
    const Id across = m.tadj[3 * t + (vertex_index(m, t, a) + 2) % 3];
    if (across == kNoId) return kNoId;
    t = across / 3;
    test(t);
    if (found != kNoId) return found;
  }
}

std::vector<Id> renumber_tail(TriMesh& m, Id first) {
  using namespace detail;
  TailOrder o = tail_order(
      m.vertex_capacity(), static_cast<std::size_t>(first), [&m](Id v) { return m.vert_alive(v); },
      [&m](Id v) { return m.xy[v].x; }, 2, m.tv, 3);
  gather_records(m.xy, o.vertex_new2old, 1);
  gather_records(m.metric, o.vertex_new2old, 1);
  if (!m.log_metric.empty()) gather_records(m.log_metric, o.vertex_new2old, 1);
  gather_records(m.vref, o.vertex_new2old, 1);
  gather_records(m.vtag, o.vertex_new2old, 1);
  gather_records(m.vcurve, o.vertex_new2old, 1);
  gather_records(m.vparam, o.vertex_new2old, 1);
  gather_records(m.vtri, o.vertex_new2old, 1);
  gather_records(m.tv, o.elem_new2old, 3);
  gather_records(m.tadj, o.elem_new2old, 3);
  gather_records(m.tref, o.elem_new2old, 1);
  gather_records(m.ecurve, o.elem_new2old, 3);
  gather_records(m.eref, o.elem_new2old, 3);
  gather_records(m.etag, o.elem_new2old, 3);
  for (Id& v : m.tv) v = o.vertex_old2new[v];
  renumber_slots(m.tadj, o.elem_old2new, 3);
  for (Id& t : m.vtri)
    if (t != kNoId) t = o.elem_old2new[t];
  m.free_tris.clear();
  std::erase_if(m.free_verts, [first](Id v) { return v >= first; });
  return std::move(o.vertex_old2new);
}

std::string check_tri_mesh(const TriMesh& m) {
  auto fail = [](const char* what, long id) { return std::string(what) + " at " + std::to_string(id); };
  for (std::size_t t = 0; t < m.triangle_capacity(); ++t) {
    const Id ti = static_cast<Id>(t);
    if (!m.tri_alive(ti)) continue;
    for (int i = 0; i < 3; ++i) {
      const Id v = m.tv[3 * t + i];
      if (v < 0 || static_cast<std::size_t>(v) >= m.vertex_capacity() || !m.vert_alive(v))
        return fail("triangle uses a dead or invalid vertex", ti);
      const Id s = 3 * ti + i, r = m.tadj[s];
      if (r == kNoId) {
        if (!m.is_feature(s)) return fail("boundary edge without a feature curve", s);
        continue;
      }
      if (!m.tri_alive(r / 3) || m.tadj[r] != s) return fail("asymmetric adjacency", s);
      if (m.edge_from(s) != m.edge_to(r) || m.edge_to(s) != m.edge_from(r))
        return fail("neighbour does not share the edge", s);
      if (m.ecurve[s] != m.ecurve[r] || (m.is_feature(s) && m.eref[s] != m.eref[r]))
        return fail("edge data differs across the edge", s);
    }
    const Vec2& a = m.xy[m.tv[3 * t]];
    if (!(signed_area(a, m.xy[m.tv[3 * t + 1]], m.xy[m.tv[3 * t + 2]]) > 0.0))
      return fail("triangle with non-positive area", ti);
  }
  for (std::size_t v = 0; v < m.vertex_capacity(); ++v) {
    const Id vi = static_cast<Id>(v);
    if (!m.vert_alive(vi)) continue;
    const Id t = m.vtri[v];
    if (!m.tri_alive(t) || vertex_index(m, t, vi) < 0) return fail("stale vertex back-pointer", vi);
  }
  return {};
}

}  // namespace riemesh
