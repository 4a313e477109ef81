// render_mesh: a flat-shaded picture of a planar or surface mesh with a colour legend.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "core/error.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"
#include "metric/mesh_quality.hpp"
#include "render/canvas.hpp"
#include "render/render.hpp"

namespace riemesh {
namespace {

using render_detail::Align;
using render_detail::Canvas;
using render_detail::Rgb;

/// A triangle to paint: its three vertices and the element it colours.
struct Face {
  std::array<Id, 3> v;
  std::size_t element;
};

/// The faces to draw: the triangles of a planar or surface mesh, the boundary faces of a volume
/// (faces without a neighbour, oriented outward).
std::vector<Face> faces_of(const Mesh& mesh) {
  std::vector<Face> faces;
  if (mesh.kind() != MeshKind::kVolume) {
    for (std::size_t t = 0; t < mesh.num_triangles(); ++t)
      faces.push_back(
          {{mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]}, t});
    return faces;
  }
  const Adjacency adj = build_adjacency(mesh);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int f = 0; f < 4; ++f)
      if (adj.elem2elem[4 * t + f] == kNoId)
        faces.push_back({{mesh.tets[4 * t + kTetFace[f][0]], mesh.tets[4 * t + kTetFace[f][1]],
                          mesh.tets[4 * t + kTetFace[f][2]]},
                         t});
  return faces;
}

/// Orthographic camera: screen axes (right, up) and the direction towards the viewer.
struct Camera {
  Vec3 right, up, eye;
};

Camera camera(ViewFrom view) {
  Vec3 eye{{0, 0, 1}}, up_hint{{0, 0, 1}};
  switch (view) {
    case ViewFrom::kX:
      eye = Vec3{{1, 0, 0}};
      break;
    case ViewFrom::kY:
      eye = Vec3{{0, 1, 0}};
      break;
    case ViewFrom::kZ:
      up_hint = Vec3{{0, 1, 0}};
      break;
    case ViewFrom::kIso:
      eye = normalize(Vec3{{1, 1, 1}});
      break;
  }
  const Vec3 right = normalize(cross(up_hint, eye));
  return {right, cross(eye, right), eye};
}

Vec3 point3(const Mesh& m, Id v) {
  Vec3 p{};
  for (int c = 0; c < m.dim; ++c) p[c] = m.coords[static_cast<std::size_t>(m.dim) * v + c];
  return p;
}

/// Colour of each element and the legend that explains it.
struct Coloring {
  std::vector<Rgb> colors;
  std::string label;  // what the colours are, for the title
  // Colour bar: value range and whether it is logarithmic; or ref swatches.
  double lo = 0.0, hi = 1.0;
  bool log_scale = false;
  std::vector<std::int32_t> refs;
  std::vector<double> values;  // the coloured values (empty for refs)
};

Coloring color_by_value(std::vector<double> values, bool quality, bool metric) {
  Coloring c;
  c.label = quality ? (metric ? "quality in the metric" : "Euclidean quality")
                    : (metric ? "metric size" : "element size");
  if (!quality) {
    c.lo = *std::min_element(values.begin(), values.end());
    c.hi = *std::max_element(values.begin(), values.end());
    c.log_scale = c.lo > 0.0 && c.hi > 10.0 * c.lo;
    if (!(c.hi > c.lo)) c.hi = c.lo + 1.0;
  }
  for (double v : values) {
    if (quality && v < 0.0) {
      c.colors.push_back({0.85, 0.0, 0.0});  // inverted: red, outside the colour map
      continue;
    }
    const double t =
        c.log_scale ? std::log(v / c.lo) / std::log(c.hi / c.lo) : (v - c.lo) / (c.hi - c.lo);
    c.colors.push_back(render_detail::viridis(t));
  }
  c.values = std::move(values);
  return c;
}

