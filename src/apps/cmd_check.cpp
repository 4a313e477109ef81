// `riemesh check FILE`: validity report of a mesh (surfaces: also crossing triangles); exit 0
// valid, 1 invalid, 2 unreadable.
#include <cstdio>
#include <memory>
#include <string>

#include "apps/commands.hpp"
#include "apps/mesh_args.hpp"
#include "mesh/check.hpp"
#include "mesh/self_intersection.hpp"
#include "mesh/stats.hpp"

namespace riemesh::cli {
namespace {

const char* entity_name(EntityKind k) {
  switch (k) {
    case EntityKind::kVertex:
      return "vertex";
    case EntityKind::kEdge:
      return "edge";
    case EntityKind::kTriangle:
      return "triangle";
    case EntityKind::kTet:
      return "tetrahedron";
    case EntityKind::kNone:
      break;
  }
  return "";
}

const char* kind_name(MeshKind k) {
  switch (k) {
    case MeshKind::kPlanar:
      return "planar triangle mesh";
    case MeshKind::kSurface:
      return "surface triangle mesh";
    case MeshKind::kVolume:
      return "tetrahedral mesh";
    case MeshKind::kEmpty:
      break;
  }
  return "mesh without elements";
}

/// "  inverted element: 3 (first: triangle 12 at (0.5, 0.25))", ids 1-based as in the files.
std::string issue_line(const CheckIssue& i, int dim) {
  std::string s = "  ";
  s += to_string(i.category);
  s += ": ";
  s += std::to_string(i.count);
  if (i.example != kNoId && i.entity != EntityKind::kNone) {
    char where[128];
    if (dim == 2)
      std::snprintf(where, sizeof where, " at (%.6g, %.6g)", i.location[0], i.location[1]);
    else
      std::snprintf(where, sizeof where, " at (%.6g, %.6g, %.6g)", i.location[0], i.location[1],
                    i.location[2]);
    s += " (first: ";
    s += entity_name(i.entity);
    s += " ";
    s += std::to_string(i.example + 1);
    if (i.local_face >= 0) {
      s += i.entity == EntityKind::kTet ? " face " : " edge ";
      s += std::to_string(i.local_face + 1);
    }
    s += where;
    s += ")";
  }
  return s;
}

/// Crossing triangles of a surface, or overlapping in one plane (mesh/self_intersection.hpp), when
/// its ids and coordinates can be read: "  self-intersection: 12 pairs (first: triangles 5 and 40
/// at (x, y, z))", or "" when there is none.
std::string crossing_line(const Mesh& mesh, const CheckReport& report) {
  if (mesh.kind() != MeshKind::kSurface) return {};
  for (CheckCategory c : {CheckCategory::kArraySize, CheckCategory::kIdOutOfRange,
                          CheckCategory::kNonFiniteCoordinate})
    if (report.count(c) > 0) return {};
  constexpr std::size_t kMaxPairs = 1000;
  const SelfIntersections x = find_self_intersections(mesh, kMaxPairs, /*coplanar=*/true);
  if (x.pairs == 0) return {};
  double c[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i)
      c[i] +=
          mesh.coords[3 * static_cast<std::size_t>(mesh.triangles[3 * x.first_a + k]) + i] / 3.0;
  char line[256];
  std::snprintf(
      line, sizeof line,
      "  self-intersection: %s%zu pairs of triangles (first: triangles %d and %d at (%.6g, "
      "%.6g, %.6g))",
      x.pairs >= kMaxPairs ? "at least " : "", x.pairs, x.first_a + 1, x.first_b + 1, c[0], c[1],
      c[2]);
  return line;
}

void run_check(const std::string& path) {
  const Mesh mesh = load_mesh(path);
  const CheckReport report = check_mesh(mesh);
  const std::string crossing = crossing_line(mesh, report);
  const bool valid = report.valid() && crossing.empty();
  std::printf("%s: %s, %s: %zu vertices, %zu triangles, %zu tetrahedra, %zu edges\n", path.c_str(),
              valid ? "valid" : "INVALID", kind_name(mesh.kind()), mesh.num_vertices(),
              mesh.num_triangles(), mesh.num_tets(), mesh.num_edges());
  for (const CheckIssue& i : report.issues) std::printf("%s\n", issue_line(i, mesh.dim).c_str());
  if (!crossing.empty()) std::printf("%s\n", crossing.c_str());
  for (const CheckIssue& i : report.notes)
    std::printf("  note, %s\n", issue_line(i, mesh.dim).substr(2).c_str());
  if (!report.notes.empty())
    std::printf(
        "  (a surface of several regions: edges where they meet are on 3 or more triangles, and an "
        "interface may face either region)\n");
  std::fflush(stdout);
  if (!valid) throw ExitStatus{1};
}

}  // namespace

void register_check(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "check",
      "Check a mesh (ids, orientation, conformity, boundary; surfaces: crossing triangles): exit 0 "
      "valid, 1 invalid, 2 unreadable. Ids in the report are 1-based, as in Medit files. A "
      "surface may bound several regions (edges on 3 or more triangles, noted, valid)");
  auto path = std::make_shared<std::string>();
  cmd->add_option("file", *path, "Mesh file (.mesh, .meshb, .msh)")->required();
  cmd->callback([path] { run_check(*path); });
}

}  // namespace riemesh::cli
