#include "metric/mesh_quality.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "mesh/stats.hpp"
#include "metric/edge_length.hpp"
#include "metric/element.hpp"
#include "metric/metric.hpp"

namespace riemesh {
namespace {

template <int D>
Vec<D> point(const Mesh& m, Id v) {
  Vec<D> p{};
  for (int c = 0; c < D; ++c) p[c] = m.coords[static_cast<std::size_t>(D) * v + c];
  return p;
}

template <int D>
SymMat<D> metric_at(std::span<const double> metric, Id v) {
  SymMat<D> m{};
  for (int k = 0; k < SymMat<D>::kSize; ++k)
    m.c[k] = metric[static_cast<std::size_t>(SymMat<D>::kSize) * v + k];
  return m;
}

/// The element's metric: the log-Euclidean mean of its vertex metrics, or the identity.
template <int D, int N>
SymMat<D> element_metric_of(std::span<const Id> v, std::span<const double> metric) {
  if (metric.empty()) return SymMat<D>::identity();
  SymMat<D> m[N];
  for (int i = 0; i < N; ++i) m[i] = metric_at<D>(metric, v[i]);
  return log_euclidean_mean(m, N);
}

/// Mean ratio of a triangle in 3D (a surface element) in metric m: 4√3 |K|_M / Σ l², with
/// |K|_M = ½ sqrt(det G), G the Gram matrix of two edges in M. Unsigned.
double surface_quality(const SymMat3& m, const Vec3& a, const Vec3& b) {
  const Vec3 c = b - a;
  const double aa = quadratic(m, a), bb = quadratic(m, b), ab = bilinear(m, a, b);
  const double sum_l2 = aa + bb + quadratic(m, c);
  if (sum_l2 == 0.0) return 0.0;
  const double area = 0.5 * std::sqrt(std::max(0.0, aa * bb - ab * ab));
  return 4.0 * std::sqrt(3.0) * area / sum_l2;
}

template <int D, int N>
double quality_of(const Mesh& mesh, std::span<const Id> v, std::span<const double> metric) {
  const SymMat<D> m = element_metric_of<D, N>(v, metric);
  if constexpr (D == 3 && N == 3) {
    const Vec3 p0 = point<3>(mesh, v[0]);
    return surface_quality(m, point<3>(mesh, v[1]) - p0, point<3>(mesh, v[2]) - p0);
  } else {
    Vec<D> p[D + 1];
    for (int i = 0; i <= D; ++i) p[i] = point<D>(mesh, v[i]);
    return quality(m, p);
  }
}

template <int D, int N>
double size_of(std::span<const Id> v, std::span<const double> metric) {
  return std::pow(det(element_metric_of<D, N>(v, metric)), -0.5 / D);
}

template <int D, int N>
void for_elements(const Mesh& mesh, std::vector<double>& out, auto f) {
  for (std::size_t e = 0; e < out.size(); ++e)
    out[e] = f.template operator()<D, N>(element(mesh, e));
}

}  // namespace

std::vector<double> length_histogram_edges() {
  std::vector<double> e{0.0};
  for (int k = -4; k <= 5; ++k) e.push_back(std::exp2(0.5 * k));
  return e;
}

std::vector<double> quality_histogram_edges() { return uniform_histogram(0.0, 1.0, 10).edges; }

void validate_metric_field(const Mesh& mesh, std::span<const double> metric) {
  const int dim = mesh.dim;
  if (dim != 2 && dim != 3) throw InputError("metric: the mesh dimension must be 2 or 3");
  const std::size_t k = static_cast<std::size_t>(dim) * (dim + 1) / 2;
  const std::size_t nv = mesh.num_vertices();
  if (metric.size() != k * nv)
    throw InputError("metric: expected " + std::to_string(nv) + " tensors of " + std::to_string(k) +
                     " numbers (one per vertex), got " + std::to_string(metric.size()) +
                     " numbers");
  for (std::size_t v = 0; v < nv; ++v) {
    const std::string what = "vertex " + std::to_string(v + 1);
    if (dim == 2)
      require_metric(metric_at<2>(metric, static_cast<Id>(v)), what);
    else
      require_metric(metric_at<3>(metric, static_cast<Id>(v)), what);
  }
}

namespace {

/// f<D, N>(vertex ids) for every element of the mesh's kind (planar triangles, surface
/// triangles or tetrahedra), in element order.
template <class F>
std::vector<double> per_element(const Mesh& mesh, F f) {
  std::vector<double> out(mesh.kind() == MeshKind::kEmpty ? 0 : num_elements(mesh));
  switch (mesh.kind()) {
    case MeshKind::kPlanar:
      for_elements<2, 3>(mesh, out, f);
      break;
    case MeshKind::kSurface:
      for_elements<3, 3>(mesh, out, f);
      break;
    case MeshKind::kVolume:
      for_elements<3, 4>(mesh, out, f);
      break;
    case MeshKind::kEmpty:
      break;
  }
  return out;
}

}  // namespace

std::vector<double> element_qualities(const Mesh& mesh, std::span<const double> metric) {
  return per_element(mesh, [&]<int D, int N>(std::span<const Id> v) {
    return quality_of<D, N>(mesh, v, metric);
  });
}

std::vector<double> element_sizes(const Mesh& mesh, std::span<const double> metric) {
  if (metric.empty()) {
    // Regular triangle: |K| = √3/4 h²; regular tetrahedron: |K| = h³ / (6√2).
    std::vector<double> out = element_measures(mesh);
    const bool volume = mesh.kind() == MeshKind::kVolume;
    for (double& m : out)
      m = volume ? std::cbrt(6.0 * std::numbers::sqrt2 * std::abs(m))
                 : std::sqrt(4.0 * std::abs(m) / std::sqrt(3.0));
    return out;
  }
  return per_element(mesh, [&]<int D, int N>(std::span<const Id> v) {
    return size_of<D, N>(v, metric);
  });
}

std::vector<double> metric_edge_lengths(const Mesh& mesh, const Adjacency& adj,
                                        std::span<const double> metric) {
  std::vector<double> out(adj.num_edges());
  for (std::size_t e = 0; e < out.size(); ++e) {
    const Id a = adj.edges[2 * e], b = adj.edges[2 * e + 1];
    if (mesh.dim == 2)
      out[e] = edge_length_simpson(metric_at<2>(metric, a), metric_at<2>(metric, b),
                                   point<2>(mesh, b) - point<2>(mesh, a));
    else
      out[e] = edge_length_simpson(metric_at<3>(metric, a), metric_at<3>(metric, b),
                                   point<3>(mesh, b) - point<3>(mesh, a));
  }
  return out;
}

double unit_length_fraction(std::span<const double> lengths) {
  if (lengths.empty()) return 0.0;
  std::size_t n = 0;
  for (double l : lengths) n += l >= std::numbers::sqrt2 / 2.0 && l <= std::numbers::sqrt2;
  return static_cast<double>(n) / static_cast<double>(lengths.size());
}

}  // namespace riemesh
