// Metric interpolation schemes (BOOK.md §1, "Interpolation of metrics").
#include "metric/interpolation.hpp"

#include <array>
#include <cmath>
#include <string>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "core/mat.hpp"
#include "core/spd.hpp"
#include "metric/simultaneous_reduction.hpp"

namespace riemesh {
namespace {

struct SchemeName {
  InterpScheme scheme;
  std::string_view name;
};
constexpr std::array<SchemeName, 10> kSchemeNames{{
    {InterpScheme::kLinear, "linear"},
    {InterpScheme::kIsoLinear, "iso-linear"},
    {InterpScheme::kIsoGeometric, "iso-geometric"},
    {InterpScheme::kIsoHarmonic, "iso-harmonic"},
    {InterpScheme::kSimredLinear, "simred-linear"},
    {InterpScheme::kSimredGeometric, "simred-geometric"},
    {InterpScheme::kPower, "power"},
    {InterpScheme::kLogEuclidean, "log"},
    {InterpScheme::kCholesky, "cholesky"},
    {InterpScheme::kCholeskyGeometric, "cholesky-geometric"},
}};

/// Index of the metric carrying all the weight (wᵢ = 1, the others 0), or -1. Returning that
/// metric itself makes every scheme exact at the vertices, with no rounding from log/exp.
int sole_support(std::span<const double> w) {
  int found = -1;
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (w[i] == 1.0 && found < 0) {
      found = static_cast<int>(i);
    } else if (w[i] != 0.0) {
      return -1;
    }
  }
  return found;
}

template <int D>
SymMat<D> linear(std::span<const SymMat<D>> m, std::span<const double> w) {
  SymMat<D> r = SymMat<D>::zero();
  for (std::size_t i = 0; i < m.size(); ++i) r += w[i] * m[i];
  return r;
}

/// The iso-* schemes: isotropic size hᵢ = det(Mᵢ)^{-1/(2D)} (the geometric mean of the principal
/// sizes, so the unit ball keeps its volume), interpolated, then I/h².
template <int D>
SymMat<D> isotropic(InterpScheme s, std::span<const SymMat<D>> m, std::span<const double> w) {
  double acc = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double log_det = std::log(det(m[i]));
    if (s == InterpScheme::kIsoLinear) acc += w[i] * std::exp(-log_det / (2 * D));      // Σ wh
    if (s == InterpScheme::kIsoGeometric) acc += w[i] * log_det;                      // Σ w ln det
    if (s == InterpScheme::kIsoHarmonic) acc += w[i] * std::exp(log_det / (2 * D));   // Σ w/h
  }
  if (s == InterpScheme::kIsoLinear) return SymMat<D>::diagonal(1.0 / (acc * acc));
  if (s == InterpScheme::kIsoGeometric) return SymMat<D>::diagonal(std::exp(acc / D));
  return SymMat<D>::diagonal(acc * acc);
}

/// Two metrics by simultaneous reduction: the sizes hᵢ = mu^{-1/2} along the common basis are
/// interpolated linearly or geometrically (the latter keeps the maximum principle).
template <int D>
SymMat<D> simred_pair(const SymMat<D>& a, const SymMat<D>& b, double t, bool geometric) {
  const SimultaneousReduction<D> r = simultaneous_reduction(a, b);
  Vec<D> mu{};
  for (int i = 0; i < D; ++i) mu[i] = interpolate_reduced(r.mu_a[i], r.mu_b[i], t, geometric);
  return rebuild_metric(r, mu);
}

/// n metrics by pairwise simultaneous reduction in the given order (order dependent).
template <int D>
SymMat<D> simred(std::span<const SymMat<D>> m, std::span<const double> w, bool geometric) {
  SymMat<D> acc = m[0];
  double acc_weight = w[0];
  for (std::size_t i = 1; i < m.size(); ++i) {
    if (w[i] == 0.0) continue;
    if (acc_weight == 0.0) {
      acc = m[i];
      acc_weight = w[i];
      continue;
    }
    acc_weight += w[i];
    acc = simred_pair(acc, m[i], w[i] / acc_weight, geometric);
  }
  return acc;
}

template <int D>
SymMat<D> power(std::span<const SymMat<D>> m, std::span<const double> w) {
  SymMat<D> s = SymMat<D>::zero();
  for (std::size_t i = 0; i < m.size(); ++i) s += w[i] * pow_spd(m[i], -0.5);
  return pow_spd(s, -2.0);
}

/// acc += w log M, with the weight folded into the eigenvalues (one pass, no temporaries).
template <int D>
inline void add_weighted_log(SymMat<D>& acc, const SymMat<D>& m, double w) {
  SymEigen<D> e = eigen(m);
  for (int i = 0; i < D; ++i) e.values[i] = w * std::log(e.values[i]);
  acc += congruence_diag(e.vectors, e.values);
}

template <int D>
SymMat<D> log_euclidean(std::span<const SymMat<D>> m, std::span<const double> w) {
  SymMat<D> s = SymMat<D>::zero();
  for (std::size_t i = 0; i < m.size(); ++i)
    if (w[i] != 0.0) add_weighted_log(s, m[i], w[i]);
  return exp_sym(s);
}

/// Lower Cholesky factor L of an SPD tensor, M = LLᵀ.
template <int D>
Mat<D> cholesky_lower(const SymMat<D>& m) {
  Mat<D> l{};
  for (int j = 0; j < D; ++j) {
    double d = m(j, j);
    for (int k = 0; k < j; ++k) d -= l(j, k) * l(j, k);
    l(j, j) = std::sqrt(d);
    for (int i = j + 1; i < D; ++i) {
      double s = m(i, j);
      for (int k = 0; k < j; ++k) s -= l(i, k) * l(j, k);
      l(i, j) = s / l(j, j);
    }
  }
  return l;
}