Coloring coloring(const Mesh& mesh, const RenderOptions& o) {
  const bool metric = !o.metric.empty();
  if (o.color == ColorBy::kQuality)
    return color_by_value(element_qualities(mesh, o.metric), true, metric);
  if (o.color == ColorBy::kSize)
    return color_by_value(element_sizes(mesh, o.metric), false, metric);
  Coloring c;
  c.label = "element reference";
  const std::vector<std::int32_t>& refs =
      mesh.kind() == MeshKind::kVolume ? mesh.tet_ref : mesh.tri_ref;
  c.refs = refs;
  std::sort(c.refs.begin(), c.refs.end());
  c.refs.erase(std::unique(c.refs.begin(), c.refs.end()), c.refs.end());
  for (std::int32_t r : refs)
    c.colors.push_back(render_detail::category_color(
        std::lower_bound(c.refs.begin(), c.refs.end(), r) - c.refs.begin()));
  return c;
}

void draw_colorbar(const Canvas& cv, const Coloring& c, double x, double y, double h) {
  const double w = 16.0;
  const int steps = 64;
  for (int i = 0; i < steps; ++i) {
    cv.set_color(render_detail::viridis((i + 0.5) / steps));
    cv.rectangle(x, y + h * (1.0 - (i + 1.0) / steps), w, h / steps + 0.5);
    cv.fill();
  }
  cv.set_color({0, 0, 0});
  cv.set_line_width(1.0);
  cv.rectangle(x, y, w, h);
  cv.stroke();
  const int ticks = 5;
  for (int i = 0; i <= ticks; ++i) {
    const double t = static_cast<double>(i) / ticks;
    const double v = c.log_scale ? c.lo * std::pow(c.hi / c.lo, t) : c.lo + t * (c.hi - c.lo);
    const double ty = y + h * (1.0 - t);
    cv.move_to(x + w, ty);
    cv.line_to(x + w + 4, ty);
    cv.stroke();
    cv.text(x + w + 7, ty + 4, render_detail::format_number(v), 11);
  }
  // Inverted elements (negative quality) are red, outside the colour map.
  if (std::any_of(c.values.begin(), c.values.end(), [](double v) { return v < 0.0; })) {
    cv.set_color({0.85, 0.0, 0.0});
    cv.rectangle(x, y + h + 14, w, 12);
    cv.fill();
    cv.set_color({0, 0, 0});
    cv.text(x + w + 7, y + h + 24, "inverted", 11);
  }
}

void draw_swatches(const Canvas& cv, const Coloring& c, double x, double y, double h) {
  const std::size_t fit = static_cast<std::size_t>(std::max(1.0, h / 18.0));
  for (std::size_t i = 0; i < c.refs.size() && i < fit; ++i) {
    const double ty = y + 18.0 * i;
    if (i + 1 == fit && c.refs.size() > fit) {
      cv.set_color({0, 0, 0});
      cv.text(x, ty + 12, "... (" + std::to_string(c.refs.size()) + " refs)", 11);
      break;
    }
    cv.set_color(render_detail::category_color(i));
    cv.rectangle(x, ty, 14, 14);
    cv.fill();
    cv.set_color({0, 0, 0});
    cv.text(x + 20, ty + 12, "ref " + std::to_string(c.refs[i]), 11);
  }
}

std::string title_line(const Mesh& mesh, const RenderOptions& o, const Coloring& c) {
  std::string s = o.title;
  if (!s.empty()) s += ": ";
  s += c.label;
  if (!c.values.empty()) {
    const Summary sum = summarize(c.values);
    s += " (min ";
    s += render_detail::format_number(sum.min);
    s += ", mean ";
    s += render_detail::format_number(sum.mean());
    s += ")";
  }
  s += ", ";
  s += std::to_string(num_elements(mesh));
  s += mesh.kind() == MeshKind::kVolume ? " tetrahedra" : " triangles";
  return s;
}

}  // namespace

