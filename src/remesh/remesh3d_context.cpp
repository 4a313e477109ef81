#include "remesh/remesh3d_context.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "mesh/adjacency.hpp"
#include "metric/metric.hpp"
#include "remesh/planar_pieces3d.hpp"
#include "remesh/plane_fit.hpp"
#include "remesh/renumber_tail.hpp"

namespace riemesh {
namespace {

/// The input's vertices as points (its coords are freed).
std::vector<Vec3> take_points(Mesh& input) {
  std::vector<Vec3> out(input.num_vertices());
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = Vec3{{input.coords[3 * v], input.coords[3 * v + 1], input.coords[3 * v + 2]}};
  std::vector<double>().swap(input.coords);
  return out;
}

/// The tets' neighbours as build_face_adjacency gives them, read off the fresh TetMesh.
std::vector<Id> tet_neighbours(const TetMesh& m) {
  std::vector<Id> out(m.tadj.size());
  for (std::size_t s = 0; s < out.size(); ++s) out[s] = m.tadj[s] == kNoId ? kNoId : m.tadj[s] / 4;
  return out;
}

/// Where to split an edge of metric length L (sizes varying geometrically from a to b): at the
/// fraction k/n of its metric length, n = max(2, round(L)), k = floor(n/2), so that repeated
/// splits cut it into n pieces of length L/n ~ 1 instead of 2^j pieces (bisection overshoots:
/// the first run from a coarse mesh went to 3x the final count before collapsing). As in 2D.
double split_fraction(double la, double lb) {
  const double q = lb / la;
  const bool uniform = std::abs(q - 1.0) < 1e-9;
  const double total = uniform ? la : la * (q - 1.0) / std::log(q);
  const long n = std::max(2L, std::lround(total));
  const double f = static_cast<double>(n / 2) / static_cast<double>(n);
  if (uniform) return f;
  return std::log(1.0 + f * (q - 1.0)) / std::log(q);
}

/// The diagonal of the vertices' bounding box.
double diagonal(const TetMesh& m) {
  Vec3 lo = m.xyz.empty() ? Vec3{} : m.xyz[0], hi = lo;
  for (const Vec3& p : m.xyz)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  return norm(hi - lo);
}

/// The listed faces holding edge (a, b) of the shell, an interface face once: their refs in
/// refs[0..n) (at most 4; false beyond) and whether one is an interface.
bool edge_faces(const TetMesh& m, const std::vector<Id>& shell, Id a, Id b, std::int32_t* refs,
                int& n, bool& interface) {
  n = 0, interface = false;
  for (const Id t : shell)
    for (int i = 0; i < 4; ++i) {
      const Id v = m.tv[4 * t + i], s = 4 * t + i, r = m.tadj[s];
      if (v == a || v == b || !m.fbdy[s] || (r != kNoId && r < s)) continue;
      if (n == 4) return false;
      refs[n++] = m.face_ref(s);
      interface = interface || r != kNoId;
    }
  return true;
}

}  // namespace

Remesh3dContext::Remesh3dContext(const Mesh& input, std::span<const SymMat3> metrics,
                                 const Adapt3dOptions& options)
    : Remesh3dContext(Mesh(input), std::vector<SymMat3>(metrics.begin(), metrics.end()), options) {}

Remesh3dContext::Remesh3dContext(Mesh&& input, std::vector<SymMat3>&& metrics,
                                 const Adapt3dOptions& options)
    : options_(options),
      mesh_(build_tet_mesh(input, metrics)),
      background_(take_points(input), std::move(input.tets), std::move(metrics), options.interp,
                  tet_neighbours(mesh_)),
      constant_(same_metric<3>(background_.metrics())) {
  flat_tol_ = kFlatness * diagonal(mesh_);
  if (!options.keep_surface && options.detect_angles)
    pieces_ = split_planar_pieces(mesh_, options.angle_deg, flat_tol_);
  find_planes();
  std::vector<std::int32_t> curved;
  // Curved patches are reconstructed from their listed faces (an interface's once): outer
  // patches and curved interfaces whose faces form a manifold surface (a sphere in a box, a
  // cylinder through a box: its rims are feature lines, see classify_vertices); other curved
  // interfaces are kept as given (a ref only on interfaces was taken for a curved patch with an
  // empty surface: every gmsh multi-volume mesh was refused).
  for (const auto& [ref, pl] : planes_)
    if (!pl.planar && (pl.outer || rebuildable_interface(ref))) curved.push_back(ref);
  if (!options.keep_surface && !curved.empty())
    boundary_ = std::make_unique<Boundary3d>(mesh_, std::move(curved), options),
    mesh_.surface = boundary_.get();
  while (classify_vertices()) {
  }
  // Curved interfaces, kept or rebuilt, get the kept surface's split floor: the coarse facets of
  // a closed one far from its smooth surface (gmsh's pole of a sphere of size 0.2) refuse their
  // splits within --hausd, and the splits around them made tets of quality 0.001.
  for (const auto& [ref, pl] : planes_)
    has_interfaces_ = has_interfaces_ || (pl.inner && !pl.planar);
  num_input_vertices_ = mesh_.vertex_capacity();
  hint_.assign(mesh_.vertex_capacity(), kNoId);
  for (std::size_t v = 0; v < hint_.size(); ++v) hint_[v] = mesh_.vtet[v];
  classify_line_vertices();
}

void Remesh3dContext::find_planes() {
  const TetMesh& m = mesh_;
  std::map<std::int32_t, std::vector<Tri3>> faces;  // each listed face once
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    const Id t = static_cast<Id>(s / 4);
    if (!m.fbdy[s] || !m.tet_alive(t)) continue;
    Plane& pl = planes_[m.face_ref(s)];
    if (m.tadj[s] == kNoId) pl.outer = true;
    else
      pl.inner = true;
    if (!m.face_side_listed(s)) continue;
    const int i = static_cast<int>(s % 4);
    faces[m.face_ref(s)].push_back(Tri3{m.xyz[m.tv[4 * t + kTetFace[i][0]]],
                                        m.xyz[m.tv[4 * t + kTetFace[i][1]]],
                                        m.xyz[m.tv[4 * t + kTetFace[i][2]]]});
  }
  // Planar patches and interfaces are remeshed on their plane; curved interfaces that are not
  // closed are kept as given (plane_fit.hpp).
  const double diag = diagonal(m);
  for (const auto& [ref, f] : faces) {
    const PlaneFit fit = fit_plane(f);
    Plane& pl = planes_.at(ref);
    pl.n = fit.n, pl.d = fit.d;
    pl.planar = is_planar(fit, diag);
  }
}

