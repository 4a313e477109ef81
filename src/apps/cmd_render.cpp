// `riemesh render FILE -o OUT.svg|OUT.png [--color quality|size|ref] [--metric M.sol]
// [--width PX] [--view x|y|z|iso]`: a picture of a mesh coloured by quality, size or ref.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
#include "apps/parse.hpp"
#include "core/error.hpp"
#include "render/render.hpp"

namespace riemesh::cli {
namespace {

struct RenderArgs {
  std::string file, out, metric, color = "quality", view;
  int width = 800;
};

ViewFrom parse_view(const std::string& v) {
  return v == "x"     ? ViewFrom::kX
         : v == "y"   ? ViewFrom::kY
         : v == "iso" ? ViewFrom::kIso
                      : ViewFrom::kZ;
}

void run_render(const RenderArgs& a) {
  if (a.color == "ref" && !a.metric.empty())
    throw InputError("--metric has no effect with --color ref");
  // The output first: its errors were reported after the drawing, under the input's name.
  require_image_output(a.out);
  const Mesh mesh = load_mesh(a.file);
  require_measurable(mesh, a.file);
  if (!a.view.empty() && mesh.dim == 2)
    throw InputError("--view applies to 3D meshes; " + a.file + " is planar");
  const std::vector<double> metric =
      a.metric.empty() ? std::vector<double>{} : load_metric(a.metric, mesh);
  RenderOptions o;
  o.color = a.color == "size"  ? ColorBy::kSize
            : a.color == "ref" ? ColorBy::kRef
                               : ColorBy::kQuality;
  o.view = parse_view(a.view);
  o.width = a.width;
  o.title = a.file.substr(a.file.find_last_of('/') + 1);
  o.metric = metric;
  naming_file(a.file, [&] { render_mesh(mesh, a.out, o); });
}

}  // namespace

void register_render(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "render", "Draw a planar mesh, or a surface (volume boundary) from a view, as PNG or SVG");
  auto a = std::make_shared<RenderArgs>();
  cmd->add_option("file", a->file, "Mesh file (.mesh, .meshb, .msh)")->required();
  cmd->add_option("-o,--output", a->out, "Picture to write: OUT.png or OUT.svg")->required();
  cmd->add_option("--color", a->color,
                  "Fill: quality (mean ratio, in the metric if given), size (element or metric "
                  "size), ref (element reference)")
      ->capture_default_str()
      ->check(CLI::IsMember({"quality", "size", "ref"}));
  cmd->add_option("--metric", a->metric, "Metric field (.sol/.solb) for quality or size");
  cmd->add_option("--width", a->width, "Width in pixels")
      ->capture_default_str()
      ->check(CLI::Range(64, 8192));
  cmd->add_option("--view", a->view, "3D meshes: look from +x, +y, +z (default) or iso (1,1,1)")
      ->check(CLI::IsMember({"x", "y", "z", "iso"}));
  cmd->callback([a] { run_render(*a); });
}

}  // namespace riemesh::cli
