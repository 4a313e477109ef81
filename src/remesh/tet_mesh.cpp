#include "remesh/tet_mesh.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <utility>

#include "mesh/adjacency.hpp"
#include "remesh/renumber_tail.hpp"
#include "remesh/vertex_logs.hpp"

namespace riemesh {
namespace {

/// A face as its sorted vertices and the parity of the sort (orientation).
struct FaceKey {
  Id v[3];
  int parity;
  bool degenerate() const { return v[0] == v[1] || v[1] == v[2]; }
  bool same(const FaceKey& o) const { return v[0] == o.v[0] && v[1] == o.v[1] && v[2] == o.v[2]; }
};

FaceKey make_key(Id a, Id b, Id c) {
  FaceKey k{{a, b, c}, 0};
  if (k.v[0] > k.v[1]) std::swap(k.v[0], k.v[1]), k.parity ^= 1;
  if (k.v[1] > k.v[2]) std::swap(k.v[1], k.v[2]), k.parity ^= 1;
  if (k.v[0] > k.v[1]) std::swap(k.v[0], k.v[1]), k.parity ^= 1;
  return k;
}

FaceKey face_key(const Id* tet, int i) {
  return make_key(tet[kTetFace[i][0]], tet[kTetFace[i][1]], tet[kTetFace[i][2]]);
}

bool holds(const FaceKey& k, Id v) { return k.v[0] == v || k.v[1] == v || k.v[2] == v; }

/// The key of face i of tet tv with sub.x replaced by sub.y; false when the face lacks sub.x.
bool substituted_key(const Id* tv, int i, const Substitution& sub, FaceKey& key) {
  Id w[3] = {tv[kTetFace[i][0]], tv[kTetFace[i][1]], tv[kTetFace[i][2]]};
  bool hit = false;
  for (Id& x : w)
    if (x == sub.x) x = sub.y, hit = true;
  if (hit) key = make_key(w[0], w[1], w[2]);
  return hit;
}

/// A face holding both vertices of a substitution (a collapsed edge's face) vanishes.
bool vanishes(const FaceKey& k, std::span<const Substitution> subst) {
  for (const Substitution& sub : subst)
    if (holds(k, sub.x) && holds(k, sub.y)) return true;
  return false;
}

/// A face of the cavity's boundary: seen from inside, with what lies across it.
struct CavityFace {
  FaceKey key;
  Id outer;  // slot across, or kNoId
  std::int32_t ref;  // for an overflow ref code only
  std::uint8_t bdy;  // the ref code (TetMesh::fbdy)
  int direct = 0, substituted = 0;
};

/// A face of a new tet and what it was matched with.
struct NewFace {
  FaceKey key;
  int slot;        // 4 * (index in tets) + local face
  int partner;     // index of the new face across (internal), or -1
  int cavity;      // index of the cavity face it is (directly or substituted), or -1
  bool substituted;
};

std::uint32_t next_stamp(const TetMesh& m) {
  if (m.mark.size() < m.tet_capacity()) m.mark.resize(m.tet_capacity(), 0);
  if (++m.stamp == 0) {  // wrapped: clear once
    std::fill(m.mark.begin(), m.mark.end(), 0);
    m.stamp = 1;
  }
  return m.stamp;
}

Id alloc_tet(TetMesh& m) {
  if (!m.free_tets.empty()) {
    const Id t = m.free_tets.back();
    m.free_tets.pop_back();
    return t;
  }
  const Id t = static_cast<Id>(m.tref.size());
  m.tv.insert(m.tv.end(), 4, kNoId);
  m.tadj.insert(m.tadj.end(), 4, kNoId);
  m.fbdy.insert(m.fbdy.end(), 4, 0);
  m.tref.push_back(0);
  return t;
}

}  // namespace

std::uint8_t TetMesh::ref_code(std::int32_t ref) {
  const auto it = std::find(ref_table.begin(), ref_table.end(), ref);
  if (it != ref_table.end()) return static_cast<std::uint8_t>(it - ref_table.begin() + 1);
  if (ref_table.size() + 1 >= kRefOverflow) return kRefOverflow;
  ref_table.push_back(ref);
  return static_cast<std::uint8_t>(ref_table.size());
}

void TetMesh::set_face(std::size_t slot, std::uint8_t code, std::int32_t ref) {
  if (fbdy[slot] == kRefOverflow && code != kRefOverflow) ref_overflow.erase(static_cast<Id>(slot));
  fbdy[slot] = code;
  if (code == kRefOverflow) ref_overflow[static_cast<Id>(slot)] = ref;
}

void TetMesh::set_metric(Id v, const SymMat3& m) {
  metric[v] = m;
  sync_log(metric, log_metric, static_cast<std::size_t>(v));
}

Id TetMesh::add_vertex(const Vec3& p, const SymMat3& m) {
  Id v;
  if (!free_verts.empty()) {
    v = free_verts.back();
    free_verts.pop_back();
    xyz[v] = p, metric[v] = m, vref[v] = 0, vtag[v] = kTagNone, vkind[v] = VertexKind::kInterior;
    vplane[2 * v] = vplane[2 * v + 1] = 0;
  } else {
    v = static_cast<Id>(xyz.size());
    xyz.push_back(p), metric.push_back(m), vref.push_back(0), vtag.push_back(kTagNone);
    vkind.push_back(VertexKind::kInterior), vplane.insert(vplane.end(), {0, 0});
    vtet.push_back(kNoId);
  }
  sync_log(metric, log_metric, static_cast<std::size_t>(v));
  vtet[v] = kNoId;
  return v;
}

void TetMesh::kill_vertex(Id v) {
  vtet[v] = kNoId;
  free_verts.push_back(v);
}

std::vector<Id> renumber_tail(TetMesh& m, Id first, std::vector<Id>* tet_old2new) {
  using namespace detail;
  TailOrder o = tail_order(
      m.vertex_capacity(), static_cast<std::size_t>(first), [&m](Id v) { return m.vert_alive(v); },
      [&m](Id v) { return m.xyz[v].x; }, 3, m.tv, 4);
  const std::size_t nv = m.vertex_capacity(), nt = m.tet_capacity();
  // The lazily grown arrays first brought to full size (the values they stand for when short).
  if (!m.vtouch.empty() || !m.vmoved.empty())
    m.vtouch.resize(nv, 0), m.vmoved.resize(nv, 0);
  if (!m.quality.empty()) m.quality.resize(nt, std::numeric_limits<double>::quiet_NaN());
  gather_records(m.xyz, o.vertex_new2old, 1);
  gather_records(m.metric, o.vertex_new2old, 1);
  if (!m.log_metric.empty()) gather_records(m.log_metric, o.vertex_new2old, 1);
  gather_records(m.vref, o.vertex_new2old, 1);
  gather_records(m.vtag, o.vertex_new2old, 1);
  gather_records(m.vkind, o.vertex_new2old, 1);
  gather_records(m.vplane, o.vertex_new2old, 2);
  gather_records(m.vtet, o.vertex_new2old, 1);
  if (!m.vtouch.empty()) {
    gather_records(m.vtouch, o.vertex_new2old, 1);
    gather_records(m.vmoved, o.vertex_new2old, 1);
  }
  gather_records(m.tv, o.elem_new2old, 4);
  gather_records(m.tadj, o.elem_new2old, 4);
  gather_records(m.tref, o.elem_new2old, 1);
  gather_records(m.fbdy, o.elem_new2old, 4);
  if (!m.quality.empty()) gather_records(m.quality, o.elem_new2old, 1);
  for (Id& v : m.tv) v = o.vertex_old2new[v];
  renumber_slots(m.tadj, o.elem_old2new, 4);
  for (Id& t : m.vtet)
    if (t != kNoId) t = o.elem_old2new[t];
  std::map<Id, std::int32_t> overflow;
  for (const auto& [slot, ref] : m.ref_overflow)
    if (const Id t = o.elem_old2new[static_cast<std::size_t>(slot / 4)]; t != kNoId)
      overflow[4 * t + slot % 4] = ref;
  m.ref_overflow.swap(overflow);
  std::unordered_map<std::uint64_t, std::int32_t> lines;
  for (const auto& [key, ref] : m.line_ref) {
    const Id a = o.vertex_old2new[key & 0xffffffffu], b = o.vertex_old2new[key >> 32];
    if (a != kNoId && b != kNoId) lines.emplace(TetMesh::line_key(a, b), ref);
  }
  m.line_ref.swap(lines);
  m.mark.assign(m.tet_capacity(), 0);  // scratch: no walk is under way
  m.free_tets.clear();
  std::erase_if(m.free_verts, [first](Id v) { return v >= first; });
  if (tet_old2new) *tet_old2new = std::move(o.elem_old2new);
  return std::move(o.vertex_old2new);
}

void ball_neighbours(const TetMesh& m, Id v, std::span<const Id> ball, std::vector<Id>& out) {
  out.clear();
  for (const Id t : ball)
    for (int i = 0; i < 4; ++i)
      if (m.tv[4 * t + i] != v) out.push_back(m.tv[4 * t + i]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void collect_ball(const TetMesh& m, Id v, std::vector<Id>& out) {
  out.clear();
  const Id start = m.vtet[v];
  if (start == kNoId) return;
  const std::uint32_t s = next_stamp(m);
  out.push_back(start);
  m.mark[start] = s;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Id t = out[k];
    const int i = tet_index(m, t, v);
    for (int j = 0; j < 4; ++j) {
      if (j == i) continue;
      const Id r = m.tadj[4 * t + j];
      if (r == kNoId) continue;
      const Id n = r / 4;
      if (m.mark[n] != s) m.mark[n] = s, out.push_back(n);
    }
  }
}

Id find_edge_tet(const TetMesh& m, Id a, Id b) {
  const Id start = m.vtet[a];
  if (start == kNoId || !m.vert_alive(b)) return kNoId;
  thread_local std::vector<Id> queue;
  const std::uint32_t s = next_stamp(m);
  queue.assign(1, start);
  m.mark[start] = s;
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const Id t = queue[k];
    if (tet_index(m, t, b) >= 0) return t;
    const int i = tet_index(m, t, a);
    for (int j = 0; j < 4; ++j) {
      const Id r = m.tadj[4 * t + j];
      if (j == i || r == kNoId) continue;
      if (m.mark[r / 4] != s) m.mark[r / 4] = s, queue.push_back(r / 4);
    }
  }
  return kNoId;
}

void collect_shell(const TetMesh& m, Id a, Id b, std::vector<Id>& out, Id hint) {
  out.clear();
  if (hint == kNoId || !m.tet_alive(hint) || tet_index(m, hint, a) < 0 || tet_index(m, hint, b) < 0)
    hint = find_edge_tet(m, a, b);
  if (hint == kNoId) return;
  // Turn around the edge: across the two faces of each tet that hold it.
  const std::uint32_t s = next_stamp(m);
  out.push_back(hint);
  m.mark[hint] = s;
  for (std::size_t k = 0; k < out.size(); ++k) {
    const Id t = out[k];
    for (int j = 0; j < 4; ++j) {
      const Id v = m.tv[4 * t + j], r = m.tadj[4 * t + j];
      if (v == a || v == b || r == kNoId) continue;
      if (m.mark[r / 4] != s) m.mark[r / 4] = s, out.push_back(r / 4);
    }
  }
}

bool replace_cavity(TetMesh& m, std::span<const Id> cavity, std::span<const NewTet> tets,
                    std::span<const Substitution> subst, std::vector<Id>* created) {
  thread_local std::vector<CavityFace> cf, inner;
  thread_local std::vector<NewFace> nf;
  thread_local std::vector<int> order;
  thread_local std::vector<Id> verts;
  const std::uint32_t s = next_stamp(m);
  for (const Id t : cavity) m.mark[t] = s;
  cf.clear();
  inner.clear();  // listed faces between two cavity tets (an interface), once each
  for (const Id t : cavity)
    for (int i = 0; i < 4; ++i) {
      const Id r = m.tadj[4 * t + i];
      const std::uint8_t code = m.fbdy[4 * t + i];
      const CavityFace face{face_key(&m.tv[4 * t], i), r,
                            code == TetMesh::kRefOverflow ? m.face_ref(4 * t + i) : 0, code};
      if (r != kNoId && m.mark[r / 4] == s) {
        if (code && 4 * t + i < r) inner.push_back(face);
        continue;
      }
      cf.push_back(face);
    }
  nf.clear();
  for (std::size_t k = 0; k < tets.size(); ++k)
    for (int i = 0; i < 4; ++i) {
      const FaceKey key = face_key(tets[k].v, i);
      if (key.degenerate()) return false;
      nf.push_back({key, static_cast<int>(4 * k + i), -1, -1, false});
    }
  // Internal faces: pairs of new faces with opposite orientations.
  order.resize(nf.size());
  for (std::size_t k = 0; k < nf.size(); ++k) order[k] = static_cast<int>(k);
  std::sort(order.begin(), order.end(), [](int x, int y) {
    const FaceKey &a = nf[x].key, &b = nf[y].key;
    if (a.v[0] != b.v[0]) return a.v[0] < b.v[0];
    if (a.v[1] != b.v[1]) return a.v[1] < b.v[1];
    if (a.v[2] != b.v[2]) return a.v[2] < b.v[2];
    return x < y;
  });
  for (std::size_t k = 0; k + 1 < order.size(); ++k) {
    NewFace &f = nf[order[k]], &g = nf[order[k + 1]];
    if (!f.key.same(g.key)) continue;
    if (f.partner >= 0 || f.key.parity == g.key.parity) return false;  // three, or overlapping
    f.partner = order[k + 1], g.partner = order[k];
  }
  // An internal new face lying in a listed face inside the cavity (the same face, or its image
  // by a substitution: the halves of a split interface face, an interface face dragged by a
  // collapse) is listed with it (f.cavity: -2 - its index in `inner`). Every listed inner face
  // must have an image or vanish (hold both vertices of a substitution): an operator that would
  // remove an interface is refused.
  if (!inner.empty()) {
    for (NewFace& f : nf) {
      if (f.partner < 0 || f.cavity != -1) continue;
      const Id* tv = tets[f.slot / 4].v;
      const int i = f.slot % 4;
      for (std::size_t c = 0; c < inner.size() && f.cavity == -1; ++c)
        if (inner[c].key.same(f.key)) f.cavity = -2 - static_cast<int>(c), ++inner[c].direct;
      for (const Substitution& sub : subst) {
        FaceKey key;
        if (f.cavity != -1) break;
        if (!substituted_key(tv, i, sub, key)) continue;
        for (std::size_t c = 0; c < inner.size() && f.cavity == -1; ++c)
          if (inner[c].key.same(key)) f.cavity = -2 - static_cast<int>(c), ++inner[c].direct;
      }
      if (f.cavity != -1) nf[f.partner].cavity = f.cavity;  // (counted once per pair)
    }
    for (const CavityFace& c : inner)
      if (c.direct == 0 && !vanishes(c.key, subst)) return false;
  }
  // The others are faces of the cavity's boundary.
  for (NewFace& f : nf) {
    if (f.partner >= 0) continue;
    for (std::size_t c = 0; c < cf.size() && f.cavity < 0; ++c)
      if (cf[c].key.same(f.key)) {
        if (cf[c].key.parity != f.key.parity || cf[c].direct > 0) return false;
        f.cavity = static_cast<int>(c), ++cf[c].direct;
      }
    if (f.cavity >= 0) continue;
    const Id* tv = tets[f.slot / 4].v;
    const int i = f.slot % 4;
    for (const Substitution& sub : subst) {
      FaceKey key;
      if (!substituted_key(tv, i, sub, key) || key.degenerate()) continue;
      for (std::size_t c = 0; c < cf.size(); ++c)
        if (cf[c].key.same(key) && cf[c].key.parity == key.parity && cf[c].outer == kNoId &&
            cf[c].bdy) {
          f.cavity = static_cast<int>(c), f.substituted = true, ++cf[c].substituted;
          break;
        }
      if (f.cavity >= 0) break;
    }
    if (f.cavity < 0) return false;
  }
  for (const CavityFace& c : cf) {
    if (c.direct == 1 && c.substituted == 0) continue;
    if (c.outer != kNoId || c.direct > 0) return false;
    if (c.substituted > 0) continue;
    if (!vanishes(c.key, subst)) return false;
  }
  // Apply: free the cavity, create the new tets, link their faces.
  verts.clear();
  for (const Id t : cavity) {
    for (int i = 0; i < 4; ++i) verts.push_back(m.tv[4 * t + i]);
    m.tv[4 * t] = kNoId;
    m.free_tets.push_back(t);
  }
  if (m.vtouch.size() < m.vertex_capacity()) m.vtouch.resize(m.vertex_capacity(), 0);
  for (const Id v : verts) m.vtet[v] = kNoId, m.vtouch[v] = m.clock;
  thread_local std::vector<Id> ids;
  ids.clear();
  for (const NewTet& nt : tets) {
    const Id t = alloc_tet(m);
    ids.push_back(t);
    if (static_cast<std::size_t>(t) < m.quality.size())
      m.quality[t] = std::numeric_limits<double>::quiet_NaN();
    for (int i = 0; i < 4; ++i) {
      m.tv[4 * t + i] = nt.v[i];
      m.vtet[nt.v[i]] = t, m.vtouch[nt.v[i]] = m.clock;
    }
    m.tref[t] = nt.ref;
  }
  for (const NewFace& f : nf) {
    const Id slot = 4 * ids[f.slot / 4] + f.slot % 4;
    if (f.partner >= 0) {
      m.tadj[slot] = 4 * ids[nf[f.partner].slot / 4] + nf[f.partner].slot % 4;
      if (f.cavity <= -2) {
        const CavityFace& c = inner[static_cast<std::size_t>(-2 - f.cavity)];
        m.set_face(slot, c.bdy, c.ref);
      } else {
        m.set_face(slot, 0);
      }
      continue;
    }
    const CavityFace& c = cf[f.cavity];
    m.set_face(slot, c.bdy, c.ref);
    m.tadj[slot] = f.substituted ? kNoId : c.outer;
    if (!f.substituted && c.outer != kNoId) m.tadj[c.outer] = slot;
  }
  if (created) created->assign(ids.begin(), ids.end());
  return true;
}

std::string check_tet_mesh(const TetMesh& m) {
  for (std::size_t ti = 0; ti < m.tet_capacity(); ++ti) {
    const Id t = static_cast<Id>(ti);
    if (!m.tet_alive(t)) continue;
    const std::string at = "tet " + std::to_string(t);
    const Id* v = &m.tv[4 * t];
    for (int i = 0; i < 4; ++i)
      if (v[i] < 0 || static_cast<std::size_t>(v[i]) >= m.vertex_capacity() || !m.vert_alive(v[i]))
        return at + ": dead or bad vertex";
    if (!(tet_volume(m.xyz[v[0]], m.xyz[v[1]], m.xyz[v[2]], m.xyz[v[3]]) > 0.0))
      return at + ": volume not positive";
    for (int i = 0; i < 4; ++i) {
      const Id s = 4 * t + i, r = m.tadj[s];
      if (r == kNoId) {
        if (!m.fbdy[s]) return at + ": boundary face not listed";
        continue;
      }
      if (!m.tet_alive(r / 4) || m.tadj[r] != s) return at + ": asymmetric neighbour";
      const FaceKey a = face_key(v, i), b = face_key(&m.tv[4 * (r / 4)], r % 4);
      if (!a.same(b) || a.parity == b.parity) return at + ": neighbour face mismatch";
      if ((m.fbdy[s] != 0) != (m.fbdy[r] != 0) || (m.fbdy[s] && m.face_ref(s) != m.face_ref(r)))
        return at + ": listed face data differ between sides";
    }
  }
  for (std::size_t vi = 0; vi < m.vertex_capacity(); ++vi) {
    const Id v = static_cast<Id>(vi);
    if (!m.vert_alive(v)) continue;
    const Id t = m.vtet[v];
    if (!m.tet_alive(t) || tet_index(m, t, v) < 0)
      return "vertex " + std::to_string(v) + ": stale tet pointer";
  }
  for (const auto& [key, ref] : m.line_ref) {
    const auto a = static_cast<Id>(key & 0xffffffffu), b = static_cast<Id>(key >> 32);
    if (!m.vert_alive(a) || !m.vert_alive(b) || find_edge_tet(m, a, b) == kNoId)
      return "line edge (" + std::to_string(a) + ", " + std::to_string(b) + "): no such edge";
  }
  return {};
}

}  // namespace riemesh
