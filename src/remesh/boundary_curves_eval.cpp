// Reconstruction and evaluation of boundary curves: Bézier segments, arc length, midpoints,
// projection and the --hausd size (boundary_curves.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "metric/edge_length.hpp"
#include "remesh/boundary_curves.hpp"

namespace riemesh {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Loc {
  long g;  // unwrapped segment index (floor of s on a closed curve)
  int k;   // segment index in [0, n)
  double t;
};

int mod(long g, int n) {
  const long r = g % n;
  return static_cast<int>(r < 0 ? r + n : r);
}

/// Bessel tangent at a vertex with incoming chord a and outgoing chord b: the derivative of the
/// parabola through the three points in chord-length parametrisation, which is also the tangent
/// of their circumcircle (|b| â + |a| b̂ balances the half-angles of both chords). At a cusp
/// (a ≈ −b, possible only without angle detection) the outgoing direction.
Vec2 bessel_tangent(const Vec2& a, const Vec2& b) {
  const double la = norm(a), lb = norm(b);
  const Vec2 t = (lb * lb) * a + (la * la) * b;
  const double nt = norm(t);
  if (!(nt > 1e-12 * la * lb * (la + lb))) return b / lb;
  return t / nt;
}

/// Mirror image of the unit tangent t across the unit chord direction u.
Vec2 reflect(const Vec2& t, const Vec2& u) { return 2.0 * dot(t, u) * u - t; }

double angle_between(const Vec2& a, const Vec2& b) {
  return std::atan2(std::abs(cross(a, b)), dot(a, b));
}

/// Derivative at node c of the polynomial through the w values q at the nodes tau (w <= 5):
/// Σ_j L_j'(τ_c) (q_j − q_c), since Σ_j L_j' = 0.
template <class T>
T stencil_derivative(const double* tau, const T* q, int w, int c) {
  T d = q[c] - q[c];
  for (int j = 0; j < w; ++j) {
    if (j == c) continue;
    double l = 1.0 / (tau[j] - tau[c]);
    for (int m = 0; m < w; ++m)
      if (m != j && m != c) l *= (tau[c] - tau[m]) / (tau[j] - tau[m]);
    d += l * (q[j] - q[c]);
  }
  return d;
}

/// Cumulative chord lengths of w points.
void chord_params(const Vec2* q, int w, double* tau) {
  tau[0] = 0.0;
  for (int j = 1; j < w; ++j) tau[j] = tau[j - 1] + norm(q[j] - q[j - 1]);
}

Vec2 rotate(const Vec2& u, double a) {
  const double c = std::cos(a), s = std::sin(a);
  return {{c * u[0] - s * u[1], s * u[0] + c * u[1]}};
}

/// Unit tangent at q[c] of the curve through the w (2..5) consecutive points q. The tangent
/// angle φ(s) is reconstructed from its chord averages (a chord's direction is the mean tangent
/// angle over it, to O(h²)): the primitive Φ(τ_j) = Σ_{i<j} ψ_i l_i (ψ_i the direction of chord
/// i, unwrapped, l_i its length) is interpolated by a polynomial in chord length τ and
/// differentiated at τ_c. Exact on lines and on uniformly sampled circles (φ linear, Φ
/// quadratic), one-sided stencils included; on other smooth curves the positions of the cubics
/// converge at order 4 (measured in the tests).
Vec2 stencil_tangent(const Vec2* q, int w, int c) {
  double tau[5], phi[5];
  chord_params(q, w, tau);
  phi[0] = 0.0;
  double psi = 0.0;  // direction of chord j − 1 relative to chord 0, unwrapped
  for (int j = 1; j < w; ++j) {
    if (j > 1) {
      const Vec2 a = q[j - 1] - q[j - 2], b = q[j] - q[j - 1];
      psi += std::atan2(cross(a, b), dot(a, b));
    }
    phi[j] = phi[j - 1] + psi * (tau[j] - tau[j - 1]);
  }
  return rotate(normalize(q[1] - q[0]), stencil_derivative(tau, phi, w, c));
}

/// The stencil tangent at vertex k from up to 5 consecutive vertices around it (centred when
/// possible, one-sided near the ends of an open curve).
Vec2 vertex_tangent(std::span<const Vec2> p, bool closed, int k) {
  const int n = static_cast<int>(p.size()) - 1;
  const int w = std::min(5, closed ? n : n + 1);
  const int lo = closed ? k - (w - 1) / 2 : std::clamp(k - 2, 0, n + 1 - w);
  Vec2 q[5] = {};
  for (int j = 0; j < w; ++j) q[j] = p[closed ? mod(lo + j, n) : lo + j];
  return stencil_tangent(q, w, k - lo);
}

/// The stencil tangent unless it strays from the low-order estimate `safe` by more than
/// `limit` radians (irregular spacing can make a quartic oscillate); then `safe`.
Vec2 guarded(const Vec2& high, const Vec2& safe, double limit) {
  return dot(high, safe) >= std::cos(std::max(limit, 1e-3)) ? high : safe;
}

Loc locate(const BoundaryCurve& c, double s) {
  const int n = c.num_edges();
  RIEMESH_CHECK(n > 0 && std::isfinite(s));  // (a NaN parameter indexed far out of the curve)
  if (!c.closed) {
    s = std::clamp(s, 0.0, static_cast<double>(n));
    const int k = std::min(static_cast<int>(s), n - 1);
    return {k, k, s - k};
  }
  const double g = std::floor(s);
  return {static_cast<long>(g), mod(static_cast<long>(g), n), s - g};
}

const Vec2* seg(const BoundaryCurve& c, int k) { return c.bezier.data() + 3 * k; }

/// a + t (b − a): exact where a == b, so a constant coordinate (an axis-parallel side) stays
/// exactly constant.
Vec2 lerp(const Vec2& a, const Vec2& b, double t) { return a + t * (b - a); }

/// De Casteljau: the point, and the first and second derivatives from the same intermediates.
struct Casteljau {
  Vec2 q0, q1, q2, r0, r1;
  Casteljau(const Vec2* b, double t)
      : q0(lerp(b[0], b[1], t)),
        q1(lerp(b[1], b[2], t)),
        q2(lerp(b[2], b[3], t)),
        r0(lerp(q0, q1, t)),
        r1(lerp(q1, q2, t)) {}
};

Vec2 eval(const Vec2* b, double t) {
  const Casteljau c(b, t);
  return lerp(c.r0, c.r1, t);
}
Vec2 eval_d1(const Vec2* b, double t) {
  const Casteljau c(b, t);
  return 3.0 * (c.r1 - c.r0);
}
Vec2 eval_d2(const Vec2* b, double t) {
  const Casteljau c(b, t);
  return 6.0 * (c.q2 - 2.0 * c.q1 + c.q0);
}

/// Arc length of segment b over [ta, tb] by 8-point Gauss–Legendre (|γ'| is the square root of
/// a quartic: smooth on a regular segment).
double seg_length(const Vec2* b, double ta, double tb) {
  const detail::GaussNode* rule = detail::kGaussLegendre01 + 28;  // n = 8
  double sum = 0.0;
  for (int q = 0; q < 8; ++q) sum += rule[q].w * norm(eval_d1(b, ta + (tb - ta) * rule[q].t));
  return sum * (tb - ta);
}

/// Arc length from the start of the curve to the start of unwrapped segment g.
double prefix(const BoundaryCurve& c, long g) {
  const int n = c.num_edges();
  const long turns = (g - mod(g, n)) / n;
  return static_cast<double>(turns) * c.total_length() + c.arc_length[mod(g, n)];
}

/// The t in [ta, tb] with seg_length(b, ta, t) = r (0 <= r <= len = seg_length(b, ta, tb)):
/// Newton safeguarded by bisection.
double solve_length(const Vec2* b, double ta, double tb, double r, double len) {
  double lo = ta, hi = tb;
  double t = len > 0.0 ? ta + (tb - ta) * (r / len) : ta;
  for (int it = 0; it < 100; ++it) {
    const double g = seg_length(b, ta, t) - r;
    if (std::abs(g) <= 1e-15 * len) break;
    (g > 0.0 ? hi : lo) = t;
    const double d = norm(eval_d1(b, t));
    double tn = d > 0.0 ? t - g / d : lo;
    if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
    if (tn == t) break;
    t = tn;
  }
  return t;
}

/// Distance from p to the segment [a, b]; inside its slab the normal distance |ab × ap| / |ab|
/// (exactly 0 for a point on an axis-parallel segment).
double dist_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double l2 = dot(ab, ab), t = dot(p - a, ab);
  if (l2 == 0.0 || t <= 0.0) return norm(p - a);
  if (t >= l2) return norm(p - b);
  return std::abs(cross(ab, p - a)) / std::sqrt(l2);
}

}  // namespace

