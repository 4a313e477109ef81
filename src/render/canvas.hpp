#pragma once
// A cairo drawing surface that ends as a PNG or SVG file written atomically, and the colour maps
// the pictures share. Internal to the render layer (the only place that includes cairo).
#include <cairo.h>

#include <cstddef>
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

/// An image being drawn with cairo; save() encodes it and writes the file atomically.
class Canvas {
 public:
  Canvas(ImageFormat format, int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  cairo_t* cr() const { return cr_; }
  int width() const { return width_; }
  int height() const { return height_; }

  void set_color(const Rgb& c, double alpha = 1.0) const;
  /// Text with its baseline at y, aligned on x.
  void text(double x, double y, const std::string& s, double size, Align align = Align::kLeft,
            bool bold = false) const;
  /// Width of the text at that font size.
  double text_width(const std::string& s, double size, bool bold = false) const;
  /// Finishes the drawing and writes it to path (PNG or SVG, as constructed), atomically.
  void save(const std::string& path);

 private:
  ImageFormat format_;
  int width_, height_;
  std::string svg_bytes_;  // the SVG surface streams here until save()
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

/// "%.3g" of v.
std::string format_number(double v);

}  // namespace riemesh::render_detail
