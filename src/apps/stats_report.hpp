#pragma once
// What `riemesh stats` reports about a mesh (and a metric field), gathered from the library's
// statistics, printed for people or as one JSON object (keys documented in README.md).
#include <optional>
#include <span>
#include <string>

#include "mesh/mesh.hpp"
#include "mesh/stats.hpp"

namespace riemesh::cli {

struct ValueStats {
  Summary summary;
  Histogram histogram;
};

struct MetricReport {
  ValueStats edge_length;
  double unit_fraction = 0.0;  // edges with length in [1/√2, √2]
  ValueStats quality;
};

struct StatsReport {
  std::string file;
  int dim = 0;
  MeshKind kind = MeshKind::kEmpty;
  bool valid = false;
  MeshCounts counts;
  MeshRefs refs;
  Summary measure;
  ValueStats quality;  // Euclidean
  std::optional<MetricReport> metric;
};

/// Gathers the report; `metric` is empty or a validated field.
StatsReport make_stats_report(const Mesh& mesh, const std::string& file,
                              std::span<const double> metric);

std::string to_json(const StatsReport& r);
std::string to_text(const StatsReport& r);

}  // namespace riemesh::cli
