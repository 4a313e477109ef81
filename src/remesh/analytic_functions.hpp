#pragma once
// Analytic test functions on [−1,1]² for the adaptation loop (`riemesh loop`, issue #5): the
// standard fields of the anisotropic-adaptation literature, with steep fronts, several scales,
// crossing fronts, oscillations and boundary layers. Each has a name, its formula as text and a
// value function; see analytic_functions.cpp for where each form comes from.
#include <span>
#include <string_view>

namespace riemesh {

struct AnalyticFunction {
  std::string_view name;     ///< "tanh", "multiscale", "interweaved", "hyperbolic", "boundary-layer"
  std::string_view formula;  ///< the formula in plain text, as documented in the README
  double (*value)(double x, double y);  ///< u(x, y) on [−1,1]²
};

/// The built-in functions, in a fixed order.
std::span<const AnalyticFunction> analytic_functions();

/// The function of that name; throws InputError listing the valid names otherwise.
const AnalyticFunction& analytic_function(std::string_view name);

}  // namespace riemesh
