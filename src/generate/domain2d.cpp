#include "generate/domain2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "core/predicates.hpp"
#include "generate/cdt2d.hpp"
#include "generate/delaunay2d.hpp"
#include "remesh/prepare_metrics.hpp"

namespace riemesh {

namespace {

std::string place(const double* p) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g)", p[0], p[1]);
  return buf;
}

/// The boundary edges as constraints between representative vertices, without repeats.
struct Constraints {
  std::vector<Id> ends;         // 2 per constraint: a → b as first given
  std::vector<Id> input_edge;   // the input edge it comes from (first occurrence)
  std::vector<std::uint8_t> both_ways;  // also given as b → a: an interface
};

Constraints gather_constraints(const Mesh& in, const Triangulation2d& t) {
  const std::size_t nv = in.num_vertices();
  Constraints c;
  std::unordered_map<std::uint64_t, Id> seen;
  for (std::size_t e = 0; e < in.num_edges(); ++e) {
    const Id va = in.edges[2 * e], vb = in.edges[2 * e + 1];
    if (va < 0 || vb < 0 || static_cast<std::size_t>(va) >= nv || static_cast<std::size_t>(vb) >= nv) {
      std::string msg = "boundary edge ";
      msg += std::to_string(e + 1);
      msg += " uses a vertex that does not exist";
      throw InputError(msg);
    }
    const Id a = t.representative[va], b = t.representative[vb];
    if (a == b) {
      std::string msg = "boundary edge ";
      msg += std::to_string(e + 1);
      msg += " has zero length, at ";
      msg += place(&in.coords[2 * va]);
      throw InputError(msg);
    }
    const auto [it, added] = seen.emplace(edge_key(a, b), static_cast<Id>(c.input_edge.size()));
    if (!added) {
      if (c.ends[2 * it->second] != a) c.both_ways[it->second] = 1;
      // One edge keeps one ref: a second ref was dropped silently.
      const auto first = static_cast<std::size_t>(c.input_edge[it->second]);
      if (!in.edge_ref.empty() && in.edge_ref[first] != in.edge_ref[e])
        refuse_edge_refs("boundary edge", first, e, in.edge_ref[first], in.edge_ref[e]);
      continue;
    }
    c.ends.insert(c.ends.end(), {a, b});
    c.input_edge.push_back(static_cast<Id>(e));
    c.both_ways.push_back(0);
  }
  return c;
}

/// Two distinct boundary points closer than 1e-12 of the domain's size (a curve touching
/// itself: a figure-eight spline met itself 8.9e-16 away from its own node) would make
/// zero-area triangles, and the boundary is no simple curve there: refused. Nearest neighbours
/// are Delaunay neighbours, so the triangulation's edges find every such pair.
void require_apart(const Triangulation2d& t) {
  double lo[2] = {0, 0}, hi[2] = {0, 0};
  for (std::size_t v = 0; v < t.num_points; ++v)
    for (int k = 0; k < 2; ++k) {
      const double x = t.xy[2 * v + k];
      if (v == 0 || x < lo[k]) lo[k] = x;
      if (v == 0 || x > hi[k]) hi[k] = x;
    }
  const double eps = 1e-12 * std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  for (std::size_t e = 0; e < t.tri.size(); ++e) {
    const Id a = t.tri[e], b = t.tri[e - e % 3 + (e % 3 + 1) % 3];
    if (a > b || t.is_super(a) || t.is_super(b)) continue;
    const double d = std::hypot(t.xy[2 * a] - t.xy[2 * b], t.xy[2 * a + 1] - t.xy[2 * b + 1]);
    if (d > 0.0 && d < eps) {
      char msg[200];
      std::snprintf(msg, sizeof msg,
                    "boundary vertices %d and %d are %.2g apart, closer than 1e-12 of the domain's "
                    "size: the boundary touches itself near ",
                    a + 1, b + 1, d);
      throw InputError(msg + place(&t.xy[2 * a]));
    }
  }
}

/// Every vertex of the boundary must continue into another edge: no open curve.
void require_closed(const Mesh& in, const Constraints& c) {
  std::vector<int> degree(in.num_vertices(), 0);
  std::vector<Id> some_edge(in.num_vertices(), kNoId);
  for (std::size_t k = 0; k < c.input_edge.size(); ++k)
    for (int i = 0; i < 2; ++i) {
      ++degree[c.ends[2 * k + i]];
      some_edge[c.ends[2 * k + i]] = c.input_edge[k];
    }
  for (std::size_t v = 0; v < degree.size(); ++v)
    if (degree[v] == 1) {
      std::string msg = "open boundary: vertex ";
      msg += std::to_string(v + 1);
      msg += " ";
      msg += place(&in.coords[2 * v]);
      msg += " ends boundary edge ";
      msg += std::to_string(some_edge[v] + 1);
      msg += " and no other edge continues it";
      throw InputError(msg);
    }
}