void render_mesh(const Mesh& mesh, const std::string& path, const RenderOptions& o) {
  const render_detail::ImageFormat format = render_detail::image_format(path);
  if (o.width < 64 || o.width > 8192)
    throw InputError("render: width must be in 64..8192 pixels, got " + std::to_string(o.width));
  if (mesh.kind() == MeshKind::kEmpty) throw InputError("render: the mesh has no elements");
  const std::vector<Face> faces = faces_of(mesh);
  const Coloring col = coloring(mesh, o);
  const Camera cam = mesh.dim == 2 ? camera(ViewFrom::kZ) : camera(o.view);

  // Project the vertices; bounding box of the drawn ones.
  const std::size_t nv = mesh.num_vertices();
  std::vector<double> sx(nv), sy(nv), depth(nv);
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const Face& f : faces)
    for (Id v : f.v) {
      const Vec3 p = point3(mesh, v);
      sx[v] = dot(p, cam.right);
      sy[v] = dot(p, cam.up);
      depth[v] = dot(p, cam.eye);
      x0 = std::min(x0, sx[v]), x1 = std::max(x1, sx[v]);
      y0 = std::min(y0, sy[v]), y1 = std::max(y1, sy[v]);
    }
  const double bw = std::max(x1 - x0, 1e-300), bh = std::max(y1 - y0, 1e-300);

  // Layout: title line on top, legend on the right, the mesh fitted in the rest.
  const double margin = 12, title_h = 30, legend_w = 110;
  const double area_w = o.width - legend_w - 2 * margin;
  const double area_h = std::clamp(area_w * bh / bw, 240.0, 1.5 * area_w);
  const double scale = std::min(area_w / bw, area_h / bh);
  const int height = static_cast<int>(std::ceil(title_h + area_h + 2 * margin));
  const double ox = margin + 0.5 * (area_w - scale * bw),
               oy = title_h + margin + 0.5 * (area_h - scale * bh);
  auto to_px = [&](Id v) {
    return std::array<double, 2>{ox + scale * (sx[v] - x0), oy + scale * (y1 - sy[v])};
  };

  // Painter's algorithm: far faces first (a planar mesh has one depth).
  std::vector<std::size_t> order(faces.size());
  std::iota(order.begin(), order.end(), 0);
  auto face_depth = [&](const Face& f) { return depth[f.v[0]] + depth[f.v[1]] + depth[f.v[2]]; };
  if (mesh.dim == 3)
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return face_depth(faces[a]) < face_depth(faces[b]);
    });

  // Edges: thin; fainter when the faces are only a few pixels wide.
  const double mean_px = scale * std::sqrt(bw * bh / std::max<std::size_t>(faces.size(), 1));
  const double edge_alpha = std::clamp(mean_px / 12.0, 0.15, 0.7);

  Canvas cv(format, o.width, height);
  cv.set_line_width(0.4);
  cv.set_round_joins();
  for (std::size_t i : order) {
    const Face& f = faces[i];
    double shade = 1.0;
    if (mesh.dim == 3) {
      // Flat shading, lit from the viewer, both sides alike.
      const Vec3 n = cross(point3(mesh, f.v[1]) - point3(mesh, f.v[0]),
                           point3(mesh, f.v[2]) - point3(mesh, f.v[0]));
      const double len = norm(n);
      shade = 0.35 + 0.65 * (len > 0 ? std::abs(dot(n, cam.eye)) / len : 0.0);
    }
    for (int k = 0; k < 3; ++k) {
      const auto p = to_px(f.v[k]);
      k == 0 ? cv.move_to(p[0], p[1]) : cv.line_to(p[0], p[1]);
    }
    cv.close_path();
    const Rgb c = col.colors[f.element];
    cv.set_color({shade * c.r, shade * c.g, shade * c.b});
    cv.fill_preserve();
    cv.set_color({0.1, 0.1, 0.1}, edge_alpha);
    cv.stroke();
  }

  cv.set_color({0, 0, 0});
  // The title shrinks to fit the width.
  const std::string title = title_line(mesh, o, col);
  const double room = o.width - 2 * margin, natural = cv.text_width(title, 13);
  cv.text(margin, 20, title, natural > room ? 13 * room / natural : 13);
  const double lx = o.width - legend_w + 10, ly = title_h + margin + 10;
  if (o.color == ColorBy::kRef)
    draw_swatches(cv, col, lx, ly, area_h - 20);
  else
    draw_colorbar(cv, col, lx, ly, std::min(area_h - 50, 300.0));
  cv.save(path);
}

}  // namespace riemesh
