// Mesh <-> TetMesh: neighbours and listed faces in, compacted arrays and ridge edges out.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <vector>

#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/simplex_geometry.hpp"
#include "remesh/tet_mesh.hpp"
#include "remesh/vertex_logs.hpp"

namespace riemesh {
namespace {

std::array<Id, 3> sorted3(Id a, Id b, Id c) {
  std::array<Id, 3> k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

/// InputError when the tets at a vertex are not joined through faces (two solids touching along
/// an edge or at a point): the operators walk a vertex's ball and an edge's shell through faces,
/// and an edge's shell came up empty ("internal check failed: !shell.empty()").
void require_manifold(const TetMesh& m) {
  std::vector<std::uint32_t> tets_at(m.vertex_capacity(), 0);
  for (const Id v : m.tv) ++tets_at[static_cast<std::size_t>(v)];
  std::vector<Id> ball;
  std::size_t pinched = 0;
  Id first = kNoId;
  for (std::size_t v = 0; v < m.vertex_capacity(); ++v) {
    if (m.vtet[v] == kNoId) continue;
    collect_ball(m, static_cast<Id>(v), ball);
    if (ball.size() != tets_at[v] && pinched++ == 0) first = static_cast<Id>(v);
  }
  if (!pinched) return;
  const Vec3& p = m.xyz[static_cast<std::size_t>(first)];
  char msg[320];
  std::snprintf(msg, sizeof msg,
                "the volume is not a manifold at %zu vertices (first: (%g, %g, %g)): the "
                "tetrahedra there are not joined through faces (solids touching along an edge "
                "or at a point); 3D remeshing needs them joined",
                pinched, p[0], p[1], p[2]);
  throw InputError(msg);
}

}  // namespace

TetMesh build_tet_mesh(const Mesh& mesh, std::span<const SymMat3> metrics) {
  if (mesh.dim != 3 || mesh.tets.empty()) throw InputError("3D remeshing needs a tetrahedral mesh");
  const std::size_t nv = mesh.num_vertices(), nt = mesh.num_tets();
  if (metrics.size() != nv)
    throw InputError("the metric has " + std::to_string(metrics.size()) + " values but the mesh " +
                     std::to_string(nv) + " vertices");
  TetMesh m;
  // Room for 1/8 more vertices and tets than the input: at steady state (input close to the
  // output) the passes then never double the arrays' capacity, the largest part of the peak.
  const std::size_t rv = nv + nv / 8 + 16, rt = nt + nt / 8 + 16;
  m.xyz.reserve(rv), m.metric.reserve(rv), m.vref.reserve(rv), m.vtag.reserve(rv);
  m.vkind.reserve(rv), m.vplane.reserve(2 * rv), m.vtet.reserve(rv);
  m.tv.reserve(4 * rt), m.tadj.reserve(4 * rt), m.fbdy.reserve(4 * rt);
  m.tref.reserve(rt), m.mark.reserve(rt), m.quality.reserve(rt);
  m.xyz.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
    m.xyz[v] = Vec3{{mesh.coords[3 * v], mesh.coords[3 * v + 1], mesh.coords[3 * v + 2]}};
  m.metric.assign(metrics.begin(), metrics.end());
  sync_logs(m.metric, m.log_metric);
  m.vref.assign(mesh.vert_ref.begin(), mesh.vert_ref.end());
  m.vref.resize(nv, 0);
  m.vtag.assign(mesh.vert_tag.begin(), mesh.vert_tag.end());
  m.vtag.resize(nv, kTagNone);
  m.vkind.assign(nv, VertexKind::kFixed);
  m.vplane.assign(2 * nv, 0);
  m.vtet.assign(nv, kNoId);
  const Adjacency adj = build_face_adjacency(mesh.tets, 4, nv);
  if (!adj.nonmanifold_faces.empty()) throw InputError("the tetrahedra share a face three times");
  m.tv.assign(mesh.tets.begin(), mesh.tets.end());
  m.tref.assign(mesh.tet_ref.begin(), mesh.tet_ref.end());
  m.tref.resize(nt, 0);
  m.tadj.assign(4 * nt, kNoId);
  m.fbdy.assign(4 * nt, 0);
  std::map<std::array<Id, 3>, std::size_t> listed;
  // Only a face whose three vertices are on listed triangles is looked up (most are interior).
  std::vector<std::uint8_t> on_listed(nv, 0);
  for (const Id v : mesh.triangles)
    if (v >= 0 && static_cast<std::size_t>(v) < nv) on_listed[v] = 1;
  for (std::size_t f = 0; f < mesh.num_triangles(); ++f)
    listed.emplace(sorted3(mesh.triangles[3 * f], mesh.triangles[3 * f + 1],
                           mesh.triangles[3 * f + 2]), f);
  // A face between tets of different refs that is not listed is an interface all the same, kept
  // as given (tets changed subdomain across it, the sphere of a gmsh sphere-in-box written with
  // Physical Volumes only moved by 0.07): it gets the ref after the largest listed one (before
  // the smallest when the largest is INT32_MAX).
  std::vector<std::uint8_t> found(mesh.num_triangles(), 0);
  std::int64_t above = 1, below = 0;
  for (const int r : mesh.tri_ref)
    above = std::max<std::int64_t>(above, std::int64_t{r} + 1),
    below = std::min(below, std::int64_t{r} - 1);
  const auto interface_ref = static_cast<std::int32_t>(
      above <= std::numeric_limits<std::int32_t>::max()
          ? above
          : std::max<std::int64_t>(below, std::numeric_limits<std::int32_t>::min()));
  for (std::size_t t = 0; t < nt; ++t) {
    const Id* v = &mesh.tets[4 * t];
    // Rounded to zero or below, the exact orientation decides (a valid flat sliver of a
    // Delaunay tetrahedralisation; the sliver sweeps remove it).
    const Vec3 x[4] = {m.xyz[v[0]], m.xyz[v[1]], m.xyz[v[2]], m.xyz[v[3]]};
    if (!(tet_volume(x[0], x[1], x[2], x[3]) > 0.0) && !(simplex::exact_orientation(x) > 0.0))
      throw InputError("tetrahedron " + std::to_string(t + 1) +
                       " has a negative or zero volume (3D remeshing needs positive tets)");
    for (int i = 0; i < 4; ++i) {
      m.vtet[v[i]] = static_cast<Id>(t);
      const Id n = adj.elem2elem[4 * t + i];
      if (n != kNoId) {
        const Id* w = &mesh.tets[4 * n];
        int j = 0;
        while (j < 4 && std::find(v, v + 4, w[j]) != v + 4) ++j;  // n's vertex not in t
        m.tadj[4 * t + i] = 4 * n + j;
      }
      const Id a = v[kTetFace[i][0]], b = v[kTetFace[i][1]], c = v[kTetFace[i][2]];
      const auto it = on_listed[a] && on_listed[b] && on_listed[c] ? listed.find(sorted3(a, b, c))
                                                                    : listed.end();
      if (it != listed.end()) {
        found[it->second] = 1;
        const std::int32_t ref = mesh.tri_ref.empty() ? 0 : mesh.tri_ref[it->second];
        m.set_face(4 * t + i, m.ref_code(ref), ref);
      } else if (n == kNoId) {
        m.set_face(4 * t + i, m.ref_code(0), 0);  // an unlisted boundary face: ref 0
      } else if (m.tref[t] != m.tref[static_cast<std::size_t>(n)]) {
        m.set_face(4 * t + i, m.ref_code(interface_ref), interface_ref);
      }
    }
  }
  // A listed triangle that is no tet face (a stray or misnumbered one) was dropped silently, its
  // ref with it. (A triangle listed twice is found through its first copy.)
  std::size_t stray = mesh.num_triangles();
  for (const auto& [key, f] : listed)
    if (!found[f]) stray = std::min(stray, f);
  if (stray < mesh.num_triangles())
    throw InputError("triangle " + std::to_string(stray + 1) + " (ref " +
                     std::to_string(mesh.tri_ref.empty() ? 0 : mesh.tri_ref[stray]) +
                     ") is no face of any tetrahedron");
  // The Edges on listed triangles are the feature lines kept with their refs (the first listing
  // of an edge wins); an Edge on no listed triangle bounds nothing the remesher keeps.
  if (mesh.num_edges() > 0) {
    std::vector<std::uint64_t> on_triangles;
    on_triangles.reserve(3 * mesh.num_triangles());
    for (std::size_t f = 0; f < mesh.num_triangles(); ++f)
      for (int k = 0; k < 3; ++k)
        on_triangles.push_back(
            TetMesh::line_key(mesh.triangles[3 * f + k], mesh.triangles[3 * f + (k + 1) % 3]));
    std::sort(on_triangles.begin(), on_triangles.end());
    for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
      const Id a = mesh.edges[2 * e], b = mesh.edges[2 * e + 1];
      const std::uint64_t key = TetMesh::line_key(a, b);
      if (a != b && std::binary_search(on_triangles.begin(), on_triangles.end(), key))
        m.line_ref.emplace(key, e < mesh.edge_ref.size() ? mesh.edge_ref[e] : 0);
    }
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (m.vtet[v] == kNoId) m.free_verts.push_back(static_cast<Id>(v));  // in no tet: dropped
  std::reverse(m.free_verts.begin(), m.free_verts.end());
  require_manifold(m);
  return m;
}

Mesh to_mesh(const TetMesh& m, std::vector<SymMat3>* metrics) {
  Mesh out;
  out.dim = 3;
  std::vector<Id> id(m.vertex_capacity(), kNoId);
  for (std::size_t v = 0; v < m.vertex_capacity(); ++v) {
    if (!m.vert_alive(static_cast<Id>(v))) continue;
    id[v] = static_cast<Id>(out.vert_ref.size());
    out.coords.insert(out.coords.end(), {m.xyz[v][0], m.xyz[v][1], m.xyz[v][2]});
    out.vert_ref.push_back(m.vref[v]);
    std::uint8_t tag = m.vtag[v];
    if (m.vkind[v] == VertexKind::kRidge || m.vkind[v] == VertexKind::kCurve) tag |= kTagRidge;
    out.vert_tag.push_back(tag);
    if (metrics) metrics->push_back(m.metric[v]);
  }
  // The refs of the listed outer faces at each boundary edge.
  std::map<std::pair<Id, Id>, std::vector<std::int32_t>> edge_faces;
  for (std::size_t t = 0; t < m.tet_capacity(); ++t) {
    if (!m.tet_alive(static_cast<Id>(t))) continue;
    const Id* v = &m.tv[4 * t];
    out.tets.insert(out.tets.end(), {id[v[0]], id[v[1]], id[v[2]], id[v[3]]});
    out.tet_ref.push_back(m.tref[t]);
    for (int i = 0; i < 4; ++i) {
      const std::size_t s = 4 * t + i;
      if (!m.fbdy[s]) continue;
      const Id r = m.tadj[s];
      if (!m.face_side_listed(s)) continue;  // interface: once, out of its lower region
      const Id a = v[kTetFace[i][0]], b = v[kTetFace[i][1]], c = v[kTetFace[i][2]];
      out.triangles.insert(out.triangles.end(), {id[a], id[b], id[c]});
      out.tri_ref.push_back(m.face_ref(s));
      out.tri_tag.push_back(kTagNone);
      if (r != kNoId) continue;
      for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
        edge_faces[{std::min(id[p], id[q]), std::max(id[p], id[q])}].push_back(m.face_ref(s));
    }
  }
  // Ridges between patches of different refs (ref 0), then the input's lines with their refs
  // (a ridge on a line takes the line's ref: edges between the same two patches may carry
  // different refs, one per line, and lines inside a patch are kept too).
  std::map<std::pair<Id, Id>, std::int32_t> edges;
  for (const auto& [e, refs] : edge_faces)
    if (refs.size() == 2 && refs[0] != refs[1]) edges.emplace(e, 0);
  for (const auto& [key, ref] : m.line_ref) {
    const auto a = static_cast<Id>(key & 0xffffffffu), b = static_cast<Id>(key >> 32);
    if (!m.vert_alive(a) || !m.vert_alive(b)) continue;
    edges[{std::min(id[a], id[b]), std::max(id[a], id[b])}] = ref;
  }
  for (const auto& [e, ref] : edges) {
    out.edges.insert(out.edges.end(), {e.first, e.second});
    out.edge_ref.push_back(ref);
    out.edge_tag.push_back(kTagRidge);
  }
  return out;
}

}  // namespace riemesh
