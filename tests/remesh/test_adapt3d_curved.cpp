// adapt3d on volumes with curved boundaries (issue #7): new boundary vertices on the smooth
// reconstruction of the input surface, within hausd of it, the rest of the behaviour unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "curved_test_meshes.hpp"
#include "io/mesh_file.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/check.hpp"
#include "mesh/distance.hpp"
#include "mesh/fixtures.hpp"
#include "metric/element.hpp"
#include "metric/metric.hpp"
#include "remesh/adapt3d.hpp"
#include "remesh/boundary3d.hpp"

using namespace riemesh;
using riemesh::test::point;

namespace {

/// Largest | distance to the axis − r | over the vertices of the side (0 < z < height) that are
/// on the boundary (in a listed triangle of ref 1).
double side_error(const Mesh& m, double r) {
  std::vector<char> side(m.num_vertices(), 0);
  for (std::size_t f = 0; f < m.num_triangles(); ++f)
    if (m.tri_ref[f] == 1)
      for (int k = 0; k < 3; ++k) side[m.triangles[3 * f + k]] = 1;
  double worst = 0.0;
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    if (side[v]) {
      const Vec3 p = point(m, static_cast<Id>(v));
      worst = std::max(worst, std::abs(std::hypot(p[0], p[1]) - r));
    }
  return worst;
}

std::size_t count_side_vertices(const Mesh& m) {
  std::vector<char> side(m.num_vertices(), 0);
  for (std::size_t f = 0; f < m.num_triangles(); ++f)
    if (m.tri_ref[f] == 1)
      for (int k = 0; k < 3; ++k) side[m.triangles[3 * f + k]] = 1;
  return static_cast<std::size_t>(std::count(side.begin(), side.end(), 1));
}

double worst_quality(const Adapt3dResult& r) { return r.report.passes.back().q_min; }

/// The listed triangles of ref `ref` as a surface (the vertices all kept).
Mesh faces_of_ref(const Mesh& m, std::int32_t ref) {
  Mesh s;
  s.dim = 3;
  s.coords = m.coords;
  s.vert_ref.assign(m.num_vertices(), 0);
  s.vert_tag.assign(m.num_vertices(), 0);
  for (std::size_t f = 0; f < m.num_triangles(); ++f)
    if (m.tri_ref[f] == ref) {
      s.triangles.insert(s.triangles.end(), &m.triangles[3 * f], &m.triangles[3 * f + 3]);
      s.tri_ref.push_back(ref);
    }
  return s;
}

/// The longest edge of the triangles of s.
double longest_edge(const Mesh& s) {
  double longest = 0.0;
  for (std::size_t f = 0; f < s.num_triangles(); ++f)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, norm(point(s, s.triangles[3 * f + k]) -
                                       point(s, s.triangles[3 * f + (k + 1) % 3])));
  return longest;
}

/// The fraction of the output's tets below quality 0.1 in the metric it followed (the mean of
/// their vertices' metrics).
double fraction_flat(const Adapt3dResult& r) {
  const Mesh& m = r.mesh;
  std::size_t flat = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    Vec3 p[4];
    SymMat3 mean = SymMat3::zero();
    for (int k = 0; k < 4; ++k) {
      const Id v = m.tets[4 * t + static_cast<std::size_t>(k)];
      p[k] = point(m, v);
      mean += 0.25 * r.metrics[static_cast<std::size_t>(v)];
    }
    if (quality<3>(mean, p) < 0.1) ++flat;
  }
  return static_cast<double>(flat) / static_cast<double>(m.num_tets());
}

struct CylinderCase {
  Mesh input = test::faceted_cylinder(24, 2, 1.0, 1.0);
  std::vector<SymMat3> metric = test::cylinder_metric(input, 1.0, 0.3, 0.03);
};

Adapt3dResult adapt_cylinder(const CylinderCase& c, const Adapt3dOptions& o = {}) {
  return adapt3d(c.input, c.metric, o);
}

}  // namespace

TEST(Adapt3dCurved, FixturesAreValid) {
  for (const Mesh& m : {test::faceted_cylinder(24, 2, 1.0, 1.0), test::unit_ball(4)}) {
    const CheckReport c = check_mesh(m);
    EXPECT_TRUE(c.valid()) << (c.issues.empty() ? "" : to_string(c.issues[0].category));
  }
}

