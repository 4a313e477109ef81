#pragma once
// Log-log line plots (error against vertex count for `riemesh loop`), as PNG or SVG by the file
// extension, drawn with cairo and written atomically. No printing.
#include <span>
#include <string>
#include <vector>

namespace riemesh {

/// One curve: points joined by a line, a marker at each point.
struct PlotSeries {
  std::string label;  ///< legend text (e.g. "adapted L2, slope -1.01")
  std::vector<double> x, y;
  int color = 0;        ///< index in the categorical palette
  bool dashed = false;  ///< dashed line (e.g. the uniform reference)
};

struct LogLogPlot {
  std::string title, x_label, y_label;
  std::vector<PlotSeries> series;
};

/// Draws the series on log-log axes (decade grid lines and labels, legend on the right) and
/// writes `path` (.png or .svg). Non-positive or non-finite points are skipped. Throws InputError
/// for an unknown extension, a bad width, no series, or no drawable point.
void plot_loglog(const LogLogPlot& plot, const std::string& path, int width = 800);

}  // namespace riemesh
