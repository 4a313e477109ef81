#include "mesh/stats.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"

namespace riemesh {

void Summary::add(double v) {
  ++count;
  min = std::min(min, v);
  max = std::max(max, v);
  sum += v;
}

Summary summarize(std::span<const double> values) {
  Summary s;
  for (double v : values) s.add(v);
  return s;
}

std::size_t Histogram::total() const {
  std::size_t n = 0;
  for (std::size_t c : counts) n += c;
  return n;
}

Histogram make_histogram(std::vector<double> edges) {
  if (edges.size() < 2) throw InputError("histogram: need at least two bin edges");
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (!(edges[i] > edges[i - 1])) throw InputError("histogram: bin edges must increase");
  Histogram h;
  h.counts.assign(edges.size() - 1, 0);
  h.edges = std::move(edges);
  return h;
}

Histogram uniform_histogram(double lo, double hi, int bins) {
  if (bins < 1) throw InputError("histogram: need at least one bin");
  std::vector<double> edges(bins + 1);
  for (int i = 0; i <= bins; ++i) edges[i] = lo + (hi - lo) * i / bins;
  edges[bins] = hi;
  return make_histogram(std::move(edges));
}

void add(Histogram& h, double v) {
  // upper_bound: the first edge > v; bin = that index - 1, clamped to the end bins.
  const auto it = std::upper_bound(h.edges.begin(), h.edges.end(), v);
  const std::ptrdiff_t bin = std::clamp<std::ptrdiff_t>(
      it - h.edges.begin() - 1, 0, static_cast<std::ptrdiff_t>(h.counts.size()) - 1);
  ++h.counts[bin];
}

Histogram histogram(std::vector<double> edges, std::span<const double> values) {
  Histogram h = make_histogram(std::move(edges));
  for (double v : values) add(h, v);
  return h;
}

std::size_t num_elements(const Mesh& mesh) {
  return mesh.kind() == MeshKind::kVolume ? mesh.num_tets() : mesh.num_triangles();
}

int verts_per_element(const Mesh& mesh) { return mesh.kind() == MeshKind::kVolume ? 4 : 3; }

std::span<const Id> element(const Mesh& mesh, std::size_t e) {
  const int k = verts_per_element(mesh);
  const std::vector<Id>& conn = k == 4 ? mesh.tets : mesh.triangles;
  return std::span<const Id>(conn).subspan(k * e, k);
}

MeshCounts count_entities(const Mesh& mesh) {
  MeshCounts c;
  c.vertices = mesh.num_vertices();
  c.triangles = mesh.num_triangles();
  c.tetrahedra = mesh.num_tets();
  c.boundary_edges = mesh.num_edges();
  if (mesh.kind() == MeshKind::kVolume) c.boundary_triangles = mesh.num_triangles();
  if (mesh.kind() != MeshKind::kEmpty) c.edges = build_adjacency(mesh).num_edges();
  for (std::uint8_t t : mesh.vert_tag) {
    c.corners += (t & kTagCorner) != 0;
    c.required_vertices += (t & kTagRequired) != 0;
  }
  for (std::uint8_t t : mesh.edge_tag) c.ridges += (t & kTagRidge) != 0;
  return c;
}

namespace {
std::vector<std::int32_t> distinct(std::vector<std::int32_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

template <int D>
Vec<D> point(const Mesh& m, Id v) {
  Vec<D> p{};
  for (int c = 0; c < D; ++c) p[c] = m.coords[static_cast<std::size_t>(D) * v + c];
  return p;
}
}  // namespace

MeshRefs distinct_refs(const Mesh& mesh) {
  return {distinct(mesh.vert_ref), distinct(mesh.edge_ref), distinct(mesh.tri_ref),
          distinct(mesh.tet_ref)};
}

std::vector<double> element_measures(const Mesh& mesh) {
  const std::size_t n = num_elements(mesh);
  std::vector<double> out(mesh.kind() == MeshKind::kEmpty ? 0 : n);
  for (std::size_t e = 0; e < out.size(); ++e) {
    const std::span<const Id> v = element(mesh, e);
    if (mesh.kind() == MeshKind::kVolume) {
      const Vec3 p0 = point<3>(mesh, v[0]);
      out[e] = dot(point<3>(mesh, v[1]) - p0,
                   cross(point<3>(mesh, v[2]) - p0, point<3>(mesh, v[3]) - p0)) /
               6.0;
    } else if (mesh.dim == 2) {
      const Vec2 p0 = point<2>(mesh, v[0]);
      out[e] = 0.5 * cross(point<2>(mesh, v[1]) - p0, point<2>(mesh, v[2]) - p0);
    } else {
      const Vec3 p0 = point<3>(mesh, v[0]);
      out[e] = 0.5 * norm(cross(point<3>(mesh, v[1]) - p0, point<3>(mesh, v[2]) - p0));
    }
  }
  return out;
}

}  // namespace riemesh
