// Gradation of a metric field along the edges of a mesh (BOOK.md §1 "Gradation").
#include "metric/gradation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/spd.hpp"
#include "metric/metric.hpp"

namespace riemesh {

void GradationOptions::validate() const {
  if (!std::isfinite(threshold)) throw InputError("gradation: threshold must be finite");
  switch (mode) {
    case GradationMode::kHVariation:
      if (!(threshold > 0.0)) throw InputError("gradation: H-variation threshold must be > 0");
      break;
    case GradationMode::kHShock:
    case GradationMode::kGrowth:
    case GradationMode::kGrowthPhysical:
      if (!(threshold > 1.0)) throw InputError("gradation: H-shock/growth threshold must be > 1");
      break;
    default:
      throw InputError("gradation: unknown mode");
  }
  if (max_passes < 1) throw InputError("gradation: max_passes must be >= 1");
}

namespace {

// A size change below this relative amount does not count (nor is it applied): it keeps the
// fixed-point loop from chasing rounding, and makes a converged field an exact fixed point.
constexpr double kRelTol = 1e-9;

/// The pass in which each vertex's metric last changed (0: never). An edge whose end metrics have
/// not changed since it was last corrected is a fixed point of its correction (each correction is
/// a function of the two end metrics that changes nothing when it reports no change), so a pass
/// only visits the edges with an end changed in this pass or the previous one: the result is the
/// one of full sweeps, and the later passes of a near-converged field cost almost nothing.
struct Marks {
  std::vector<int> stamp;
  int pass = 1;
  void mark(int32_t v) { stamp[static_cast<std::size_t>(v)] = pass; }
  bool active(int32_t a, int32_t b) const {
    return pass == 1 || std::max(stamp[static_cast<std::size_t>(a)],
                                 stamp[static_cast<std::size_t>(b)]) >= pass - 1;
  }
};

template <int D>
struct EdgeGeom {
  int32_t a, b;
  Vec<D> u;    // unit vector from a to b
  double len;  // Euclidean |AB|
};

template <int D>
Vec<D> vertex(std::span<const double> coords, int32_t v) {
  Vec<D> p{};
  for (int k = 0; k < D; ++k) p[k] = coords[static_cast<std::size_t>(v) * D + k];
  return p;
}

/// Checks the arrays and precomputes unit edge vectors and lengths.
template <int D>
std::vector<EdgeGeom<D>> edge_geometry(std::span<const double> coords,
                                       std::span<const int32_t> edges, std::size_t n_metrics) {
  if (coords.size() % D != 0 || coords.size() / D != n_metrics)
    throw InputError("gradation: need D coordinates and one metric per vertex");
  if (edges.size() % 2 != 0) throw InputError("gradation: edge id count is odd");
  const auto nv = static_cast<int64_t>(n_metrics);
  std::vector<EdgeGeom<D>> out(edges.size() / 2);
  for (std::size_t e = 0; e < out.size(); ++e) {
    const int32_t a = edges[2 * e], b = edges[2 * e + 1];
    const auto fail = [e](const char* why) {  // the message built only on failure
      return InputError("gradation: edge " + std::to_string(e) + why);
    };
    if (a < 0 || b < 0 || a >= nv || b >= nv) throw fail(": vertex id out of range");
    const Vec<D> ab = vertex<D>(coords, b) - vertex<D>(coords, a);
    const double len = norm(ab);
    if (!(len > 0.0) || !std::isfinite(len)) throw fail(": zero or non-finite length");
    out[e] = {a, b, ab / len, len};
  }
  return out;
}

/// Mean size h = det(M)^{-1/(2D)}: the size of the isotropic metric of the same unit-ball volume.
template <int D>
double mean_size(const SymMat<D>& m) {
  return std::pow(det(m), -0.5 / D);
}

/// The gradation rule of the corrections: its mode and threshold β, and ln β computed once.
struct Rule {
  GradationMode mode;
  double threshold, log_beta;
};

struct Shock {
  double log_c;   // ln c, c the H-shock
  double length;  // L, the edge length under geometric size interpolation
};

/// H-shock of an edge of length len with sizes hs <= hl at its ends (BOOK.md §1). Stable as
/// hl → hs: with r = hl/hs, q = ln r/(r − 1) → 1, L = len/(hl q) and ln c = ln r / L.
Shock h_shock(double hs, double hl, double len) {
  const double d = (hl - hs) / hs;
  const double log_r = std::log1p(d);
  const double q = d > 0.0 ? log_r / d : 1.0;
  const double l = len / (hl * q);
  return {log_r / l, l};
}

/// The largest size the larger end (size hl) may keep given the smaller end's size hs (hs <= hl):
/// Hv: hs + α|AB|; Hc: hs β^L = η hl with η = (β/c)^L; isotropic growth: hs(1 + (|AB|/hs) ln β).
double graded_size(const Rule& o, double hs, double hl, double len) {
  switch (o.mode) {
    case GradationMode::kHVariation:
      return std::min(hl, hs + o.threshold * len);
    case GradationMode::kHShock: {
      const Shock s = h_shock(hs, hl, len);
      return s.log_c > o.log_beta ? hs * std::exp(s.length * o.log_beta) : hl;
    }
    case GradationMode::kGrowth:
    case GradationMode::kGrowthPhysical:
      return std::min(hl, hs + len * o.log_beta);
  }
  return hl;
}

/// Isotropic correction of edge e on the cached mean sizes h; the corrected metric is rescaled
/// uniformly, which keeps its directions and anisotropy and sets its mean size exactly.
template <int D>
bool correct_isotropic(const EdgeGeom<D>& e, std::span<SymMat<D>> m, std::vector<double>& h,
                       const Rule& o, Marks& touched) {
  const int32_t s = h[e.a] <= h[e.b] ? e.a : e.b, l = (s == e.a) ? e.b : e.a;
  const double target = graded_size(o, h[s], h[l], e.len);
  if (!(target < h[l] * (1.0 - kRelTol))) return false;
  const double ratio = h[l] / target;
  m[l] = (ratio * ratio) * m[l];
  h[l] = target;
  touched.mark(l);
  return true;
}

/// The shrink factor η* that brings the size along the edge to `target` when the principal sizes
/// hᵢ (squared direction cosines wᵢ = (u·rᵢ)², Σwᵢ = 1) become min(hᵢ, max(η hᵢ, h_iso)).
/// Repeating the book's rule on one edge multiplies the unfloored sizes by a new η each time and
/// converges to η* only linearly, at a rate equal to the floored share of 1/target² (thousands of
/// passes when it is near 1); solving for the limit takes one step. 1/h_AB² = Σ wᵢ/hᵢ(η)² is
/// A + B/η² between breakpoints η = h_iso/hᵢ, visited from η = 1 down. Returns 0 when even
/// flooring every size cannot reach the target (all free sizes then go to h_iso).
template <int D>
double floored_eta(const Vec<D>& w, const Vec<D>& h, double h_iso, double target) {
  const double goal = 1.0 / (target * target);
  int free_ids[D];
  int n_free = 0;
  double a = 0.0, b = 0.0;
  for (int i = 0; i < D; ++i) {
    if (h[i] > h_iso) {
      free_ids[n_free++] = i;
      b += w[i] / (h[i] * h[i]);
    } else {
      a += w[i] / (h[i] * h[i]);
    }
  }
  std::sort(free_ids, free_ids + n_free, [&h](int i, int j) { return h[i] < h[j]; });
  double hi = 1.0;  // the interval [lo, hi] where the sizes before free_ids[k] are floored
  for (int k = 0; k < n_free; ++k) {
    const int i = free_ids[k];
    const double lo = h_iso / h[i];  // below lo, size i sits at the floor
    if (a + b / (lo * lo) >= goal) {
      // f(hi) < goal <= f(lo): the root of a + b/η² = goal, clamped against rounding (b or
      // goal − a may vanish when the remaining free directions are orthogonal to the edge).
      const double eta = (b > 0.0 && goal > a) ? std::sqrt(b / (goal - a)) : lo;
      return std::clamp(eta, lo, hi);
    }
    a += w[i] / (h_iso * h_iso);
    b -= w[i] / (h[i] * h[i]);
    hi = lo;
  }
  return 0.0;
}

/// Anisotropic correction of edge e (BOOK.md §1): the target from the sizes along the edge, the
/// lower bound h*_iso from the isotropic correction of the smallest principal sizes, then
/// hᵢ ← max(η hᵢ, h*_iso) (never above hᵢ) with the principal directions kept; η as in
/// floored_eta (equal to target/h_AB when the floor is not reached).
template <int D>
bool correct_anisotropic(const EdgeGeom<D>& e, std::span<SymMat<D>> m, const Rule& o,
                         Marks& touched) {
  const double ha = 1.0 / length(m[e.a], e.u), hb = 1.0 / length(m[e.b], e.u);
  const int32_t s = ha <= hb ? e.a : e.b, l = (s == e.a) ? e.b : e.a;
  const double hs = std::min(ha, hb), hl = std::max(ha, hb);
  const double target = graded_size(o, hs, hl, e.len);
  if (!(target < hl * (1.0 - kRelTol))) return false;
  const MetricSizes<D> zs = sizes(m[s]), zl = sizes(m[l]);  // sizes in descending order
  const double hmin_s = zs.sizes[D - 1], hmin_l = zl.sizes[D - 1];
  const double h_iso = hmin_l > hmin_s ? graded_size(o, hmin_s, hmin_l, e.len) : hmin_l;
  Vec<D> w{};
  for (int i = 0; i < D; ++i)
    w[i] = dot(e.u, zl.directions.column(i)) * dot(e.u, zl.directions.column(i));
  const double eta = floored_eta(w, zl.sizes, h_iso, target);
  Vec<D> nh = zl.sizes;
  bool changed = false;
  for (int i = 0; i < D; ++i) {
    nh[i] = std::min(zl.sizes[i], std::max(eta * zl.sizes[i], h_iso));
    changed = changed || nh[i] < zl.sizes[i] * (1.0 - kRelTol);
  }
  if (!changed) return false;
  m[l] = metric_from_sizes(zl.directions, nh);
  touched.mark(l);
  return true;
}

/// a ← a ∩ b by simultaneous reduction (BOOK.md §1 "Intersection"), done locally: with
/// A^{-1/2} B A^{-1/2} = Q diag(μ) Qᵀ and P = A^{1/2} Q, A = P⁻ᵀ I P⁻¹ and B = P⁻ᵀ diag(μ) P⁻¹,
/// so a ∩ b = P diag(max(1, μ)) Pᵀ. Returns false (a untouched) when b shrinks no size of a by
/// more than kRelTol.
template <int D>
bool intersect_into(SymMat<D>& a, const SymMat<D>& b) {
  const SymEigen<D> ea = eigen(a);
  Vec<D> root{}, inv_root{};
  for (int i = 0; i < D; ++i) {
    root[i] = std::sqrt(ea.values[i]);
    inv_root[i] = 1.0 / root[i];
  }
  const SymMat<D> a_inv_half = compose(ea.vectors, inv_root);
  const SymEigen<D> ec = eigen(congruence(a_inv_half.to_mat(), b));
  // μ carries round-off of order eps · cond(a) (a^{-1/2} b a^{-1/2} on a metric of anisotropy
  // 1:10⁴ loses 8 digits): a "shrink" below that is noise, and counting it kept up to 2% of the
  // edges of an adapted front mesh active for all max_passes.
  const double noise = 64.0 * std::numeric_limits<double>::epsilon() * ea.values[D - 1] / ea.values[0];
  const double tol = std::max(kRelTol, noise);
  if (!(ec.values[D - 1] > (1.0 + tol) * (1.0 + tol))) return false;
  Vec<D> mu{};
  for (int i = 0; i < D; ++i) mu[i] = std::max(1.0, ec.values[i]);
  const Mat<D> p = compose(ea.vectors, root).to_mat() * ec.vectors;
  a = congruence_diag(p, mu);
  return true;
}

/// M_A ← M_A ∩ grown(M_B) and M_B ← M_B ∩ grown(M_A) for edge e, where grown(M) is the metric
/// of a neighbour carried across the edge by the growth law. True when either changed.
template <int D, class Grown>
bool intersect_grown_both_ways(const EdgeGeom<D>& e, std::span<SymMat<D>> m,
                               Marks& touched, Grown grown) {
  auto grow = [&](int32_t to, int32_t from) {
    if (!intersect_into(m[to], grown(m[from]))) return false;
    touched.mark(to);
    return true;
  };
  const bool into_a = grow(e.a, e.b);
  const bool into_b = grow(e.b, e.a);
  return into_a || into_b;
}

/// Metric-space growth (Alauzet 2010): M_B grown to A is η² M_B with η = (1 + ℓ_{M_B}(AB) ln β)⁻¹
/// (sizes grow linearly in the metric length of the edge).
template <int D>
bool correct_growth(const EdgeGeom<D>& e, std::span<SymMat<D>> m, const Rule& o,
                    Marks& touched) {
  return intersect_grown_both_ways<D>(e, m, touched, [&](const SymMat<D>& from) {
    const double eta = 1.0 / (1.0 + e.len * length(from, e.u) * o.log_beta);
    return (eta * eta) * from;
  });
}

/// Physical-space growth: M_B grown to A keeps B's directions with sizes h_i + |AB| ln β, i.e.
/// η_i = (1 + |AB| ln β / h_i)⁻² per principal direction.
template <int D>
bool correct_growth_physical(const EdgeGeom<D>& e, std::span<SymMat<D>> m,
                             const Rule& o, Marks& touched) {
  const double add = e.len * o.log_beta;
  return intersect_grown_both_ways<D>(e, m, touched, [add](const SymMat<D>& from) {
    MetricSizes<D> s = sizes(from);
    for (int i = 0; i < D; ++i) s.sizes[i] += add;
    return metric_from_sizes(s.directions, s.sizes);
  });
}

/// Max over edges of the H-variation (hv) or H-shock of the field.
template <int D>
double field_measure(const std::vector<EdgeGeom<D>>& geom, std::span<const SymMat<D>> m,
                     bool anisotropic, bool hv) {
  double worst = hv ? 0.0 : 1.0;
  for (const EdgeGeom<D>& e : geom) {
    double ha, hb;
    if (anisotropic) {
      ha = 1.0 / length(m[e.a], e.u);
      hb = 1.0 / length(m[e.b], e.u);
    } else {
      ha = mean_size(m[e.a]);
      hb = mean_size(m[e.b]);
    }
    const double hs = std::min(ha, hb), hl = std::max(ha, hb);
    const double v = hv ? (hl - hs) / e.len : std::exp(h_shock(hs, hl, e.len).log_c);
    worst = std::max(worst, v);
  }
  return worst;
}

}  // namespace

template <int D>
GradationReport gradate(std::span<const double> coords, std::span<const int32_t> edges,
                        std::span<SymMat<D>> metrics, const GradationOptions& options) {
  options.validate();
  const std::vector<EdgeGeom<D>> geom = edge_geometry<D>(coords, edges, metrics.size());
  for (std::size_t v = 0; v < metrics.size(); ++v)
    if (!is_finite(metrics[v]) || !is_spd(metrics[v]))  // the message built only on failure
      require_metric(metrics[v], "gradation: vertex " + std::to_string(v));
  const bool hv = options.mode == GradationMode::kHVariation;
  const std::span<const SymMat<D>> view(metrics.data(), metrics.size());
  GradationReport r;
  if (options.measure) r.measure_before = field_measure(geom, view, options.anisotropic, hv);

  Marks touched;
  touched.stamp.assign(metrics.size(), 0);
  std::vector<double> h;  // cached mean sizes for the isotropic variant
  if (!options.anisotropic)
    for (const SymMat<D>& m : metrics) h.push_back(mean_size(m));
  // Every counted correction shrinks a size by more than kRelTol, and no size drops below the
  // smallest initial size (the h*_iso floor, the intersection keeps the smaller size), so the
  // sizes decrease to a limit; max_passes bounds the cost at O(edges × passes).
  const Rule rule{options.mode, options.threshold, std::log(options.threshold)};
  for (int pass = 1; pass <= options.max_passes; ++pass) {
    bool changed = false;
    touched.pass = pass;
    for (const EdgeGeom<D>& e : geom) {
      if (!touched.active(e.a, e.b)) continue;
      // Equal ends change nothing under any rule (a grown metric is never larger, and the
      // variation is 0): a constant field costs a comparison per edge, not two reductions.
      if (metrics[e.a] == metrics[e.b]) continue;
      bool c;
      if (!options.anisotropic)
        c = correct_isotropic(e, metrics, h, rule, touched);
      else if (options.mode == GradationMode::kGrowth)
        c = correct_growth(e, metrics, rule, touched);
      else if (options.mode == GradationMode::kGrowthPhysical)
        c = correct_growth_physical(e, metrics, rule, touched);
      else
        c = correct_anisotropic(e, metrics, rule, touched);
      changed = changed || c;
    }
    r.passes = pass;
    if (!changed) {
      r.converged = true;
      break;
    }
  }
  r.modified_vertices = static_cast<std::size_t>(std::count_if(touched.stamp.begin(), touched.stamp.end(), [](int p) { return p > 0; }));
  if (options.measure) r.measure_after = field_measure(geom, view, options.anisotropic, hv);
  return r;
}

template <int D>
double max_h_variation(std::span<const double> coords, std::span<const int32_t> edges,
                       std::span<const SymMat<D>> metrics, bool anisotropic) {
  return field_measure(edge_geometry<D>(coords, edges, metrics.size()), metrics, anisotropic, true);
}

template <int D>
double max_h_shock(std::span<const double> coords, std::span<const int32_t> edges,
                   std::span<const SymMat<D>> metrics, bool anisotropic) {
  return field_measure(edge_geometry<D>(coords, edges, metrics.size()), metrics, anisotropic,
                       false);
}

#define RIEMESH_GRADATION_INSTANTIATE(D)                                                 \
  template GradationReport gradate<D>(std::span<const double>, std::span<const int32_t>, \
                                      std::span<SymMat<D>>, const GradationOptions&);    \
  template double max_h_variation<D>(std::span<const double>, std::span<const int32_t>,  \
                                     std::span<const SymMat<D>>, bool);                  \
  template double max_h_shock<D>(std::span<const double>, std::span<const int32_t>,      \
                                 std::span<const SymMat<D>>, bool);
RIEMESH_GRADATION_INSTANTIATE(2)
RIEMESH_GRADATION_INSTANTIATE(3)
#undef RIEMESH_GRADATION_INSTANTIATE

}  // namespace riemesh
