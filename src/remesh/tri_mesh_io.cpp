#include "remesh/tri_mesh_io.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/vertex_logs.hpp"

namespace riemesh {
namespace {

std::string tri_name(std::size_t t) { return "triangle " + std::to_string(t + 1); }

/// The slot of edge (a, b) in triangle t (either direction), or kNoId.
Id find_slot(const TriMesh& m, Id t, Id a, Id b) {
  for (int i = 0; i < 3; ++i) {
    const Id s = 3 * t + i, x = m.edge_from(s), y = m.edge_to(s);
    if ((x == a && y == b) || (x == b && y == a)) return s;
  }
  return kNoId;
}

/// The vertices, in one go (as add_vertex one by one would set them). Each array is written
/// once (no zero fill first) and reserved with room for as many again: splits then append
/// without reallocating (copying) every array; the room is address space only until used.
void add_vertices(TriMesh& m, const Mesh& mesh, std::span<const SymMat2> metrics,
                  std::span<const VertexCurve> curves) {
  const std::size_t nv = mesh.num_vertices(), room = 2 * nv;
  reserve_huge(m.xy, room);
  reserve_huge(m.metric, room);
  reserve_huge(m.vref, room);
  reserve_huge(m.vtag, room);
  reserve_huge(m.vcurve, room);
  reserve_huge(m.vparam, room);
  reserve_huge(m.vtri, room);
  m.metric.assign(metrics.begin(), metrics.begin() + static_cast<std::ptrdiff_t>(nv));
  sync_logs(m.metric, m.log_metric);
  m.vtri.assign(nv, kNoId);
  for (std::size_t v = 0; v < nv; ++v) {
    m.xy.push_back(Vec2{{mesh.coords[2 * v], mesh.coords[2 * v + 1]}});
    m.vref.push_back(mesh.vert_ref.empty() ? 0 : mesh.vert_ref[v]);
    const std::uint8_t tag = mesh.vert_tag.empty() ? std::uint8_t{kTagNone} : mesh.vert_tag[v];
    m.vtag.push_back(curves[v].curve != kNoCurve ? static_cast<std::uint8_t>(tag | kTagRidge) : tag);
    m.vcurve.push_back(curves[v].curve);
    m.vparam.push_back(curves[v].param);
  }
}

/// The triangles in one go (as add_triangle one by one would set them), then the neighbours:
/// the slot of edge (a, b) in neighbour n is the one opposite n's vertex that is neither.
void add_triangles(TriMesh& m, const Mesh& mesh, const Adjacency& adj) {
  if (!adj.nonmanifold_faces.empty()) {
    // Named by place: the remesher works on a renumbered copy, whose triangle ids the user never
    // saw. A triangle listed twice is the usual cause, named as such (it was "non-manifold edge
    // at" a triangle elsewhere).
    auto centroid = [&mesh](std::size_t t) {
      double c[2] = {0.0, 0.0};
      for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 2; ++i)
          c[i] += mesh.coords[2 * static_cast<std::size_t>(mesh.triangles[3 * t + k]) + i] / 3.0;
      char where[64];
      std::snprintf(where, sizeof where, "(%g, %g)", c[0], c[1]);
      return std::string(where);
    };
    std::vector<std::pair<std::array<Id, 3>, std::size_t>> keys;
    keys.reserve(mesh.num_triangles());
    for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
      std::array<Id, 3> k{mesh.triangles[3 * t], mesh.triangles[3 * t + 1],
                          mesh.triangles[3 * t + 2]};
      std::sort(k.begin(), k.end());
      keys.push_back({k, t});
    }
    std::sort(keys.begin(), keys.end());
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first)
        throw InputError("a triangle is listed twice, at " + centroid(keys[i].second));
    throw InputError("an edge is shared by more than two triangles, at the triangle " +
                     centroid(static_cast<std::size_t>(adj.nonmanifold_faces[0] / 3)));
  }
  const std::size_t nt = mesh.num_triangles(), room = 6 * nt;  // room for as many again
  reserve_huge(m.tv, room);
  reserve_huge(m.tadj, room);
  reserve_huge(m.tref, room / 3);
  reserve_huge(m.ecurve, room);
  reserve_huge(m.eref, room);
  reserve_huge(m.etag, room);
  m.tv.assign(mesh.triangles.begin(), mesh.triangles.begin() + static_cast<std::ptrdiff_t>(3 * nt));
  m.ecurve.assign(3 * nt, kNoCurve);
  m.eref.assign(3 * nt, 0);
  m.etag.assign(3 * nt, kTagNone);
  if (mesh.tri_ref.empty()) m.tref.assign(nt, 0);
  else m.tref.assign(mesh.tri_ref.begin(), mesh.tri_ref.begin() + static_cast<std::ptrdiff_t>(nt));
  for (std::size_t t = 0; t < nt; ++t) {
    const Id* v = &mesh.triangles[3 * t];
    if (!(signed_area(m.xy[v[0]], m.xy[v[1]], m.xy[v[2]]) > 0.0))
      throw InputError(tri_name(t) + " is clockwise or degenerate");
    for (int i = 0; i < 3; ++i) m.vtri[v[i]] = static_cast<Id>(t);
  }
  constexpr int kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};  // edge i runs next -> prev
  for (std::size_t t = 0; t < nt; ++t)
    for (int i = 0; i < 3; ++i) {
      const Id n = adj.elem2elem[3 * t + i];
      if (n == kNoId) {
        m.tadj.push_back(kNoId);
        continue;
      }
      const Id a = m.tv[3 * t + kNext[i]], b = m.tv[3 * t + kPrev[i]];
      const Id* w = &m.tv[3 * static_cast<std::size_t>(n)];
      int j = 0;
      while (j < 3 && (w[j] == a || w[j] == b)) ++j;
      const bool same = j < 3 && ((w[kNext[j]] == b && w[kPrev[j]] == a) ||
                                  (w[kNext[j]] == a && w[kPrev[j]] == b));
      m.tadj.push_back(same ? 3 * n + j : find_slot(m, n, a, b));
    }
}

}  // namespace

