// Intersection of several metrics: sequential, and the maximal-volume (John) ellipsoid.
//
// Maximal volume. With Y = M⁻¹ the unit ball of M is {x : xᵀY⁻¹x <= 1}, contained in the unit
// ball of mᵢ iff Y ⪯ Cᵢ = mᵢ⁻¹. Its volume grows with det Y, so we solve
//     maximise log det Y  subject to  Cᵢ - Y ⪰ 0,
// a convex problem (log det is strictly concave) with a unique optimum. Barrier method (Boyd &
// Vandenberghe, "Convex Optimization", §11.3): minimise
//     F_ε(Y) = -log det Y - ε Σᵢ log det(Cᵢ - Y)
// by damped Newton steps over the D(D+1)/2 coefficients of Y, then divide ε by 10. A minimiser
// of F_ε is within ε·n·D of the optimal log det (each log det barrier has parameter D).
//
// The problem is posed in the frame of the sequential intersection Mₛ (Ỹ = S Y S, S = Mₛ^{1/2}):
// there Cᵢ ⪰ I, so Ỹ = 0.99 I is strictly feasible, and all quantities are O(1) whatever the
// units of the input. Every loop has a fixed bound, so the solver always terminates; a final
// scaling by the smallest factor >= 1 restores containment lost to rounding.
#include "metric/intersection.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/spd.hpp"

namespace riemesh {
namespace {

constexpr int kMaxOuter = 40;       // ε from 1 down to ~1e-16: at most 16 are needed
constexpr int kMaxNewton = 60;      // per ε; Newton converges in a handful from the previous ε
constexpr int kMaxHalvings = 50;    // backtracking line search (step >= 2^-50)
constexpr double kArmijo = 0.25;
// Below ε ~ 1e-7 the small eigenvalues of Cᵢ - Y (~ε) drown in the rounding of the difference,
// and the central-path point stalls ~1e-8 away from the optimum. Instead the path
// Y(ε) = Y* + ε Y₁ + ε² Y₂ + ... (analytic under strict complementarity) is extrapolated to
// ε = 0 from three levels where it is computed accurately (Richardson / Lagrange at 0).
constexpr int kLevels = 3;
constexpr double kEpsLevel[kLevels] = {1e-3, 1e-4, 1e-5};
constexpr double kExtrapolation[kLevels] = {
    (1e-4 * 1e-5) / ((1e-3 - 1e-4) * (1e-3 - 1e-5)),
    (1e-3 * 1e-5) / ((1e-4 - 1e-3) * (1e-4 - 1e-5)),
    (1e-3 * 1e-4) / ((1e-5 - 1e-3) * (1e-5 - 1e-4))};
constexpr double kEpsFloor = 1e-9;
constexpr int kMaxPairScan = 16;

/// log det m if m is positive definite (by Cholesky), otherwise false.
template <int D>
bool log_det_pd(const SymMat<D>& m, double& out) {
  double l[D][D] = {};
  out = 0.0;
  for (int j = 0; j < D; ++j) {
    double d = m(j, j);
    for (int k = 0; k < j; ++k) d -= l[j][k] * l[j][k];
    if (!(d > 0.0)) return false;
    l[j][j] = std::sqrt(d);
    out += 2.0 * std::log(l[j][j]);
    for (int i = j + 1; i < D; ++i) {
      double s = m(i, j);
      for (int k = 0; k < j; ++k) s -= l[i][k] * l[j][k];
      l[i][j] = s / l[j][j];
    }
  }
  return true;
}

/// The barrier objective F_ε, or false when Y or some Cᵢ - Y is not positive definite.
template <int D>
bool barrier(const SymMat<D>& y, std::span<const SymMat<D>> c, double eps, double& f) {
  double ld = 0.0;
  if (!log_det_pd(y, ld)) return false;
  f = -ld;
  for (const SymMat<D>& ci : c) {
    if (!log_det_pd(ci - y, ld)) return false;
    f -= eps * ld;
  }
  return true;
}

/// Gradient and Hessian of F_ε in the packed coefficients of Y. For -log det X with
/// dX/dy_k = ±E_k (E_k = eₚe_qᵀ + e_qeₚᵀ, or eₚeₚᵀ on the diagonal) and W = X⁻¹:
/// gradient ∓tr(W E_k), Hessian tr(W E_k W E_l).
template <int D>
struct Derivatives {
  static constexpr int kN = SymMat<D>::kSize;
  double g[kN] = {};
  double h[kN][kN] = {};

