// `riemesh stats FILE [--metric M.sol] [--json] [--plot OUT.png]`: counts, measures, quality
// and (with a metric) metric edge lengths and quality, with histograms.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
#include "apps/stats_report.hpp"
#include "render/render.hpp"

namespace riemesh::cli {
namespace {

struct StatsArgs {
  std::string file, metric, plot;
  bool json = false;
  int width = 900;
  const CLI::Option* width_given = nullptr;
};

void write_plot(const StatsReport& r, const std::string& path, int width) {
  std::vector<HistogramPanel> panels;
  panels.push_back({"Euclidean quality", r.quality.histogram, {}});
  if (r.metric) {
    // Bins 4 and 5 of the length histogram make up the unit range [1/√2, √2).
    std::vector<bool> unit(r.metric->edge_length.histogram.counts.size(), false);
    unit[4] = unit[5] = true;
    panels.push_back({"Edge length in the metric", r.metric->edge_length.histogram, unit});
    panels.push_back({"Quality in the metric", r.metric->quality.histogram, {}});
  }
  plot_histograms(panels, path, width);
}

void run_stats(const StatsArgs& a) {
  if (a.plot.empty() && a.width_given->count() > 0)
    throw InputError("--width applies to --plot: give the picture with --plot OUT.png");
  const Mesh mesh = load_mesh(a.file);
  require_measurable(mesh, a.file);
  const std::vector<double> metric =
      a.metric.empty() ? std::vector<double>{} : load_metric(a.metric, mesh);
  const StatsReport r = make_stats_report(mesh, a.file, metric);
  if (!a.plot.empty()) write_plot(r, a.plot, a.width);
  std::fputs(a.json ? (to_json(r) + "\n").c_str() : to_text(r).c_str(), stdout);
}

}  // namespace

void register_stats(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "stats",
      "Mesh statistics: counts, measures, quality; with --metric, edge lengths and "
      "quality in the metric");
  auto a = std::make_shared<StatsArgs>();
  cmd->add_option("file", a->file, "Mesh file (.mesh, .meshb, .msh)")->required();
  cmd->add_option("--metric", a->metric, "Metric field (.sol/.solb, one tensor per vertex)");
  cmd->add_flag("--json", a->json, "Print one JSON object (keys in README.md)");
  cmd->add_option("--plot", a->plot, "Draw the histograms into OUT.png or OUT.svg");
  a->width_given = cmd->add_option("--width", a->width, "Width of the --plot picture in pixels")
                       ->capture_default_str()
                       ->check(CLI::Range(64, 8192));
  cmd->callback([a] { run_stats(*a); });
}

}  // namespace riemesh::cli