bool Remesh3dContext::kept_interface(std::int32_t ref) const {
  const auto it = planes_.find(ref);
  return it != planes_.end() && it->second.inner && !it->second.planar &&
         !(boundary_ && boundary_->curved(ref));
}

bool Remesh3dContext::rebuildable_interface(std::int32_t ref) const {
  const auto it = planes_.find(ref);
  if (it == planes_.end() || it->second.outer || !it->second.inner) return false;
  const TetMesh& m = mesh_;
  std::vector<std::pair<Id, Id>> edges;
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    const Id t = static_cast<Id>(s / 4), r = m.tadj[s];
    if (!m.fbdy[s] || !m.tet_alive(t) || r < static_cast<Id>(s) || m.face_ref(s) != ref) continue;
    const int i = static_cast<int>(s % 4);
    const Id f[3] = {m.tv[4 * t + kTetFace[i][0]], m.tv[4 * t + kTetFace[i][1]],
                     m.tv[4 * t + kTetFace[i][2]]};
    for (int k = 0; k < 3; ++k)
      edges.push_back({std::min(f[k], f[(k + 1) % 3]), std::max(f[k], f[(k + 1) % 3])});
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t k = 0; k + 2 < edges.size(); ++k)
    if (edges[k] == edges[k + 2]) return false;  // an edge on 3 of its faces
  return true;
}

const Remesh3dContext::Plane* Remesh3dContext::plane(std::int32_t ref) const {
  const auto it = planes_.find(ref);
  return it != planes_.end() && it->second.planar ? &it->second : nullptr;
}

