// adapt3d on the unit cube: valid conforming output (no inverted tet), boundary refs and planes
// kept, edge lengths and qualities in measured ranges, determinism, bad input refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "metric/element.hpp"
#include "metric/metric.hpp"
#include "remesh/adapt3d.hpp"
#include "remesh/curved_test_meshes.hpp"

using namespace riemesh;

namespace {

/// UGAWG "linear" at a coarse scale: hx = hy = hmax, hz = h0 + 2 (hmax − h0) |z − 0.5|.
std::vector<SymMat3> linear_metric(const Mesh& m, double h0, double hmax) {
  std::vector<SymMat3> out;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const double hz = h0 + 2.0 * (hmax - h0) * std::abs(m.coords[3 * v + 2] - 0.5);
    out.push_back(SymMat3::diagonal(Vec3{{1 / (hmax * hmax), 1 / (hmax * hmax), 1 / (hz * hz)}}));
  }
  return out;
}

/// Area of the boundary triangles of each ref.
std::map<int, double> area_by_ref(const Mesh& m) {
  std::map<int, double> out;
  for (std::size_t f = 0; f < m.num_triangles(); ++f) {
    Vec3 p[3];
    for (int k = 0; k < 3; ++k) {
      const Id v = m.triangles[3 * f + k];
      p[k] = Vec3{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
    }
    out[m.tri_ref[f]] += 0.5 * norm(cross(p[1] - p[0], p[2] - p[0]));
  }
  return out;
}

/// Every boundary triangle of ref r (1..6 = x=0, x=1, y=0, y=1, z=0, z=1) lies on its plane.
bool refs_on_planes(const Mesh& m) {
  for (std::size_t f = 0; f < m.num_triangles(); ++f) {
    const int r = m.tri_ref[f] - 1;
    if (r < 0 || r > 5) return false;
    for (int k = 0; k < 3; ++k)
      if (std::abs(m.coords[3 * m.triangles[3 * f + k] + r / 2] - (r % 2)) > 1e-12) return false;
  }
  return true;
}

double total_volume(const Mesh& m) {
  double s = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) {
      const Id v = m.tets[4 * t + k];
      p[k] = Vec3{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
    }
    s += dot(p[1] - p[0], cross(p[2] - p[0], p[3] - p[0])) / 6.0;
  }
  return s;
}

void expect_valid_cube(const Adapt3dResult& r) {
  const CheckReport c = check_mesh(r.mesh);
  EXPECT_TRUE(c.valid()) << (c.issues.empty() ? "" : to_string(c.issues[0].category));
  EXPECT_NEAR(total_volume(r.mesh), 1.0, 1e-12);
  EXPECT_TRUE(refs_on_planes(r.mesh));
  const std::map<int, double> areas = area_by_ref(r.mesh);
  ASSERT_EQ(areas.size(), 6u);
  for (const auto& [ref, a] : areas) EXPECT_NEAR(a, 1.0, 1e-12) << "ref " << ref;
  EXPECT_EQ(r.metrics.size(), r.mesh.num_vertices());
}

}  // namespace

TEST(Adapt3d, IsotropicSizeOnTheCube) {
  const Mesh cube = unit_cube(3);
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult r =
      adapt3d(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(0.15)), o);
  expect_valid_cube(r);
  const PassStats& s = r.report.passes.back();
  // Measured: 96.9% in band, lengths 0.54..1.41, q_min 0.624, q_mean 0.851, 3177 tets.
  EXPECT_GT(s.len_in, 0.93);
  EXPECT_GT(s.len_min, 0.5);
  EXPECT_LT(s.len_max, 1.5);
  EXPECT_GT(s.q_min, 0.55);
  EXPECT_GT(s.q_mean, 0.75);
  // A unit regular tet of side 0.15 has volume 0.15³/(6√2); the count is within a factor 2.
  const double ideal = 1.0 / (std::pow(0.15, 3) / (6.0 * std::sqrt(2.0)));
  EXPECT_GT(static_cast<double>(s.triangles), 0.5 * ideal);
  EXPECT_LT(static_cast<double>(s.triangles), 2.0 * ideal);
  EXPECT_EQ(s.triangles, r.mesh.num_tets());
}

TEST(Adapt3d, AnisotropicLinearMetricAtCoarseScale) {
  const Mesh cube = unit_cube(5);
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult r = adapt3d(cube, linear_metric(cube, 0.02, 0.25), o);
  expect_valid_cube(r);
  const PassStats& s = r.report.passes.back();
  // Measured: 95.5% in band, lengths 0.52..1.44, q_min 0.585, q_mean 0.785, 1676 tets (the
  // targets of issue #7: q_min >= 0.5, lengths in [0.5, 1.7], >= 95% in band).
  EXPECT_GT(s.len_in, 0.93);
  EXPECT_GT(s.len_min, 0.5);
  EXPECT_LT(s.len_max, 1.5);
  EXPECT_GT(s.q_min, 0.5);
  EXPECT_GT(s.q_mean, 0.72);
}

