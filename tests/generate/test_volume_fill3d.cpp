// Interior points of a volume meshed from its boundary: sizes from the boundary edges, and the
// filled mesh valid, of the same volume, with the recovered boundary kept and determinism.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "core/error.hpp"
#include "generate/boundary_recovery3d.hpp"
#include "generate/volume_fill3d.hpp"
#include "mesh/check.hpp"
#include "mesh/distance.hpp"
#include "metric/mesh_quality.hpp"
#include "remesh/surface_adapt.hpp"
#include "remesh/surface_test_meshes.hpp"

namespace riemesh {
namespace {

double tet_volume_sum(const Mesh& m) {
  double s = 0.0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    double p[4][3];
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c) p[i][c] = m.coords[3 * static_cast<std::size_t>(m.tets[4 * t + i]) + c];
    double a[3], b[3], d[3];
    for (int c = 0; c < 3; ++c) {
      a[c] = p[1][c] - p[0][c];
      b[c] = p[2][c] - p[0][c];
      d[c] = p[3][c] - p[0][c];
    }
    s += (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
          a[2] * (b[0] * d[1] - b[1] * d[0])) / 6.0;
  }
  return s;
}

std::set<std::array<double, 3>> boundary_points(const Mesh& m) {
  std::set<std::array<double, 3>> out;
  for (Id v : m.triangles) {
    const auto k = 3 * static_cast<std::size_t>(v);
    out.insert({m.coords[k], m.coords[k + 1], m.coords[k + 2]});
  }
  return out;
}

TEST(VolumeFill3d, BoundarySizesAreTheMeanEdgeLengths) {
  const RecoveredVolume r = recover_volume(test::cube_surface(4));
  const std::vector<double> h = boundary_sizes(r.volume);
  ASSERT_EQ(h.size(), r.volume.num_vertices());
  for (double x : h) {
    EXPECT_GE(x, 0.125 - 1e-12);  // Steiner points halve some edges of the 0.25 grid
    EXPECT_LE(x, 0.25 * std::sqrt(2.0) + 1e-12);
  }
}

TEST(VolumeFill3d, FilledCubeIsValidAndKeepsItsBoundary) {
  const RecoveredVolume r = recover_volume(test::cube_surface(3));
  const auto before = boundary_points(r.volume);
  Adapt3dOptions o;
  Mesh copy = r.volume;
  const Adapt3dResult f = fill_volume(std::move(copy), 0.25, o);
  EXPECT_TRUE(check_mesh(f.mesh).valid());
  EXPECT_NEAR(tet_volume_sum(f.mesh), 1.0, 1e-12);
  EXPECT_EQ(boundary_points(f.mesh), before);  // the recovered boundary, unchanged
  EXPECT_EQ(f.mesh.num_triangles(), r.volume.num_triangles());
  EXPECT_GT(f.mesh.num_vertices(), r.volume.num_vertices() + 5);  // interior points
  EXPECT_GT(f.report.passes.back().q_min, 0.2);
  Mesh again = r.volume;
  const Adapt3dResult g = fill_volume(std::move(again), 0.25, o);
  EXPECT_EQ(g.mesh.coords, f.mesh.coords);
  EXPECT_EQ(g.mesh.tets, f.mesh.tets);
}

