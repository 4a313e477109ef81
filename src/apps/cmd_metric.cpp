// `riemesh metric calc ...`: placeholder, filled in by the metric calculator work.
#include "apps/commands.hpp"

namespace riemesh::cli {
void register_metric(CLI::App& app) {
  auto* metric = app.add_subcommand("metric", "Metric tools: calculator");
  metric->require_subcommand(1);
}
}  // namespace riemesh::cli