TEST(Adapt3d, Deterministic) {
  const Mesh cube = unit_cube(3);
  Adapt3dOptions o;
  const Adapt3dResult a = adapt3d(cube, linear_metric(cube, 0.05, 0.3), o);
  const Adapt3dResult b = adapt3d(cube, linear_metric(cube, 0.05, 0.3), o);
  EXPECT_EQ(a.mesh.coords, b.mesh.coords);
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.tri_ref, b.mesh.tri_ref);
}

TEST(Adapt3d, StagedApproachFromACoarseCube) {
  // The 4x4x4 cube has edges of 0.25; the metric asks 0.005 at z = 0.5: with the default
  // growth of 4 per stage the passes go through an intermediate field first (issue #7:
  // the splits of a mesh far coarser than its target cascade in every direction), and the
  // result meets the same bounds as the target at once.
  const Mesh cube = unit_cube(4);
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult staged = adapt3d(cube, linear_metric(cube, 0.005, 0.3), o);
  expect_valid_cube(staged);
  const std::vector<PassStats>& p = staged.report.passes;
  ASSERT_GE(p.size(), 3u);
  EXPECT_EQ(p.front().stage, 1);
  // The longest input edge in the target, 0.25 along z from z = 0.5 (size 0.005) to 0.25 (size
  // 0.1525): (50 − 1.64) / ln(50 / 1.64) = 14.1; ceil(ln 14.1 / ln 4) = 2 stages.
  EXPECT_EQ(p.front().stages, 2);
  EXPECT_EQ(p.back().stage, p.back().stages);
  for (std::size_t k = 1; k < p.size(); ++k) EXPECT_GE(p[k].stage, p[k - 1].stage);
  EXPECT_LT(p.front().vertices * 2, p.back().vertices) << "the first stage is far coarser";
  o.approach_growth = 0.0;
  const Adapt3dResult direct = adapt3d(cube, linear_metric(cube, 0.005, 0.3), o);
  expect_valid_cube(direct);
  EXPECT_EQ(direct.report.passes.front().stages, 0);
  // Measured: staged 94.8% in band, lengths 0.571..1.593, q_min 0.573, 3711 tets; direct 95.6%,
  // 0.503..1.436, 0.570, 3740 tets (2026-12-05, with the sliver optimiser's compass search; before:
  // staged 95.9%, 0.584..1.498, 0.551; direct 95.5%, 0.538..1.475, 0.564).
  for (const Adapt3dResult* r : {&staged, &direct}) {
    const PassStats& s = r->report.passes.back();
    EXPECT_GT(s.len_in, 0.94);
    EXPECT_GT(s.len_min, 0.5);
    EXPECT_LT(s.len_max, 1.6);
    EXPECT_GT(s.q_min, 0.5);
  }
  // Near its target already: one stage, no intermediate field.
  const Adapt3dResult again = adapt3d(staged.mesh, staged.metrics, {});
  EXPECT_EQ(again.report.passes.front().stages, 0);
}

// The vertices created by the split sweeps renumbered for locality (Adapt3dOptions::
// renumber_after, 65,536 by default, here 300 to renumber a small case several times, the
// memos, collapse candidates and neighbour table following): the same bounds as without, and
// deterministic. Measured: 96.3% in band / lengths 0.578..1.490 / q_min 0.557 with, 96.3% /
// 0.601..1.438 / 0.568 without (linear metric, h0 = 0.02, ~2,290 tets).
TEST(Adapt3d, RenumberingTheNewVerticesKeepsTheBounds) {
  const Mesh cube = unit_cube(4);
  Adapt3dOptions o;
  o.hgrad = 0.0;
  o.renumber_after = 300;
  const Adapt3dResult a = adapt3d(cube, linear_metric(cube, 0.02, 0.25), o);
  const Adapt3dResult again = adapt3d(cube, linear_metric(cube, 0.02, 0.25), o);
  o.renumber_after = SIZE_MAX;
  const Adapt3dResult never = adapt3d(cube, linear_metric(cube, 0.02, 0.25), o);
  expect_valid_cube(a);
  EXPECT_EQ(a.mesh.coords, again.mesh.coords);
  EXPECT_EQ(a.mesh.tets, again.mesh.tets);
  EXPECT_NE(a.mesh.tets, never.mesh.tets);  // renumbered: swept in another order
  for (const Adapt3dResult* r : {&a, &never}) {
    const PassStats& s = r->report.passes.back();
    EXPECT_GT(s.len_in, 0.93);
    EXPECT_GT(s.len_min, 0.5);
    EXPECT_LT(s.len_max, 1.6);
    EXPECT_GT(s.q_min, 0.5);
  }
}