TEST(VolumeFill3d, FieldPointsAreInsideAwayFromTheSurfaceAtTheSizeSpacing) {
  const RecoveredVolume r = recover_volume(test::cube_surface(4));
  const double h = 0.1;
  // Sizes that vary (by 0.1%): the octree's jittered cell centres (a uniform size gets the
  // lattice of the next test).
  std::vector<double> sizes(r.volume.num_vertices(), h);
  for (std::size_t v = 0; v < sizes.size(); v += 2) sizes[v] = 0.999 * h;
  const FieldPoints3 f = field_points3d(r.volume, sizes);
  // Octree leaves of side 1/16 (the first ≤ 0.1 of the unit box), kept when more than 1.5 h from
  // the faces: the cells 2..13 along each axis (centres (i + ½)/16, jitter ±0.2/32).
  ASSERT_EQ(f.size(), 12u * 12u * 12u);
  ASSERT_EQ(f.coords.size(), 3 * f.size());
  const TriangleTree surface(r.volume);
  for (std::size_t k = 0; k < f.size(); ++k) {
    const Vec3 p{f.coords[3 * k], f.coords[3 * k + 1], f.coords[3 * k + 2]};
    for (int c = 0; c < 3; ++c) {
      EXPECT_GT(p[c], 0.0);
      EXPECT_LT(p[c], 1.0);
    }
    EXPECT_GE(surface.nearest(p).distance, 1.5 * f.sizes[k] - 1e-12);
    EXPECT_GE(f.sizes[k], 0.999 * h * (1 - 1e-12));  // interpolated inside a tet
    EXPECT_LE(f.sizes[k], h * (1 + 1e-12));
  }
  // Nearest neighbours at about the cell side (1/16, jitter ±20%).
  for (std::size_t k = 0; k < f.size(); k += 17) {
    double best = 1e300;
    for (std::size_t j = 0; j < f.size(); ++j) {
      if (j == k) continue;
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c) d2 += std::pow(f.coords[3 * k + c] - f.coords[3 * j + c], 2);
      best = std::min(best, d2);
    }
    EXPECT_GT(std::sqrt(best), 0.6 / 16);
    EXPECT_LT(std::sqrt(best), 1.4 / 16);
  }
  const FieldPoints3 again = field_points3d(r.volume, sizes);
  EXPECT_EQ(again.coords, f.coords);
}

TEST(VolumeFill3d, UniformSizeGetsTheBodyCentredCubicLattice) {
  // Spacing a = h √(6/5) from the box's corner, the points more than 1.5 h from the faces: the
  // corners i a for i = 2..7 and the centres (i + ½) a for i = 1..7 along each axis, 6³ + 7³.
  // Each point's nearest neighbours are at a √3/2, and the Delaunay tets of the lattice have
  // edges a and a √3/2 (root-mean-square h).
  const RecoveredVolume r = recover_volume(test::cube_surface(4));
  const double h = 0.1, a = h * std::sqrt(1.2);
  const std::vector<double> sizes(r.volume.num_vertices(), h);
  const FieldPoints3 f = field_points3d(r.volume, sizes);
  ASSERT_EQ(f.size(), 6u * 6u * 6u + 7u * 7u * 7u);
  const TriangleTree surface(r.volume);
  for (std::size_t k = 0; k < f.size(); ++k) {
    const Vec3 p{f.coords[3 * k], f.coords[3 * k + 1], f.coords[3 * k + 2]};
    EXPECT_GE(surface.nearest(p).distance, 1.5 * h);
    EXPECT_EQ(f.sizes[k], h);
    double best = 1e300;
    for (std::size_t j = 0; j < f.size(); ++j)
      if (j != k)
        best = std::min(best, std::hypot(f.coords[3 * k] - f.coords[3 * j],
                                         f.coords[3 * k + 1] - f.coords[3 * j + 1],
                                         f.coords[3 * k + 2] - f.coords[3 * j + 2]));
    EXPECT_NEAR(best, a * std::sqrt(0.75), 1e-12);
  }
}

TEST(VolumeFill3d, InteriorPointsAreRecoveredInside) {
  BoundaryRecoveryOptions o;
  o.interior_points = {0.5, 0.5, 0.5, 0.3, 0.6, 0.4};
  const RecoveredVolume r = recover_volume(test::cube_surface(3), o);
  EXPECT_TRUE(check_mesh(r.volume).valid());
  EXPECT_NEAR(tet_volume_sum(r.volume), 1.0, 1e-12);
  const std::size_t first = r.stats.surface_vertices;
  EXPECT_EQ(r.volume.coords[3 * first], 0.5);
  EXPECT_EQ(r.volume.coords[3 * (first + 1) + 1], 0.6);
  std::set<Id> used(r.volume.tets.begin(), r.volume.tets.end());
  EXPECT_TRUE(used.count(static_cast<Id>(first)) && used.count(static_cast<Id>(first + 1)));
  o.interior_points = {1.5, 0.5, 0.5};
  try {
    recover_volume(test::cube_surface(3), o);
    ADD_FAILURE() << "a point outside was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("interior point 1 is not inside the surface"), std::string::npos)
        << e.what();
  }
  o.interior_points = {0.5, 0.5};
  EXPECT_THROW(recover_volume(test::cube_surface(3), o), InputError);
}

