#include "generate/boundary_recovery3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/delaunay3d.hpp"
#include "generate/planar_patches3d.hpp"
#include "generate/surface_delaunay3d.hpp"
#include "mesh/self_intersection.hpp"

namespace riemesh {

namespace {

using Tri = std::array<Id, 3>;

/// Inside tets with volume <= this × (longest edge)³ are refined away (check_mesh's zero-measure
/// tolerance is 1e-12).
constexpr double kFlatTolerance = 1e-10;
using Bary = std::array<double, 3>;

Tri sorted3(const Tri& t) {
  Tri s = t;
  std::sort(s.begin(), s.end());
  return s;
}

std::uint64_t pair_key(Id a, Id b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return hi << 32 | lo;
}

/// Sign of det(a, b, c) of three barycentric triples, exact: > 0 when a, b, c turn like the
/// triangle's corners.
int bary_orient(const Bary& a, const Bary& b, const Bary& c) {
  static constexpr double kZero[3] = {0, 0, 0};
  const double d = orient3d(kZero, a.data(), b.data(), c.data());
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

/// How a point lies on the surface.
enum class Kind : std::uint8_t { kVertex, kEdge, kFace, kInterior };
struct PointInfo {
  Kind kind = Kind::kVertex;
  Id owner = kNoId;  // input edge (kEdge) or input triangle (kFace)
  double t = 0;      // kEdge: position along the edge, from its lower vertex
  Bary lambda{};     // kFace: barycentric coordinates in the triangle
};

struct EdgePoint {
  double t;
  Id id;
};

/// An input edge a < b, its points in order of t (a at 0, b at 1), and its triangles (two, or
/// more where regions meet).
struct InputEdge {
  Id a, b;
  std::vector<EdgePoint> points;
  std::vector<Id> tri;
};

/// An input triangle: corners, the edge opposite each corner, a frame of its plane (corner 0 at
/// the origin, corner 1 at (bx, 0), corner 2 at (cx, cy), cy > 0) and its subfaces, each turning
/// like the corners.
struct Facet {
  Id c[3];
  Id edge[3];
  double bx = 0, cx = 0, cy = 0;
  std::vector<Tri> sub;
};

class Recovery {
 public:
  Recovery(const Mesh& surface, const BoundaryRecoveryOptions& options);
  RecoveredVolume run();

 private:
  const double* xyz(Id v) const { return &coords_[3 * static_cast<std::size_t>(v)]; }
  Bary bary(std::size_t f, Id p) const;
  std::array<double, 2> frame(std::size_t f, const Bary& l) const {
    const Facet& t = facets_[f];
    return {l[1] * t.bx + l[2] * t.cx, l[2] * t.cy};
  }
  std::array<double, 2> frame(std::size_t f, Id p) const { return frame(f, bary(f, p)); }
  bool on_boundary(std::size_t f, Id a, Id b) const;
  Id new_point(const double* p, const PointInfo& info);
  void split_subsegment(std::size_t e, std::size_t k);
  double split_param(const InputEdge& e, std::size_t k) const;
  void refine_subface(std::size_t f, const Tri& s);
  bool locate(std::size_t f, const Bary& l, std::size_t* tri, int* zero) const;
  void insert_in_facet(std::size_t f, Id p, std::size_t tri, int zero);
  void split_in_facet(std::size_t f, Id u, Id v, Id p);
  void legalize(std::size_t f, std::vector<std::pair<Id, Id>>& stack);
  std::optional<std::size_t> find_directed(std::size_t f, Id a, Id b) const;
  Mesh volume(const Tetrahedralization& tz) const;
  bool refine_flat_tets(const Mesh& v);
  std::size_t flip_cocircular_edges(
      const std::vector<std::pair<std::size_t, std::size_t>>& missing_segments);
  void require_interior_used(const Mesh& v) const;

  const Mesh& surface_;
  std::vector<Id> vertices_;    // surface vertex of each input point
  std::size_t interior_ = 0;    // interior points, after the surface's (coords_, info_)
  std::vector<double> hole_points_;
  bool no_holes_ = false;
  std::vector<double> coords_;  // all points, input then Steiner
  std::vector<PointInfo> info_;
  std::vector<InputEdge> edges_;
  std::vector<Facet> facets_;
  std::vector<int> facet_ref_, facet_tag_;  // per facet (the input's, or a planar patch's)
  double thinnest_angle_ = 180.0;           // the input's smallest triangle angle (degrees)
  std::size_t thinnest_triangle_ = 0;       // and its triangle, for the give-up message
  std::size_t cap_ = 0;
  double max_steiner_per_vertex_ = 0.0;
  bool refine_flat_ = true;
  // The Steiner count when near-flat tets were first refined (the points from then on serve them).
  static constexpr std::size_t kNoFlat = std::numeric_limits<std::size_t>::max();
  std::size_t flat_from_ = kNoFlat;
  std::optional<Delaunay3d> kernel_;
  std::optional<Tetrahedralization> first_tz_;  // the constructor's, until run()'s first round
  std::optional<TetSkeleton> first_skeleton_;
  BoundaryRecoveryStats stats_;
};

const double* xyz_of(const Mesh& s, Id v) { return &s.coords[3 * static_cast<std::size_t>(v)]; }

std::string vertex_pair(Id a, Id b) {
  std::string s = "vertices ";
  s += std::to_string(a + 1);
  s += " and ";
  s += std::to_string(b + 1);
  return s;
}

Recovery::Recovery(const Mesh& s, const BoundaryRecoveryOptions& options) : surface_(s) {
  stats_.inconsistent_edges = require_closed_surface(s);
  const SelfIntersections crossing = find_self_intersections(s, 1, true);
  if (crossing.pairs > 0) {
    // Two triangulations of one face (a face of two volumes given by each, cut differently)
    // overlap in one plane: said so.
    bool flat = true;
    const Id* a = &s.triangles[3 * static_cast<std::size_t>(crossing.first_a)];
    const Id* b = &s.triangles[3 * static_cast<std::size_t>(crossing.first_b)];
    for (int k = 0; k < 3; ++k)
      flat = flat &&
             orient3d(xyz_of(s, a[0]), xyz_of(s, a[1]), xyz_of(s, a[2]), xyz_of(s, b[k])) == 0.0;
    std::string msg = "the surface cannot bound a volume: it intersects itself (first: triangles ";
    msg += std::to_string(crossing.first_a + 1);
    msg += " and ";
    msg += std::to_string(crossing.first_b + 1);
    msg +=
        flat ? ", which overlap in one plane: a face given twice, triangulated differently?)" : ")";
    throw InputError(msg);
  }
  std::vector<Id> old2new(s.num_vertices(), kNoId);
  for (Id v : s.triangles) old2new[static_cast<std::size_t>(v)] = 0;
  for (std::size_t v = 0; v < old2new.size(); ++v)
    if (old2new[v] != kNoId) {
      old2new[v] = static_cast<Id>(vertices_.size());
      vertices_.push_back(static_cast<Id>(v));
      coords_.insert(coords_.end(), s.coords.begin() + static_cast<std::ptrdiff_t>(3 * v),
                     s.coords.begin() + static_cast<std::ptrdiff_t>(3 * v + 3));
    }
  const std::size_t nv = vertices_.size();
  if (options.interior_points.size() % 3 != 0)
    throw InputError("interior points: 3 coordinates per point expected");
  for (double c : options.interior_points)
    if (!std::isfinite(c)) throw InputError("interior points: a coordinate is not finite");
  coords_.insert(coords_.end(), options.interior_points.begin(), options.interior_points.end());
  interior_ = options.interior_points.size() / 3;
  if (options.hole_points.size() % 3 != 0)
    throw InputError("hole points: 3 coordinates per point expected");
  if (options.no_holes && !options.hole_points.empty())
    throw InputError("hole points and no holes contradict");
  hole_points_ = options.hole_points;
  no_holes_ = options.no_holes;
  info_.assign(nv + interior_, PointInfo{Kind::kInterior});
  stats_.surface_vertices = nv;
  max_steiner_per_vertex_ = options.max_steiner_per_vertex;
  refine_flat_ = options.refine_flat;
  cap_ = static_cast<std::size_t>(options.max_steiner_per_vertex * static_cast<double>(nv));

  std::vector<Id> order = insertion_order(coords_, InsertionOrder::kBrio);
  kernel_.emplace(&coords_, order);
  for (std::size_t k = 0; k < nv; ++k) info_[k].kind = Kind::kVertex;
  kernel_->reserve(2 * nv + interior_);
  for (std::size_t k = 4; k < order.size(); ++k) {
    Id same = kNoId;
    if (!kernel_->insert(order[k], &same)) {
      const auto a = static_cast<std::size_t>(same), b = static_cast<std::size_t>(order[k]);
      if (a >= nv || b >= nv) {
        std::string msg = "interior point ";
        msg += std::to_string(std::max(a, b) - nv + 1);
        msg += " coincides with another point";
        throw InputError(msg);
      }
      std::string msg =
          "the surface cannot bound a volume: 1 pairs of vertices at the same place (first: ";
      msg += vertex_pair(vertices_[a], vertices_[b]);
      msg += ")";
      throw InputError(msg);
    }
  }

  // Planar patches whose triangles are no Delaunay faces (fans of thin triangles) take the
  // tetrahedralisation's faces on their plane, when those tile them (planar_patches3d.hpp).
  std::vector<Id> local(s.triangles.size());
  for (std::size_t k = 0; k < local.size(); ++k)
    local[k] = old2new[static_cast<std::size_t>(s.triangles[k])];
  std::vector<int> refs(s.num_triangles(), 0), tags(s.num_triangles(), 0);
  for (std::size_t f = 0; f < refs.size(); ++f) {
    if (f < s.tri_ref.size()) refs[f] = s.tri_ref[f];
    if (f < s.tri_tag.size()) tags[f] = s.tri_tag[f];
  }
  for (std::size_t f = 0; f < s.num_triangles(); ++f) {
    const double* c[3];
    for (int j = 0; j < 3; ++j)
      c[j] = &s.coords[3 * static_cast<std::size_t>(s.triangles[3 * f + j])];
    for (int j = 0; j < 3; ++j) {
      double u[3], w[3], uu = 0, ww = 0, uw = 0;
      for (int i = 0; i < 3; ++i) {
        u[i] = c[(j + 1) % 3][i] - c[j][i];
        w[i] = c[(j + 2) % 3][i] - c[j][i];
        uu += u[i] * u[i], ww += w[i] * w[i], uw += u[i] * w[i];
      }
      const double angle =
          std::acos(std::clamp(uw / std::sqrt(uu * ww), -1.0, 1.0)) * 57.29577951308232;
      if (angle < thinnest_angle_) thinnest_angle_ = angle, thinnest_triangle_ = f;
    }
  }
  // The tetrahedralisation and its skeleton serve the first recovery round too (run()).
  first_tz_ = kernel_->result();
  first_skeleton_.emplace(*first_tz_);
  PatchTriangulation patches = retriangulate_planar_patches(
      local, refs, tags, coords_, *first_tz_, *first_skeleton_, !options.keep_triangles);
  local = {};
  stats_.missing_edges = patches.missing_edges;
  stats_.missing_faces = patches.missing_faces;
  stats_.planar_patches = patches.patches;
  stats_.patch_triangles = patches.replaced;
  facet_ref_ = std::move(patches.refs);
  facet_tag_ = std::move(patches.tags);

  std::map<std::uint64_t, Id> edge_of;
  facets_.resize(patches.triangles.size() / 3);
  for (std::size_t f = 0; f < facets_.size(); ++f) {
    Facet& t = facets_[f];
    for (int j = 0; j < 3; ++j) t.c[j] = patches.triangles[3 * f + j];
    for (int j = 0; j < 3; ++j) {
      const Id a = t.c[(j + 1) % 3], b = t.c[(j + 2) % 3];
      auto [it, added] = edge_of.try_emplace(pair_key(a, b), static_cast<Id>(edges_.size()));
      if (added) {
        InputEdge e;
        e.a = std::min(a, b);
        e.b = std::max(a, b);
        e.points = {{0.0, e.a}, {1.0, e.b}};
        edges_.push_back(std::move(e));
      }
      InputEdge& e = edges_[static_cast<std::size_t>(it->second)];
      e.tri.push_back(static_cast<Id>(f));
      t.edge[j] = it->second;
    }
    const double* p0 = xyz(t.c[0]);
    double u[3], w[3];
    for (int i = 0; i < 3; ++i) {
      u[i] = xyz(t.c[1])[i] - p0[i];
      w[i] = xyz(t.c[2])[i] - p0[i];
    }
    t.bx = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    t.cx = (u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / t.bx;
    t.cy = std::sqrt(std::max(0.0, w[0] * w[0] + w[1] * w[1] + w[2] * w[2] - t.cx * t.cx));
    t.sub.push_back({t.c[0], t.c[1], t.c[2]});
  }
}

Bary Recovery::bary(std::size_t f, Id p) const {
  const Facet& t = facets_[f];
  const PointInfo& info = info_[static_cast<std::size_t>(p)];
  Bary l{0, 0, 0};
  const auto slot = [&](Id v) {
    for (int j = 0; j < 3; ++j)
      if (t.c[j] == v) return j;
    RIEMESH_CHECK(false);
    return 0;
  };
  switch (info.kind) {
    case Kind::kVertex:
      l[static_cast<std::size_t>(slot(p))] = 1;
      break;
    case Kind::kEdge: {
      const InputEdge& e = edges_[static_cast<std::size_t>(info.owner)];
      l[static_cast<std::size_t>(slot(e.a))] = 1 - info.t;
      l[static_cast<std::size_t>(slot(e.b))] = info.t;
      break;
    }
    case Kind::kFace:
      RIEMESH_CHECK(static_cast<std::size_t>(info.owner) == f);
      l = info.lambda;
      break;
    case Kind::kInterior:  // never on a facet
      RIEMESH_CHECK(false);
      break;
  }
  return l;
}

/// Both ends on the same side of the triangle (a subsegment: never flipped).
bool Recovery::on_boundary(std::size_t f, Id a, Id b) const {
  const Bary la = bary(f, a), lb = bary(f, b);
  for (int i = 0; i < 3; ++i)
    if (la[static_cast<std::size_t>(i)] == 0 && lb[static_cast<std::size_t>(i)] == 0) return true;
  return false;
}

Id Recovery::new_point(const double* p, const PointInfo& info) {
  // (The interior points given are no Steiner points: counting them made a fine --hsiz give up
  // at its first Steiner point once it had 20 field points per surface vertex.)
  const std::size_t steiner = info_.size() - vertices_.size() - interior_;
  if (steiner >= cap_) {
    char cap[32];
    std::snprintf(cap, sizeof cap, "%g", max_steiner_per_vertex_);
    std::string msg = "boundary recovery gave up after ";
    msg += std::to_string(steiner);
    msg += " Steiner points (the cap is ";
    msg += cap;
    msg +=
        " per surface vertex): parts of the surface are too close together or its triangles "
        "too thin (smallest angle ";
    char angle[64];
    std::snprintf(angle, sizeof angle, "%.3g degrees, triangle %zu)", thinnest_angle_,
                  thinnest_triangle_ + 1);
    msg += angle;
    throw InputError(msg);
  }
  const auto id = static_cast<Id>(info_.size());
  coords_.insert(coords_.end(), p, p + 3);
  info_.push_back(info);
  Id same = kNoId;
  if (!kernel_->insert(id, &same)) {
    std::string msg = "boundary recovery: a Steiner point falls on vertex ";
    msg += std::to_string((same < static_cast<Id>(vertices_.size())
                               ? vertices_[static_cast<std::size_t>(same)]
                               : same) + 1);
    msg += " (surface parts closer than rounding allows, or the surface intersects itself)";
    throw InputError(msg);
  }
  if (info.kind == Kind::kEdge)
    ++stats_.steiner_on_edges;
  else
    ++stats_.steiner_in_faces;
  return id;
}

/// Where to split subsegment k of e: its middle, or, when exactly one end is an input vertex, the
/// point at a power-of-two distance from that vertex nearest to the middle (concentric shells).
double Recovery::split_param(const InputEdge& e, std::size_t k) const {
  const double tp = e.points[k].t, tq = e.points[k + 1].t;
  const double mid = 0.5 * (tp + tq);
  if ((tp == 0) != (tq == 1)) {
    const double* a = xyz(e.a);
    const double* b = xyz(e.b);
    const double length =
        std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                  (b[2] - a[2]) * (b[2] - a[2]));
    const double half = 0.5 * (tq - tp) * length;
    const double d = std::exp2(std::round(std::log2(half))) / length;
    const double t = tp == 0 ? d : 1 - d;
    if (t > tp + 0.25 * (tq - tp) && t < tq - 0.25 * (tq - tp)) return t;
  }
  return mid;
}

void Recovery::split_subsegment(std::size_t ei, std::size_t k) {
  InputEdge& e = edges_[ei];
  const double t = split_param(e, k);
  const Id u = e.points[k].id, v = e.points[k + 1].id;
  if (!(t > e.points[k].t && t < e.points[k + 1].t)) {
    std::string msg = "boundary recovery: the edge between ";
    msg += vertex_pair(vertices_[static_cast<std::size_t>(e.a)],
                       vertices_[static_cast<std::size_t>(e.b)]);
    msg += " cannot be split further (surface parts closer than rounding allows)";
    throw InputError(msg);
  }
  double p[3];
  const double* a = xyz(e.a);
  const double* b = xyz(e.b);
  for (int i = 0; i < 3; ++i) p[i] = (1 - t) * a[i] + t * b[i];
  PointInfo info;
  info.kind = Kind::kEdge;
  info.owner = static_cast<Id>(ei);
  info.t = t;
  const Id id = new_point(p, info);
  e.points.insert(e.points.begin() + static_cast<std::ptrdiff_t>(k + 1), EdgePoint{t, id});
  for (Id f : e.tri) split_in_facet(static_cast<std::size_t>(f), u, v, id);
}

std::optional<std::size_t> Recovery::find_directed(std::size_t f, Id a, Id b) const {
  const std::vector<Tri>& sub = facets_[f].sub;
  for (std::size_t i = 0; i < sub.size(); ++i)
    for (int j = 0; j < 3; ++j)
      if (sub[i][static_cast<std::size_t>(j)] == a && sub[i][static_cast<std::size_t>((j + 1) % 3)] == b)
        return i;
  return std::nullopt;
}

/// Rotates t so that (t[0], t[1]) = (a, b).
Tri rotate_to(const Tri& t, Id a) {
  if (t[0] == a) return t;
  if (t[1] == a) return {t[1], t[2], t[0]};
  return {t[2], t[0], t[1]};
}

void Recovery::split_in_facet(std::size_t f, Id u, Id v, Id p) {
  std::optional<std::size_t> i = find_directed(f, u, v);
  Id a = u;
  if (!i) {
    i = find_directed(f, v, u);
    a = v;
  }
  RIEMESH_CHECK(i.has_value());
  std::vector<Tri>& sub = facets_[f].sub;
  const Tri t = rotate_to(sub[*i], a);
  sub[*i] = {t[0], p, t[2]};
  sub.push_back({p, t[1], t[2]});
  std::vector<std::pair<Id, Id>> stack = {{t[1], t[2]}, {t[2], t[0]}};
  legalize(f, stack);
}

/// Lawson flips towards the Delaunay triangulation in the facet's frame, never across a
/// subsegment and only where the quadrilateral is strictly convex in barycentric coordinates.
void Recovery::legalize(std::size_t f, std::vector<std::pair<Id, Id>>& stack) {
  std::vector<Tri>& sub = facets_[f].sub;
  std::size_t flips = 0;
  while (!stack.empty() && flips < 64 * sub.size() + 64) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    if (on_boundary(f, a, b)) continue;
    const std::optional<std::size_t> i = find_directed(f, a, b), j = find_directed(f, b, a);
    if (!i || !j) continue;
    const Id c = rotate_to(sub[*i], a)[2], d = rotate_to(sub[*j], b)[2];
    const auto pa = frame(f, a), pb = frame(f, b), pc = frame(f, c), pd = frame(f, d);
    if (incircle(pa.data(), pb.data(), pc.data(), pd.data()) <= 0) continue;
    const Bary la = bary(f, a), lb = bary(f, b), lc = bary(f, c), ld = bary(f, d);
    if (bary_orient(la, ld, lc) <= 0 || bary_orient(ld, lb, lc) <= 0) continue;
    sub[*i] = {a, d, c};
    sub[*j] = {d, b, c};
    ++flips;
    stack.insert(stack.end(), {{a, d}, {d, b}, {b, c}, {c, a}});
  }
}

/// The subface containing l (closed) and, when l is on its side opposite vertex k, k in *zero
/// (-1 inside, -2 on a vertex). False when no subface contains it.
bool Recovery::locate(std::size_t f, const Bary& l, std::size_t* tri, int* zero) const {
  const std::vector<Tri>& sub = facets_[f].sub;
  for (std::size_t i = 0; i < sub.size(); ++i) {
    Bary x[3];
    for (int j = 0; j < 3; ++j) x[j] = bary(f, sub[i][static_cast<std::size_t>(j)]);
    int o[3];
    bool inside = true;
    for (int j = 0; j < 3 && inside; ++j) {
      o[j] = bary_orient(x[(j + 1) % 3], x[(j + 2) % 3], l);
      inside = o[j] >= 0;
    }
    if (!inside) continue;
    const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
    *tri = i;
    *zero = zeros == 0 ? -1 : zeros == 1 ? (o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2) : -2;
    return true;
  }
  return false;
}

void Recovery::insert_in_facet(std::size_t f, Id p, std::size_t i, int zero) {
  std::vector<Tri>& sub = facets_[f].sub;
  const Tri t = sub[i];
  std::vector<std::pair<Id, Id>> stack;
  if (zero == -1) {
    sub[i] = {t[0], t[1], p};
    sub.push_back({t[1], t[2], p});
    sub.push_back({t[2], t[0], p});
    stack = {{t[0], t[1]}, {t[1], t[2]}, {t[2], t[0]}};
  } else {
    // p on the side (x1, x2) opposite x0 = t[zero]; the neighbour (x2, x1, y) across it.
    const Tri x = rotate_to(t, t[static_cast<std::size_t>(zero)]);
    const std::optional<std::size_t> j = find_directed(f, x[2], x[1]);
    RIEMESH_CHECK(j.has_value());
    const Id y = rotate_to(sub[*j], x[2])[2];
    sub[i] = {x[0], x[1], p};
    sub.push_back({x[0], p, x[2]});
    sub[*j] = {y, x[2], p};
    sub.push_back({y, p, x[1]});
    stack = {{x[0], x[1]}, {x[2], x[0]}, {y, x[2]}, {x[1], y}};
  }
  legalize(f, stack);
}

/// A missing subface s of facet f: a point at its circumcentre, or, if that point encroaches a
/// subsegment of f (or leaves f), that subsegment split; the centroid when neither applies.
void Recovery::refine_subface(std::size_t f, const Tri& s) {
  const Facet& t = facets_[f];
  const auto pa = frame(f, s[0]), pb = frame(f, s[1]), pc = frame(f, s[2]);
  const double bx = pb[0] - pa[0], by = pb[1] - pa[1], cx = pc[0] - pa[0], cy = pc[1] - pa[1];
  const double den = 2 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double ox = pa[0] + (cy * b2 - by * c2) / den, oy = pa[1] + (bx * c2 - cx * b2) / den;
  Bary l;
  l[2] = oy / t.cy;
  l[1] = (ox - l[2] * t.cx) / t.bx;
  l[0] = 1 - l[1] - l[2];
  const bool finite = std::isfinite(l[0]) && std::isfinite(l[1]) && std::isfinite(l[2]);
  // Encroached subsegments of f: the circumcentre strictly inside their diametral circle.
  if (finite) {
    std::size_t best_edge = 0, best_k = 0;
    double best = 0;
    for (int j = 0; j < 3; ++j) {
      const std::size_t ei = static_cast<std::size_t>(t.edge[j]);
      const InputEdge& e = edges_[ei];
      for (std::size_t k = 0; k + 1 < e.points.size(); ++k) {
        const auto p = frame(f, e.points[k].id), q = frame(f, e.points[k + 1].id);
        const double dot = (ox - p[0]) * (ox - q[0]) + (oy - p[1]) * (oy - q[1]);
        const double len2 = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
        if (dot < 0 && dot / len2 < best) {
          best = dot / len2;
          best_edge = ei;
          best_k = k;
        }
      }
    }
    if (best < 0) {
      split_subsegment(best_edge, best_k);
      return;
    }
  }
  std::size_t tri = 0;
  int zero = 0;
  const bool usable = finite && l[0] > 0 && l[1] > 0 && l[2] > 0 && locate(f, l, &tri, &zero) &&
                      zero != -2;
  if (!usable) {
    // The centroid, strictly inside s.
    const Bary x0 = bary(f, s[0]), x1 = bary(f, s[1]), x2 = bary(f, s[2]);
    for (std::size_t i = 0; i < 3; ++i) l[i] = (x0[i] + x1[i] + x2[i]) / 3;
    if (!locate(f, l, &tri, &zero) || zero == -2)
      throw Error("boundary recovery: a subface's centroid is not inside it");
  }
  if (zero >= 0 && on_boundary(f, facets_[f].sub[tri][static_cast<std::size_t>((zero + 1) % 3)],
                               facets_[f].sub[tri][static_cast<std::size_t>((zero + 2) % 3)]))
    throw Error("boundary recovery: a point inside a triangle falls on its side");
  double p[3];
  for (int i = 0; i < 3; ++i)
    p[i] = l[0] * xyz(t.c[0])[i] + l[1] * xyz(t.c[1])[i] + l[2] * xyz(t.c[2])[i];
  PointInfo info;
  info.kind = Kind::kFace;
  info.owner = static_cast<Id>(f);
  info.lambda = l;
  const Id id = new_point(p, info);
  insert_in_facet(f, id, tri, zero);
}

Mesh Recovery::volume(const Tetrahedralization& tz) const {
  // The refined surface (all points, the subfaces) and volume_inside on it.
  Mesh refined;
  refined.dim = 3;
  refined.coords = coords_;
  const std::size_t n = info_.size();
  refined.vert_ref.assign(n, 0);
  refined.vert_tag.assign(n, 0);
  for (std::size_t k = 0; k < vertices_.size(); ++k) {
    const auto v = static_cast<std::size_t>(vertices_[k]);
    if (v < surface_.vert_ref.size()) refined.vert_ref[k] = surface_.vert_ref[v];
    if (v < surface_.vert_tag.size()) refined.vert_tag[k] = surface_.vert_tag[v];
  }
  for (std::size_t f = 0; f < facets_.size(); ++f)
    for (const Tri& s : facets_[f].sub) {
      refined.triangles.insert(refined.triangles.end(), s.begin(), s.end());
      refined.tri_ref.push_back(facet_ref_[f]);
      refined.tri_tag.push_back(facet_tag_[f]);
    }
  SurfaceDelaunay d;
  d.vertices.resize(n);
  for (std::size_t k = 0; k < n; ++k) d.vertices[k] = static_cast<Id>(k);
  d.coords = coords_;
  d.tz = tz;
  d.num_faces = refined.num_triangles();
  return volume_inside(refined, d, hole_points_, no_holes_);
}

/// Every interior point must be a vertex of an inside tet (else it was outside or on the surface).
void Recovery::require_interior_used(const Mesh& v) const {
  if (interior_ == 0) return;
  const std::size_t first = vertices_.size();
  std::vector<char> used(interior_, 0);
  for (Id q : v.tets) {
    const auto k = static_cast<std::size_t>(q);
    if (k >= first && k < first + interior_) used[k - first] = 1;
  }
  for (std::size_t k = 0; k < interior_; ++k)
    if (!used[k]) {
      std::string msg = "interior point ";
      msg += std::to_string(k + 1);
      msg += " is not inside the surface";
      throw InputError(msg);
    }
}

/// Inside tets of (relative) volume near zero: four nearly cocircular surface points, whose
/// tetrahedron rounding made positive, both diagonals present. Each such tet gets a subsegment
/// of its edges split, or else a subface of its faces refined, which puts a point inside its
/// circumsphere. False when there is none (or none can be treated).
bool Recovery::refine_flat_tets(const Mesh& v) {
  std::map<std::uint64_t, std::pair<std::size_t, std::size_t>> subsegment;
  std::map<Tri, std::pair<std::size_t, Tri>> subface;
  bool acted = false;
  for (std::size_t t = 0; t < v.num_tets(); ++t) {
    const Id* q = &v.tets[4 * t];
    const double* p[4] = {xyz(q[0]), xyz(q[1]), xyz(q[2]), xyz(q[3])};
    double longest = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
        longest = std::max(longest, d2);
      }
    longest = std::sqrt(longest);
    const double vol = orient3d(p[0], p[1], p[2], p[3]) / 6;
    if (vol > kFlatTolerance * longest * longest * longest) continue;
    if (subsegment.empty()) {
      for (std::size_t e = 0; e < edges_.size(); ++e)
        for (std::size_t k = 0; k + 1 < edges_[e].points.size(); ++k)
          subsegment[pair_key(edges_[e].points[k].id, edges_[e].points[k + 1].id)] = {e, k};
      for (std::size_t f = 0; f < facets_.size(); ++f)
        for (const Tri& s : facets_[f].sub) subface[sorted3(s)] = {f, s};
    }
    bool done = false;
    for (int i = 0; i < 4 && !done; ++i)
      for (int j = i + 1; j < 4 && !done; ++j) {
        const auto it = subsegment.find(pair_key(q[i], q[j]));
        if (it == subsegment.end()) continue;
        // Still a subsegment (an earlier split this round may have changed it)?
        const InputEdge& e = edges_[it->second.first];
        const std::size_t k = it->second.second;
        if (k + 1 < e.points.size() && pair_key(e.points[k].id, e.points[k + 1].id) == it->first) {
          split_subsegment(it->second.first, k);
          acted = done = true;
        }
      }
    for (int i = 0; i < 4 && !done; ++i) {
      const auto it = subface.find(sorted3({q[(i + 1) % 4], q[(i + 2) % 4], q[(i + 3) % 4]}));
      if (it == subface.end()) continue;
      const auto& [f, s] = it->second;
      const std::vector<Tri>& sub = facets_[f].sub;
      if (std::find(sub.begin(), sub.end(), s) != sub.end()) {
        refine_subface(f, s);
        acted = done = true;
      }
    }
  }
  return acted;
}

/// Missing input edges that are the other diagonal of a cocircular quad (two coplanar input
/// triangles not refined yet, whose four corners lie on one circle: a grid of right triangles
/// on a planar face) are recovered by a flip of the tetrahedralisation, which stays Delaunay
/// (Delaunay3d::flip_cocircular), instead of Steiner points, which cascade there (a cube's faces
/// remeshed to 1/14: 3,174 Steiner points, tets down to quality 0.057). Returns the flips.
std::size_t Recovery::flip_cocircular_edges(
    const std::vector<std::pair<std::size_t, std::size_t>>& missing_segments) {
  std::vector<std::array<Id, 4>> quads;
  const auto third = [&](Id t, Id a, Id b) {
    const Facet& f = facets_[static_cast<std::size_t>(t)];
    for (const Id c : f.c)
      if (c != a && c != b) return c;
    return kNoId;
  };
  for (const auto& [e, k] : missing_segments) {
    const InputEdge& edge = edges_[e];
    if (edge.points.size() != 2 || edge.tri.size() != 2) continue;
    if (facets_[static_cast<std::size_t>(edge.tri[0])].sub.size() != 1 ||
        facets_[static_cast<std::size_t>(edge.tri[1])].sub.size() != 1)
      continue;
    const Id b = third(edge.tri[0], edge.a, edge.b), d = third(edge.tri[1], edge.a, edge.b);
    if (b == kNoId || d == kNoId || orient3d(xyz(edge.a), xyz(b), xyz(edge.b), xyz(d)) != 0.0)
      continue;
    quads.push_back({edge.a, b, edge.b, d});
  }
  const std::size_t flipped = kernel_->flip_cocircular(quads);
  stats_.flips += flipped;
  return flipped;
}

RecoveredVolume Recovery::run() {
  for (;;) {
    // The first round's tetrahedralisation is the constructor's (nothing inserted since).
    const Tetrahedralization tz = first_tz_ ? std::move(*first_tz_) : kernel_->result();
    const TetSkeleton skeleton = first_skeleton_ ? std::move(*first_skeleton_) : TetSkeleton(tz);
    first_tz_.reset(), first_skeleton_.reset();
    const auto has_edge = [&](Id a, Id b) { return skeleton.has_edge(a, b); };
    const auto has_face = [&](const Tri& s) { return skeleton.has_face(s); };

    std::vector<std::pair<std::size_t, std::size_t>> missing_segments;
    for (std::size_t e = 0; e < edges_.size(); ++e)
      for (std::size_t k = 0; k + 1 < edges_[e].points.size(); ++k)
        if (!has_edge(edges_[e].points[k].id, edges_[e].points[k + 1].id))
          missing_segments.push_back({e, k});
    std::vector<std::pair<std::size_t, Tri>> missing_faces;
    for (std::size_t f = 0; f < facets_.size(); ++f)
      for (const Tri& s : facets_[f].sub)
        if (!has_face(s)) missing_faces.push_back({f, s});
    // (The missing edges and faces are counted on the input's triangles, before the planar
    // patches: in the constructor.)
    if (stats_.rounds == 0) stats_.delaunay_tets = tz.num_tets();
    ++stats_.rounds;
    if (flip_cocircular_edges(missing_segments) > 0) continue;
    if (!missing_segments.empty()) {
      // Later subsegments of an edge first, so that the indices of earlier ones stay valid.
      for (auto it = missing_segments.rbegin(); it != missing_segments.rend(); ++it)
        split_subsegment(it->first, it->second);
      continue;
    }
    if (missing_faces.empty()) {
      Mesh v = volume(tz);
      const std::size_t before = stats_.steiner();
      if (!refine_flat_ || !refine_flat_tets(v)) {
        require_interior_used(v);
        if (flat_from_ != kNoFlat) stats_.steiner_for_flat_tets = stats_.steiner() - flat_from_;
        return {std::move(v), stats_};
      }
      if (flat_from_ == kNoFlat) flat_from_ = before;
      continue;
    }
    for (const auto& [f, s] : missing_faces) {
      const std::vector<Tri>& sub = facets_[f].sub;
      if (std::find(sub.begin(), sub.end(), s) != sub.end()) refine_subface(f, s);
    }
  }
}

}  // namespace

RecoveredVolume recover_volume(const Mesh& surface, const BoundaryRecoveryOptions& options) {
  std::size_t merged = 0;
  const std::optional<Mesh> single = merge_interfaces_listed_twice(surface, &merged);
  Recovery r(single ? *single : surface, options);
  RecoveredVolume out = r.run();
  out.stats.interfaces_listed_twice = merged;
  return out;
}

}  // namespace riemesh