  void add(const SymMat<D>& w, double coef, double sign) {
    Mat<D> we[kN];  // W E_k
    for (int j = 0, k = 0; j < D; ++j)
      for (int i = 0; i <= j; ++i, ++k) {
        we[k] = Mat<D>{};
        for (int r = 0; r < D; ++r) {
          we[k](r, j) += w(r, i);
          if (i != j) we[k](r, i) += w(r, j);
        }
        g[k] += sign * coef * (i == j ? w(i, i) : 2.0 * w(i, j));
      }
    for (int k = 0; k < kN; ++k)
      for (int l = 0; l <= k; ++l) {
        double t = 0.0;
        for (int r = 0; r < D; ++r)
          for (int s = 0; s < D; ++s) t += we[k](r, s) * we[l](s, r);
        h[k][l] += coef * t;
        h[l][k] = h[k][l];
      }
  }
};

/// Solves H x = -g by Cholesky; false if H is not numerically positive definite.
template <int N>
bool newton_direction(double (&h)[N][N], const double (&g)[N], double (&x)[N]) {
  for (int j = 0; j < N; ++j) {
    for (int k = 0; k < j; ++k) h[j][j] -= h[j][k] * h[j][k];
    if (!(h[j][j] > 0.0)) return false;
    h[j][j] = std::sqrt(h[j][j]);
    for (int i = j + 1; i < N; ++i) {
      for (int k = 0; k < j; ++k) h[i][j] -= h[i][k] * h[j][k];
      h[i][j] /= h[j][j];
    }
  }
  for (int i = 0; i < N; ++i) {  // L z = -g, then Lᵀ x = z
    double s = -g[i];
    for (int k = 0; k < i; ++k) s -= h[i][k] * x[k];
    x[i] = s / h[i][i];
  }
  for (int i = N - 1; i >= 0; --i) {
    double s = x[i];
    for (int k = i + 1; k < N; ++k) s -= h[k][i] * x[k];
    x[i] = s / h[i][i];
  }
  return true;
}

/// Newton minimisation of F_ε from a strictly feasible y (updated in place). Damped phase
/// (Armijo backtracking) while the Newton decrement λ >= 1/2; then pure Newton steps, which
/// for a self-concordant F stay feasible and converge quadratically (Boyd & Vandenberghe §9.6),
/// and need no Armijo test — that test fails spuriously once F - min F reaches rounding level.
template <int D>
void center(SymMat<D>& y, std::span<const SymMat<D>> c, double eps) {
  constexpr int kN = SymMat<D>::kSize;
  double f = 0.0, prev_lambda2 = HUGE_VAL;
  if (!barrier(y, c, eps, f)) return;
  for (int it = 0; it < kMaxNewton; ++it) {
    Derivatives<D> d;
    d.add(inverse(y), 1.0, -1.0);
    for (const SymMat<D>& ci : c) d.add(inverse(ci - y), eps, 1.0);
    double step[kN];
    if (!newton_direction(d.h, d.g, step)) return;
    double lambda2 = 0.0;  // λ² = -gᵀΔ
    for (int k = 0; k < kN; ++k) lambda2 -= d.g[k] * step[k];
    // Converged (λ²/2 estimates F - min F, F being O(1) in the normalised frame), or stalled at
    // rounding level (quadratic convergence would at least halve λ²).
    if (!(lambda2 > 1e-20) || (lambda2 < 1e-10 && lambda2 > 0.5 * prev_lambda2)) return;
    prev_lambda2 = lambda2;
    const bool pure = lambda2 < 0.25;
    double s = 1.0, f_new = 0.0;
    SymMat<D> y_new{};
    int halvings = 0;
    for (; halvings < kMaxHalvings; ++halvings, s *= 0.5) {
      for (int k = 0; k < kN; ++k) y_new.c[k] = y.c[k] + s * step[k];
      if (barrier(y_new, c, eps, f_new) && (pure || f_new <= f - kArmijo * s * lambda2)) break;
    }
    if (halvings == kMaxHalvings) return;  // no progress possible at this precision
    y = y_new;
    f = f_new;
  }
}

/// The smallest c >= 1 with c·m ⪰ mᵢ for every i.
template <int D>
double containment_factor(const SymMat<D>& m, std::span<const SymMat<D>> inputs) {
  double c = 1.0;
  for (const SymMat<D>& mi : inputs) c = std::max(c, relative_eigenvalues(m, mi)[D - 1]);
  return c;
}

/// Index i·n + j of a pair whose intersection contains every input, or -1. Such a pair's
/// intersection solves the problem restricted to two constraints and is feasible for all, so it
/// is the optimum, exactly — the common case of inactive extra constraints, and the degenerate
/// one (a constraint touching with zero multiplier) where the barrier path converges slowly.
/// Only tried for up to kMaxPairScan metrics (O(n³) eigensolves).
template <int D>
int feasible_pair(std::span<const SymMat<D>> m) {
  const int n = static_cast<int>(m.size());
  if (n > kMaxPairScan) return -1;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (containment_factor(intersect(m[i], m[j]), m) <= 1.0 + 1e-12) return i * n + j;
  return -1;
}

}  // namespace

template <int D>
SymMat<D> intersect_sequential(std::span<const SymMat<D>> m) {
  if (m.empty()) throw InputError("intersect: no metric given");
  SymMat<D> r = m[0];
  for (std::size_t i = 1; i < m.size(); ++i) r = intersect(r, m[i]);
  return r;
}

template <int D>
SymMat<D> intersect_max_volume(std::span<const SymMat<D>> m, double tol) {
  if (m.empty()) throw InputError("intersect: no metric given");
  const SymMat<D> seq = intersect_sequential(m);
  if (m.size() <= 2) return seq;  // exact: see intersect(a, b)
  if (const int pair = feasible_pair(m); pair >= 0) {
    const std::size_t n = m.size(), p = static_cast<std::size_t>(pair);
    return intersect(m[p / n], m[p % n]);
  }
  // Frame of the sequential intersection: C̃ᵢ = (S⁻¹ mᵢ S⁻¹)⁻¹ ⪰ I.
  const SymEigen<D> es = eigen(seq);
  Vec<D> root{}, inv_root{};
  for (int i = 0; i < D; ++i) {
    root[i] = std::sqrt(es.values[i]);
    inv_root[i] = 1.0 / root[i];
  }
  const Mat<D> s = compose(es.vectors, root).to_mat();
  const Mat<D> s_inv = compose(es.vectors, inv_root).to_mat();
  std::vector<SymMat<D>> c(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) c[i] = inverse(congruence(s_inv, m[i]));
  const std::span<const SymMat<D>> cs(c);
  // Follow the central path ε = 1, 1/10, ...; keep the points at the extrapolation levels.
  SymMat<D> y = SymMat<D>::diagonal(0.99), at_level[kLevels]{};
  const double eps_final = std::max(tol / (static_cast<double>(m.size()) * D), kEpsFloor);
  double eps = 1.0;
  for (int outer = 0, level = 0; outer < kMaxOuter; ++outer, eps *= 0.1) {
    center(y, cs, eps);
    if (level < kLevels && eps <= kEpsLevel[level] * 1.000001) at_level[level++] = y;
    if (eps <= eps_final && level == kLevels) break;
  }
  SymMat<D> y_extrapolated = SymMat<D>::zero();
  for (int k = 0; k < kLevels; ++k) y_extrapolated += kExtrapolation[k] * at_level[k];
  // Candidates, each scaled to contain every input: the extrapolated point (when it is positive
  // definite), the last central-path point and the sequential intersection. Keep the largest ball.
  SymMat<D> best = seq;
  for (const SymMat<D>& cand : {y_extrapolated, y}) {
    double log_det = 0.0;
    if (!log_det_pd(cand, log_det)) continue;
    SymMat<D> r = congruence(s, inverse(cand));
    r = containment_factor(r, m) * r;
    if (det(r) < det(best)) best = r;
  }
  return best;
}

template SymMat<2> intersect_sequential(std::span<const SymMat<2>>);
template SymMat<3> intersect_sequential(std::span<const SymMat<3>>);
template SymMat<2> intersect_max_volume(std::span<const SymMat<2>>, double);
template SymMat<3> intersect_max_volume(std::span<const SymMat<3>>, double);

}  // namespace riemesh