TEST(Adapt3d, TakingOverTheInputGivesTheSameMesh) {
  const Mesh cube = unit_cube(3);
  const std::vector<SymMat3> metrics = linear_metric(cube, 0.05, 0.3);
  Adapt3dOptions o;
  const Adapt3dResult a = adapt3d(cube, metrics, o);
  Mesh moved = cube;
  const Adapt3dResult b = adapt3d(std::move(moved), metrics, o);
  EXPECT_GT(b.mesh.num_tets(), cube.num_tets());
  EXPECT_EQ(a.mesh.coords, b.mesh.coords);
  EXPECT_EQ(a.mesh.tets, b.mesh.tets);
  EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
  EXPECT_EQ(a.mesh.tri_ref, b.mesh.tri_ref);
  EXPECT_EQ(a.metrics.size(), b.metrics.size());
  // Taking over the metrics too (the CLI's call), with and without gradation (the full
  // adjacency is only built for it), and on a mesh whose faces carry many distinct refs.
  // (300 boundary triangles, each its own ref: more than the TetMesh's one-byte ref table.)
  Mesh many = unit_cube(5);
  for (std::size_t f = 0; f < many.num_triangles(); ++f) many.tri_ref[f] = 7 + static_cast<int>(f);
  const std::vector<SymMat3> many_metrics = linear_metric(many, 0.05, 0.3);
  for (const auto& [input, m, hgrad] : {std::tuple{&cube, &metrics, 0.0},
                                        std::tuple{&cube, &metrics, 1.3},
                                        std::tuple{static_cast<const Mesh*>(&many), &many_metrics, 0.0}}) {
    o.hgrad = hgrad;
    const Adapt3dResult c = adapt3d(*input, *m, o);
    Mesh moved_mesh = *input;
    std::vector<SymMat3> moved_metrics = *m;
    const Adapt3dResult d = adapt3d(std::move(moved_mesh), std::move(moved_metrics), o);
    EXPECT_GT(d.mesh.num_tets(), input->num_tets());
    EXPECT_EQ(c.mesh.coords, d.mesh.coords);
    EXPECT_EQ(c.mesh.tets, d.mesh.tets);
    EXPECT_EQ(c.mesh.tet_ref, d.mesh.tet_ref);
    EXPECT_EQ(c.mesh.triangles, d.mesh.triangles);
    EXPECT_EQ(c.mesh.tri_ref, d.mesh.tri_ref);
    EXPECT_EQ(c.mesh.edges, d.mesh.edges);
    ASSERT_EQ(c.metrics.size(), d.metrics.size());
    for (std::size_t v = 0; v < c.metrics.size(); ++v)
      for (int k = 0; k < 6; ++k) EXPECT_EQ(c.metrics[v].c[k], d.metrics[v].c[k]);
  }
}

TEST(Adapt3d, KeepSurfaceLeavesTheBoundaryAsGiven) {
  const Mesh cube = unit_cube(3);
  Adapt3dOptions o;
  o.keep_surface = true;
  o.hgrad = 0.0;
  o.max_passes = 4;
  const Adapt3dResult r =
      adapt3d(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(0.15)), o);
  expect_valid_cube(r);
  EXPECT_EQ(r.mesh.num_triangles(), cube.num_triangles());
}

TEST(Adapt3d, RidgeEdgesKeepTheirRefs) {
  const Mesh cube = unit_cube(2);
  Adapt3dOptions o;
  const Adapt3dResult r =
      adapt3d(cube, std::vector<SymMat3>(cube.num_vertices(), isotropic_metric<3>(0.2)), o);
  // The 12 cube edges come back as ridge Edges, refined, with the input refs 1..12.
  std::map<int, double> len;
  for (std::size_t e = 0; e < r.mesh.num_edges(); ++e) {
    const Id a = r.mesh.edges[2 * e], b = r.mesh.edges[2 * e + 1];
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += std::pow(r.mesh.coords[3 * a + k] - r.mesh.coords[3 * b + k], 2);
    len[r.mesh.edge_ref[e]] += std::sqrt(d2);
  }
  ASSERT_EQ(len.size(), 12u);
  for (const auto& [ref, l] : len) {
    EXPECT_GE(ref, 1);
    EXPECT_LE(ref, 12);
    EXPECT_NEAR(l, 1.0, 1e-12);
  }
  EXPECT_GT(r.mesh.num_edges(), cube.num_edges());
}

