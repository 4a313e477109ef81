// plot_loglog: curves on log-log axes with decade grid lines and a legend.
#include "render/line_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "render/canvas.hpp"

namespace riemesh {
namespace {

using render_detail::Align;
using render_detail::Canvas;

bool drawable(double x, double y) { return x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y); }

/// log10 range of the data, widened to at least one decade and padded by 5%.
struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    lo = std::min(lo, std::log10(v));
    hi = std::max(hi, std::log10(v));
  }
  void pad() {
    if (hi - lo < 1.0) {
      const double mid = 0.5 * (lo + hi);
      lo = mid - 0.5;
      hi = mid + 0.5;
    }
    const double m = 0.05 * (hi - lo);
    lo -= m;
    hi += m;
  }
};

/// "10^k" as text for the decade labels (1, 10, 100, 1000 written out; others as 1e-3).
std::string decade_label(int k) {
  if (k >= 0 && k <= 4) return std::to_string(static_cast<long>(std::lround(std::pow(10.0, k))));
  return "1e" + std::to_string(k);
}

/// A 2·10^k or 5·10^k label: whole numbers written out (2000, not 2e+03).
std::string tick_label(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v >= 1.0 && v < 1e6 ? "%.0f" : "%.3g", v);
  return buf;
}

struct Frame {
  double x0, y0, w, h;  // plot area in pixels (y0 at the top)
  Range rx, ry;
  double px(double x) const { return x0 + w * (std::log10(x) - rx.lo) / (rx.hi - rx.lo); }
  double py(double y) const { return y0 + h * (1.0 - (std::log10(y) - ry.lo) / (ry.hi - ry.lo)); }
};

void draw_axes(const Canvas& cv, const Frame& f, const LogLogPlot& plot) {
  cv.set_line_width(1.0);
  // Grid and labels at each decade, light lines at 2..9 times it.
  for (int axis = 0; axis < 2; ++axis) {
    const Range& r = axis == 0 ? f.rx : f.ry;
    for (int k = static_cast<int>(std::floor(r.lo)); k <= static_cast<int>(std::ceil(r.hi)); ++k) {
      for (int m = 1; m <= 9; ++m) {
        const double v = m * std::pow(10.0, k), lv = std::log10(v);
        if (lv < r.lo || lv > r.hi) continue;
        cv.set_color({0.5, 0.5, 0.5}, m == 1 ? 0.45 : 0.15);
        if (axis == 0) {
          cv.move_to(f.px(v), f.y0);
          cv.line_to(f.px(v), f.y0 + f.h);
        } else {
          cv.move_to(f.x0, f.py(v));
          cv.line_to(f.x0 + f.w, f.py(v));
        }
        cv.stroke();
        // Labels at the decades, and at 2 and 5 times them on an axis of under two decades.
        const bool label = m == 1 || (r.hi - r.lo < 2.0 && (m == 2 || m == 5));
        if (!label) continue;
        const std::string text = m == 1 ? decade_label(k) : tick_label(v);
        cv.set_color({0, 0, 0});
        if (axis == 0)
          cv.text(f.px(v), f.y0 + f.h + 16, text, 11, Align::kCenter);
        else
          cv.text(f.x0 - 6, f.py(v) + 4, text, 11, Align::kRight);
      }
    }
  }
  cv.set_color({0, 0, 0});
  cv.rectangle(f.x0, f.y0, f.w, f.h);
  cv.stroke();
  cv.text(f.x0 + 0.5 * f.w, 22, plot.title, 14, Align::kCenter, true);
  cv.text(f.x0 + 0.5 * f.w, f.y0 + f.h + 36, plot.x_label, 12, Align::kCenter);
  cv.push_state();
  cv.translate(18, f.y0 + 0.5 * f.h);
  cv.rotate(-std::numbers::pi / 2);
  cv.text(0, 0, plot.y_label, 12, Align::kCenter);
  cv.pop_state();
}

void draw_series(const Canvas& cv, const Frame& f, const PlotSeries& s) {
  cv.set_color(render_detail::category_color(static_cast<std::size_t>(s.color)));
  cv.set_line_width(2.0);
  cv.set_dash(s.dashed);
  bool started = false;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!drawable(s.x[i], s.y[i])) continue;
    if (started)
      cv.line_to(f.px(s.x[i]), f.py(s.y[i]));
    else
      cv.move_to(f.px(s.x[i]), f.py(s.y[i]));
    started = true;
  }
  cv.stroke();
  cv.set_dash(false);
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!drawable(s.x[i], s.y[i])) continue;
    cv.arc(f.px(s.x[i]), f.py(s.y[i]), 3.5, 0, 2 * std::numbers::pi);
    cv.fill();
  }
}

/// Legend in a column right of the plot area (it never hides a curve).
void draw_legend(const Canvas& cv, const Frame& f, const LogLogPlot& plot) {
  const double row = 17, bx = f.x0 + f.w + 10, by = f.y0;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const double y = by + 4 + row * (i + 0.5);
    cv.set_color(render_detail::category_color(static_cast<std::size_t>(s.color)));
    cv.set_line_width(2.0);
    cv.set_dash(s.dashed);
    cv.move_to(bx + 6, y);
    cv.line_to(bx + 34, y);
    cv.stroke();
    cv.set_dash(false);
    cv.set_color({0, 0, 0});
    cv.text(bx + 40, y + 4, s.label, 11);
  }
}

}  // namespace

void plot_loglog(const LogLogPlot& plot, const std::string& path, int width) {
  const render_detail::ImageFormat format = render_detail::image_format(path);
  if (plot.series.empty()) throw InputError("plot: no series to draw");
  if (width < 64 || width > 8192)
    throw InputError("plot: width must be in 64..8192 pixels, got " + std::to_string(width));
  Frame f{};
  f.rx = Range{};
  f.ry = Range{};
  for (const PlotSeries& s : plot.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (drawable(s.x[i], s.y[i])) {
        f.rx.add(s.x[i]);
        f.ry.add(s.y[i]);
      }
  if (!(f.rx.lo <= f.rx.hi)) throw InputError("plot: no positive finite point to draw");
  f.rx.pad();
  f.ry.pad();
  const int height = static_cast<int>(0.75 * width);
  f.x0 = 70;
  f.y0 = 36;
  f.w = width - f.x0 - 20;
  f.h = height - f.y0 - 50;
  Canvas cv(format, width, height);
  double legend_w = 0;
  for (const PlotSeries& s : plot.series)
    legend_w = std::max(legend_w, cv.text_width(s.label, 11) + 56);
  f.w = std::max(0.5 * f.w, f.w - legend_w);
  draw_axes(cv, f, plot);
  cv.push_state();
  cv.rectangle(f.x0, f.y0, f.w, f.h);
  cv.clip();
  for (const PlotSeries& s : plot.series) draw_series(cv, f, s);
  cv.pop_state();
  draw_legend(cv, f, plot);
  cv.save(path);
}

}  // namespace riemesh