/// Connected sets of triangles across edges that are not constraints.
std::vector<Id> flood_regions(const Triangulation2d& t, const std::vector<Id>& on_constraint,
                              int* count) {
  const std::size_t nt = t.num_triangles();
  std::vector<Id> region = huge_vector<Id>(nt, kNoId), stack;
  int r = 0;
  for (std::size_t seed = 0; seed < nt; ++seed) {
    if (region[seed] != kNoId) continue;
    region[seed] = r;
    stack.push_back(static_cast<Id>(seed));
    while (!stack.empty()) {
      const Id tri = stack.back();
      stack.pop_back();
      for (int s = 0; s < 3; ++s) {
        const Id h = 3 * tri + s, g = t.nbr[h];
        if (g == kNoId || on_constraint[h] != kNoId || region[g / 3] != kNoId) continue;
        region[g / 3] = r;
        stack.push_back(g / 3);
      }
    }
    ++r;
  }
  *count = r;
  return region;
}

/// The region holding each hole point (closed triangles, exact orientation tests).
/// A hole point on a boundary edge or vertex belongs to no region: the first triangle found
/// decided (a point on an airfoil's leading edge made the far field the hole), now refused.
std::vector<std::uint8_t> holes_from_points(const Triangulation2d& t, const std::vector<Id>& region,
                                            int nregions, const std::vector<std::uint8_t>& outside,
                                            const std::vector<Id>& on_constraint,
                                            std::span<const double> points) {
  std::vector<std::uint8_t> hole(nregions, 0);
  for (std::size_t k = 0; 2 * k + 1 < points.size(); ++k) {
    const double* p = &points[2 * k];
    Id found = kNoId;
    bool on_boundary = false;
    for (std::size_t tri = 0; tri < t.num_triangles() && found == kNoId; ++tri) {
      const Id* v = &t.tri[3 * tri];
      const double* x[3] = {&t.xy[2 * v[0]], &t.xy[2 * v[1]], &t.xy[2 * v[2]]};
      const double o[3] = {orient2d(x[1], x[2], p), orient2d(x[2], x[0], p),
                           orient2d(x[0], x[1], p)};
      if (o[0] < 0 || o[1] < 0 || o[2] < 0) continue;
      found = static_cast<Id>(tri);
      // o[i] == 0: on the side opposite vertex i; two of them: on a vertex.
      const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
      for (int i = 0; i < 3; ++i)
        on_boundary |= o[i] == 0 && on_constraint[3 * tri + static_cast<std::size_t>(i)] != kNoId;
      on_boundary |= zeros >= 2;
    }
    if (found != kNoId && on_boundary) {
      std::string msg = "hole point ";
      msg += place(p);
      msg += " lies on the boundary: give a point inside the hole";
      throw InputError(msg);
    }
    if (found == kNoId || outside[region[found]]) {
      std::string msg = "hole point ";
      msg += place(p);
      msg += " is outside the domain";
      throw InputError(msg);
    }
    hole[region[found]] = 1;
  }
  return hole;
}

}  // namespace