TEST(Adapt3dCurved, RefinedCylinderStaysACylinder) {
  const CylinderCase c;
  const Adapt3dResult r = adapt_cylinder(c);
  std::printf(
      "refined cylinder: %zu side vertices (input %zu), %zu tets, %.4f in band, q min %.3f\n",
      count_side_vertices(r.mesh), count_side_vertices(c.input), r.mesh.num_tets(),
      r.report.passes.back().len_in, worst_quality(r));
  const CheckReport check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << (check.issues.empty() ? "" : to_string(check.issues[0].category));
  // Many new side vertices, all on the cylinder (the facets' midpoints are 8.6e-3 inside).
  // Measured 134 for 72 (170 while the fixture's one facet listed the other way round gave its
  // edges' vertices a sector normal tangent to the side, and a wrong curvature there).
  EXPECT_GT(2 * count_side_vertices(r.mesh), 3 * count_side_vertices(c.input));
  EXPECT_LT(side_error(r.mesh, 1.0), 1e-3);
  EXPECT_GT(worst_quality(r), 0.2);
  EXPECT_GT(r.report.passes.back().len_in, 0.8);
}

TEST(Adapt3dCurved, ObliqueAnisotropyFollowedOnACurvedPatch) {
  // A constant 1:50 metric across the direction (1, 1, 1): the side's triangles are thin, and
  // where their long edges run round the cylinder they lean far from its normal (a chord's
  // sagitta over their width). The boundary checks refused every operation turning such a
  // triangle by more than 30°: 88.4% of edges in band, 8,676 tets; 93.1% and 8,092 since. Then
  // 16 tets below quality 0.1 (and 177 in some variants), strung along interior edges lying in
  // the side (kCurvedSplitFloor, adapt3d.cpp): 8,068 tets, 93.1%, 8 below 0.1 since. Those
  // figures came with a wrong curvature along one generator: the fixture lists one facet's
  // triangles the other way round, and their normals cancelled the neighbours' in the sector
  // normals (fixed in surface_sectors). Since: 4,629 tets, 90.4% in band, 0.28% below 0.1 (the
  // same as with that facet listed like the others).
  const Mesh input = test::faceted_cylinder(24, 2, 1.0, 1.0);
  const double h = 1.0, hd = 0.02;
  const Vec3 d = (1.0 / std::sqrt(3.0)) * Vec3{{1.0, 1.0, 1.0}};
  SymMat3 m = isotropic_metric<3>(h);
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) m.at(i, j) += (1.0 / (hd * hd) - 1.0 / (h * h)) * d[i] * d[j];
  Adapt3dOptions o;
  o.hausd = 0.03;
  const Adapt3dResult r = adapt3d(input, std::vector<SymMat3>(input.num_vertices(), m), o);
  std::printf("oblique 1:50: %zu tets, %.4f in band, %.5f below quality 0.1\n", r.mesh.num_tets(),
              r.report.passes.back().len_in, fraction_flat(r));
  const CheckReport check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << (check.issues.empty() ? "" : to_string(check.issues[0].category));
  EXPECT_GT(r.report.passes.back().len_in, 0.89);
  EXPECT_LT(fraction_flat(r), 0.004);
  EXPECT_LT(side_error(r.mesh, 1.0), 1e-3);
}

TEST(Adapt3dCurved, BoundaryTrianglesInAnyOrientation) {
  // The fixture lists one facet's triangles the other way round (volume meshes list boundary
  // triangles in any orientation). The curvature sizes are those of the facets listed alike,
  // or of every other side triangle reversed: the flipped triangles' normals cancelled their
  // neighbours' in the sector normals, and the sizes along that generator were wrong.
  const CylinderCase c;
  Mesh alike = c.input, mixed = c.input;
  const std::size_t facets = 24;
  // The side triangles come first, two per facet and layer, the reversed facet last in each.
  for (std::size_t layer = 0; layer < 2; ++layer)
    for (std::size_t k = 0; k < 2; ++k) {
      const std::size_t t = layer * 2 * facets + 2 * (facets - 1) + k;
      std::swap(alike.triangles[3 * t + 1], alike.triangles[3 * t + 2]);
    }
  for (std::size_t t = 0; t < 4 * facets; t += 2)
    std::swap(mixed.triangles[3 * t + 1], mixed.triangles[3 * t + 2]);
  Adapt3dOptions o;
  o.hausd = 0.003;
  auto sizes = [&](const Mesh& m) {
    std::vector<SymMat3> metric(m.num_vertices(), SymMat3::diagonal(1.0));
    intersect_curvature_sizes(m, metric, o);
    return metric;
  };
  const std::vector<SymMat3> ref = sizes(alike);
  double finest = 0.0;
  for (const SymMat3& x : ref) finest = std::max(finest, x(0, 0) + x(1, 1) + x(2, 2));
  EXPECT_GT(finest, 100.0);  // the side's curvature sizes are there (about 0.15)
  for (const Mesh* m : {&c.input, static_cast<const Mesh*>(&mixed)}) {
    const std::vector<SymMat3> x = sizes(*m);
    ASSERT_EQ(x.size(), ref.size());
    for (std::size_t v = 0; v < x.size(); ++v)
      for (int i = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j) EXPECT_NEAR(x[v](i, j), ref[v](i, j), 1e-9 * finest) << v;
  }
}