void build_curve_geometry(BoundaryCurve& c, std::span<const Vec2> p) {
  if (p.size() < 2) throw InputError("boundary curve: fewer than 2 points");
  const int n = static_cast<int>(p.size()) - 1;
  if (c.closed && (n < 3 || p[n] != p[0]))
    throw InputError("boundary curve: a closed curve needs 3 edges and must end at its start");
  for (int k = 0; k < n; ++k)
    if (p[k + 1] == p[k]) {
      std::string msg = "boundary curve: zero-length segment ";
      msg += std::to_string(k);
      throw InputError(msg);
    }
  // Unit tangents: the high-order estimate, guarded by the Bessel tangent (interior) or the
  // symmetric-arc mirror tangent (ends), allowed to differ by the local turning angle.
  std::vector<Vec2> tan(static_cast<std::size_t>(n) + 1);
  const auto interior = [&](int k, const Vec2& a, const Vec2& b) {
    return guarded(vertex_tangent(p, c.closed, k), bessel_tangent(a, b), angle_between(a, b));
  };
  for (int k = 1; k < n; ++k) tan[k] = interior(k, p[k] - p[k - 1], p[k + 1] - p[k]);
  if (c.closed) {
    tan[0] = tan[n] = interior(0, p[n] - p[n - 1], p[1] - p[0]);
  } else if (n == 1) {
    tan[0] = tan[1] = normalize(p[1] - p[0]);
  } else {  // corners: one-sided stencils, guarded by the symmetric-arc tangents
    const Vec2 u0 = normalize(p[1] - p[0]), un = normalize(p[n] - p[n - 1]);
    tan[0] =
        guarded(vertex_tangent(p, false, 0), reflect(tan[1], u0), angle_between(u0, p[2] - p[1]));
    tan[n] = guarded(vertex_tangent(p, false, n), reflect(tan[n - 1], un),
                     angle_between(un, p[n - 1] - p[n - 2]));
  }
  c.bezier.assign(3 * static_cast<std::size_t>(n) + 1, Vec2::zero());
  c.arc_length.assign(static_cast<std::size_t>(n) + 1, 0.0);
  for (int k = 0; k < n; ++k) {
    const Vec2 chord = p[k + 1] - p[k];
    const double len = norm(chord);
    const Vec2 u = chord / len;
    // Speed of the cubic approximating a circular arc whose tangents make the angle φ with the
    // chord: the Bézier arm is (4/3) tan(θ/4) ρ with θ = 2φ, i.e. m = 2c / (1 + cos φ).
    const double a0 = std::acos(std::clamp(dot(tan[k], u), -1.0, 1.0));
    const double a1 = std::acos(std::clamp(dot(tan[k + 1], u), -1.0, 1.0));
    const double m = 2.0 * len / (1.0 + std::max(std::cos(0.5 * (a0 + a1)), 0.0));
    c.bezier[3 * k] = p[k];
    c.bezier[3 * k + 1] = p[k] + (m / 3.0) * tan[k];
    c.bezier[3 * k + 2] = p[k + 1] - (m / 3.0) * tan[k + 1];
  }
  c.bezier[3 * n] = p[n];
  for (int k = 0; k < n; ++k)
    c.arc_length[k + 1] = c.arc_length[k] + seg_length(seg(c, k), 0.0, 1.0);
  // Straight: every control point exactly on the line of the ends and in order along it (a side
  // of a box: the cubic pieces then run along the line, monotonically).
  c.straight = !c.closed;
  const Vec2 dir = c.bezier.back() - c.bezier.front();
  for (std::size_t i = 1; c.straight && i < c.bezier.size(); ++i)
    c.straight = cross(dir, c.bezier[i] - c.bezier.front()) == 0.0 &&
                 dot(dir, c.bezier[i] - c.bezier[i - 1]) >= 0.0;
}