// Errors about the input name its own ids, not those of the renumbered copy the remesher uses.
TEST(Adapt3d, InvertedTetNamedByItsInputId) {
  const Mesh cube = unit_cube(3);
  for (const std::size_t t : {std::size_t{7}, std::size_t{100}}) {
    Mesh inverted = cube;
    std::swap(inverted.tets[4 * t], inverted.tets[4 * t + 1]);
    try {
      adapt3d(inverted, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()), {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("tetrahedron " + std::to_string(t + 1) + " ", 0), 0u)
          << e.what();
    }
  }
}

TEST(Adapt3d, BadMetricNamedByItsInputVertex) {
  const Mesh cube = unit_cube(3);
  for (const std::size_t v : {std::size_t{5}, std::size_t{40}}) {
    std::vector<SymMat3> metrics(cube.num_vertices(), SymMat3::identity());
    metrics[v].at(2, 2) = -1.0;
    try {
      adapt3d(cube, metrics, {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("vertex " + std::to_string(v + 1) + ":", 0), 0u)
          << e.what();
    }
  }
}

TEST(Adapt3d, BadInputIsRefused) {
  const Mesh cube = unit_cube(2);
  std::vector<SymMat3> metrics(cube.num_vertices(), SymMat3::identity());
  metrics[5].at(2, 2) = -1.0;
  EXPECT_THROW(adapt3d(cube, metrics, {}), InputError);
  metrics.pop_back();
  EXPECT_THROW(adapt3d(cube, metrics, {}), InputError);
  Mesh inverted = cube;
  std::swap(inverted.tets[0], inverted.tets[1]);
  EXPECT_THROW(adapt3d(inverted, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()), {}),
               InputError);
  // Sizes 1e-102 at one vertex: the metric asks for more vertices than 32-bit ids hold.
  metrics.assign(cube.num_vertices(), SymMat3::identity());
  metrics[5] = SymMat3::diagonal(1e204);
  EXPECT_THROW(adapt3d(cube, metrics, {}), InputError);
  // A listed triangle that is no tet face was dropped silently, its ref with it.
  Mesh stray = cube;
  stray.triangles.insert(stray.triangles.end(), {0, 4, 26});  // across the cube: no tet face
  stray.tri_ref.push_back(7);
  stray.tri_tag.push_back(0);
  try {
    adapt3d(stray, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()), {});
    ADD_FAILURE() << "a stray triangle was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("(ref 7) is no face of any tetrahedron"),
              std::string::npos)
        << e.what();
  }
  const Mesh square = unit_square(2, 2);
  EXPECT_THROW(adapt3d(square, std::vector<SymMat3>(square.num_vertices(), SymMat3::identity()), {}),
               InputError);
  Adapt3dOptions o;
  o.hgrad = 0.5;
  EXPECT_THROW(adapt3d(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()), o),
               InputError);
  o.hgrad = 1.3;
  for (const double g : {0.5, 1.0, -1.0, std::nan("")}) {
    o.approach_growth = g;
    EXPECT_THROW(adapt3d(cube, std::vector<SymMat3>(cube.num_vertices(), SymMat3::identity()), o),
                 InputError);
  }
}

namespace {

/// unit_cube(n) cut into two subdomains at x = 0.5 (tet refs 1 and 2), with the interface's
/// triangles listed with ref 10 when `listed`.
Mesh two_subdomains(int n, bool listed) {
  Mesh m = unit_cube(n);
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    double x = 0.0;
    for (int i = 0; i < 4; ++i) x += m.coords[3 * static_cast<std::size_t>(m.tets[4 * t + i])] / 4;
    m.tet_ref[t] = x < 0.5 ? 1 : 2;
  }
  if (!listed) return m;
  // The faces of the x < 0.5 tets whose three vertices are at x = 0.5.
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    if (m.tet_ref[t] != 1) continue;
    const Id* v = &m.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      Id f[3];
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i) f[k++] = v[j];
      bool mid = true;
      for (const Id w : f) mid = mid && m.coords[3 * static_cast<std::size_t>(w)] == 0.5;
      if (!mid) continue;
      m.triangles.insert(m.triangles.end(), {f[0], f[1], f[2]});
      m.tri_ref.push_back(10);
      m.tri_tag.push_back(0);
    }
  }
  return m;
}

std::map<int, double> volume_by_ref(const Mesh& m) {
  std::map<int, double> out;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) {
      const Id v = m.tets[4 * t + k];
      p[k] = Vec3{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
    }
    out[m.tet_ref[t]] += dot(cross(p[1] - p[0], p[2] - p[0]), p[3] - p[0]) / 6.0;
  }
  return out;
}

