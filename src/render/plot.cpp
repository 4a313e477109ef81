// plot_histograms: bar charts of histograms side by side.
#include <algorithm>
#include <string>

#include "core/error.hpp"
#include "render/canvas.hpp"
#include "render/render.hpp"

namespace riemesh {
namespace {

using render_detail::Align;
using render_detail::Canvas;

void draw_panel(const Canvas& cv, const HistogramPanel& p, double x, double y, double w, double h) {
  cv.set_color({0, 0, 0});
  cv.text(x + 0.5 * w, y + 16, p.title, 13, Align::kCenter, true);
  const std::size_t bins = p.histogram.counts.size();
  const std::size_t total = p.histogram.total();
  std::size_t most = 1;
  for (std::size_t c : p.histogram.counts) most = std::max(most, c);
  // Plot area: room for the title above, count labels over the bars and edge labels below.
  const double px = x + 10, pw = w - 20, py = y + 44, ph = h - 44 - 34;
  const double bar_w = pw / static_cast<double>(bins);
  for (std::size_t i = 0; i < bins; ++i) {
    const std::size_t c = p.histogram.counts[i];
    const double bh = ph * static_cast<double>(c) / static_cast<double>(most);
    const bool hi = i < p.highlight.size() && p.highlight[i];
    cv.set_color(hi ? render_detail::Rgb{0.173, 0.627, 0.173}
                    : render_detail::Rgb{0.122, 0.467, 0.706});
    cv.rectangle(px + i * bar_w + 1, py + ph - bh, bar_w - 2, bh);
    cv.fill();
    cv.set_color({0.2, 0.2, 0.2});
    if (c > 0)
      cv.text(px + (i + 0.5) * bar_w, py + ph - bh - 3, std::to_string(c), 9, Align::kCenter);
  }
  cv.set_color({0, 0, 0});
  cv.set_line_width(1.0);
  cv.move_to(px, py + ph + 0.5);
  cv.line_to(px + pw, py + ph + 0.5);
  cv.stroke();
  // Edge labels, every other one when the bins are narrow.
  const std::size_t step = bar_w < 40 ? 2 : 1;
  for (std::size_t i = 0; i <= bins; i += step)
    cv.text(px + i * bar_w, py + ph + 14, render_detail::format_number(p.histogram.edges[i]), 10,
            Align::kCenter);
  cv.text(x + 0.5 * w, py + ph + 30, std::to_string(total) + " values", 10, Align::kCenter);
}

}  // namespace

void plot_histograms(std::span<const HistogramPanel> panels, const std::string& path, int width) {
  const render_detail::ImageFormat format = render_detail::image_format(path);
  if (panels.empty()) throw InputError("plot: no histogram to draw");
  if (width < 64 || width > 8192)
    throw InputError("plot: width must be in 64..8192 pixels, got " + std::to_string(width));
  const double panel_w = static_cast<double>(width) / static_cast<double>(panels.size());
  const int height = static_cast<int>(std::clamp(0.75 * panel_w, 240.0, 480.0));
  Canvas cv(format, width, height);
  for (std::size_t i = 0; i < panels.size(); ++i)
    draw_panel(cv, panels[i], i * panel_w, 0, panel_w, height);
  cv.save(path);
}

}  // namespace riemesh