bool Remesh3dContext::classify_vertices() {
  TetMesh& m = mesh_;
  const std::size_t nv = m.vertex_capacity();
  constexpr int kMostRefs = 4;  // refs recorded per vertex
  std::vector<std::int32_t> refs(kMostRefs * nv, 0);
  std::vector<int> count(nv, 0);
  // inner: on an interface; off_surface: on an interface the reconstruction does not hold (a
  // planar one, or a curved one kept as given).
  std::vector<bool> fixed(nv, false), curved(nv, false), inner(nv, false), off_surface(nv, false);
  std::map<std::pair<std::int32_t, std::int32_t>, std::vector<Id>> on_coplanar_line;
  for (std::size_t s = 0; s < m.fbdy.size(); ++s) {
    const Id t = static_cast<Id>(s / 4);
    if (!m.fbdy[s] || !m.tet_alive(t)) continue;
    const int i = static_cast<int>(s % 4);
    const std::int32_t ref = m.face_ref(s);
    const bool flat = plane(ref) != nullptr, interface = m.tadj[s] != kNoId;
    const bool rebuilt = boundary_ && boundary_->curved(ref);
    for (int k = 0; k < 3; ++k) {
      const Id v = m.tv[4 * t + kTetFace[i][k]];
      if ((interface && !flat && !rebuilt) || (!flat && !boundary_) || options_.keep_surface)
        fixed[v] = true;
      if (!flat) curved[v] = true;
      if (interface) inner[v] = true;
      if (interface && !rebuilt) off_surface[v] = true;
      int& c = count[v];
      std::int32_t* r = &refs[kMostRefs * v];
      if (std::find(r, r + std::min(c, kMostRefs), ref) != r + std::min(c, kMostRefs)) continue;
      if (c < kMostRefs) r[c] = ref;
      ++c;
    }
  }
  std::vector<bool> rim_corner(nv, false);
  for (std::size_t v = 0; v < nv; ++v) {
    VertexKind k = VertexKind::kFixed;
    const std::int32_t* r = &refs[kMostRefs * v];
    std::int32_t r1 = 0, r2 = 0;
    const bool tagged = m.vtag[v] & (kTagCorner | kTagRequired);
    if (!tagged && !fixed[v] && inner[v] && rim(r, count[v], r1, r2)) {
      // The rim of a rebuilt curved patch on coplanar planar ones, an interface among them: on
      // the reconstruction's feature line (its corners fixed), in the plane (constrain).
      k = boundary_->kind(static_cast<Id>(v));
      rim_corner[v] = k == VertexKind::kFixed;
      if (k == VertexKind::kCurve) m.vplane[2 * v] = r1, m.vplane[2 * v + 1] = r2;
      m.vkind[v] = k == VertexKind::kCurve ? k : VertexKind::kFixed;
      continue;
    }
    // A curved patch meeting an interface its reconstruction does not hold.
    if (tagged || fixed[v] || (off_surface[v] && curved[v]) ||
        (count[v] > 2 && !(inner[v] && interface_line(r, count[v], r1, r2)))) {
      k = VertexKind::kFixed;
    } else if (count[v] > 2) {  // where a planar interface meets coplanar outer patches
      k = VertexKind::kRidge;
      m.vplane[2 * v] = r1, m.vplane[2 * v + 1] = r2;
    } else if (count[v] == 0) {
      k = VertexKind::kInterior;
    } else if (curved[v]) {  // on the reconstruction of the curved patches (boundary3d.hpp)
      k = boundary_->kind(static_cast<Id>(v));
      m.vplane[2 * v] = std::min(r[0], r[count[v] - 1]);
      m.vplane[2 * v + 1] = std::max(r[0], r[count[v] - 1]);
    } else if (count[v] == 1) {
      k = VertexKind::kPlanar;
      m.vplane[2 * v] = m.vplane[2 * v + 1] = r[0];
    } else {
      r1 = std::min(r[0], r[1]), r2 = std::max(r[0], r[1]);
      m.vplane[2 * v] = r1, m.vplane[2 * v + 1] = r2;
      if (std::abs(dot(plane(r1)->n, plane(r2)->n)) < 1.0 - kPlaneNormal)
        k = VertexKind::kRidge;
      else
        on_coplanar_line[{r1, r2}].push_back(static_cast<Id>(v));
    }
    m.vkind[v] = k;
  }
  // Coplanar patches of different refs (the outer faces of a gmsh multi-volume box, split where
  // the volumes meet): their common line had no direction from the planes, its vertices were
  // fixed and its edges never split (4x the size asked). When its vertices are collinear, the
  // line is a ridge of that direction.
  const double tol = kFlatness * diagonal(m);
  for (const auto& [pair, line] : on_coplanar_line) {
    if (line.size() < 2) continue;
    const Vec3& o = m.xyz[static_cast<std::size_t>(line[0])];
    Vec3 far = o;
    for (const Id v : line)
      if (norm(m.xyz[static_cast<std::size_t>(v)] - o) > norm(far - o))
        far = m.xyz[static_cast<std::size_t>(v)];
    if (!(norm(far - o) > tol)) continue;
    const Vec3 d = normalize(far - o);
    bool straight = true;
    for (const Id v : line) {
      const Vec3 r = m.xyz[static_cast<std::size_t>(v)] - o;
      straight = straight && norm(r - dot(r, d) * d) <= tol;
    }
    if (!straight) continue;
    coplanar_lines_[pair] = d;
    for (const Id v : line) m.vkind[static_cast<std::size_t>(v)] = VertexKind::kRidge;
  }
  // A planar interface whose rim cannot move (it meets a curved patch or a kept interface) is
  // kept as given as a whole: remeshed up to a fixed rim, it strung vertices within 1e-5 of the
  // rim's long edges (tets of quality 1e-7). Kept, it gets the kept surface's floor and note.
  if (options_.keep_surface) return false;
  bool froze = false;
  for (std::size_t v = 0; v < nv; ++v) {
    if (m.vkind[v] != VertexKind::kFixed || !inner[v] || !(fixed[v] || curved[v]) ||
        rim_corner[v] || (m.vtag[v] & (kTagCorner | kTagRequired)))
      continue;
    for (int c = 0; c < std::min(count[v], kMostRefs); ++c) {
      const auto it = planes_.find(refs[kMostRefs * v + c]);
      if (it == planes_.end() || !it->second.inner || !it->second.planar) continue;
      it->second.planar = false;
      froze = true;
    }
  }
  return froze;
}