Domain2d triangulate_domain2d(const Mesh& in, std::span<const double> hole_points,
                              InsertionOrder order, bool no_holes) {
  if (in.dim != 2) throw InputError("meshing a domain needs a planar boundary (Dimension 2)");
  if (in.edges.empty())
    throw InputError(in.triangles.empty()
                         ? "the domain has no boundary Edges"
                         : "the domain has no boundary Edges: a planar mesh of triangles (or a "
                           "surface whose z are all 0) is adapted with riemesh adapt; riemesh mesh "
                           "meshes a domain from its Edges, or the volume inside a closed surface");
  Triangulation2d t = delaunay2d(in.coords, order);
  require_apart(t);
  const Constraints c = gather_constraints(in, t);
  require_closed(in, c);
  const std::vector<Id> on_constraint = recover_edges(t, c.ends);

  int nregions = 0;
  const std::vector<Id> region = flood_regions(t, on_constraint, &nregions);
  std::vector<std::uint8_t> outside(nregions, 0), left(nregions, 0);
  std::vector<Id> first_edge(nregions, std::numeric_limits<Id>::max());
  for (std::size_t tri = 0; tri < t.num_triangles(); ++tri)
    for (int s = 0; s < 3; ++s)
      if (t.is_super(t.tri[3 * tri + s])) outside[region[tri]] = 1;
  for (std::size_t h = 0; h < on_constraint.size(); ++h) {
    const Id k = on_constraint[h];
    if (k == kNoId) continue;
    const Id r = region[h / 3];
    const Id from = t.tri[3 * (h / 3) + (h % 3 + 1) % 3];  // the triangle is left of from → to
    if (c.ends[2 * k] == from || c.both_ways[k]) left[r] = 1;
    first_edge[r] = std::min(first_edge[r], c.input_edge[k]);
  }
  std::vector<std::uint8_t> hole(nregions, 0);
  if (!hole_points.empty())
    hole = holes_from_points(t, region, nregions, outside, on_constraint, hole_points);
  else if (!no_holes)
    for (int r = 0; r < nregions; ++r) hole[r] = !left[r];

  // Kept regions, numbered by their first edge.
  std::vector<Id> kept;
  Domain2d out;
  for (int r = 0; r < nregions; ++r) {
    if (outside[r]) continue;
    if (hole[r]) ++out.holes;
    else kept.push_back(r);
  }
  if (kept.empty())
    throw InputError("nothing to mesh: every region is a hole or outside (outer loops must turn "
                     "counter-clockwise, with the domain on the left of each edge)");
  std::sort(kept.begin(), kept.end(), [&](Id a, Id b) { return first_edge[a] < first_edge[b]; });
  std::vector<std::int32_t> ref_of(nregions, 0);
  for (std::size_t k = 0; k < kept.size(); ++k) ref_of[kept[k]] = static_cast<std::int32_t>(k + 1);
  out.regions = static_cast<int>(kept.size());

  Mesh& m = out.mesh;
  m.dim = 2;
  std::vector<Id> new_id = huge_vector<Id>(t.num_points, kNoId);
  std::vector<std::uint8_t> used = huge_vector<std::uint8_t>(t.num_points, 0);
  for (std::size_t tri = 0; tri < t.num_triangles(); ++tri)
    if (ref_of[region[tri]] > 0)
      for (int s = 0; s < 3; ++s) used[t.tri[3 * tri + s]] = 1;
  std::size_t num_used = 0, num_kept = 0;
  for (const auto u : used) num_used += u;
  for (std::size_t tri = 0; tri < t.num_triangles(); ++tri) num_kept += ref_of[region[tri]] > 0;
  reserve_huge(out.input_vertex, num_used);
  reserve_huge(m.coords, 2 * num_used), reserve_huge(m.vert_ref, num_used);
  reserve_huge(m.vert_tag, num_used);
  reserve_huge(m.triangles, 3 * num_kept), reserve_huge(m.tri_ref, num_kept);
  for (std::size_t v = 0; v < t.num_points; ++v) {
    if (!used[v]) continue;
    new_id[v] = static_cast<Id>(out.input_vertex.size());
    out.input_vertex.push_back(static_cast<Id>(v));
    m.coords.insert(m.coords.end(), {in.coords[2 * v], in.coords[2 * v + 1]});
    m.vert_ref.push_back(in.vert_ref.size() == t.num_points ? in.vert_ref[v] : 0);
    m.vert_tag.push_back(in.vert_tag.size() == t.num_points ? in.vert_tag[v] : std::uint8_t{kTagNone});
  }
  for (std::size_t tri = 0; tri < t.num_triangles(); ++tri) {
    if (ref_of[region[tri]] == 0) continue;
    for (int s = 0; s < 3; ++s) m.triangles.push_back(new_id[t.tri[3 * tri + s]]);
    m.tri_ref.push_back(ref_of[region[tri]]);
  }
  reserve_huge(m.tri_tag, num_kept);
  m.tri_tag.assign(m.num_triangles(), kTagNone);
  // Edges next to a kept triangle, in input order and orientation.
  std::vector<std::uint8_t> edge_kept(c.input_edge.size(), 0);
  for (std::size_t h = 0; h < on_constraint.size(); ++h)
    if (on_constraint[h] != kNoId && ref_of[region[h / 3]] > 0) edge_kept[on_constraint[h]] = 1;
  for (std::size_t k = 0; k < c.input_edge.size(); ++k) {
    if (!edge_kept[k]) continue;
    const Id e = c.input_edge[k];
    m.edges.insert(m.edges.end(), {new_id[c.ends[2 * k]], new_id[c.ends[2 * k + 1]]});
    m.edge_ref.push_back(in.edge_ref.size() == in.num_edges() ? in.edge_ref[e] : 0);
    m.edge_tag.push_back(in.edge_tag.size() == in.num_edges() ? in.edge_tag[e] : std::uint8_t{kTagNone});
  }
  return out;
}