TEST(Adapt3dCurved, Deterministic) {
  const CylinderCase c;
  Adapt3dOptions o;
  o.max_passes = 3;
  const Adapt3dResult a = adapt_cylinder(c, o), b = adapt_cylinder(c, o);
  EXPECT_EQ(a.mesh.coords, b.mesh.coords);
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
}

TEST(Adapt3dCurved, NosurfKeepsTheSurface) {
  const CylinderCase c;
  Adapt3dOptions o;
  o.keep_surface = true;
  o.max_passes = 1;
  const Adapt3dResult r = adapt_cylinder(c, o);
  EXPECT_EQ(r.mesh.num_triangles(), c.input.num_triangles());
  EXPECT_EQ(count_side_vertices(r.mesh), count_side_vertices(c.input));
}

TEST(Adapt3dCurved, BallWithinHausd) {
  const Mesh ball = test::unit_ball(4);
  Adapt3dOptions o;
  o.hausd = 0.01;
  const Adapt3dResult r =
      adapt3d(ball, std::vector<SymMat3>(ball.num_vertices(), isotropic_metric<3>(0.12)), o);
  const CheckReport check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << (check.issues.empty() ? "" : to_string(check.issues[0].category));
  EXPECT_GT(r.mesh.num_triangles(), 2 * ball.num_triangles());
  // Both ways, between the boundary surfaces (as `riemesh distance`).
  Mesh in_s, out_s;
  for (const auto& [src, dst] : {std::pair{&ball, &in_s}, std::pair{&r.mesh, &out_s}}) {
    dst->dim = 3;
    dst->coords = src->coords;
    dst->vert_ref.assign(src->num_vertices(), 0);
    dst->vert_tag.assign(src->num_vertices(), 0);
    dst->triangles = src->triangles;
    dst->tri_ref = src->tri_ref;
  }
  const HausdorffDistance d = hausdorff_distance(in_s, out_s, DistanceOptions{});
  EXPECT_LT(d.two_sided(), o.hausd);
  EXPECT_GT(worst_quality(r), 0.2);
}

TEST(Adapt3dCurved, CoarseFacetsSplitOnTheirEdgesWithinHausd) {
  // The coarse ball's facets (16 round the equator) lie further from the sphere than --hausd
  // 0.002: the reconstruction's point of a split is lifted to the limit, its halves left hausd
  // or its tets inverted, and edges stayed unsplit (longest 0.239 for size 0.1, q min 0.418).
  // The split then takes the point on the edge.
  const Mesh ball = test::unit_ball(4);
  Adapt3dOptions o;
  o.hausd = 0.002;
  const double h = 0.1;
  const Adapt3dResult r =
      adapt3d(ball, std::vector<SymMat3>(ball.num_vertices(), isotropic_metric<3>(h)), o);
  const CheckReport check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << (check.issues.empty() ? "" : to_string(check.issues[0].category));
  const Mesh before = faces_of_ref(ball, 1), after = faces_of_ref(r.mesh, 1);
  EXPECT_LT(hausdorff_distance(before, after, DistanceOptions{}).two_sided(), o.hausd);
  std::printf("coarse ball, hausd 0.002: longest boundary edge %.3f, q min %.3f\n",
              longest_edge(after), worst_quality(r));
  EXPECT_LT(longest_edge(after), 1.6 * h);
  EXPECT_GT(worst_quality(r), 0.4);
}

/// The unit ball unit_ball(n) with the tets inside radius 0.5 (a sphere of cube shells when n
/// is a multiple of 4) of tet ref 2, the faces between them and the rest listed with ref 12.
Mesh ball_in_ball(int n) {
  return test::with_regions(test::unit_ball(n),
                            [](const Vec3& c) { return norm(c) < 0.5 ? 2 : 1; });
}