double wrap_param(const BoundaryCurve& c, double s) {
  const double n = c.param_end();
  if (!c.closed) return std::clamp(s, 0.0, n);
  double w = s - n * std::floor(s / n);
  if (w >= n || w < 0.0) w = 0.0;  // rounding of a tiny negative s
  return w;
}

double unwrap_near(const BoundaryCurve& c, double s_ref, double s) {
  if (!c.closed) return s;
  const double n = c.param_end();
  return s + n * std::round((s_ref - s) / n);
}

Vec2 point(const BoundaryCurve& c, double s) {
  const Loc l = locate(c, s);
  return eval(seg(c, l.k), l.t);
}

Vec2 tangent(const BoundaryCurve& c, double s) {
  const Loc l = locate(c, s);
  return eval_d1(seg(c, l.k), l.t);
}

double curvature(const BoundaryCurve& c, double s) {
  const Loc l = locate(c, s);
  const Vec2 d1 = eval_d1(seg(c, l.k), l.t), d2 = eval_d2(seg(c, l.k), l.t);
  const double v = norm(d1);
  return v > 0.0 ? cross(d1, d2) / (v * v * v) : 0.0;
}

double length(const BoundaryCurve& c, double s0, double s1) {
  if (s0 > s1) std::swap(s0, s1);
  const Loc a = locate(c, s0), b = locate(c, s1);
  if (a.g == b.g) return seg_length(seg(c, a.k), a.t, b.t);
  return seg_length(seg(c, a.k), a.t, 1.0) + (prefix(c, b.g) - prefix(c, a.g + 1)) +
         seg_length(seg(c, b.k), 0.0, b.t);
}

