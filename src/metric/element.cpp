// The metric implied by a mesh (BOOK.md §1 "Element metric and quality").
#include "metric/element.hpp"

#include <string>

namespace riemesh {

namespace {

template <int D>
void check_mesh_arrays(std::span<const double> coords, std::span<const int32_t> simplices) {
  if (coords.size() % D != 0)
    throw InputError("implied_metric: coordinate count is not a multiple of " + std::to_string(D));
  if (simplices.size() % (D + 1) != 0)
    throw InputError("implied_metric: simplex id count is not a multiple of " +
                     std::to_string(D + 1));
  const auto nv = static_cast<int64_t>(coords.size() / D);
  for (std::size_t k = 0; k < simplices.size(); ++k)
    if (simplices[k] < 0 || simplices[k] >= nv)
      throw InputError("element " + std::to_string(k / (D + 1) + 1) + " has vertex id " +
                       std::to_string(simplices[k] + 1) + " out of range");
}

}  // namespace

template <int D>
std::vector<SymMat<D>> implied_log_metric(std::span<const double> coords,
                                          std::span<const int32_t> simplices,
                                          std::vector<bool>* in_simplex) {
  check_mesh_arrays<D>(coords, simplices);
  const std::size_t nv = coords.size() / D;
  // Scatter form of implied_vertex_metric: accumulating Σ|K| log M_K per vertex visits every
  // element once (no vertex-to-element adjacency needed) and takes each log only once.
  std::vector<SymMat<D>> log_sum(nv, SymMat<D>::zero());
  std::vector<double> weight(nv, 0.0);
  const std::size_t ns = simplices.size() / (D + 1);
  for (std::size_t s = 0; s < ns; ++s) {
    Vec<D> p[D + 1];
    for (int i = 0; i < D + 1; ++i)
      for (int k = 0; k < D; ++k) p[i][k] = coords[simplices[s * (D + 1) + i] * D + k];
    SymMat<D> mk;
    try {
      mk = element_metric(p);
    } catch (const InputError& e) {
      throw InputError("element " + std::to_string(s + 1) + " has no implied metric: " + e.what() +
                       " (zero measure)");
    }
    const double w = std::abs(simplex_measure(p));
    const SymMat<D> wlog = w * log_spd(mk);
    for (int i = 0; i < D + 1; ++i) {
      const auto v = static_cast<std::size_t>(simplices[s * (D + 1) + i]);
      log_sum[v] += wlog;
      weight[v] += w;
    }
  }
  if (in_simplex) in_simplex->assign(nv, true);
  for (std::size_t v = 0; v < nv; ++v) {
    if (weight[v] > 0.0) {
      log_sum[v] = (1.0 / weight[v]) * log_sum[v];
    } else if (in_simplex) {
      (*in_simplex)[v] = false;
    } else {
      throw InputError("vertex " + std::to_string(v + 1) + " is in no element: no implied metric");
    }
  }
  return log_sum;
}

template <int D>
std::vector<SymMat<D>> implied_metric(std::span<const double> coords,
                                      std::span<const int32_t> simplices) {
  std::vector<SymMat<D>> out = implied_log_metric<D>(coords, simplices, nullptr);
  for (SymMat<D>& m : out) m = exp_sym(m);
  return out;
}

template std::vector<SymMat<2>> implied_log_metric<2>(std::span<const double>,
                                                             std::span<const int32_t>,
                                                             std::vector<bool>*);
template std::vector<SymMat<3>> implied_log_metric<3>(std::span<const double>,
                                                             std::span<const int32_t>,
                                                             std::vector<bool>*);
template std::vector<SymMat<2>> implied_metric<2>(std::span<const double>,
                                                  std::span<const int32_t>);
template std::vector<SymMat<3>> implied_metric<3>(std::span<const double>,
                                                  std::span<const int32_t>);

}  // namespace riemesh