/// The edges of ref `ref`'s outline (on one triangle of that ref): their count and the longest.
std::pair<std::size_t, double> interface_outline(const Mesh& m, int ref) {
  std::map<std::pair<Id, Id>, int> on;
  for (std::size_t f = 0; f < m.num_triangles(); ++f)
    for (int k = 0; m.tri_ref[f] == ref && k < 3; ++k) {
      const Id p = m.triangles[3 * f + k], q = m.triangles[3 * f + (k + 1) % 3];
      ++on[{std::min(p, q), std::max(p, q)}];
    }
  double longest = 0.0;
  std::size_t outline = 0;
  for (const auto& [e, count] : on) {
    if (count != 1) continue;
    ++outline;
    double l2 = 0.0;
    for (int i = 0; i < 3; ++i)
      l2 += std::pow(m.coords[3 * e.first + i] - m.coords[3 * e.second + i], 2);
    longest = std::max(longest, std::sqrt(l2));
  }
  return {outline, longest};
}

}  // namespace

// Interfaces between subdomains are kept as given. Listed: their ref was taken for a curved
// patch with no outer face, and every gmsh multi-volume mesh was refused ("surface analysis
// needs a surface mesh"). Not listed: tets changed subdomain across them; now they are kept
// and written with the ref after the largest listed one (7 here).
TEST(Adapt3d, SubdomainInterfacesAreKept) {
  for (const bool listed : {true, false}) {
    const Mesh in = two_subdomains(4, listed);
    const std::vector<SymMat3> metrics(in.num_vertices(), isotropic_metric<3>(0.12));
    Adapt3dOptions o;
    o.hgrad = 0.0;
    const Adapt3dResult r = adapt3d(in, metrics, o);
    const std::string name = listed ? "listed" : "unlisted";
    EXPECT_TRUE(check_mesh(r.mesh).valid()) << name;
    EXPECT_GT(r.mesh.num_tets(), 4 * in.num_tets()) << name;
    const std::map<int, double> v = volume_by_ref(r.mesh);
    ASSERT_EQ(v.size(), 2u) << name;
    EXPECT_NEAR(v.at(1), 0.5, 1e-12) << name;
    EXPECT_NEAR(v.at(2), 0.5, 1e-12) << name;
    const std::map<int, double> a = area_by_ref(r.mesh);
    const int interface = listed ? 10 : 7;
    ASSERT_TRUE(a.count(interface)) << name;
    EXPECT_NEAR(a.at(interface), 1.0, 1e-12) << name;
  }
}

// Sizes finer than the interface near it. Kept as given, splits strung vertices along its flat
// facets (two gmsh cubes: 42% of the tets below quality 0.1, q min 7e-6, edges of 1.7e-6) and
// then got the kept surface's quality floor, with a note. A planar interface is now remeshed like
// a planar patch: its edges follow the sizes, its faces stay listed between the two regions.
TEST(Adapt3d, FineSizesAtAPlanarInterface) {
  const Mesh in = two_subdomains(4, true);
  std::vector<SymMat3> metrics;
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    metrics.push_back(isotropic_metric<3>(std::abs(in.coords[3 * v] - 0.5) < 0.2 ? 0.06 : 0.2));
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult r = adapt3d(in, metrics, o);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  double q_min = 1.0;
  for (std::size_t t = 0; t < r.mesh.num_tets(); ++t) {
    Vec3 p[4];
    for (int k = 0; k < 4; ++k) {
      const Id v = r.mesh.tets[4 * t + static_cast<std::size_t>(k)];
      p[k] = Vec3{{r.mesh.coords[3 * v], r.mesh.coords[3 * v + 1], r.mesh.coords[3 * v + 2]}};
    }
    q_min = std::min(q_min, quality<3>(SymMat3::identity(), p));
  }
  // The interface (ref 10): still the plane x = 0.5 and of area 1, its edges near 0.06.
  std::size_t faces = 0;
  double longest = 0.0;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t) {
    if (r.mesh.tri_ref[t] != 10) continue;
    ++faces;
    for (int k = 0; k < 3; ++k) {
      const Id a = r.mesh.triangles[3 * t + k], b = r.mesh.triangles[3 * t + (k + 1) % 3];
      EXPECT_NEAR(r.mesh.coords[3 * a], 0.5, 1e-12);
      double l2 = 0.0;
      for (int i = 0; i < 3; ++i)
        l2 += std::pow(r.mesh.coords[3 * a + i] - r.mesh.coords[3 * b + i], 2);
      longest = std::max(longest, std::sqrt(l2));
    }
  }
  std::printf(
      "planar interface, sizes 0.06 at it: %zu tets, q min %.3g, %zu interface faces "
      "(input %d), longest edge %.3g\n",
      r.mesh.num_tets(), q_min, faces, 2 * 4 * 4, longest);
  EXPECT_NEAR(area_by_ref(r.mesh).at(10), 1.0, 1e-12);
  const std::map<int, double> v = volume_by_ref(r.mesh);
  EXPECT_NEAR(v.at(1), 0.5, 1e-12);
  EXPECT_NEAR(v.at(2), 0.5, 1e-12);
  EXPECT_GT(faces, 10u * 32u);  // (1 / 0.06)^2 * 2 / sqrt(3) ~ 320 for unit triangles
  EXPECT_LT(longest, 0.06 * 1.8);
  EXPECT_GT(q_min, 0.3);
  for (const std::string& n : r.report.notes)
    EXPECT_EQ(n.find("interfaces between subdomains"), std::string::npos) << n;
}

