#pragma once
// Pictures of meshes and of their statistics, as PNG or SVG (chosen by the file extension),
// drawn with cairo and written atomically. Pure functions of their inputs: no printing.
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "mesh/stats.hpp"

namespace riemesh {

/// What fills the elements.
enum class ColorBy {
  kQuality,  ///< mean-ratio quality in the metric (Euclidean without one), viridis on [0, 1]
  kSize,     ///< element size (metric size with a metric), viridis on a log scale
  kRef,      ///< element reference, categorical palette
};

/// Direction a 3D mesh is looked at from: +x, +y, +z, or the (1, 1, 1) diagonal.
enum class ViewFrom { kX, kY, kZ, kIso };

struct RenderOptions {
  ColorBy color = ColorBy::kQuality;
  ViewFrom view = ViewFrom::kZ;    // ignored for planar meshes
  int width = 800;                 // pixels (SVG: points), 64 .. 8192
  std::string title;               // first part of the title line (e.g. the file name)
  std::span<const double> metric;  // optional per-vertex metric field (validated by the caller)
};

/// Draws a planar mesh, or a surface mesh (the boundary faces of a volume) seen from
/// options.view with flat shading and the painter's algorithm, elements filled by colour, edges
/// thin, with a legend (colour bar or ref swatches) and a title line; writes `path` (.png or
/// .svg). Throws InputError for an unknown extension, a bad width or a mesh without elements.
void render_mesh(const Mesh& mesh, const std::string& path, const RenderOptions& options);

/// One bar chart: a histogram with its title; bins flagged `highlight` are drawn in accent
/// colour (e.g. the unit-length bins).
struct HistogramPanel {
  std::string title;
  Histogram histogram;
  std::vector<bool> highlight;  // empty or one per bin
};

/// Draws the panels side by side as bar charts (count above each bar, bin edges below).
void plot_histograms(std::span<const HistogramPanel> panels, const std::string& path,
                     int width = 900);

}  // namespace riemesh
