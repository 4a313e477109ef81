#include "remesh/tri_mesh.hpp"

#include <algorithm>
#include <string>

#include "core/huge_pages.hpp"
#include "mesh/hilbert.hpp"
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

namespace {

/// a = the records new2old lists, `stride` values each, in that order; the storage reserved
/// with room for as many again (splits then append without copying).
template <class T>
void gather_records(std::vector<T>& a, const std::vector<Id>& new2old, std::size_t stride) {
  std::vector<T> out;
  reserve_huge(out, 2 * stride * new2old.size());
  for (const Id old : new2old)
    for (std::size_t k = 0; k < stride; ++k) out.push_back(a[stride * static_cast<std::size_t>(old) + k]);
  a.swap(out);
}

}  // namespace

std::vector<Id> renumber_tail(TriMesh& m, Id first) {
  const std::size_t nv = m.vertex_capacity(), head = static_cast<std::size_t>(first);
  // Vertices: the head in place, then the live tail in Hilbert order.
  std::vector<Id> tail;
  std::vector<double> coords;
  for (std::size_t v = head; v < nv; ++v)
    if (m.vert_alive(static_cast<Id>(v))) {
      tail.push_back(static_cast<Id>(v));
      coords.insert(coords.end(), {m.xy[v][0], m.xy[v][1]});
    }
  std::vector<Id> new2old(head);
  for (std::size_t v = 0; v < head; ++v) new2old[v] = static_cast<Id>(v);
  for (const Id k : hilbert_order(coords, 2)) new2old.push_back(tail[k]);
  std::vector<Id> old2new(nv, kNoId);
  for (std::size_t v = 0; v < new2old.size(); ++v) old2new[new2old[v]] = static_cast<Id>(v);
  // Triangles: live ones by their smallest new vertex id (a counting sort, stable).
  const std::size_t nt = m.triangle_capacity();
  std::vector<Id> start(new2old.size() + 1, 0);
  for (std::size_t t = 0; t < nt; ++t) {
    if (!m.tri_alive(static_cast<Id>(t))) continue;
    const Id* v = &m.tv[3 * t];
    ++start[std::min({old2new[v[0]], old2new[v[1]], old2new[v[2]]}) + 1];
  }
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<Id> tri_new2old(static_cast<std::size_t>(start.back()));
  std::vector<Id> tri_old2new(nt, kNoId);
  for (std::size_t t = 0; t < nt; ++t) {
    if (!m.tri_alive(static_cast<Id>(t))) continue;
    const Id* v = &m.tv[3 * t];
    const Id at = start[std::min({old2new[v[0]], old2new[v[1]], old2new[v[2]]})]++;
    tri_new2old[at] = static_cast<Id>(t);
    tri_old2new[t] = at;
  }
  gather_records(m.xy, new2old, 1);
  gather_records(m.metric, new2old, 1);
  if (!m.log_metric.empty()) gather_records(m.log_metric, new2old, 1);
  gather_records(m.vref, new2old, 1);
  gather_records(m.vtag, new2old, 1);
  gather_records(m.vcurve, new2old, 1);
  gather_records(m.vparam, new2old, 1);
  gather_records(m.vtri, new2old, 1);
  gather_records(m.tv, tri_new2old, 3);
  gather_records(m.tadj, tri_new2old, 3);
  gather_records(m.tref, tri_new2old, 1);
  gather_records(m.ecurve, tri_new2old, 3);
  gather_records(m.eref, tri_new2old, 3);
  gather_records(m.etag, tri_new2old, 3);
  for (Id& v : m.tv) v = old2new[v];
  for (Id& s : m.tadj)
    if (s != kNoId) s = 3 * tri_old2new[s / 3] + s % 3;
  for (Id& t : m.vtri)
    if (t != kNoId) t = tri_old2new[t];
  m.free_tris.clear();
  std::erase_if(m.free_verts, [head](Id v) { return static_cast<std::size_t>(v) >= head; });
  return old2new;
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