// An interface written with 10 significant digits is off its plane by ~1e-10: it was taken for
// curved and kept as given. So was the whole of two boxes turned off the axes and written with 7
// significant digits (%.7g): every slanted face off the plane of its first triangle by ~1e-7.
// Planes are fitted to all their faces and hold their vertices within 1e-6 of the diagonal
// (plane_fit.hpp).
TEST(Adapt3d, InterfaceRoundedToTenDigitsIsRemeshed) {
  Mesh ten = two_subdomains(4, true);
  int k = 0;
  for (std::size_t v = 0; v < ten.num_vertices(); ++v)
    if (ten.coords[3 * v] == 0.5) ten.coords[3 * v] += (k++ % 2 ? 1 : -1) * 3e-10;
  Mesh seven = two_subdomains(4, true);
  const double c = std::cos(0.5), s = std::sin(0.5), c2 = std::cos(0.3), s2 = std::sin(0.3);
  for (std::size_t v = 0; v < seven.num_vertices(); ++v) {
    double* p = &seven.coords[3 * v];
    const double x = c * p[0] - s * p[1], y = s * p[0] + c * p[1], z = p[2];
    const double q[3] = {x, c2 * y - s2 * z, s2 * y + c2 * z};
    for (int i = 0; i < 3; ++i) {
      char digits[32];
      std::snprintf(digits, sizeof digits, "%.7g", q[i]);
      p[i] = std::strtod(digits, nullptr);
    }
  }
  for (const Mesh* in : {&ten, &seven}) {
    Adapt3dOptions o;
    o.hgrad = 0.0;
    const Adapt3dResult r =
        adapt3d(*in, std::vector<SymMat3>(in->num_vertices(), isotropic_metric<3>(0.1)), o);
    const std::string name = in == &ten ? "10 digits" : "7 digits, turned";
    EXPECT_TRUE(check_mesh(r.mesh).valid()) << name;
    const auto faces = [](const Mesh& m) {
      return std::count(m.tri_ref.begin(), m.tri_ref.end(), 10);
    };
    EXPECT_GT(faces(r.mesh), 5 * faces(*in)) << name;
    EXPECT_TRUE(r.report.notes.empty()) << name;
  }
}

// Two solids as gmsh writes them: each with its own outer faces (refs 3..6 split at x = 0.5 into
// r and r + 20) and the interface between them. The line where the interface meets the outer
// faces lies on three refs; its vertices were fixed (and the interface kept as given). It is a
// ridge of the interface and the outer plane: refined, the refs' areas kept, also in an
// anisotropic field across the interface.
TEST(Adapt3d, InterfaceMeetingSplitOuterFacesIsRemeshed) {
  Mesh in = two_subdomains(4, true);
  for (std::size_t f = 0; f < in.num_triangles(); ++f) {
    if (in.tri_ref[f] < 3 || in.tri_ref[f] > 6) continue;
    double x = 0.0;
    for (int k = 0; k < 3; ++k)
      x += in.coords[3 * static_cast<std::size_t>(in.triangles[3 * f + k])] / 3;
    if (x > 0.5) in.tri_ref[f] += 20;
  }
  for (const bool aniso : {false, true}) {
    std::vector<SymMat3> metrics;
    for (std::size_t v = 0; v < in.num_vertices(); ++v) {
      const double hx = aniso ? 0.01 + 0.2 * std::abs(in.coords[3 * v] - 0.5) : 0.1;
      metrics.push_back(SymMat3::diagonal(Vec3{{1 / (hx * hx), 100.0, 100.0}}));
    }
    Adapt3dOptions o;
    o.hgrad = 0.0;
    const Adapt3dResult r = adapt3d(in, metrics, o);
    const std::string name = aniso ? "anisotropic" : "isotropic";
    EXPECT_TRUE(check_mesh(r.mesh).valid()) << name;
    const std::map<int, double> a = area_by_ref(r.mesh);
    EXPECT_NEAR(a.at(10), 1.0, 1e-12) << name;
    for (const int ref : {3, 4, 5, 6}) {
      EXPECT_NEAR(a.at(ref), 0.5, 1e-12) << name << " ref " << ref;
      EXPECT_NEAR(a.at(ref + 20), 0.5, 1e-12) << name << " ref " << ref + 20;
    }
    const std::map<int, double> v = volume_by_ref(r.mesh);
    EXPECT_NEAR(v.at(1), 0.5, 1e-12) << name;
    EXPECT_NEAR(v.at(2), 0.5, 1e-12) << name;
    // The interface's outline: input 4 per side of 0.25.
    const auto [outline, longest] = interface_outline(r.mesh, 10);
    std::printf("%s: %zu tets, interface outline %zu edges, longest %.3g, notes %zu\n",
                name.c_str(), r.mesh.num_tets(), outline, longest, r.report.notes.size());
    EXPECT_GE(outline, 32u) << name;  // 4 sides of 1 at 0.1
    EXPECT_LT(longest, 0.1 * 1.6) << name;
    EXPECT_TRUE(r.report.notes.empty()) << name;
  }
}

