// `riemesh mesh SURFACE.mesh -o VOL.mesh`: the volume inside a closed surface, its boundary
// recovered with Steiner points on the surface (see cmd_mesh3d.hpp and
// generate/boundary_recovery3d.hpp).
#include "apps/cmd_mesh3d.hpp"

#include <algorithm>
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
  BoundaryRecoveryOptions recovery;
  recovery.keep_triangles = args.keep_triangles;
  recovery.hole_points = args.holes;
  recovery.no_holes = args.no_holes;
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
          recovery);
      s = filled.stats;
      field_points = filled.field_points;
      out = std::move(filled.adapted.mesh);
    } else {
      RecoveredVolume r = recover_volume(surface, recovery);
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
  if (s.interfaces_listed_twice > 0 && !args.quiet)
    std::fprintf(stderr,
                 "riemesh: note: %s: %zu triangles are listed twice, in opposite orientations (an "
                 "interface given by both its volumes): each taken once, with the ref of its "
                 "first listing\n",
                 input.c_str(), s.interfaces_listed_twice);
  if (s.inconsistent_edges > 0 && !args.quiet)
    std::fprintf(stderr,
                 "riemesh: note: %s: %zu edges are traversed the same way by both their triangles "
                 "(inconsistent orientation): accepted, since the surface bounds several regions "
                 "(an interface separates its two regions whichever way it faces; an enclosed "
                 "shell is a hole only when all of it faces into it); the output's triangles face "
                 "out of their regions\n",
                 input.c_str(), s.inconsistent_edges);
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
    std::printf(": %zu tetrahedra, %zu faces and %zu edges missing, recovered in %zu round%s",
                s.delaunay_tets, s.missing_faces, s.missing_edges, s.rounds,
                s.rounds == 1 ? "" : "s");
    if (s.flips > 0) std::printf(" (%zu edges by flips of cocircular quads)", s.flips);
    if (s.steiner_for_flat_tets > 0)
      std::printf(
          "; %zu Steiner point%s split near-flat tetrahedra between nearly cocircular "
          "surface points inside the volume",
          s.steiner_for_flat_tets, s.steiner_for_flat_tets == 1 ? "" : "s");
    if (s.planar_patches > 0)
      std::printf(
          "; %zu planar patch%s of %zu triangles re-triangulated with Delaunay faces "
          "(--keep-triangles keeps them)",
          s.planar_patches, s.planar_patches == 1 ? "" : "es", s.patch_triangles);
    int regions = 0;
    for (const int r : out.tet_ref) regions = std::max(regions, r);
    std::printf("; %d region%s (tet refs 1", regions, regions == 1 ? "" : "s");
    if (regions > 1) std::printf("-%d", regions);
    std::printf(")\n");
  }
}

}  // namespace riemesh::cli