void Remesh3dContext::classify_line_vertices() {
  TetMesh& m = mesh_;
  struct Ends {
    Id other[2];
    std::int32_t ref[2];
    int n = 0;
  };
  std::map<Id, Ends> at;  // per vertex on a line: its first two line edges and their count
  for (const auto& [key, ref] : m.line_ref)
    for (const auto& [v, w] :
         {std::pair{static_cast<Id>(key & 0xffffffffu), static_cast<Id>(key >> 32)},
          std::pair{static_cast<Id>(key >> 32), static_cast<Id>(key & 0xffffffffu)}}) {
      Ends& e = at[v];
      if (e.n < 2) e.other[e.n] = w, e.ref[e.n] = ref;
      ++e.n;
    }
  // The refs of the listed faces at edge (a, b) (an interface's once), sorted, then their count
  // (+ 8 on an interface).
  const auto faces = [this](Id a, Id b, std::array<std::int32_t, 5>& out) {
    thread_local std::vector<Id> shell;
    collect_shell(mesh_, a, b, shell);
    std::int32_t refs[4] = {0, 0, 0, 0};
    int n = 0;
    bool interface = false;
    if (shell.empty() || !edge_faces(mesh_, shell, a, b, refs, n, interface)) return false;
    std::sort(refs, refs + 4);  // (the unused entries are 0 on both edges compared)
    std::copy(refs, refs + 4, out.begin());
    out[4] = n + (interface ? 8 : 0);
    return true;
  };
  for (const auto& [v, e] : at) {
    VertexKind& k = m.vkind[v];
    if (k == VertexKind::kFixed) continue;
    // Inside a line: two line edges of one ref on the same patches, else a corner of the lines
    // (an end, a junction, a ref change, a line leaving a ridge across a patch).
    std::array<std::int32_t, 5> f0{}, f1{};
    bool inside = e.n == 2 && e.ref[0] == e.ref[1] && faces(v, e.other[0], f0) &&
                  faces(v, e.other[1], f1) && f0 == f1;
    if (inside && k == VertexKind::kPlanar) {  // a straight line inside a planar patch
      const Vec3 &p = m.xyz[v], &p0 = m.xyz[e.other[0]], &p1 = m.xyz[e.other[1]];
      const Vec3 d = p1 - p0;
      const double t = dot(p - p0, d) / dot(d, d);
      inside = t > 0.0 && t < 1.0 && norm(p - (p0 + t * d)) <= flat_tol_;
      if (inside) k = VertexKind::kRidge;  // (vplane: the patch twice)
    } else if (k != VertexKind::kRidge && k != VertexKind::kCurve) {
      inside = false;  // a curved patch whose reconstruction does not hold the line
    }
    if (!inside) k = VertexKind::kFixed;
  }
}