double param_at_fraction(const BoundaryCurve& c, double s0, double s1, double fraction) {
  if (!c.closed) {
    s0 = wrap_param(c, s0);
    s1 = wrap_param(c, s1);
  }
  if (s0 == s1) return s0;
  if (s0 > s1) return param_at_fraction(c, s1, s0, 1.0 - fraction);
  double r = std::clamp(fraction, 0.0, 1.0) * length(c, s0, s1);
  const Loc a = locate(c, s0), b = locate(c, s1);
  double ta = a.t;
  for (long g = a.g;; ++g) {
    const bool last = g == b.g;
    const double tb = last ? b.t : 1.0;
    const Vec2* sg = seg(c, mod(g, c.num_edges()));
    const double len = seg_length(sg, ta, tb);
    if (r <= len || last)
      return static_cast<double>(g) + solve_length(sg, ta, tb, std::min(r, len), len);
    r -= len;
    ta = 0.0;
  }
}

double midpoint(const BoundaryCurve& c, double s0, double s1) {
  return param_at_fraction(c, s0, s1, 0.5);
}

double project(const BoundaryCurve& c, const Vec2& p, double s_hint) {
  const int n = c.num_edges();
  const Loc h = locate(c, s_hint);
  double best_d = kInf, best_s = s_hint;
  for (long g = h.g - 1; g <= h.g + 1; ++g) {
    if (!c.closed && (g < 0 || g >= n)) continue;
    const Vec2* b = seg(c, mod(g, n));
    double bt = 0.0, bd = kInf;
    for (int i = 0; i <= 4; ++i) {
      const double d = norm(eval(b, 0.25 * i) - p);
      if (d < bd) bd = d, bt = 0.25 * i;
    }
    // Newton on (γ − p)·γ' = 0, kept in [0, 1].
    double t = bt;
    for (int it = 0; it < 30; ++it) {
      const Vec2 q = eval(b, t) - p, d1 = eval_d1(b, t), d2 = eval_d2(b, t);
      const double f = dot(q, d1), fp = dot(d1, d1) + dot(q, d2);
      if (!(fp > 0.0)) break;
      const double tn = std::clamp(t - f / fp, 0.0, 1.0);
      if (std::abs(tn - t) <= 1e-16) break;
      t = tn;
    }
    const double d = norm(eval(b, t) - p);
    if (d < bd) bd = d, bt = t;
    if (bd < best_d) best_d = bd, best_s = static_cast<double>(g) + bt;
  }
  return best_s;
}

double hausd_chord_length(double radius, double hausd) {
  if (!(hausd > 0.0)) {
    std::string msg = "hausd must be positive, got ";
    msg += std::to_string(hausd);
    throw InputError(msg);
  }
  if (!(radius < kInf)) return kInf;
  if (hausd >= radius) return 2.0 * radius;
  return 2.0 * std::sqrt(hausd * (2.0 * radius - hausd));
}

double hausd_size(const BoundaryCurve& c, double s, double hausd) {
  const double k = std::abs(curvature(c, s));
  return hausd_chord_length(k > 0.0 ? 1.0 / k : kInf, hausd);
}

double chord_deviation(const BoundaryCurve& c, double s0, double s1, int samples) {
  // On a straight curve every point between s0 and s1 lies on the chord: the samples would
  // all find 0 (exactly, for the axis-aligned sides of a box).
  if (c.straight) return 0.0;
  const Vec2 a = point(c, s0), b = point(c, s1);
  const int n = std::max({samples, 8 * static_cast<int>(std::ceil(std::abs(s1 - s0))), 1});
  double worst = 0.0;
  for (int i = 1; i < n; ++i)
    worst = std::max(worst, dist_to_segment(point(c, s0 + (s1 - s0) * i / n), a, b));
  return worst;
}

}  // namespace riemesh