TriMesh build_tri_mesh(const Mesh& mesh, std::span<const SymMat2> metrics,
                       std::span<const TriFeature> features,
                       std::span<const VertexCurve> vertex_curves,
                       const Adjacency* adjacency) {
  if (mesh.dim != 2) throw InputError("2D remeshing needs a planar mesh (Dimension 2)");
  if (metrics.size() != mesh.num_vertices() || vertex_curves.size() != mesh.num_vertices())
    throw InputError("one metric and one curve record per vertex expected");
  TriMesh m;
  add_vertices(m, mesh, metrics, vertex_curves);
  const Adjacency own = adjacency ? Adjacency{} : build_adjacency(mesh.triangles, 3, mesh.num_vertices());
  const Adjacency& adj = adjacency ? *adjacency : own;
  add_triangles(m, mesh, adj);
  // Features: mark both sides of each listed edge, found through the triangles around a.
  for (const TriFeature& f : features) {
    for (const Id t : ball(adj, f.a)) {
      const Id s = find_slot(m, t, f.a, f.b);
      if (s == kNoId) continue;
      m.ecurve[s] = f.curve;
      m.eref[s] = f.ref;
      m.etag[s] = f.tag;
    }
  }
  for (std::size_t s = 0; s < m.tadj.size(); ++s)
    if (m.tadj[s] == kNoId && m.ecurve[s] == kNoCurve)
      throw InputError("boundary edge of " + tri_name(s / 3) + " belongs to no boundary curve");
  return m;
}

Mesh to_mesh(const TriMesh& m, std::vector<SymMat2>* metrics) {
  Mesh out;
  out.dim = 2;
  std::vector<Id> new_id(m.vertex_capacity(), kNoId);
  if (metrics) metrics->clear();
  // Exact sizes up front: no growth by copies, huge pages for the large arrays.
  const std::size_t nv = m.num_live_vertices(), nt = m.num_live_triangles();
  reserve_huge(out.coords, 2 * nv);
  reserve_huge(out.vert_ref, nv);
  reserve_huge(out.vert_tag, nv);
  reserve_huge(out.triangles, 3 * nt);
  reserve_huge(out.tri_ref, nt);
  if (metrics) reserve_huge(*metrics, nv);
  for (std::size_t v = 0; v < m.vertex_capacity(); ++v) {
    if (!m.vert_alive(static_cast<Id>(v))) continue;
    new_id[v] = static_cast<Id>(out.num_vertices());
    out.coords.insert(out.coords.end(), {m.xy[v][0], m.xy[v][1]});
    out.vert_ref.push_back(m.vref[v]);
    out.vert_tag.push_back(m.vtag[v] & (kTagCorner | kTagRequired));
    if (metrics) metrics->push_back(m.metric[v]);
  }
  for (std::size_t t = 0; t < m.triangle_capacity(); ++t) {
    if (!m.tri_alive(static_cast<Id>(t))) continue;
    for (int i = 0; i < 3; ++i) out.triangles.push_back(new_id[m.tv[3 * t + i]]);
    out.tri_ref.push_back(m.tref[t]);
    for (int i = 0; i < 3; ++i) {
      const Id s = 3 * static_cast<Id>(t) + i;
      if (!m.is_feature(s) || (m.tadj[s] != kNoId && m.tadj[s] < s)) continue;
      out.edges.insert(out.edges.end(), {new_id[m.edge_from(s)], new_id[m.edge_to(s)]});
      out.edge_ref.push_back(m.eref[s]);
      out.edge_tag.push_back(m.etag[s] & kTagRequired);
    }
  }
  out.tri_tag.assign(out.num_triangles(), kTagNone);
  return out;
}

}  // namespace riemesh