bool Remesh3dContext::line_direction(Id v, Vec3& d) const {
  thread_local std::vector<Id> ball;
  collect_ball(mesh_, v, ball);
  for (const Id t : ball)
    for (int i = 0; i < 4; ++i) {
      const Id x = mesh_.tv[4 * t + i];
      if (x == v || !mesh_.on_line(v, x)) continue;
      d = normalize(mesh_.xyz[x] - mesh_.xyz[v]);
      return true;
    }
  return false;
}

bool Remesh3dContext::interface_line(const std::int32_t* r, int n, std::int32_t& r1,
                                     std::int32_t& r2) const {
  if (n < 3 || n > 4) return false;
  bool any_inner = false;
  const Plane* pl[4];
  for (int k = 0; k < n; ++k) {
    pl[k] = plane(r[k]);
    if (!pl[k]) return false;
    any_inner = any_inner || planes_.at(r[k]).inner;
  }
  if (!any_inner) return false;
  // The first two planes that cross; every plane must hold their common line.
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (std::abs(dot(pl[i]->n, pl[j]->n)) >= 1.0 - kPlaneNormal) continue;
      const Vec3 d = normalize(cross(pl[i]->n, pl[j]->n));
      for (int k = 0; k < n; ++k)
        if (std::abs(dot(pl[k]->n, d)) > 1e-6) return false;
      r1 = std::min(r[i], r[j]), r2 = std::max(r[i], r[j]);
      return true;
    }
  return false;
}

bool Remesh3dContext::rim(const std::int32_t* r, int n, std::int32_t& curved,
                          std::int32_t& flat) const {
  if (!boundary_ || n < 2 || n > 4) return false;
  int nc = 0, nf = 0;
  for (int k = 0; k < n; ++k) {
    if (boundary_->curved(r[k])) {
      if (nc++ == 0) curved = r[k];
    } else if (const Plane* pl = plane(r[k])) {
      if (nf++ == 0)
        flat = r[k];
      else if (std::abs(dot(pl->n, plane(flat)->n)) < 1.0 - kPlaneNormal)
        return false;  // two planes: the rim would be on their line
    } else {
      return false;  // a kept interface
    }
  }
  return nc > 0 && nf > 0;
}

bool Remesh3dContext::ridge_direction(std::int32_t r1, std::int32_t r2, Vec3& d) const {
  const Plane *p1 = plane(r1), *p2 = plane(r2);
  if (!p1 || !p2) return false;
  if (std::abs(dot(p1->n, p2->n)) < 1.0 - kPlaneNormal) {
    d = normalize(cross(p1->n, p2->n));
    return true;
  }
  const auto it = coplanar_lines_.find({std::min(r1, r2), std::max(r1, r2)});
  if (it == coplanar_lines_.end()) return false;
  d = it->second;
  return true;
}