// A ball of radius 0.5 inside the unit ball (a closed curved interface between two regions, as
// a sphere inclusion in gmsh): kept as given, its facets of 0.25 stayed while the sizes around
// them were 0.08 (a gmsh sphere in a box at --hsiz 0.1: metric lengths up to 5.0, q min 0.302).
// Now remeshed on its reconstruction like a curved patch: refined, within hausd of the input
// interface both ways, the faces listed between the two regions, no note.
TEST(Adapt3dCurved, ClosedCurvedInterfaceIsRemeshed) {
  Mesh in = ball_in_ball(8);
  const auto interface = [](const Mesh& m) { return faces_of_ref(m, 12); };
  const Mesh before = interface(in);
  ASSERT_EQ(before.num_triangles(), 6u * 4 * 4 * 2);
  Adapt3dOptions o;
  o.hausd = 0.01;
  o.hgrad = 0.0;
  const Adapt3dResult r =
      adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(0.08)), o);
  const CheckReport check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << (check.issues.empty() ? "" : to_string(check.issues[0].category));
  const Mesh after = interface(r.mesh);
  EXPECT_GT(after.num_triangles(), 4 * before.num_triangles());
  EXPECT_LT(hausdorff_distance(before, after, DistanceOptions{}).two_sided(), o.hausd);
  EXPECT_LT(longest_edge(after), 0.08 * 1.8);
  for (const std::string& n : r.report.notes)
    EXPECT_EQ(n.find("interfaces between subdomains"), std::string::npos) << n;
  EXPECT_GT(worst_quality(r), 0.3);
}

TEST(Adapt3dCurved, CurvedInterfaceWithRimsOnPlanesIsRemeshed) {
  // gmsh's cylinder of radius 0.4 through a box (tests/data/cylinder_through_box.geo): the
  // cylinder's side, ref 7, is a curved interface whose rims lie on the top and bottom faces
  // (z = ±1), there split into a disc (refs 8, 9) and the rest (12, 14). Kept as given before
  // (the note: edges up to 3.06 long, 128 triangles); now remeshed on its reconstruction, the
  // rims on their feature lines and exactly in the planes.
  const Mesh in = read_mesh(RIEMESH_TEST_DATA "/cylinder_through_box.mesh");
  const Mesh before = faces_of_ref(in, 7);
  ASSERT_EQ(before.num_triangles(), 128u);
  Adapt3dOptions o;
  o.hausd = 0.01;
  const Adapt3dResult r =
      adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(0.15)), o);
  const CheckReport check = check_mesh(r.mesh);
  EXPECT_TRUE(check.valid()) << (check.issues.empty() ? "" : to_string(check.issues[0].category));
  const Mesh after = faces_of_ref(r.mesh, 7);
  EXPECT_GT(after.num_triangles(), 3 * before.num_triangles());
  EXPECT_LT(hausdorff_distance(before, after, DistanceOptions{}).two_sided(), o.hausd);
  EXPECT_LT(longest_edge(after), 0.15 * 1.8);
  // The rims: every vertex of the side within 1e-6 of z = ±1 is there within rounding (the
  // reconstructed rim of a planar patch is in its plane), and on a disc.
  std::vector<int> on_disc(r.mesh.num_vertices(), 0);
  for (std::size_t f = 0; f < r.mesh.num_triangles(); ++f)
    if (r.mesh.tri_ref[f] == 8 || r.mesh.tri_ref[f] == 9)
      for (int k = 0; k < 3; ++k) on_disc[r.mesh.triangles[3 * f + k]] = 1;
  int rim = 0;
  for (const Id v : after.triangles) {
    const double z = point(r.mesh, v)[2];
    if (std::abs(std::abs(z) - 1.0) > 1e-6) continue;
    EXPECT_NEAR(std::abs(z), 1.0, 1e-12);
    EXPECT_TRUE(on_disc[v]);
    ++rim;
  }
  EXPECT_GT(rim, 3 * 2 * 16);  // (each rim vertex counted on its triangles)
  for (const std::string& n : r.report.notes)
    EXPECT_EQ(n.find("interfaces between subdomains"), std::string::npos) << n;
  EXPECT_GT(worst_quality(r), 0.4);
}

TEST(Adapt3dCurved, PlanarCubeUnchanged) {
  // No curved patch: the curved-boundary machinery is not built, so --hausd changes nothing.
  const Mesh cube = unit_cube(2);
  const std::vector<SymMat3> metric(cube.num_vertices(), isotropic_metric<3>(0.25));
  Adapt3dOptions a, b;
  a.max_passes = b.max_passes = 3;
  b.hausd = 0.5;
  const Adapt3dResult ra = adapt3d(cube, metric, a), rb = adapt3d(cube, metric, b);
  EXPECT_EQ(ra.mesh.coords, rb.mesh.coords);
  EXPECT_EQ(ra.mesh.tets, rb.mesh.tets);
  EXPECT_EQ(ra.mesh.triangles, rb.mesh.triangles);
}
