// Metrics from Hessians (BOOK.md §2): L∞ metric for a tolerance, Lp-optimal metric for a target
// complexity, clipping, and the combination of several fields by intersection.
//
// Every vertex's |H| is decomposed once. The Lp metric is K · det|H|^{-1/(2p+D)} |H|: only the
// scalar K depends on N, and clipping acts on eigenvalues, so the normalisation loop works on the
// eigenvalues alone and rebuilds the tensors at the end.
#include "metric/hessian_metric.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "metric/complexity.hpp"
#include "metric/intersection.hpp"
#include "metric/metric.hpp"

namespace riemesh {
namespace {

template <int D>
const std::vector<Id>& elements(const Mesh& mesh) {
  return D == 2 ? mesh.triangles : mesh.tets;
}

/// InputError unless the mesh is a planar triangle mesh (D = 2) or a tetrahedral volume (D = 3)
/// with n vertex values.
template <int D>
void require_mesh(const Mesh& mesh, std::size_t n, const char* what) {
  const bool ok = D == 2 ? mesh.dim == 2 && mesh.num_triangles() > 0 && mesh.tets.empty()
                         : mesh.dim == 3 && mesh.num_tets() > 0;
  if (!ok)
    throw InputError(D == 2 ? "a 2D metric needs a planar triangle mesh"
                            : "a 3D metric needs a tetrahedral mesh");
  if (n != mesh.num_vertices())
    throw InputError(std::string(what) + ": " + std::to_string(n) + " values for " +
                     std::to_string(mesh.num_vertices()) + " vertices");
}

template <int D>
void corners(const Mesh& mesh, std::size_t e, Vec<D> (&p)[D + 1]) {
  const Id* s = &elements<D>(mesh)[(D + 1) * e];
  for (int i = 0; i <= D; ++i)
    for (int k = 0; k < D; ++k) p[i][k] = mesh.coords[D * static_cast<std::size_t>(s[i]) + k];
}

/// ∫ sqrt(det M) for a log-Euclidean field given a_v = ½ ln det M_v at the vertices: the same
/// analytic formula as complexity() (D! |K| exp[a₀..a_D]), with the element measures given.
template <int D>
double complexity_from_half_log_dets(const Mesh& mesh, const std::vector<double>& measures,
                                     const std::vector<double>& a) {
  const std::vector<Id>& elems = elements<D>(mesh);
  double sum = 0.0;
  for (std::size_t e = 0; e < measures.size(); ++e) {
    double x[D + 1];
    for (int i = 0; i <= D; ++i) x[i] = a[elems[(D + 1) * e + i]];
    std::sort(x, x + D + 1);
    sum += factorial<D>() * measures[e] * detail::exp_divided_difference(x, D);
  }
  return sum;
}

template <int D>
std::vector<double> element_measures(const Mesh& mesh) {
  std::vector<double> out(elements<D>(mesh).size() / (D + 1));
  for (std::size_t e = 0; e < out.size(); ++e) {
    Vec<D> p[D + 1];
    corners<D>(mesh, e, p);
    out[e] = std::abs(simplex_measure<D>(p));
  }
  return out;
}

/// Eigenvalues of the metric K·μ clipped to sizes in [hmin, hmax], then the
/// smallest raised to λ_max / aniso_max² (which keeps them within the size bounds).
template <int D>
Vec<D> clip(const Vec<D>& mu, double k, const HessianMetricOptions& o) {
  const double lo = 1.0 / (o.hmax * o.hmax);  // 0 for hmax = ∞
  const double hi = o.hmin > 0.0 ? 1.0 / (o.hmin * o.hmin) : std::numeric_limits<double>::infinity();
  Vec<D> l{};
  double top = 0.0;
  for (int i = 0; i < D; ++i) top = std::max(top, l[i] = std::clamp(k * mu[i], lo, hi));
  const double floor = top / (o.aniso_max * o.aniso_max);  // 0 for aniso_max = ∞
  for (int i = 0; i < D; ++i) l[i] = std::max(l[i], floor);
  return l;
}

/// |H| per vertex, scaled by det|H|^e: eigenvalues μ (as many as the columns of the eigenvectors). Absolute
/// eigenvalues below 1e-12 of the largest over the mesh are raised to that floor (so that every
/// tensor is SPD); a Hessian zero everywhere (a linear field) gives the identity shape.
template <int D>
struct Shapes {
  std::vector<Vec<D>> mu;
  std::vector<Mat<D>> vectors;
  bool zero = false;  ///< the Hessian is zero everywhere
};

template <int D>
Shapes<D> shapes(std::span<const SymMat<D>> hessians, double det_exponent, bool unit_scale) {
  Shapes<D> s{std::vector<Vec<D>>(hessians.size()), std::vector<Mat<D>>(hessians.size()), false};
  // The eigenvalues of H / (its largest coefficient over the mesh): entries of 1e201 (a field
  // of magnitude 1e200) overflowed in the eigen solver's discriminant.
  double biggest = 0.0;
  for (std::size_t v = 0; v < hessians.size(); ++v) {
    if (!is_finite(hessians[v]))
      throw InputError("the Hessian at vertex " + std::to_string(v + 1) + " is not finite");
    for (const double c : hessians[v].c) biggest = std::max(biggest, std::abs(c));
  }
  const double pre = biggest > 0.0 ? 1.0 / biggest : 1.0;
  double largest = 0.0;
  for (std::size_t v = 0; v < hessians.size(); ++v) {
    const SymEigen<D> e = eigen(pre * hessians[v]);
    s.vectors[v] = e.vectors;
    for (int i = 0; i < D; ++i) largest = std::max(largest, s.mu[v][i] = std::abs(e.values[i]));
  }
  // For a complexity the metric does not depend on the field's scale: |H| / largest keeps the
  // determinants below in range (a field of magnitude 1e-200 made det|H| underflow and the
  // metric NaN); for a tolerance, |H| itself.
  const double unit = unit_scale && largest > 0.0 ? 1.0 / largest : 1.0 / pre;
  const double floor = largest > 0.0 ? 1e-12 * largest * unit : 1.0;
  for (Vec<D>& mu : s.mu) {
    double det = 1.0;
    for (int i = 0; i < D; ++i) det *= (mu[i] = std::max(mu[i] * unit, floor));
    const double scale = std::pow(det, det_exponent);
    for (int i = 0; i < D; ++i) mu[i] *= scale;  // kept in the order of the eigenvectors
  }
  s.zero = largest == 0.0;
  return s;
}

/// The scale K such that the clipped field K·μ has complexity N (to 1e-12 relative when
/// reachable): a secant iteration on ln C(ln K), whose slope lies in [0, D/2] (each vertex's
/// sqrt det grows like K^{j/2}, j the number of unclipped eigenvalues). Returns the last K when
/// clipping makes N unreachable (the slope vanishes).
template <int D>
double normalize(const Mesh& mesh, const Shapes<D>& s, const HessianMetricOptions& o, double k0) {
  const std::vector<double> measures = element_measures<D>(mesh);
  std::vector<double> a(s.mu.size());
  auto log_complexity = [&](double log_k) {
    const double k = std::exp(log_k);
    for (std::size_t v = 0; v < a.size(); ++v) {
      const Vec<D> l = clip<D>(s.mu[v], k, o);
      double sum = 0.0;
      for (int i = 0; i < D; ++i) sum += std::log(l[i]);
      a[v] = 0.5 * sum;
    }
    return std::log(complexity_from_half_log_dets<D>(mesh, measures, a));
  };
  const double target = std::log(o.complexity);
  double x = std::log(k0), y = log_complexity(x);
  // Without size or anisotropy bounds nothing is clipped and C(K) = K^{D/2} C(1) exactly: one
  // step of slope D/2 lands on N (to round-off), with no second pass over the elements.
  if (!(o.hmin > 0.0) && !std::isfinite(o.hmax) && !std::isfinite(o.aniso_max))
    return std::exp(x + (target - y) / (0.5 * D));
  double x_prev = 0.0, y_prev = 0.0;
  for (int it = 0; it < 60 && std::abs(y - target) > 1e-12; ++it) {
    double slope = 0.5 * D;
    if (it > 0 && x != x_prev) slope = std::clamp((y - y_prev) / (x - x_prev), 0.0, 0.5 * D);
    if (slope < 1e-9) break;  // every size clipped: N out of reach
    x_prev = x;
    y_prev = y;
    x += std::clamp((target - y) / slope, -50.0, 50.0);
    y = log_complexity(x);
  }
  return std::exp(x);
}

/// The P1 quadrature of ∫ det|H|^{p/(2p+D)}, which is ∫ sqrt(det μ) of the shapes.
template <int D>
double shape_integral(const Mesh& mesh, const Shapes<D>& s) {
  const std::vector<Id>& elems = elements<D>(mesh);
  const std::vector<double> measures = element_measures<D>(mesh);
  double sum = 0.0;
  for (std::size_t e = 0; e < measures.size(); ++e) {
    double mean = 0.0;
    for (int i = 0; i <= D; ++i) {
      const Vec<D>& mu = s.mu[elems[(D + 1) * e + i]];
      double det = 1.0;
      for (int j = 0; j < D; ++j) det *= mu[j];
      mean += std::sqrt(det) / (D + 1);
    }
    sum += measures[e] * mean;
  }
  return sum;
}

constexpr double kCd[4] = {0.0, 0.0, 2.0 / 9.0, 9.0 / 32.0};

}  // namespace

namespace {

/// Whether 1/size² and size² are both normal numbers: metrics of that size can be stored.
bool storable_size(double size) {
  return size > 0.0 && std::isnormal(1.0 / (size * size)) && std::isfinite(size * size);
}

}  // namespace

void HessianMetricOptions::validate() const {
  if (!(norm >= 1.0))
    throw InputError("--norm must be a number >= 1 or inf, got " + format_g(norm));
  // (Out of these ranges the metric's coefficients under- or overflow: complexity 1e-300 printed
  // "complexity: -nan" and wrote a file that riemesh then refused.)
  if (!(complexity == 0.0 || (complexity >= 1e-6 && complexity <= 1e15)))
    throw InputError("--complexity must be a number from 1e-6 to 1e15, got " +
                     format_g(complexity));
  if (!(tolerance == 0.0 || (tolerance >= 1e-150 && tolerance <= 1e150)))
    throw InputError("--tolerance must be a number from 1e-150 to 1e150, got " +
                     format_g(tolerance));
  if (complexity > 0.0 && tolerance > 0.0)
    throw InputError("--complexity and --tolerance contradict: give one of them");
  if (complexity == 0.0 && tolerance == 0.0)
    throw InputError("no target: give --complexity N (Lp metric) or --tolerance E (L∞ metric)");
  if (tolerance > 0.0 && std::isfinite(norm))
    throw InputError(
        "--tolerance gives the L∞ metric c|H|/E: use it with --norm inf, or give "
        "--complexity N for the L" +
        format_g(norm) + " metric");
  if (!(hmin == 0.0 || storable_size(hmin)))
    throw InputError("--hmin must be 0 or a finite size from 1e-150 to 1e150, got " +
                     format_g(hmin));
  if (!(hmax == std::numeric_limits<double>::infinity() || storable_size(hmax)))
    throw InputError("--hmax must be a size from 1e-150 to 1e150, got " + format_g(hmax));
  if (hmin > hmax)
    throw InputError("--hmin " + format_g(hmin) + " is larger than --hmax " + format_g(hmax));
  if (!(aniso_max >= 1.0))
    throw InputError("--aniso-max must be a ratio >= 1, got " + format_g(aniso_max));
}

template <int D>
std::vector<SymMat<D>> hessian_metric(const Mesh& mesh, std::span<const SymMat<D>> hessians,
                                      const HessianMetricOptions& options, MetricReport* report) {
  options.validate();
  require_mesh<D>(mesh, hessians.size(), "Hessians");
  const bool lp = options.complexity > 0.0;
  const double p = options.norm;
  // Lp: det|H|^{-1/(2p+D)} |H| (exponent 0 for p = ∞); L∞: c_d |H| / ε.
  const double det_exponent = lp && std::isfinite(p) ? -1.0 / (2.0 * p + D) : 0.0;
  const Shapes<D> s = shapes<D>(hessians, det_exponent, lp);
  double k = kCd[D] / options.tolerance;
  if (lp) {
    // BOOK.md §2: K = N^{2/D} (∫ det|H|^{p/(2p+D)})^{-2/D}, then refined so that the clipped
    // field's log-Euclidean complexity (what field_complexity measures) is N.
    const double k0 = std::pow(options.complexity / shape_integral<D>(mesh, s), 2.0 / D);
    k = normalize<D>(mesh, s, options, k0);
  } else if (s.zero) {
    // A linear field has no interpolation error: the L∞ metric is as coarse as hmax allows.
    if (!std::isfinite(options.hmax))
      throw InputError("the Hessian is zero everywhere: give --hmax for the L∞ metric");
    k = 0.0;
  }
  std::vector<SymMat<D>> out(hessians.size());
  for (std::size_t v = 0; v < out.size(); ++v)
    out[v] = compose(s.vectors[v], clip<D>(s.mu[v], k, options));
  if (report) *report = metric_report<D>(mesh, out);
  return out;
}

template <int D>
double field_complexity(const Mesh& mesh, std::span<const SymMat<D>> metrics) {
  require_mesh<D>(mesh, metrics.size(), "metrics");
  std::vector<double> a(metrics.size());
  for (std::size_t v = 0; v < a.size(); ++v) a[v] = 0.5 * std::log(det(metrics[v]));
  return complexity_from_half_log_dets<D>(mesh, element_measures<D>(mesh), a);
}

template <int D>
MetricReport metric_report(const Mesh& mesh, std::span<const SymMat<D>> metrics) {
  MetricReport r;
  r.complexity = field_complexity<D>(mesh, metrics);
  // A unit simplex has measure √3/4 (2D) or √2/12 (3D): elements = C / that measure.
  r.predicted_elements = (D == 2 ? 4.0 / std::sqrt(3.0) : 6.0 * std::sqrt(2.0)) * r.complexity;
  // Vertices: half the triangles (Euler, interior dominated) in 2D; about a sixth of the
  // tetrahedra in 3D. Measured in 2D: the adaptation loop gives 1.19-1.23 C vertices at
  // N = 8000 ... 128000 (mean edge length slightly below 1), 2/√3 C = 1.155 C predicted.
  r.predicted_vertices = r.predicted_elements / (D == 2 ? 2.0 : 6.0);
  return r;
}

template <int D>
void normalize_hessians_relative(std::span<SymMat<D>> hessians, std::span<const double> u) {
  if (hessians.size() != u.size())
    throw InputError("relative normalisation: " + std::to_string(hessians.size()) +
                     " Hessians for " + std::to_string(u.size()) + " values");
  double umax = 0.0;
  for (double x : u) umax = std::max(umax, std::abs(x));
  if (!(umax > 0.0) || !std::isfinite(umax)) return;
  for (SymMat<D>& h : hessians) h = (1.0 / umax) * h;
}

template <int D>
std::vector<SymMat<D>> combine_metrics(std::span<const std::vector<SymMat<D>>> fields) {
  if (fields.empty()) throw InputError("no metric to combine");
  const std::size_t n = fields[0].size();
  for (std::size_t f = 0; f < fields.size(); ++f) {
    if (fields[f].size() != n)
      throw InputError("metric " + std::to_string(f + 1) + " has " +
                       std::to_string(fields[f].size()) + " vertices, metric 1 has " +
                       std::to_string(n));
    for (std::size_t v = 0; v < n; ++v)
      require_metric(fields[f][v], "metric " + std::to_string(f + 1) + ", vertex " +
                                       std::to_string(v + 1));
  }
  std::vector<SymMat<D>> out(fields[0]);
  std::vector<SymMat<D>> at(fields.size());
  for (std::size_t v = 0; v < n; ++v) {
    if (fields.size() == 2) {
      out[v] = intersect(fields[0][v], fields[1][v]);
    } else if (fields.size() > 2) {
      for (std::size_t f = 0; f < fields.size(); ++f) at[f] = fields[f][v];
      out[v] = intersect_max_volume<D>(at);
    }
  }
  return out;
}

#define RIEMESH_INSTANTIATE(D)                                                                  \
  template std::vector<SymMat<D>> hessian_metric<D>(const Mesh&, std::span<const SymMat<D>>,    \
                                                    const HessianMetricOptions&, MetricReport*); \
  template double field_complexity<D>(const Mesh&, std::span<const SymMat<D>>);                 \
  template MetricReport metric_report<D>(const Mesh&, std::span<const SymMat<D>>);              \
  template void normalize_hessians_relative<D>(std::span<SymMat<D>>, std::span<const double>);  \
  template std::vector<SymMat<D>> combine_metrics<D>(std::span<const std::vector<SymMat<D>>>);
RIEMESH_INSTANTIATE(2)
RIEMESH_INSTANTIATE(3)
#undef RIEMESH_INSTANTIATE

}  // namespace riemesh
