#pragma once
// Interpolation of metrics given at the vertices of an edge or element (BOOK.md §1,
// "Interpolation of metrics"). All schemes take SPD inputs (the caller validates them once with
// require_metric at the boundary; these kernels are on hot paths and do not re-check) and
// barycentric weights wᵢ >= 0 with Σ wᵢ = 1. Every scheme returns mᵢ exactly when wᵢ = 1.
//
// Properties (tested in tests/metric/test_interpolation.cpp):
//   - maximum principle on det M (det M between the inputs' extremes): kLogEuclidean,
//     kSimredGeometric, kCholeskyGeometric and the iso-* schemes; NOT kLinear, kSimredLinear,
//     kPower or kCholesky (counterexamples in the tests).
//   - rotation invariance (interpolating rotated inputs = rotating the result): all but the
//     two Cholesky schemes, which depend on the coordinate frame.
//   - order independence in the n-metric form: all but the simred schemes.
#include <cstddef>
#include <span>
#include <string_view>

#include "core/symmat.hpp"

namespace riemesh {

enum class InterpScheme {
  kLinear,             ///< "linear": M = Σ wᵢMᵢ, coefficient-wise (sound for isotropic fields only)
  kIsoLinear,          ///< "iso-linear": isotropic, h = Σ wᵢhᵢ with hᵢ = det(Mᵢ)^{-1/(2D)}
  kIsoGeometric,       ///< "iso-geometric": isotropic, h = Π hᵢ^wᵢ
  kIsoHarmonic,        ///< "iso-harmonic": isotropic, h = (Σ wᵢ/hᵢ)⁻¹
  kSimredLinear,       ///< "simred-linear": simultaneous reduction, sizes linear
  kSimredGeometric,    ///< "simred-geometric": simultaneous reduction, sizes geometric
  kPower,              ///< "power": M = (Σ wᵢ Mᵢ^{-1/2})^{-2}
  kLogEuclidean,       ///< "log": M = exp(Σ wᵢ log Mᵢ), the default
  kCholesky,           ///< "cholesky": Mᵢ = LᵢLᵢᵀ, L = (Σ wᵢ Lᵢ⁻¹)⁻¹, M = LLᵀ
  kCholeskyGeometric,  ///< "cholesky-geometric": L = L'Δ, see interpolation.cpp
};

/// The scheme called `name` ("linear", "iso-linear", ..., "log", ...); throws InputError listing
/// the valid names otherwise.
InterpScheme parse_interp_scheme(std::string_view name);

/// The name parse_interp_scheme accepts for `s`.
std::string_view scheme_name(InterpScheme s);

/// The metric at parameter t of the edge from a (t = 0) to b (t = 1).
template <int D>
SymMat<D> interpolate(InterpScheme s, const SymMat<D>& a, const SymMat<D>& b, double t);

/// The metric with barycentric weights w of the metrics m (m.size() == w.size() >= 1).
/// The simred schemes are defined for two metrics only; for more they combine the metrics
/// pairwise in the given order (m₀ with m₁ at weight w₁/(w₀+w₁), that with m₂, ...), which is
/// order dependent (BOOK.md §1: simultaneous reduction is not associative).
template <int D>
SymMat<D> interpolate(InterpScheme s, std::span<const SymMat<D>> m, std::span<const double> w);

/// Convenience form for fixed-size arrays (the vertices of an element).
template <int D, std::size_t N>
SymMat<D> interpolate(InterpScheme s, const SymMat<D> (&m)[N], const double (&w)[N]) {
  return interpolate<D>(s, std::span<const SymMat<D>>(m), std::span<const double>(w));
}

/// Log-Euclidean interpolation from precomputed logarithms: exp(Σ wᵢ logsᵢ). The fast path
/// for callers that store log-metrics (one eigendecomposition instead of n + 1).
template <int D>
SymMat<D> interpolate_log_euclidean_logs(std::span<const SymMat<D>> logs,
                                         std::span<const double> w);

}  // namespace riemesh