TEST(VolumeFill3d, MeshVolumeFromASurface) {
  // Sizes from the boundary edges (hsiz 0): the interior matches the kept surface.
  const Mesh surface = test::cube_surface(8);
  const FilledVolume f = mesh_volume(surface, 0.0, Adapt3dOptions{});
  EXPECT_GT(f.field_points, 20u);
  EXPECT_TRUE(check_mesh(f.adapted.mesh).valid());
  EXPECT_NEAR(tet_volume_sum(f.adapted.mesh), 1.0, 1e-12);
  EXPECT_EQ(f.adapted.mesh.num_triangles(), surface.num_triangles() + 2 * f.stats.steiner());
  EXPECT_GT(f.adapted.report.passes.back().q_min, 0.4);
  const FilledVolume g = mesh_volume(surface, 0.0, Adapt3dOptions{});
  EXPECT_EQ(g.adapted.mesh.coords, f.adapted.mesh.coords);
  EXPECT_EQ(g.adapted.mesh.tets, f.adapted.mesh.tets);
}

TEST(VolumeFill3d, NearlyCocircularSquaresAreLeftToTheSliverSweeps) {
  // The cube's faces remeshed to 1/10 by the surface remesher: squares of right triangles,
  // cocircular up to rounding, so no Delaunay ties. Refining the near-flat tets between them
  // (BoundaryRecoveryOptions::refine_flat) cascades into Steiner points and leaves poor tets;
  // mesh_volume leaves them to its sliver sweeps.
  SurfaceAdaptOptions so;
  so.hsiz = 0.1;
  const Mesh surface = adapt_surface(test::cube_surface(10), so);
  const FilledVolume f = mesh_volume(surface, 0.0, Adapt3dOptions{});
  EXPECT_TRUE(check_mesh(f.adapted.mesh).valid());
  EXPECT_NEAR(tet_volume_sum(f.adapted.mesh), 1.0, 1e-9);
  EXPECT_GT(f.adapted.report.passes.back().q_min, 0.4);
  const RecoveredVolume refined = recover_volume(surface);  // refine_flat: the default
  BoundaryRecoveryOptions left;
  left.refine_flat = false;
  const RecoveredVolume flat = recover_volume(surface, left);
  EXPECT_LT(flat.stats.steiner(), refined.stats.steiner());
}

TEST(VolumeFill3d, ThinSlabGetsNoSlivers) {
  // A 1 × 1 × 0.05 box filled at size 0.1: splits of the long interior edges would put vertices
  // in the layer between the kept faces (q ~ 1e-3 and below, before the split floor).
  Mesh surface = test::cube_surface(4);
  for (std::size_t v = 0; v < surface.num_vertices(); ++v) surface.coords[3 * v + 2] *= 0.05;
  RecoveredVolume r = recover_volume(surface);
  const Adapt3dResult f = fill_volume(std::move(r.volume), 0.1, Adapt3dOptions{});
  EXPECT_TRUE(check_mesh(f.mesh).valid());
  EXPECT_NEAR(tet_volume_sum(f.mesh), 0.05, 1e-12);
  const std::vector<double> q = element_qualities(f.mesh);
  EXPECT_GT(*std::min_element(q.begin(), q.end()), 0.01);
}

