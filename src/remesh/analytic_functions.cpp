#include "remesh/analytic_functions.hpp"

#include <array>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace riemesh {
namespace {

// atan(a / t) jumps by π where t changes sign. atan2(a, t) = atan(a / t) + π·[t < 0] is the
// continuous branch of the same function: identical second derivatives away from t = 0, and the
// front is the smooth arctangent ramp of width ~a across t = 0 instead of a discontinuity that no
// P1 mesh resolves at the optimal rate. The "multiscale" and "interweaved" fields use this branch.
double atan_front(double a, double t) { return std::atan2(a, t); }

// Huang, "Metric tensors for anisotropic mesh generation", J. Comput. Phys. 204 (2005), test
// function tanh(60y) − tanh(60(x − y) − 30) on [0,1]², taken to [−1,1]² by x̂ = (x + 1)/2: a layer
// along the bottom side and an oblique internal shock.
double tanh_shock(double x, double y) {
  const double xh = 0.5 * (x + 1.0), yh = 0.5 * (y + 1.0);
  return std::tanh(60.0 * yh) - std::tanh(60.0 * (xh - yh) - 30.0);
}

// Loseille & Alauzet, "Continuous mesh framework part II: validations and applications", SIAM J.
// Numer. Anal. 49(1) (2011): the multi-scale function 0.1 sin(50x) + atan(0.1/(sin(5y) − 2x)).
double multiscale(double x, double y) {
  return 0.1 * std::sin(50.0 * x) + atan_front(0.1, std::sin(5.0 * y) - 2.0 * x);
}

// Same paper: two interweaved arctangent fronts.
double interweaved(double x, double y) {
  return atan_front(0.1, std::sin(5.0 * y) - 2.0 * x) + atan_front(0.5, std::sin(3.0 * y) - 7.0 * x);
}

// Same series (Loseille–Alauzet, part I/II, and Alauzet's lecture notes): sin(50xy), oscillating
// along hyperbolae, the frequency growing towards the corners.
double hyperbolic(double x, double y) { return std::sin(50.0 * x * y); }

// The exponential layers of convection–diffusion with small diffusion δ (e.g. Formaggia &
// Perotto, Numer. Math. 89 (2001)): layers of thickness δ = 0.01 along x = −1 and y = −1.
double boundary_layer(double x, double y) {
  constexpr double kDelta = 0.01;
  return std::exp(-(1.0 + x) / kDelta) + std::exp(-(1.0 + y) / kDelta);
}

constexpr std::array<AnalyticFunction, 5> kFunctions = {{
    {"tanh", "tanh(60 y') - tanh(60 (x' - y') - 30), x' = (x+1)/2, y' = (y+1)/2 (Huang 2005)",
     tanh_shock},
    {"multiscale", "0.1 sin(50 x) + atan2(0.1, sin(5 y) - 2 x) (Loseille-Alauzet 2011)",
     multiscale},
    {"interweaved",
     "atan2(0.1, sin(5 y) - 2 x) + atan2(0.5, sin(3 y) - 7 x) (Loseille-Alauzet 2011)",
     interweaved},
    {"hyperbolic", "sin(50 x y) (Loseille-Alauzet 2011)", hyperbolic},
    {"boundary-layer", "exp(-(1 + x)/0.01) + exp(-(1 + y)/0.01)", boundary_layer},
}};

}  // namespace

std::span<const AnalyticFunction> analytic_functions() { return kFunctions; }

const AnalyticFunction& analytic_function(std::string_view name) {
  std::string names;
  for (const AnalyticFunction& f : kFunctions) {
    if (f.name == name) return f;
    if (!names.empty()) names += ", ";
    names += f.name;
  }
  std::string msg = "unknown function '";
  msg += name;
  msg += "' (expected one of: ";
  msg += names;
  msg += ")";
  throw InputError(msg);
}

}  // namespace riemesh
