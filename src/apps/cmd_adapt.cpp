// `riemesh adapt`: remesh to a metric field (planar triangles or tetrahedra) or to geometric sizes
// (surfaces), with MMG-compatible spellings.
#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "apps/adapt_surface.hpp"
#include "apps/commands.hpp"
#include "apps/field_args.hpp"
#include "apps/mesh_args.hpp"
#include "apps/parse.hpp"
#include "apps/pass_report.hpp"
#include "core/error.hpp"
#include "generate/regenerate2d.hpp"
#include "io/atomic_file.hpp"
#include "io/mesh_file.hpp"
#include "io/sol.hpp"
#include "metric/element.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/metric.hpp"
#include "metric/recovery.hpp"
#include "remesh/adapt2d.hpp"
#include "remesh/adapt3d.hpp"
#include "remesh/transfer.hpp"

namespace riemesh::cli {
namespace {

struct AdaptArgs {
  std::string input, output, metric, out_metric, fields, out_fields, interp = "log";
  std::string field, field_name, norm = "2", recovery = "lsq", geometry;
  double hsiz = 0.0, complexity = 0.0, aniso_max = std::numeric_limits<double>::infinity();
  bool optim = false, noinsert = false, noswap = false, nomove = false, nr = false;
  bool quiet = false, aniso = false, nosurf = false;
  double approach = Adapt3dOptions{}.approach_growth;
  int verbosity = 0;
  Adapt2dOptions opt;
  const CLI::Option* hsiz_given = nullptr;
  const CLI::Option* hausd_given = nullptr;
  const CLI::Option* approach_given = nullptr;
  std::vector<const CLI::Option*> field_only;  // --field-name, --norm, ... (register_adapt)
};

/// The implied metric of the mesh at the vertices of its triangles; vertices in no triangle
/// (geometry points some writers keep) get the identity, and the remesher drops them.
std::vector<SymMat2> implied_metric_of_used(const Mesh& mesh) {
  std::vector<Id> new_id(mesh.num_vertices(), kNoId);
  std::vector<double> coords;
  std::vector<Id> tris;
  for (const Id v : mesh.triangles) {
    if (new_id[v] == kNoId) {
      new_id[v] = static_cast<Id>(coords.size() / 2);
      coords.insert(coords.end(), {mesh.coords[2 * v], mesh.coords[2 * v + 1]});
    }
    tris.push_back(new_id[v]);
  }
  const std::vector<SymMat2> used = implied_metric<2>(coords, tris);
  std::vector<SymMat2> out(mesh.num_vertices(), SymMat2::identity());
  for (std::size_t v = 0; v < out.size(); ++v)
    if (new_id[v] != kNoId) out[v] = used[new_id[v]];
  return out;
}

/// The end of a 2D or 3D run: notes and stall warning, then the outputs. The transferred
/// fields are computed before anything is written, so a failing transfer leaves no file.
template <int D, class Result>
void finish(const AdaptArgs& a, const Mesh& input, const std::vector<Field>& fields,
            const Result& r) {
  if (!a.quiet)
    for (const std::string& note : r.report.notes)
      std::fprintf(stderr, "riemesh: note: %s\n", note.c_str());
  if (!r.report.converged && !a.quiet)
    std::fprintf(stderr, "riemesh: warning: stopped after %zu passes: %s\n",
                 r.report.passes.size(), r.report.stall_reason.c_str());
  const std::vector<Field> moved = fields.empty() ? fields : transfer_p1(input, fields, r.mesh);
  // All outputs or none: a full disk at the last one leaves the earlier ones as they were.
  OutputBatch out;
  out.write(a.output, [&](const std::string& path) { write_mesh(r.mesh, path); });
  if (!a.fields.empty())
    out.write(a.out_fields, [&](const std::string& path) { write_sol(path, moved, D); });
  if (!a.out_metric.empty()) {
    Field f{"metric", FieldKind::kSymTensor, {}};
    for (const SymMat<D>& m : r.metrics) f.values.insert(f.values.end(), m.c, m.c + SymMat<D>::kSize);
    out.write(a.out_metric, [&](const std::string& path) { write_sol(path, {f}, D); });
  }
  out.commit();
}

/// The Lp-optimal metric of complexity N of the solution --field: recovered Hessian (BOOK.md §2).
template <int D>
std::vector<SymMat<D>> metric_from_field(const AdaptArgs& a, const Mesh& mesh) {
  const std::vector<Field> fields = read_sol(a.field, mesh);
  const Field& u = select_field(fields, a.field_name, a.field);
  const std::vector<SymMat<D>> hessians =
      recover_hessian<D>(mesh, u.values, parse_recovery_method(a.recovery));
  HessianMetricOptions h;
  h.norm = parse_norm(a.norm);
  h.complexity = a.complexity;
  h.hmin = a.opt.hmin;
  h.hmax = a.opt.hmax;
  h.aniso_max = a.aniso_max;
  h.validate();
  return hessian_metric<D>(mesh, hessians, h);
}

/// --hsiz as a metric at each of nv vertices. (A size whose metric is too large to compute with,
/// --hsiz 1e-100, was blamed on vertex 1 of the mesh.)
template <int D>
std::vector<SymMat<D>> uniform_metric(double hsiz, std::size_t nv) {
  const SymMat<D> m = isotropic_metric<D>(hsiz);
  char what[48];
  std::snprintf(what, sizeof what, "--hsiz %g", hsiz);
  require_metric(m, what);
  return std::vector<SymMat<D>>(nv, m);
}

/// The metric field for the run: from --metric (tensor, or scalar sizes), --hsiz, --field, or
/// (--optim) the implied metric of the input mesh.
std::vector<SymMat2> load_metric(const AdaptArgs& a, const Mesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  if (!a.metric.empty()) return read_metric_file<2>(a.metric, mesh);
  if (a.hsiz > 0.0) return uniform_metric<2>(a.hsiz, nv);
  if (!a.field.empty()) return metric_from_field<2>(a, mesh);
  return naming_file(a.input, [&] { return implied_metric_of_used(mesh); });
}

/// The surface branch: geometric sizes from --hausd, capped by --hsiz (issue #6).
void run_surface(const AdaptArgs& a, const Mesh& mesh) {
  if (a.nosurf)
    throw InputError(a.input +
                     ": --nosurf applies to tetrahedral volumes (it keeps their "
                     "boundary surface); this is a surface");
  if (a.optim)
    throw InputError(a.input + ": surface remeshing takes --hausd, --metric, --field and "
                     "--hsiz/--hmin/--hmax (no --optim)");
  if (!a.field.empty() && a.recovery != "lsq")
    throw InputError("--recovery: surfaces use the least-squares tangent fit only (lsq)");
  if (!a.out_metric.empty())
    throw InputError("--out-metric is not written for surfaces yet");
  SurfaceAdaptArgs s;
  s.input = a.input;
  s.output = a.output;
  s.metric = a.metric;
  s.field = a.field;
  s.field_name = a.field_name;
  s.fields = a.fields;
  s.out_fields = a.out_fields;
  s.hessian.norm = parse_norm(a.norm);
  s.hessian.complexity = a.complexity;
  s.hessian.hmin = a.opt.hmin;
  s.hessian.hmax = a.opt.hmax;
  s.hessian.aniso_max = a.aniso_max;
  if (!a.field.empty()) s.hessian.validate();
  s.options.hausd = a.opt.hausd;
  s.options.hsiz = a.hsiz;
  s.options.hmin = a.opt.hmin;
  s.options.hmax = std::isfinite(a.opt.hmax) ? a.opt.hmax : 0.0;
  s.options.hgrad = a.opt.hgrad;
  s.options.anisotropic = a.aniso;
  s.options.features.angle_deg = a.opt.angle_deg;
  s.options.features.detect_angle = !a.nr;
  s.options.insert = !a.noinsert;
  s.options.swap = !a.noswap;
  s.options.move = !a.nomove;
  // --passes bounds the surface remesher's cycles (it had no effect); its default keeps theirs.
  if (a.opt.max_passes != Adapt2dOptions{}.max_passes) s.options.max_cycles = a.opt.max_passes;
  s.quiet = a.quiet || a.verbosity < 0;
  run_adapt_surface(s, mesh);
}

/// `-v 1` at the end of a 3D run: the peak resident memory of the process (getrusage; reading,
/// remeshing and writing included) and that per output tetrahedron (issue #7).
void print_peak_memory(std::size_t tets) {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return;
  const double bytes = 1024.0 * static_cast<double>(usage.ru_maxrss);  // ru_maxrss: KiB on Linux
  std::fprintf(stderr, "peak memory: %.1f MB, %.0f bytes per output tetrahedron (%zu tetrahedra)\n",
               bytes / 1e6, tets > 0 ? bytes / static_cast<double>(tets) : 0.0, tets);
}

/// The 3D metric field: --metric (6 tensor coefficients or sizes), --hsiz, --field or --optim.
std::vector<SymMat3> load_metric3(const AdaptArgs& a, const Mesh& mesh) {
  const std::size_t nv = mesh.num_vertices();
  if (!a.field.empty()) return metric_from_field<3>(a, mesh);
  if (!a.metric.empty()) return read_metric_file<3>(a.metric, mesh);
  if (a.hsiz > 0.0) return uniform_metric<3>(a.hsiz, nv);
  return naming_file(a.input, [&] { return implied_metric<3>(mesh.coords, mesh.tets); });
}

/// A tetrahedral mesh: adapt3d (planar boundary patches in their planes, curved ones on the
/// reconstruction of the input surface).
void run3d(const AdaptArgs& a, Mesh&& mesh) {
  std::vector<SymMat3> metrics = load_metric3(a, mesh);
  const std::vector<Field> fields = a.fields.empty() ? std::vector<Field>{} : read_sol(a.fields, mesh);
  Adapt3dOptions opt;
  static_cast<Adapt2dOptions&>(opt) = a.opt;
  opt.keep_surface = a.nosurf;
  if (a.nosurf && a.hausd_given->count() > 0)  // (accepted and ignored before)
    throw InputError("--hausd and --nosurf contradict: the surface is kept as given");
  if (!(a.approach == 0.0 || a.approach > 1.0) || !std::isfinite(a.approach))
    throw InputError("--approach must be 0 (the metric at once) or a size ratio > 1");
  opt.approach_growth = a.approach;
  Mesh geometry;
  if (!a.geometry.empty()) {
    if (a.nosurf) throw InputError("--geometry and --nosurf contradict: the surface is kept as given");
    geometry = read_mesh(a.geometry);
    if (geometry.dim != 3 || geometry.num_triangles() == 0)
      throw InputError(a.geometry + ": no triangles in 3D: --geometry takes the original volume "
                       "(its listed boundary triangles) or surface");
    opt.geometry = &geometry;
  }
  const auto progress = [&](const PassStats& s) {
    if (!a.quiet) print_pass(s, a.verbosity, "tetrahedra");
  };
  // Without fields to transfer the input is needed no more: the remesher takes it and the
  // metrics over instead of copying them (memory, issue #7); finish() reads the input only to
  // transfer fields.
  const Adapt3dResult r = naming_file(a.input, [&] {
    return fields.empty() ? adapt3d(std::move(mesh), std::move(metrics), opt, progress)
                          : adapt3d(mesh, metrics, opt, progress);
  });
  finish<3>(a, mesh, fields, r);
  if (a.verbosity > 0 && !a.quiet) print_peak_memory(r.mesh.num_tets());
}

/// Every output is named right, distinct and writable before the run: a bad second output
/// once failed after the first was written (`-o o.mesh --out-fields o.mesh` left o.mesh).
void require_outputs(const AdaptArgs& a) {
  mesh_format(a.output);
  std::vector<std::string> done{a.output};
  for (const std::string& sol : {a.fields.empty() ? std::string() : a.out_fields, a.out_metric}) {
    if (sol.empty()) continue;
    if (!sol.ends_with(".sol") && !sol.ends_with(".solb"))
      throw InputError(sol + ": not a Medit solution file name (.sol or .solb expected)");
    for (const std::string& other : done)
      if (std::filesystem::path(sol).lexically_normal() ==
          std::filesystem::path(other).lexically_normal())
        throw InputError(sol + ": named for two outputs");
    done.push_back(sol);
  }
  for (const std::string& path : done) require_writable(path);
}

void run(AdaptArgs& a) {
  if (a.output.empty()) throw InputError("no output file: give -o OUT.mesh");
  require_verbosity(a.verbosity, a.quiet);
  if (a.hsiz_given->count() > 0) require_size_option("--hsiz", a.hsiz);
  Mesh mesh = read_mesh(a.input);
  // (A mesh of Edges only was told "no size field", or "the mesh has no triangles" with one.)
  if (mesh.triangles.empty() && mesh.tets.empty())
    throw InputError(a.input + ": the mesh has no triangles or tetrahedra to adapt" +
                     (mesh.edges.empty() || mesh.dim != 2
                          ? ""
                          : " (only Edges: mesh the domain with riemesh mesh)"));
  const bool surface = mesh.kind() == MeshKind::kSurface;
  if (a.aniso && !surface)
    throw InputError(std::string("--aniso applies to surface meshes (the anisotropic geometric "
                                 "metric); for a ") +
                     (mesh.dim == 2 ? "planar" : "volume") +
                     " mesh give an anisotropic metric with --metric or --field");
  // On a surface --hsiz caps the geometric sizes: it combines with the other sources.
  const int sources = (!surface && a.hsiz > 0.0) + !a.metric.empty() + !a.field.empty() + a.optim;
  if (sources > 1)
    throw InputError("--metric, --hsiz, --field and --optim contradict: give one of them");
  if (!a.field.empty() && !(a.complexity > 0.0))
    throw InputError("--field needs the target complexity --complexity N (> 0)");
  if (a.field.empty() && a.complexity > 0.0)
    throw InputError("--complexity applies to --field: give the solution with --field F.sol");
  // (They were accepted and ignored, even with values such as --norm abc.)
  if (a.field.empty()) {
    const std::string given = first_given(a.field_only);
    if (!given.empty())
      throw InputError(given + " applies to --field: give the solution with --field F.sol");
    if (a.fields.empty() && !a.out_fields.empty())
      throw InputError("--out-fields applies to --fields (or --field): nothing to transfer");
  }
  if (!a.field.empty() && a.fields.empty()) {
    // The solution itself is transferred to the new mesh, next to it by default.
    a.fields = a.field;
    if (a.out_fields.empty())
      a.out_fields = std::filesystem::path(a.output).replace_extension(".sol").string();
    if (a.out_fields == a.out_metric)
      throw InputError("--out-metric and the transferred solution would both be written to " +
                       a.out_fields + ": give --out-fields");
  }
  if (!a.fields.empty() && a.out_fields.empty())
    throw InputError("--fields needs --out-fields OUT.sol for the transferred fields");
  if (!a.geometry.empty() && mesh.kind() != MeshKind::kVolume)
    throw InputError("--geometry applies to tetrahedral volumes");
  require_outputs(a);
  // The ranges of --hmin, --hmax, --hgrad, --hausd, --angle, --passes and --interp hold for
  // surfaces too (--hmax -1, --hgrad nan, --interp bogus were taken there).
  a.opt.interp = parse_interp_scheme(a.interp);
  a.opt.validate();
  // The default 0.01 was refused on domains over 1e7 across (QA hunt 5 F9): raised there.
  if (a.hausd_given->count() == 0 && !a.nosurf)
    a.opt.hausd = defaulted_hausd(mesh, a.verbosity > 0 && !a.quiet);
  if (surface) return run_surface(a, mesh);
  if (sources == 0)
    throw InputError("no size field: give --metric M.sol, --hsiz H, --field U.sol --complexity N or --optim");
  a.opt.insert = !a.noinsert;
  a.opt.swap = !a.noswap;
  a.opt.move = !a.nomove;
  a.opt.detect_angles = !a.nr;
  if (a.optim && a.opt.hgrad > 0.0) a.opt.hgrad = 0.0;  // the implied sizes are kept as they are
  if (a.verbosity < 0) a.quiet = true;  // MMG's -v -1: silent
  if (mesh.kind() == MeshKind::kVolume) return run3d(a, std::move(mesh));
  if (mesh.dim != 2)
    throw InputError(a.input + ": only planar, surface and tetrahedral meshes can be adapted");
  // (Accepted and ignored on planar meshes.)
  if (a.nosurf)
    throw InputError("--nosurf applies to tetrahedral volumes (it keeps their boundary surface)");
  if (a.approach_given->count() > 0) throw InputError("--approach applies to tetrahedral volumes");
  const std::vector<SymMat2> metrics = load_metric(a, mesh);
  const std::vector<Field> fields = a.fields.empty() ? std::vector<Field>{} : read_sol(a.fields, mesh);
  const bool progress = !a.quiet;
  const Adapt2dResult r = naming_file(a.input, [&] {
    return adapt_or_regenerate2d(mesh, metrics, a.opt, [&](const PassStats& s) {
      if (progress) print_pass(s, a.verbosity);
    });
  });
  finish<2>(a, mesh, fields, r);
}

}  // namespace

void register_adapt(CLI::App& app) {
  auto a = std::make_shared<AdaptArgs>();
  auto* cmd = app.add_subcommand(
      "adapt",
      "Remesh a planar triangle mesh or a tetrahedral volume to a metric field (unit mesh in "
      "the metric), or a surface (triangles in 3D) to geometric sizes within --hausd. Volumes: "
      "the boundary is remeshed with the volume, planar patches in their planes, curved ones on "
      "the smooth reconstruction of the input surface within --hausd (ridges by --angle and ref "
      "changes; --nosurf keeps the whole surface)");
  cmd->add_option("input,--in", a->input, "Input mesh (.mesh, .meshb, .msh)")->required();
  cmd->add_option("-o,--output,--out", a->output, "Output mesh (.mesh, .meshb, .msh, .vtu)");
  cmd->add_option("--metric,--met,--sol", a->metric,
                  "Metric field (.sol/.solb: symmetric tensors m11 m12 m22 [m13 m23 m33], or sizes)");
  cmd->add_option("--out-metric", a->out_metric, "Write the metric at the output vertices (.sol)");
  cmd->add_option("--field", a->field,
                  "Solution (.sol): adapt to its Lp-optimal Hessian metric of complexity N and "
                  "transfer it (to --out-fields, default OUT.sol)");
  a->field_only.push_back(cmd->add_option("--field-name", a->field_name,
                                          "Scalar field of --field by name or 0-based index"));
  cmd->add_option("--complexity", a->complexity, "Target complexity N with --field");
  a->field_only.push_back(
      cmd->add_option("--norm", a->norm, "Lp norm of the metric with --field (1, 2, ..., inf)")
          ->capture_default_str());
  a->field_only.push_back(
      cmd->add_option("--recovery", a->recovery, "Hessian recovery with --field: lsq, l2, green")
          ->capture_default_str());
  a->field_only.push_back(
      cmd->add_option("--aniso-max", a->aniso_max, "Largest anisotropy ratio with --field"));
  cmd->add_option("--fields", a->fields, "Vertex fields (.sol) to transfer to the output (P1)");
  cmd->add_option("--out-fields", a->out_fields, "Where to write the transferred fields (.sol)");
  a->hsiz_given = cmd->add_option(
      "--hsiz", a->hsiz,
      "Uniform size instead of a metric (2D, far finer than the mesh: the domain is "
      "meshed afresh from its boundary with the size's unit lattice)");
  cmd->add_option("--hmin", a->opt.hmin, "Smallest size")->capture_default_str();
  cmd->add_option("--hmax", a->opt.hmax, "Largest size");
  cmd->add_option("--hgrad", a->opt.hgrad, "Gradation: growth ratio between neighbours (0: off)")
      ->capture_default_str();
  a->hausd_given =
      cmd->add_option("--hausd", a->opt.hausd,
                      "Largest distance of boundary chords to the boundary curve (2D; 0: no "
                      "bound), of the new "
                      "boundary to the input surface (surfaces, curved patches of volumes)")
          ->capture_default_str();
  auto* angle =
      cmd->add_option("--angle,--ar", a->opt.angle_deg, "Corner angle threshold (degrees)")
          ->capture_default_str();
  cmd->add_flag("--nr", a->nr, "No corner detection by angle")->excludes(angle);
  cmd->add_flag("--aniso", a->aniso, "Surfaces: anisotropic geometric metric (BOOK.md §1)");
  cmd->add_flag("--nosurf", a->nosurf, "3D: keep the boundary surface untouched");
  cmd->add_option("--geometry", a->geometry,
                  "3D: the original geometry (volume or surface mesh): curved patches are placed on "
                  "and kept within --hausd of its triangles of the same refs, not of the input's "
                  "boundary (adaptation loops: no drift from run to run)");
  a->approach_given =
      cmd->add_option(
             "--approach", a->approach,
             "3D: largest size ratio asked from one stage to the next when the mesh is far "
             "from the metric (stages toward it from the mesh's own sizes; 0: at once)")
          ->capture_default_str();
  cmd->add_flag("--optim", a->optim, "Improve quality at the current sizes (implied metric)");
  cmd->add_flag("--noinsert", a->noinsert, "No vertex insertion or removal");
  cmd->add_flag("--noswap", a->noswap, "No edge swaps");
  cmd->add_flag("--nomove", a->nomove, "No vertex moves");
  cmd->add_option("--interp", a->interp,
                  "Metric interpolation for new vertices: log, linear, simred-geometric, ...")
      ->capture_default_str();
  cmd->add_option("--passes", a->opt.max_passes, "Largest number of passes")->capture_default_str();
  cmd->add_option("-v,--verbose", a->verbosity, "Verbosity (MMG's -v N; 1: per-pass statistics)")
      ->expected(0, 1)
      ->default_str("0");
  cmd->add_flag("--quiet,-q", a->quiet, "No progress lines");
  cmd->footer(
      "MMG spellings are accepted: -in -out -met -sol -hmin -hmax -hsiz -hgrad -hausd -ar -nr "
      "-noinsert -noswap -nomove -nosurf -optim -v N.");
  cmd->callback([a] { run(*a); });
}

}  // namespace riemesh::cli
