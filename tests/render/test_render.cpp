// render_mesh and plot_histograms: files are complete PNG/SVG images of the requested width,
// bad requests throw InputError and leave no file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "metric/mesh_quality.hpp"
#include "render/line_plot.hpp"
#include "render/render.hpp"

using namespace riemesh;
namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A fresh empty folder for one test.
fs::path temp_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("riemesh_render_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

/// Width and height from a PNG's IHDR chunk (big-endian at bytes 16 and 20).
std::pair<int, int> png_size(const std::string& b) {
  auto be32 = [&](int o) {
    return (static_cast<unsigned char>(b[o]) << 24) | (static_cast<unsigned char>(b[o + 1]) << 16) |
           (static_cast<unsigned char>(b[o + 2]) << 8) | static_cast<unsigned char>(b[o + 3]);
  };
  return {be32(16), be32(20)};
}

const std::string kPngSignature("\x89PNG\r\n\x1a\n", 8);

}  // namespace

TEST(Render, PlanarPngByQualitySizeRef) {
  const fs::path d = temp_dir("planar");
  const Mesh m = unit_square(6, 4);
  for (ColorBy c : {ColorBy::kQuality, ColorBy::kSize, ColorBy::kRef}) {
    RenderOptions o;
    o.color = c;
    o.width = 320;
    o.title = "unit square";
    const fs::path p = d / "m.png";
    render_mesh(m, p.string(), o);
    const std::string b = slurp(p);
    ASSERT_GT(b.size(), 100u);
    EXPECT_EQ(b.substr(0, 8), kPngSignature);
    EXPECT_EQ(png_size(b).first, 320);
    EXPECT_GE(png_size(b).second, 240);
  }
  // Only the image: no temporary left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator{}), 1);
}

TEST(Render, SvgWithMetricAndSurfaceViews) {
  const fs::path d = temp_dir("svg");
  const Mesh m = unit_square(3, 3);
  std::vector<double> metric;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) metric.insert(metric.end(), {4.0, 0.0, 1.0});
  RenderOptions o;
  o.metric = metric;
  render_mesh(m, (d / "m.svg").string(), o);
  const std::string svg = slurp(d / "m.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  for (ViewFrom v : {ViewFrom::kX, ViewFrom::kY, ViewFrom::kZ, ViewFrom::kIso}) {
    o = RenderOptions{};
    o.view = v;
    render_mesh(sphere_surface(2), (d / "s.png").string(), o);
    EXPECT_EQ(slurp(d / "s.png").substr(0, 8), kPngSignature);
  }
  // A volume is drawn through its boundary faces.
  o.color = ColorBy::kRef;
  render_mesh(unit_cube(2), (d / "c.svg").string(), o);
  EXPECT_NE(slurp(d / "c.svg").find("</svg>"), std::string::npos);
}

TEST(Render, BadRequestsLeaveNoFile) {
  const fs::path d = temp_dir("bad");
  const Mesh m = unit_square(2, 2);
  RenderOptions o;
  EXPECT_THROW(render_mesh(m, (d / "m.jpg").string(), o), InputError);
  o.width = 10;
  EXPECT_THROW(render_mesh(m, (d / "m.png").string(), o), InputError);
  o.width = 400;
  EXPECT_THROW(render_mesh(Mesh{}, (d / "m.png").string(), o), InputError);
  EXPECT_TRUE(fs::is_empty(d));
}

TEST(Render, HistogramPlot) {
  const fs::path d = temp_dir("plot");
  const Mesh m = unit_square(5, 5);
  std::vector<HistogramPanel> panels;
  panels.push_back({"quality", histogram(quality_histogram_edges(), element_qualities(m)), {}});
  panels.push_back({"lengths",
                    histogram(length_histogram_edges(), std::vector<double>{0.5, 1.0, 1.2}),
                    {false, false, false, false, true, true, false, false, false, false}});
  plot_histograms(panels, (d / "h.png").string(), 600);
  const std::string b = slurp(d / "h.png");
  EXPECT_EQ(b.substr(0, 8), kPngSignature);
  EXPECT_EQ(png_size(b).first, 600);
  EXPECT_THROW(plot_histograms({}, (d / "x.png").string()), InputError);
  EXPECT_THROW(plot_histograms(panels, (d / "x.txt").string()), InputError);
}

TEST(PlotLogLog, WritesPngAndSvgAndRejectsBadInput) {
  const fs::path d = temp_dir("loglog");
  LogLogPlot p;
  p.title = "errors";
  p.x_label = "vertices";
  p.y_label = "L2 error";
  p.series.push_back({"adapted, slope -1.00", {500, 1000, 2000, 4000}, {1e-2, 5e-3, 2.5e-3, 1.25e-3}, 0, false});
  p.series.push_back({"uniform", {500, 1000, 2000, 4000}, {1e-1, 7e-2, 5e-2, 0.0}, 1, true});
  plot_loglog(p, (d / "e.png").string(), 640);
  const std::string png = slurp(d / "e.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png_size(png), std::make_pair(640, 480));
  plot_loglog(p, (d / "e.svg").string(), 640);
  EXPECT_NE(slurp(d / "e.svg").find("<svg"), std::string::npos);
  EXPECT_THROW(plot_loglog(p, (d / "e.bmp").string()), InputError);
  EXPECT_THROW(plot_loglog(LogLogPlot{}, (d / "x.png").string()), InputError);
  LogLogPlot empty = p;
  for (PlotSeries& s : empty.series) s.y.assign(s.y.size(), -1.0);
  EXPECT_THROW(plot_loglog(empty, (d / "x.png").string()), InputError);
  EXPECT_FALSE(fs::exists(d / "x.png"));
}