Mesh extract_boundary2d(const Mesh& mesh) {
  if (mesh.dim != 2) throw InputError("the boundary of a planar mesh needs Dimension 2");
  // Directed edges of the triangles, turned counter-clockwise: the triangle is on their left.
  // Per edge: how many triangles, the last one's direction, and whether their refs differ (an
  // interface between subdomains).
  struct Side {
    int count = 0;
    std::pair<Id, Id> directed{kNoId, kNoId};
    std::int32_t ref = 0;
    bool interface = false;
  };
  std::unordered_map<std::uint64_t, Side> sides;
  for (std::size_t tri = 0; tri < mesh.num_triangles(); ++tri) {
    Id v[3] = {mesh.triangles[3 * tri], mesh.triangles[3 * tri + 1], mesh.triangles[3 * tri + 2]};
    if (orient2d(&mesh.coords[2 * v[0]], &mesh.coords[2 * v[1]], &mesh.coords[2 * v[2]]) < 0)
      std::swap(v[1], v[2]);
    const std::int32_t ref = mesh.tri_ref.size() == mesh.num_triangles() ? mesh.tri_ref[tri] : 0;
    for (int s = 0; s < 3; ++s) {
      Side& e = sides[edge_key(v[s], v[(s + 1) % 3])];
      e.interface = e.interface || (e.count > 0 && e.ref != ref);
      e.ref = ref;
      ++e.count;
      e.directed = {v[s], v[(s + 1) % 3]};
    }
  }
  Mesh b;
  b.dim = 2;
  std::vector<Id> edges;
  if (mesh.num_edges() > 0) {
    for (std::size_t e = 0; e < mesh.num_edges(); ++e) {
      Id x = mesh.edges[2 * e], y = mesh.edges[2 * e + 1];
      if (x < 0 || y < 0 || static_cast<std::size_t>(std::max(x, y)) >= mesh.num_vertices()) {
        std::string msg = "edge ";
        msg += std::to_string(e + 1);
        msg += " uses a vertex that does not exist";
        throw InputError(msg);
      }
      const auto it = sides.find(edge_key(x, y));
      if (it != sides.end() && it->second.count == 1)
        x = it->second.directed.first, y = it->second.directed.second;
      if (it != sides.end()) it->second.interface = false;  // listed
      edges.insert(edges.end(), {x, y});
      b.edge_ref.push_back(mesh.edge_ref.size() == mesh.num_edges() ? mesh.edge_ref[e] : 0);
      b.edge_tag.push_back(mesh.edge_tag.size() == mesh.num_edges() ? mesh.edge_tag[e] : std::uint8_t{kTagNone});
    }
  } else {
    std::vector<std::pair<Id, Id>> found;
    for (const auto& [key, side] : sides)
      if (side.count == 1) found.push_back(side.directed);
    std::sort(found.begin(), found.end());  // deterministic, whatever the hash order
    for (const auto& [x, y] : found) {
      edges.insert(edges.end(), {x, y});
      b.edge_ref.push_back(1);
      b.edge_tag.push_back(kTagNone);
    }
  }
  // Interfaces between subdomains that are not listed (adapt keeps and writes them with ref 0;
  // they were dropped, and the domain meshed from the boundary lost its regions: QA hunt 5 F10).
  std::vector<std::pair<Id, Id>> interfaces;
  for (const auto& [key, side] : sides)
    if (side.count == 2 && side.interface)
      interfaces.push_back(std::minmax(side.directed.first, side.directed.second));
  std::sort(interfaces.begin(), interfaces.end());  // deterministic, whatever the hash order
  for (const auto& [x, y] : interfaces) {
    edges.insert(edges.end(), {x, y});
    b.edge_ref.push_back(0);
    b.edge_tag.push_back(kTagNone);
  }
  std::vector<Id> new_id(mesh.num_vertices(), kNoId);
  for (const Id v : edges) new_id[v] = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    if (new_id[v] == kNoId) continue;
    new_id[v] = static_cast<Id>(b.num_vertices());
    b.coords.insert(b.coords.end(), {mesh.coords[2 * v], mesh.coords[2 * v + 1]});
    b.vert_ref.push_back(mesh.vert_ref.size() == mesh.num_vertices() ? mesh.vert_ref[v] : 0);
    b.vert_tag.push_back(mesh.vert_tag.size() == mesh.num_vertices() ? mesh.vert_tag[v] : std::uint8_t{kTagNone});
  }
  for (const Id v : edges) b.edges.push_back(new_id[v]);
  return b;
}

}  // namespace riemesh
