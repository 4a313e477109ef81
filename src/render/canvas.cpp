#include "render/canvas.hpp"

#include <cairo-svg.h>
#include <cairo.h>
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace riemesh::render_detail {

// The cairo functions the pictures use (the headers give their types; the library is loaded at
// run time). X(name) for each cairo_name.
#define RIEMESH_CAIRO_FUNCTIONS(X)                                                            \
  X(arc) X(clip) X(close_path) X(create) X(destroy) X(fill) X(fill_preserve)                  \
  X(image_surface_create) X(line_to) X(move_to) X(paint) X(rectangle) X(restore) X(rotate)    \
  X(save) X(select_font_face) X(set_dash) X(set_font_size) X(set_line_join) X(set_line_width) \
  X(set_source_rgb) X(set_source_rgba) X(show_text) X(status) X(status_to_string) X(stroke)   \
  X(surface_destroy) X(surface_finish) X(surface_status) X(surface_write_to_png_stream)       \
  X(svg_surface_create_for_stream) X(text_extents) X(translate)

struct CairoApi {
#define RIEMESH_CAIRO_POINTER(name) decltype(&::cairo_##name) name = nullptr;
  RIEMESH_CAIRO_FUNCTIONS(RIEMESH_CAIRO_POINTER)
#undef RIEMESH_CAIRO_POINTER
};

namespace {

/// Loads libcairo.so.2 (kept loaded: RTLD_NODELETE) and resolves the functions above. A missing
/// or too old library is something the user must fix on the machine, not a fault of the program:
/// InputError (the CLI reports it as an error, exit 2), naming the package to install.
std::unique_ptr<const CairoApi> load_cairo() {
  void* lib = dlopen("libcairo.so.2", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
  if (lib == nullptr) {
    const char* why = dlerror();
    std::string msg = "pictures need the cairo library (Debian package libcairo2): ";
    msg += why != nullptr ? why : "libcairo.so.2 not found";
    throw InputError(msg);
  }
  auto api = std::make_unique<CairoApi>();
  bool missing = false;
  std::string names;
#define RIEMESH_CAIRO_RESOLVE(name)                                                   \
  if (void* f = dlsym(lib, "cairo_" #name))                                          \
    api->name = reinterpret_cast<std::remove_reference_t<decltype(api->name)>>(f);   \
  else                                                                               \
    missing = true, names += " cairo_" #name;
  RIEMESH_CAIRO_FUNCTIONS(RIEMESH_CAIRO_RESOLVE)
#undef RIEMESH_CAIRO_RESOLVE
  dlclose(lib);  // NODELETE: stays loaded, the pointers stay valid
  if (missing) throw InputError("libcairo.so.2 lacks" + names + " (cairo too old?)");
  return api;
}

cairo_t* context(void* cr) { return static_cast<cairo_t*>(cr); }
cairo_surface_t* surface(void* s) { return static_cast<cairo_surface_t*>(s); }

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

void require_ok(const CairoApi& api, cairo_status_t s, const char* what) {
  if (s != CAIRO_STATUS_SUCCESS) {
    std::string msg = "cairo: ";
    msg += what;
    msg += ": ";
    msg += api.status_to_string(s);
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
    : api_(load_cairo()), format_(format), width_(width), height_(height) {
  const CairoApi& c = *api_;
  cairo_surface_t* s =
      format == ImageFormat::kPng
          ? c.image_surface_create(CAIRO_FORMAT_ARGB32, width, height)
          : c.svg_surface_create_for_stream(append_bytes, &svg_bytes_, width, height);
  cairo_t* cr = c.create(s);
  if (c.status(cr) != CAIRO_STATUS_SUCCESS) {
    const cairo_status_t status = c.status(cr);
    c.destroy(cr);
    c.surface_destroy(s);
    require_ok(c, status, "cannot create the image");
  }
  surface_ = s, cr_ = cr;
  c.set_source_rgb(cr, 1, 1, 1);
  c.paint(cr);
}

Canvas::~Canvas() {
  api_->destroy(context(cr_));
  api_->surface_destroy(surface(surface_));
}

void Canvas::set_color(const Rgb& c, double alpha) const {
  api_->set_source_rgba(context(cr_), c.r, c.g, c.b, alpha);
}
void Canvas::set_line_width(double w) const { api_->set_line_width(context(cr_), w); }
void Canvas::set_round_joins() const {
  api_->set_line_join(context(cr_), CAIRO_LINE_JOIN_ROUND);
}
void Canvas::set_dash(bool dashed, double on, double off) const {
  const double dash[2] = {on, off};
  api_->set_dash(context(cr_), dash, dashed ? 2 : 0, 0);
}
void Canvas::move_to(double x, double y) const { api_->move_to(context(cr_), x, y); }
void Canvas::line_to(double x, double y) const { api_->line_to(context(cr_), x, y); }
void Canvas::close_path() const { api_->close_path(context(cr_)); }
void Canvas::rectangle(double x, double y, double w, double h) const {
  api_->rectangle(context(cr_), x, y, w, h);
}
void Canvas::arc(double x, double y, double radius, double from, double to) const {
  api_->arc(context(cr_), x, y, radius, from, to);
}
void Canvas::stroke() const { api_->stroke(context(cr_)); }
void Canvas::fill() const { api_->fill(context(cr_)); }
void Canvas::fill_preserve() const { api_->fill_preserve(context(cr_)); }
void Canvas::clip() const { api_->clip(context(cr_)); }
void Canvas::push_state() const { api_->save(context(cr_)); }
void Canvas::pop_state() const { api_->restore(context(cr_)); }
void Canvas::translate(double x, double y) const { api_->translate(context(cr_), x, y); }
void Canvas::rotate(double radians) const { api_->rotate(context(cr_), radians); }

void Canvas::text(double x, double y, const std::string& s, double size, Align align,
                  bool bold) const {
  const double advance = text_width(s, size, bold);  // selects the font too
  const double dx = align == Align::kLeft     ? 0.0
                    : align == Align::kCenter ? -0.5 * advance
                                              : -advance;
  api_->move_to(context(cr_), x + dx, y);
  api_->show_text(context(cr_), s.c_str());
}

double Canvas::text_width(const std::string& s, double size, bool bold) const {
  cairo_t* cr = context(cr_);
  api_->select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  api_->set_font_size(cr, size);
  cairo_text_extents_t ext;
  api_->text_extents(cr, s.c_str(), &ext);
  return ext.x_advance;
}

void Canvas::save(const std::string& path) {
  const CairoApi& c = *api_;
  require_ok(c, c.status(context(cr_)), "drawing failed");
  if (format_ == ImageFormat::kPng) {
    std::string bytes;
    require_ok(c, c.surface_write_to_png_stream(surface(surface_), append_bytes, &bytes),
               "cannot encode the PNG");
    write_file_atomically(path, bytes);
  } else {
    c.surface_finish(surface(surface_));
    require_ok(c, c.surface_status(surface(surface_)), "cannot encode the SVG");
    write_file_atomically(path, svg_bytes_);
  }
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

}  // namespace riemesh::render_detail