// The same with every outer face of one ref (a "wall" physical group, as gmsh users write it):
// that ref, on six planes, was taken for one curved patch, so the interface's rim (on a curved
// patch and an interface at once) was fixed and the interface kept as given: rim edges 2.5 long
// in the metric, no note. Its planar pieces, joined at sharp edges only, are planar patches now
// (planar_pieces3d.hpp) and the rim a ridge; the output has the given refs.
TEST(Adapt3d, InterfaceMeetingOneWallRefIsRemeshed) {
  Mesh in = two_subdomains(4, true);
  for (std::int32_t& ref : in.tri_ref)
    if (ref != 10) ref = 1;
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult r =
      adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(0.1)), o);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  const std::map<int, double> a = area_by_ref(r.mesh);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_NEAR(a.at(1), 6.0, 1e-12);
  EXPECT_NEAR(a.at(10), 1.0, 1e-12);
  const std::map<int, double> v = volume_by_ref(r.mesh);
  EXPECT_NEAR(v.at(1), 0.5, 1e-12);
  EXPECT_NEAR(v.at(2), 0.5, 1e-12);
  const auto [outline, longest] = interface_outline(r.mesh, 10);
  EXPECT_GE(outline, 32u);
  EXPECT_LT(longest, 0.1 * 1.6);
  EXPECT_TRUE(r.report.notes.empty());
  // No ref changes along the outer boundary, but the cube's 12 Edges (refs 1..12, now inside
  // the one wall ref) come back whole with their refs (QA hunt 6 G2: they were dropped).
  std::map<int, double> edge_length;
  for (std::size_t e = 0; e < r.mesh.num_edges(); ++e) {
    const Id p = r.mesh.edges[2 * e], q = r.mesh.edges[2 * e + 1];
    double d2 = 0;
    for (int k = 0; k < 3; ++k)
      d2 += std::pow(r.mesh.coords[3 * p + k] - r.mesh.coords[3 * q + k], 2);
    edge_length[r.mesh.edge_ref[e]] += std::sqrt(d2);
  }
  EXPECT_EQ(edge_length.size(), 12u);
  for (const auto& [ref, l] : edge_length) EXPECT_NEAR(l, 1.0, 1e-12) << "edge ref " << ref;
  // Every boundary vertex still on the cube's surface.
  for (std::size_t f = 0; f < r.mesh.num_triangles(); ++f) {
    if (r.mesh.tri_ref[f] != 1) continue;
    for (int k = 0; k < 3; ++k) {
      const double* p = &r.mesh.coords[3 * static_cast<std::size_t>(r.mesh.triangles[3 * f + k])];
      double gap = 1.0;
      for (int i = 0; i < 3; ++i) gap = std::min({gap, std::abs(p[i]), std::abs(p[i] - 1.0)});
      EXPECT_LT(gap, 1e-12);
    }
  }
}

// Four subdomains around the line x = y = 0.5 (four planar interfaces meeting there, as gmsh's
// 2 x 2 boxes): the line's vertices were fixed, its edges kept at the input's 0.25, and an
// anisotropic field strung vertices within 1e-5 of it (tets of quality 1e-7). It is a ridge.
TEST(Adapt3d, LineWhereFourInterfacesMeetIsRefined) {
  const Mesh in = test::with_regions(
      unit_cube(4), [](const Vec3& c) { return 1 + (c[0] > 0.5 ? 1 : 0) + (c[1] > 0.5 ? 2 : 0); });
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult r =
      adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(0.1)), o);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  const std::map<int, double> v = volume_by_ref(r.mesh), a = area_by_ref(r.mesh);
  for (const int ref : {1, 2, 3, 4}) EXPECT_NEAR(v.at(ref), 0.25, 1e-12) << ref;
  for (const int ref : {12, 13, 24, 34}) EXPECT_NEAR(a.at(ref), 0.5, 1e-12) << ref;
  double longest = 0.0;  // of the edges on the line x = y = 0.5
  std::size_t on_line = 0;
  for (std::size_t t = 0; t < r.mesh.num_tets(); ++t)
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const Id p = r.mesh.tets[4 * t + i], q = r.mesh.tets[4 * t + j];
        const double* x = &r.mesh.coords[3 * static_cast<std::size_t>(p)];
        const double* y = &r.mesh.coords[3 * static_cast<std::size_t>(q)];
        if (x[0] != 0.5 || x[1] != 0.5 || y[0] != 0.5 || y[1] != 0.5) continue;
        ++on_line;
        longest = std::max(longest, std::abs(x[2] - y[2]));
      }
  std::printf("four interfaces: %zu tets, %zu tet edges on the line, longest %.3g, notes %zu\n",
              r.mesh.num_tets(), on_line, longest, r.report.notes.size());
  EXPECT_LT(longest, 0.1 * 1.6);
  EXPECT_TRUE(r.report.notes.empty());
}