bool Remesh3dContext::split_point(Id a, Id b, NewVertex3& out, Id hint) const {
  thread_local std::vector<Id> shell;
  collect_shell(mesh_, a, b, shell, hint);
  std::int32_t refs[4];
  int n = 0;
  bool interface = false;
  if (shell.empty() || !edge_faces(mesh_, shell, a, b, refs, n, interface)) return false;
  out.kind = VertexKind::kInterior;
  out.plane[0] = out.plane[1] = 0;
  if (interface && n == 2 && boundary_ && boundary_->curved(refs[0]) &&
      boundary_->curved(refs[1])) {  // on a rebuilt curved interface: on its reconstruction
    if (options_.keep_surface) return false;
    const bool line = boundary_->feature_edge(mesh_, a, b, refs[0], refs[1]);
    out.kind = line ? VertexKind::kCurve : VertexKind::kSurface;
    out.plane[0] = std::min(refs[0], refs[1]), out.plane[1] = std::max(refs[0], refs[1]);
  } else if (std::int32_t rc = 0, rp = 0; interface && rim(refs, n, rc, rp)) {
    if (options_.keep_surface) return false;  // a rebuilt curved patch's rim on a plane
    out.kind = VertexKind::kCurve;
    out.plane[0] = rc, out.plane[1] = rp;
  } else if (interface) {  // on a planar interface (its faces once), or where it meets others
    if (options_.keep_surface) return false;
    std::int32_t d[4];
    int nd = 0;
    for (int k = 0; k < n; ++k) {
      if (!plane(refs[k])) return false;
      if (std::find(d, d + nd, refs[k]) == d + nd) d[nd++] = refs[k];
    }
    Vec3 dir;
    std::int32_t r1 = 0, r2 = 0;
    if (nd == 1 && n == 2) {
      out.kind = VertexKind::kPlanar;
      r1 = r2 = d[0];
    } else if (nd == 2 && ridge_direction(d[0], d[1], dir)) {
      out.kind = VertexKind::kRidge;
      r1 = std::min(d[0], d[1]), r2 = std::max(d[0], d[1]);
    } else if (interface_line(d, nd, r1, r2)) {
      out.kind = VertexKind::kRidge;
    } else {
      return false;
    }
    out.plane[0] = r1, out.plane[1] = r2;
  } else if (n == 1 || n > 2) {
    return false;
  } else if (n == 2) {
    if (options_.keep_surface) return false;
    if (!plane(refs[0]) || !plane(refs[1])) {  // a curved patch (boundary3d.hpp)
      if (!boundary_) return false;
      const bool line = boundary_->feature_edge(mesh_, a, b, refs[0], refs[1]);
      out.kind = line ? VertexKind::kCurve : VertexKind::kSurface;
      out.plane[0] = std::min(refs[0], refs[1]), out.plane[1] = std::max(refs[0], refs[1]);
    } else if (refs[0] == refs[1]) {
      out.kind = VertexKind::kPlanar;
      out.plane[0] = out.plane[1] = refs[0];
    } else {
      Vec3 d;
      if (!ridge_direction(refs[0], refs[1], d)) return false;
      out.kind = VertexKind::kRidge;
      out.plane[0] = std::min(refs[0], refs[1]), out.plane[1] = std::max(refs[0], refs[1]);
    }
  }
  if (mesh_.on_line(a, b)) {  // on a line of the input's Edges: the new vertex on that line
    if (out.kind == VertexKind::kPlanar)
      out.kind = VertexKind::kRidge;  // inside a planar patch (straight: classify_line_vertices)
    else if (out.kind != VertexKind::kRidge && out.kind != VertexKind::kCurve)
      return false;
  }
  const Vec3 ab = mesh_.xyz[b] - mesh_.xyz[a];
  const double t = split_fraction(length(mesh_.metric[a], ab), length(mesh_.metric[b], ab));
  out.p = mesh_.xyz[a] + t * ab;
  if (on_curved_boundary(out.kind)) {
    out.p = boundary_->place(out.kind, out.p);
    if (out.kind == VertexKind::kCurve && !on_rim_plane(out.plane[0], out.plane[1], out.p))
      return false;
  }
  out.metric = metric_for(out.p, a);
  return true;
}

SymMat3 Remesh3dContext::metric_for(const Vec3& p, Id hint_vertex) const {
  const Id hint = static_cast<std::size_t>(hint_vertex) < hint_.size() ? hint_[hint_vertex] : kNoId;
  if (constant_) {
    last_found_ = hint;  // still a tet near the point, should the field stop being constant
    return *constant_;
  }
  return background_.metric_at(p, hint, &last_found_);
}