/// The smallest dihedral angle of m's tetrahedra, in degrees.
double min_dihedral_degrees(const Mesh& m) {
  double best = 180.0;
  const auto at = [&](Id v) {
    const std::size_t i = 3 * static_cast<std::size_t>(v);
    return std::array<double, 3>{m.coords[i], m.coords[i + 1], m.coords[i + 2]};
  };
  const auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  const auto cross = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return std::array<double, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                 a[0] * b[1] - a[1] * b[0]};
  };
  const auto dot = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  };
  constexpr int kPairs[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (const auto& pr : kPairs) {  // edge (a, b), faces (a, b, c) and (a, b, d)
      const auto a = at(m.tets[4 * t + pr[0]]), b = at(m.tets[4 * t + pr[1]]);
      const auto e = sub(b, a);
      const auto n1 = cross(e, sub(at(m.tets[4 * t + pr[2]]), a));
      const auto n2 = cross(e, sub(at(m.tets[4 * t + pr[3]]), a));
      const double c = dot(n1, n2) / std::sqrt(dot(n1, n1) * dot(n2, n2));
      best = std::min(best, std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI);
    }
  return best;
}

/// The surface of the slab [0, 1]² × [0, z(x, y)], z = h + bump·(x(1 − x) + y(1 − y)) (a
/// slight dome), each of its 6 faces an n × n grid of squares cut in two, outward.
Mesh dome_slab(int n, double h, double bump) {
  Mesh m;
  m.dim = 3;
  std::map<std::array<double, 3>, Id> ids;
  const auto top = [&](double x, double y) { return h + bump * (x * (1 - x) + y * (1 - y)); };
  const auto vertex = [&](std::array<double, 3> p) {
    const auto [it, fresh] = ids.try_emplace(p, static_cast<Id>(ids.size()));
    if (fresh) m.coords.insert(m.coords.end(), p.begin(), p.end());
    return it->second;
  };
  const auto grid = [&](auto face, bool flip) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double u0 = double(i) / n, u1 = double(i + 1) / n, v0 = double(j) / n,
                     v1 = double(j + 1) / n;
        const Id a = vertex(face(u0, v0)), b = vertex(face(u1, v0)), c = vertex(face(u1, v1)),
                 d = vertex(face(u0, v1));
        for (const std::array<Id, 3>& t : {std::array<Id, 3>{a, b, c}, std::array<Id, 3>{a, c, d}})
          m.triangles.insert(m.triangles.end(), {t[0], flip ? t[2] : t[1], flip ? t[1] : t[2]});
      }
  };
  grid([&](double u, double v) { return std::array<double, 3>{u, v, 0.0}; }, true);
  grid([&](double u, double v) { return std::array<double, 3>{u, v, top(u, v)}; }, false);
  grid([&](double u, double v) { return std::array<double, 3>{u, 0.0, v * top(u, 0.0)}; }, false);
  grid([&](double u, double v) { return std::array<double, 3>{u, 1.0, v * top(u, 1.0)}; }, true);
  grid([&](double u, double v) { return std::array<double, 3>{0.0, u, v * top(0.0, u)}; }, true);
  grid([&](double u, double v) { return std::array<double, 3>{1.0, u, v * top(1.0, u)}; }, false);
  m.vert_ref.assign(m.num_vertices(), 0);
  m.vert_tag.assign(m.num_vertices(), kTagNone);
  m.tri_ref.assign(m.num_triangles(), 1);
  m.tri_tag.assign(m.num_triangles(), kTagNone);
  return m;
}

TEST(VolumeFill3d, KeptSurfaceSliversGetAnInteriorVertex) {
  // A 1 × 1 × 0.05 slab whose top is a slight dome (0.002 higher in the middle): tetrahedra
  // under the dome have their four vertices on the kept surface, flat, and no swap, move or
  // collapse removes them (min dihedral 0.016 degrees before star_sliver and split_sliver gave
  // them a new interior vertex, 0.68 after; the rotor's case).
  const Mesh surface = dome_slab(10, 0.05, 0.002);
  const FilledVolume f = mesh_volume(surface, 0.0, Adapt3dOptions{});
  EXPECT_TRUE(check_mesh(f.adapted.mesh).valid());
  EXPECT_GT(min_dihedral_degrees(f.adapted.mesh), 0.3);
}

TEST(VolumeFill3d, BadSizeIsAnError) {
  RecoveredVolume r = recover_volume(test::cube_surface(2));
  EXPECT_THROW(fill_volume(std::move(r.volume), -1.0, Adapt3dOptions{}), InputError);
}

}  // namespace
}  // namespace riemesh
