// `riemesh mesh SURFACE.mesh -o VOL.mesh`: the volume inside a closed surface, its boundary
// recovered with Steiner points on the surface (see cmd_mesh3d.hpp and
// generate/boundary_recovery3d.hpp).
#include "apps/cmd_mesh3d.hpp"

#include <cmath>
#include <cstdio>

#include "apps/pass_report.hpp"
#include "core/error.hpp"
#include "generate/boundary_recovery3d.hpp"
#include "generate/volume_fill3d.hpp"
#include "io/mesh_file.hpp"
#include "mesh/check.hpp"

namespace riemesh::cli {

namespace {
/// A surface whose mean edge is longer than this many times --hsiz gets a note.
constexpr double kCoarseSurfaceRatio = 2.0;
}  // namespace

void mesh_volume_from_surface(const std::string& input, const Mesh& surface,
                              const std::string& output, const VolumeFillArgs& args) {
  if (surface.dim != 3 || !surface.tets.empty() || surface.triangles.empty())
    throw InputError(input + ": not a surface (3D triangles without tetrahedra)");
  const auto named = [&](const InputError& e) {
    std::string msg = input;
    msg += ": ";
    msg += e.what();
    return InputError(msg);
  };
  BoundaryRecoveryStats s;
  Mesh out;
  double q_min = 0.0;
  std::size_t field_points = 0;
  try {
    if (args.fill) {
      Adapt3dOptions o;
      o.hgrad = args.hgrad;
      o.hmin = args.hmin;
      o.hmax = args.hmax;
      o.max_passes = args.passes;
      FilledVolume filled = mesh_volume(
          surface, args.hsiz, o,
          [&](const PassStats& p) {
            if (!args.quiet) print_pass(p, args.verbosity, "tetrahedra", "fill ");
            q_min = p.q_min;
          },
          args.keep_triangles);
      s = filled.stats;
      field_points = filled.field_points;
      out = std::move(filled.adapted.mesh);
    } else {
      BoundaryRecoveryOptions ro;
      ro.keep_triangles = args.keep_triangles;
      RecoveredVolume r = recover_volume(surface, ro);
      s = r.stats;
      out = std::move(r.volume);
    }
  } catch (const InputError& e) {
    throw named(e);
  }
  // The surface is kept as given: far coarser than --hsiz, the tets along it are slivers (said
  // once the volume is made: a refused input gets its error line alone).
  if (args.fill && args.hsiz > 0.0 && !args.quiet) {
    const std::vector<double> h = boundary_sizes(surface);
    double mean = 0.0;
    for (const double x : h) mean += x / static_cast<double>(h.size());
    if (mean > kCoarseSurfaceRatio * args.hsiz)
      std::fprintf(stderr,
                   "riemesh: note: %s: the surface's edges are %.3g long on average, %.3g times "
                   "--hsiz; it is kept as given, so the tets along it will be poor: remesh it to "
                   "the size first (riemesh adapt %s --hsiz %g -o SURFACE.mesh)\n",
                   input.c_str(), mean, mean / args.hsiz, input.c_str(), args.hsiz);
  }
  // Nested shells give the space between them whatever their orientation: an inner shell
  // oriented like the one around it (a solid, as gmsh writes a sphere inside a box) was made a
  // cavity without a word. Then the surface's signed volume is not the volume meshed.
  if (!args.quiet) {
    double enclosed = 0.0, meshed = 0.0;
    auto point = [](const Mesh& m, Id v) {
      const double* p = &m.coords[3 * static_cast<std::size_t>(v)];
      return Vec3{{p[0], p[1], p[2]}};
    };
    for (std::size_t t = 0; t < surface.num_triangles(); ++t) {
      const Id* v = &surface.triangles[3 * t];
      enclosed +=
          dot(point(surface, v[0]), cross(point(surface, v[1]), point(surface, v[2]))) / 6.0;
    }
    for (std::size_t t = 0; t < out.num_tets(); ++t) {
      const Id* v = &out.tets[4 * t];
      const Vec3 a = point(out, v[0]);
      meshed += dot(point(out, v[1]) - a, cross(point(out, v[2]) - a, point(out, v[3]) - a)) / 6.0;
    }
    if (std::abs(std::abs(enclosed) - meshed) > 1e-6 * meshed)
      std::fprintf(stderr,
                   "riemesh: note: %s: an inner shell is oriented like the shell around it (a "
                   "solid, enclosing %.6g with it, where %.6g was meshed): riemesh meshes the "
                   "space between nested shells, so it was left empty; orient it the other way "
                   "to say so, or mesh the two regions apart\n",
                   input.c_str(), std::abs(enclosed), meshed);
  }
  write_mesh(out, output);
  // The tets of the boundary points alone may keep flat slivers between nearly cocircular
  // surface points, which the recovery could not remove (the fill's optimiser does): said, not
  // silent (`riemesh check` calls such a mesh invalid).
  if (!args.fill && !args.quiet) {
    const CheckReport check = check_mesh(out);
    if (const CheckIssue* flat = check.find(CheckCategory::kZeroMeasureElement))
      std::fprintf(stderr,
                   "riemesh: warning: %s: %zu tetrahedra of near-zero volume remain (first: "
                   "tetrahedron %d at (%g, %g, %g)), flat ones on nearly coplanar surface points; "
                   "without --nofill the optimiser removes them\n",
                   output.c_str(), flat->count, flat->example + 1, flat->location[0],
                   flat->location[1], flat->location[2]);
  }
  if (!args.quiet) {
    if (args.fill)
      std::printf("%s: %zu vertices, %zu tetrahedra (q_min %.3f), %zu boundary triangles; ",
                  output.c_str(), out.num_vertices(), out.num_tets(), q_min, out.num_triangles());
    else
      std::printf("%s: %zu vertices, %zu tetrahedra, %zu boundary triangles; ", output.c_str(),
                  out.num_vertices(), out.num_tets(), out.num_triangles());
    std::printf("%zu Steiner points "
                "(%zu on edges, %zu in faces, %zu inside); Delaunay of the %zu surface vertices",
                s.steiner(), s.steiner_on_edges, s.steiner_in_faces, s.steiner_inside,
                s.surface_vertices);
    if (args.fill) std::printf(" and %zu field points", field_points);
    std::printf(": %zu tetrahedra, %zu faces and %zu edges missing, recovered in %zu rounds",
                s.delaunay_tets, s.missing_faces, s.missing_edges, s.rounds);
    if (s.flips > 0) std::printf(" (%zu edges by flips of cocircular quads)", s.flips);
    if (s.planar_patches > 0)
      std::printf(
          "; %zu planar patch%s of %zu triangles re-triangulated with Delaunay faces "
          "(--keep-triangles keeps them)",
          s.planar_patches, s.planar_patches == 1 ? "" : "es", s.patch_triangles);
    std::printf("\n");
  }
}

}  // namespace riemesh::cli