void Remesh3dContext::set_field(std::vector<SymMat3>&& metrics) {
  background_.set_metrics(std::move(metrics));
  constant_ = same_metric<3>(background_.metrics());
  TetMesh& m = mesh_;
  const std::uint32_t now = ++m.clock;
  if (m.vmoved.size() < m.vertex_capacity()) m.vmoved.resize(m.vertex_capacity(), 0);
  for (std::size_t vi = 0; vi < m.vertex_capacity(); ++vi) {
    const Id v = static_cast<Id>(vi);
    if (!m.vert_alive(v)) continue;
    m.set_metric(v, metric_for(m.xyz[vi], v));
    inherit_hint(v);
    m.vmoved[vi] = now;
  }
  m.quality.clear();
}

void Remesh3dContext::restore_refs() {
  restore_piece_refs(mesh_, pieces_);
  pieces_.clear();
}

void Remesh3dContext::inherit_hint(Id v) {
  if (static_cast<std::size_t>(v) >= hint_.size()) hint_.resize(v + 1, kNoId);
  hint_[v] = last_found_;
}

std::vector<Id> Remesh3dContext::renumber_new_vertices(std::vector<Id>* tet_old2new) {
  std::vector<Id> old2new = renumber_tail(mesh_, static_cast<Id>(num_input_vertices_), tet_old2new);
  detail::remap_records(hint_, old2new, mesh_.vertex_capacity(), kNoId);
  return old2new;
}

bool Remesh3dContext::smoothing_target(Id v, NewVertex3& out, std::vector<Id>* ball_out,
                                       std::span<const Id> neighbours) const {
  const VertexKind k = mesh_.vkind[v];
  if (k == VertexKind::kFixed) return false;
  thread_local std::vector<Id> own_ball, own_nbrs;
  std::vector<Id>& ball = ball_out ? *ball_out : own_ball;
  collect_ball(mesh_, v, ball);
  std::span<const Id> nbrs = neighbours;
  if (nbrs.empty()) {
    ball_neighbours(mesh_, v, ball, own_nbrs);
    nbrs = own_nbrs;
  }
  const Vec3& p = mesh_.xyz[v];
  Vec3 sum{};
  double wsum = 0.0;
  for (const Id x : nbrs) {
    const double l = edge_length(mesh_, x, v);
    if (!(l > 0.0)) return false;
    sum = sum + (mesh_.xyz[x] + (1.0 / l) * (p - mesh_.xyz[x]));
    wsum += 1.0;
  }
  if (wsum == 0.0) return false;
  out.p = (1.0 / wsum) * sum;
  if (!constrain(v, out.p)) return false;
  out.kind = k;
  out.metric = metric_for(out.p, v);
  return true;
}

bool Remesh3dContext::constrain(Id v, Vec3& p) const {
  const VertexKind k = mesh_.vkind[v];
  if (k == VertexKind::kFixed) return false;
  if (k == VertexKind::kPlanar) {
    const Plane* pl = plane(mesh_.vplane[2 * v]);
    p = p - (dot(pl->n, p) - pl->d) * pl->n;
  } else if (k == VertexKind::kRidge) {  // onto the line through v where the two patches meet
    const Vec3& o = mesh_.xyz[v];
    Vec3 d;
    const std::int32_t r1 = mesh_.vplane[2 * v], r2 = mesh_.vplane[2 * v + 1];
    if (r1 == r2 ? !line_direction(v, d) : !ridge_direction(r1, r2, d)) return false;
    p = o + dot(p - o, d) * d;
  } else if (on_curved_boundary(k)) {
    p = boundary_->place(k, p);
  }
  return true;
}

bool Remesh3dContext::on_rim_plane(std::int32_t r1, std::int32_t r2, const Vec3& p) const {
  const Plane* pl = plane(r1);
  if (!pl) pl = plane(r2);
  return !pl || std::abs(dot(pl->n, p) - pl->d) <= flat_tol_;
}

}  // namespace riemesh
