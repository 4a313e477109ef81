#pragma once
// A drawing surface that ends as a PNG or SVG file written atomically, and the colour maps the
// pictures share. Internal to the render layer. The drawing is done by cairo, loaded at run time
// (dlopen of libcairo.so.2) when the first picture is made: the commands that draw nothing do not
// load cairo and the ~20 libraries under it (half the start-up time of a small `riemesh adapt`).
#include <cstddef>
#include <memory>
#include <string>

namespace riemesh::render_detail {

enum class ImageFormat { kPng, kSvg };

/// The format named by the path's extension (.png or .svg); InputError otherwise.
ImageFormat image_format(const std::string& path);

struct Rgb {
  double r, g, b;
};

/// Viridis (perceptually uniform, colour-blind safe), t clamped to [0, 1].
Rgb viridis(double t);
/// A categorical colour (Tableau 10), cycling.
Rgb category_color(std::size_t i);

enum class Align { kLeft, kCenter, kRight };

struct CairoApi;  // the cairo functions used, resolved at run time (canvas.cpp)

/// An image being drawn; save() encodes it and writes the file atomically. The drawing calls are
/// cairo's (path, stroke, fill, transformations), in pixels with y down. Error when cairo cannot
/// be loaded (Debian package libcairo2).
class Canvas {
 public:
  Canvas(ImageFormat format, int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

  void set_color(const Rgb& c, double alpha = 1.0) const;
  void set_line_width(double w) const;
  void set_round_joins() const;
  /// Dashes of `on` pixels drawn and `off` skipped; solid lines when dashed is false.
  void set_dash(bool dashed, double on = 6.0, double off = 4.0) const;
  void move_to(double x, double y) const;
  void line_to(double x, double y) const;
  void close_path() const;
  void rectangle(double x, double y, double w, double h) const;
  void arc(double x, double y, double radius, double from, double to) const;
  void stroke() const;
  void fill() const;
  void fill_preserve() const;
  void clip() const;
  /// Saves (push) and restores (pop) the drawing state: transformation, clip, colour, line.
  void push_state() const;
  void pop_state() const;
  void translate(double x, double y) const;
  void rotate(double radians) const;
  /// Text with its baseline at y, aligned on x.
  void text(double x, double y, const std::string& s, double size, Align align = Align::kLeft,
            bool bold = false) const;
  /// Width of the text at that font size.
  double text_width(const std::string& s, double size, bool bold = false) const;
  /// Finishes the drawing and writes it to path (PNG or SVG, as constructed), atomically.
  void save(const std::string& path);

 private:
  std::unique_ptr<const CairoApi> api_;
  ImageFormat format_;
  int width_, height_;
  std::string svg_bytes_;  // the SVG surface streams here until save()
  void* surface_ = nullptr;  // cairo_surface_t
  void* cr_ = nullptr;       // cairo_t
};

/// "%.3g" of v.
std::string format_number(double v);

}  // namespace riemesh::render_detail
