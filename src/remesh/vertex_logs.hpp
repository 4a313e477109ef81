#pragma once
// The logarithms of the vertex metrics of a remeshed mesh, kept beside them for the measures
// that need them where the metric turns (edge_length_simpson, tri_metric). While every vertex
// metric is diagonal (isotropic or axis-aligned fields) those measures are the closed forms and
// need no logarithm: the logs stay empty and cost nothing. At the first metric that is not
// diagonal, the logs of all vertices are computed, and kept in step from then on.
#include <cstddef>
#include <vector>

#include "core/spd.hpp"
#include "core/symmat.hpp"

namespace riemesh {

/// After metric[v] was set or appended: keeps `logs` in step (see above).
template <int D>
void sync_log(const std::vector<SymMat<D>>& metric, std::vector<SymMat<D>>& logs, std::size_t v) {
  if (logs.empty()) {
    if (is_diagonal(metric[v])) return;
    logs.resize(metric.size());
    for (std::size_t u = 0; u < metric.size(); ++u) logs[u] = log_spd(metric[u]);
    return;
  }
  if (logs.size() < metric.size()) logs.resize(metric.size());
  logs[v] = log_spd(metric[v]);
}

/// After all of `metric` was set: the logs of all vertices when some metric is not diagonal,
/// else none.
template <int D>
void sync_logs(const std::vector<SymMat<D>>& metric, std::vector<SymMat<D>>& logs) {
  logs.clear();
  for (std::size_t v = 0; v < metric.size(); ++v)
    if (!is_diagonal(metric[v])) {
      sync_log(metric, logs, v);
      return;
    }
}

/// The log of vertex v's metric when kept, else null (the measures then compute it if needed).
template <int D>
const SymMat<D>* log_of(const std::vector<SymMat<D>>& logs, std::size_t v) {
  return logs.empty() ? nullptr : &logs[v];
}

}  // namespace riemesh