/// The Cholesky schemes. kCholesky: L = (Σ wᵢ Lᵢ⁻¹)⁻¹, M = LLᵀ (BOOK.md §1).
/// kCholeskyGeometric: write Lᵢ = L'ᵢΔᵢ with L'ᵢ unit lower triangular and Δᵢ = diag(Lᵢ);
/// interpolate L' = (Σ wᵢ L'ᵢ⁻¹)⁻¹ as above (it stays unit lower triangular) and Δ⁻¹ geometrically,
/// Δ_jj = Π Δᵢ,jj^wᵢ (geometric means of Δ and of Δ⁻¹ are the same thing). Then
/// M = L'Δ²L'ᵀ and det M = Π det(Mᵢ)^wᵢ: this variant satisfies the maximum principle.
template <int D>
SymMat<D> cholesky(std::span<const SymMat<D>> m, std::span<const double> w, bool geometric) {
  Mat<D> inv_sum{};  // zero-initialised
  Vec<D> log_diag = Vec<D>::zero();
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (w[i] == 0.0) continue;
    Mat<D> l = cholesky_lower(m[i]);
    if (geometric) {
      for (int j = 0; j < D; ++j) {
        const double d = l(j, j);
        log_diag[j] += w[i] * std::log(d);
        for (int r = j; r < D; ++r) l(r, j) /= d;  // column j of L' = column j of L / Δ_jj
      }
    }
    inv_sum = inv_sum + w[i] * inverse(l);
  }
  const Mat<D> l = inverse(inv_sum);
  Vec<D> d2{};
  for (int j = 0; j < D; ++j) d2[j] = geometric ? std::exp(2.0 * log_diag[j]) : 1.0;
  return congruence_diag(l, d2);
}

}  // namespace

InterpScheme parse_interp_scheme(std::string_view name) {
  std::string valid;
  for (const SchemeName& s : kSchemeNames) {
    if (s.name == name) return s.scheme;
    valid += (valid.empty() ? "" : ", ") + std::string(s.name);
  }
  throw InputError("unknown interpolation scheme '" + std::string(name) + "' (valid: " + valid +
                   ")");
}

std::string_view scheme_name(InterpScheme s) {
  for (const SchemeName& n : kSchemeNames)
    if (n.scheme == s) return n.name;
  RIEMESH_CHECK(false && "unknown InterpScheme");
  return {};
}

template <int D>
SymMat<D> interpolate(InterpScheme s, const SymMat<D>& a, const SymMat<D>& b, double t) {
  if (t == 0.0 || a == b) return a;  // every scheme's mean of one metric is that metric, exactly
  if (t == 1.0) return b;
  if (s == InterpScheme::kSimredLinear || s == InterpScheme::kSimredGeometric)
    return simred_pair(a, b, t, s == InterpScheme::kSimredGeometric);
  const SymMat<D> m[2] = {a, b};
  const double w[2] = {1.0 - t, t};
  return interpolate<D>(s, std::span<const SymMat<D>>(m), std::span<const double>(w));
}

template <int D>
SymMat<D> interpolate(InterpScheme s, std::span<const SymMat<D>> m, std::span<const double> w) {
  RIEMESH_CHECK(!m.empty() && m.size() == w.size());
  if (const int i = sole_support(w); i >= 0) return m[static_cast<std::size_t>(i)];
  switch (s) {
    case InterpScheme::kLinear: return linear(m, w);
    case InterpScheme::kIsoLinear:
    case InterpScheme::kIsoGeometric:
    case InterpScheme::kIsoHarmonic: return isotropic(s, m, w);
    case InterpScheme::kSimredLinear: return simred(m, w, false);
    case InterpScheme::kSimredGeometric: return simred(m, w, true);
    case InterpScheme::kPower: return power(m, w);
    case InterpScheme::kLogEuclidean: return log_euclidean(m, w);
    case InterpScheme::kCholesky: return cholesky(m, w, false);
    case InterpScheme::kCholeskyGeometric: return cholesky(m, w, true);
  }
  RIEMESH_CHECK(false && "unknown InterpScheme");
  return m[0];
}

template <int D>
SymMat<D> interpolate_log_euclidean_logs(std::span<const SymMat<D>> logs,
                                         std::span<const double> w) {
  RIEMESH_CHECK(!logs.empty() && logs.size() == w.size());
  SymMat<D> s = SymMat<D>::zero();
  for (std::size_t i = 0; i < logs.size(); ++i) s += w[i] * logs[i];
  return exp_sym(s);
}

template SymMat<2> interpolate(InterpScheme, const SymMat<2>&, const SymMat<2>&, double);
template SymMat<3> interpolate(InterpScheme, const SymMat<3>&, const SymMat<3>&, double);
template SymMat<2> interpolate(InterpScheme, std::span<const SymMat<2>>, std::span<const double>);
template SymMat<3> interpolate(InterpScheme, std::span<const SymMat<3>>, std::span<const double>);
template SymMat<2> interpolate_log_euclidean_logs(std::span<const SymMat<2>>,
                                                  std::span<const double>);
template SymMat<3> interpolate_log_euclidean_logs(std::span<const SymMat<3>>,
                                                  std::span<const double>);

}  // namespace riemesh