// A planar interface across the unit ball (x = 0) meets the curved sphere along a circle that
// cannot move with the sphere's reconstruction: the interface is kept as given as a whole, with
// the kept surface's floor and a note (remeshed up to its fixed rim, vertices piled up there).
TEST(Adapt3d, PlanarInterfaceMeetingACurvedPatchIsKept) {
  const Mesh in =
      test::with_regions(test::unit_ball(4), [](const Vec3& c) { return c[0] > 0.0 ? 2 : 1; });
  Adapt3dOptions o;
  o.hgrad = 0.0;
  const Adapt3dResult r =
      adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(0.12)), o);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  const std::map<int, double> a = area_by_ref(r.mesh), a0 = area_by_ref(in);
  EXPECT_NEAR(a.at(12), a0.at(12), 1e-12);  // the same triangles
  std::size_t faces = 0;
  for (const int ref : r.mesh.tri_ref) faces += ref == 12;
  EXPECT_EQ(faces, static_cast<std::size_t>(std::count(in.tri_ref.begin(), in.tri_ref.end(), 12)));
  bool noted = false;
  for (const std::string& n : r.report.notes)
    noted |= n.find("curved interfaces between subdomains keep edges up to") != std::string::npos;
  EXPECT_TRUE(noted);
}

// Coplanar planar patches of different refs (the outer faces of a gmsh multi-volume box): the
// line between them had no direction from the planes, its vertices stayed fixed and its edges
// at the input's length (4x --hsiz, the passes thrashing around it). It is a straight ridge.
TEST(Adapt3d, LineBetweenCoplanarPatchesIsRefined) {
  Mesh in = unit_cube(4);
  for (std::size_t t = 0; t < in.num_triangles(); ++t) {
    double x = 0.0, z = 0.0;
    for (int k = 0; k < 3; ++k) {
      x += in.coords[3 * static_cast<std::size_t>(in.triangles[3 * t + k])] / 3.0;
      z = std::max(z,
                   std::abs(in.coords[3 * static_cast<std::size_t>(in.triangles[3 * t + k]) + 2]));
    }
    if (z == 0.0 && x < 0.5) in.tri_ref[t] = 77;  // the face z = 0 in two patches
  }
  in.edges.clear(), in.edge_ref.clear(), in.edge_tag.clear();
  const double h = 0.06;
  const std::vector<SymMat3> metrics(in.num_vertices(), isotropic_metric<3>(h));
  const Adapt3dResult r = adapt3d(in, metrics, {});
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  double longest = 0.0;
  int on_line = 0;
  for (std::size_t t = 0; t < r.mesh.num_triangles(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Id a = r.mesh.triangles[3 * t + k], b = r.mesh.triangles[3 * t + (k + 1) % 3];
      const double* p = &r.mesh.coords[3 * static_cast<std::size_t>(a)];
      const double* q = &r.mesh.coords[3 * static_cast<std::size_t>(b)];
      if (p[0] != 0.5 || q[0] != 0.5 || p[2] != 0.0 || q[2] != 0.0) continue;
      ++on_line;
      longest = std::max(longest, std::abs(q[1] - p[1]));
    }
  std::printf("line between coplanar patches: longest edge %.3f for size %.3f\n", longest, h);
  EXPECT_GT(on_line, 0);
  EXPECT_LT(longest, 1.6 * h);
}

// --nosurf with sizes far finer than the surface: the run cannot follow them along it, and
// says why (it ran its passes without a word).
TEST(Adapt3d, KeptSurfaceCoarserThanTheSizesIsNoted) {
  const Mesh in = unit_cube(2);
  Adapt3dOptions o;
  o.keep_surface = true;
  o.max_passes = 2;
  const Adapt3dResult r =
      adapt3d(in, std::vector<SymMat3>(in.num_vertices(), isotropic_metric<3>(0.1)), o);
  bool noted = false;
  for (const std::string& n : r.report.notes)
    noted |= n.find("the surface is kept as given") != std::string::npos;
  EXPECT_TRUE(noted);
}
