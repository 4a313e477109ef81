#include "render/canvas.hpp"

#include <cairo-svg.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace riemesh::render_detail {
namespace {

cairo_status_t append_bytes(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

bool ends_with(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  std::string tail = s.substr(s.size() - suffix.size());
  std::transform(tail.begin(), tail.end(), tail.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return tail == suffix;
}

void require_ok(cairo_status_t s, const char* what) {
  if (s != CAIRO_STATUS_SUCCESS) {
    std::string msg = "cairo: ";
    msg += what;
    msg += ": ";
    msg += cairo_status_to_string(s);
    throw Error(msg);
  }
}

}  // namespace

ImageFormat image_format(const std::string& path) {
  if (ends_with(path, ".png")) return ImageFormat::kPng;
  if (ends_with(path, ".svg")) return ImageFormat::kSvg;
  throw InputError(path + ": unknown image extension (expected .png or .svg)");
}

Rgb viridis(double t) {
  // Nine samples of matplotlib's viridis at t = 0, 1/8, ..., 1, interpolated linearly.
  static constexpr Rgb kStops[9] = {
      {0.267, 0.005, 0.329}, {0.283, 0.141, 0.458}, {0.254, 0.265, 0.530},
      {0.207, 0.372, 0.553}, {0.164, 0.471, 0.558}, {0.128, 0.567, 0.551},
      {0.135, 0.659, 0.518}, {0.478, 0.821, 0.318}, {0.993, 0.906, 0.144}};
  if (!(t > 0.0)) return kStops[0];
  if (t >= 1.0) return kStops[8];
  const double x = 8.0 * t;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  const Rgb& a = kStops[i];
  const Rgb& b = kStops[i + 1];
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

Rgb category_color(std::size_t i) {
  static constexpr Rgb kTableau[10] = {
      {0.122, 0.467, 0.706}, {1.000, 0.498, 0.055}, {0.173, 0.627, 0.173}, {0.839, 0.153, 0.157},
      {0.580, 0.404, 0.741}, {0.549, 0.337, 0.294}, {0.890, 0.467, 0.761}, {0.498, 0.498, 0.498},
      {0.737, 0.741, 0.133}, {0.090, 0.745, 0.812}};
  return kTableau[i % 10];
}

Canvas::Canvas(ImageFormat format, int width, int height)
    : format_(format), width_(width), height_(height) {
  if (format == ImageFormat::kPng)
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  else
    surface_ = cairo_svg_surface_create_for_stream(append_bytes, &svg_bytes_, width, height);
  cr_ = cairo_create(surface_);
  if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS) {
    const cairo_status_t s = cairo_status(cr_);
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
    require_ok(s, "cannot create the image");
  }
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void Canvas::set_color(const Rgb& c, double alpha) const {
  cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha);
}

void Canvas::text(double x, double y, const std::string& s, double size, Align align,
                  bool bold) const {
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr_, s.c_str(), &ext);
  const double dx = align == Align::kLeft     ? 0.0
                    : align == Align::kCenter ? -0.5 * ext.x_advance
                                              : -ext.x_advance;
  cairo_move_to(cr_, x + dx, y);
  cairo_show_text(cr_, s.c_str());
}

double Canvas::text_width(const std::string& s, double size, bool bold) const {
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr_, s.c_str(), &ext);
  return ext.x_advance;
}

void Canvas::save(const std::string& path) {
  require_ok(cairo_status(cr_), "drawing failed");
  if (format_ == ImageFormat::kPng) {
    std::string bytes;
    require_ok(cairo_surface_write_to_png_stream(surface_, append_bytes, &bytes),
               "cannot encode the PNG");
    write_file_atomically(path, bytes);
  } else {
    cairo_surface_finish(surface_);
    require_ok(cairo_surface_status(surface_), "cannot encode the SVG");
    write_file_atomically(path, svg_bytes_);
  }
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace riemesh::render_detail
