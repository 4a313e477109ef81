// `riemesh metric geometric SURFACE.mesh --hausd D [--aniso] -o M.sol`: the geometric metric of a
// surface mesh (remesh/surface_metric.hpp), e.g. for mmgs -met or for inspection.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/sol.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/surface_curvature.hpp"
#include "remesh/surface_metric.hpp"

namespace riemesh::cli {
namespace {

struct GeometricArgs {
  std::string mesh, output;
  SurfaceMetricOptions opt;
  FeatureOptions features;
  bool nr = false, json = false;
  const CLI::Option* beta_given = nullptr;
};

void run_geometric(GeometricArgs& a) {
  if (!a.opt.anisotropic && a.beta_given->count() > 0)
    throw InputError("--beta applies to --aniso (the isotropic metric has no anisotropy)");
  // The options' ranges before the mesh, named by the options (the errors came out of the
  // library prefixed with the mesh's name: "rotor.mesh: hmin must be <= hmax").
  a.opt.validate();
  a.features.validate();
  require_writable(a.output);
  const Mesh mesh = load_mesh(a.mesh);
  require_measurable(mesh, a.mesh);
  if (mesh.kind() == MeshKind::kPlanar)  // it said "needs a surface mesh" of a z = 0 surface
    throw InputError(a.mesh +
                     ": a planar mesh (Dimension 2, or Dimension 3 with every vertex in z = 0): "
                     "metric geometric needs a curved surface in 3D");
  if (mesh.kind() != MeshKind::kSurface)
    throw InputError(a.mesh + ": metric geometric needs a surface mesh (3D triangles, no tetrahedra)");
  a.features.detect_angle = !a.nr;
  const Adjacency adj = build_adjacency(mesh);
  SurfaceFeatures f;
  SurfaceMetricReport r;
  const std::vector<SymMat3> m = naming_file(a.mesh, [&] {
    f = detect_features(mesh, adj, a.features);
    const SurfaceSectors s = surface_sectors(mesh, adj, f);
    return geometric_surface_metric(mesh, adj, f, vertex_curvatures(mesh, adj, f, s), a.opt, &r);
  });
  Field out{"metric", FieldKind::kSymTensor, {}};
  out.values.reserve(6 * m.size());
  for (const SymMat3& x : m) out.values.insert(out.values.end(), x.c, x.c + 6);
  write_sol(a.output, {out}, 3);
  if (a.json) {
    std::printf("{\"vertices\": %zu, \"feature_edges\": %zu, \"corners\": %zu, \"hmin\": %.9g, "
                "\"hmax\": %.9g, \"smallest_size\": %.9g, \"largest_size\": %.9g, "
                "\"gradation_passes\": %d}\n",
                mesh.num_vertices(), f.num_feature_edges, f.num_corners, r.hmin, r.hmax,
                r.smallest, r.largest, r.gradation.passes);
    return;
  }
  std::printf("%s: %zu vertices, %zu feature edges, %zu corners; %s geometric metric for hausd "
              "%g: sizes %.6g .. %.6g (bounds %.6g .. %.6g), %d gradation passes -> %s\n",
              a.mesh.c_str(), mesh.num_vertices(), f.num_feature_edges, f.num_corners,
              a.opt.anisotropic ? "anisotropic" : "isotropic", a.opt.hausd, r.smallest, r.largest,
              r.hmin, r.hmax, r.gradation.passes, a.output.c_str());
}

}  // namespace

void register_metric_geometric(CLI::App& metric) {
  auto a = std::make_shared<GeometricArgs>();
  auto* cmd = metric.add_subcommand(
      "geometric", "Geometric metric of a surface mesh from its curvature and --hausd");
  cmd->add_option("mesh", a->mesh, "Surface mesh (.mesh, .meshb, .msh)")->required();
  cmd->add_option("-o,--output", a->output, "Output metric (.sol/.solb, m11 m12 m22 m13 m23 m33)")
      ->required();
  cmd->add_option("--hausd", a->opt.hausd, "Largest chordal gap (absolute)")->capture_default_str();
  cmd->add_flag("--aniso", a->opt.anisotropic, "Anisotropic metric (principal directions)");
  a->beta_given =
      cmd->add_option(
             "--beta", a->opt.beta_fraction,
             "With --aniso: 0 isotropic .. 1 full anisotropy (same gap in every direction)")
          ->capture_default_str();
  cmd->add_option("--hmin", a->opt.hmin, "Smallest size (default: hausd)");
  cmd->add_option("--hmax", a->opt.hmax, "Largest size (default: bounding-box diagonal)");
  cmd->add_option("--hgrad", a->opt.hgrad, "H-shock gradation (0: none)")->capture_default_str();
  auto* angle =
      cmd->add_option("--angle,--ar", a->features.angle_deg, "Ridge angle threshold (degrees)")
          ->capture_default_str();
  cmd->add_flag("--nr", a->nr, "No ridge detection by angle")->excludes(angle);
  cmd->add_flag("--json", a->json, "Print one JSON object");
  cmd->callback([a] { run_geometric(*a); });
}

}  // namespace riemesh::cli
