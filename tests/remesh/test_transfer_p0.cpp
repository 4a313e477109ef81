// Conservative P0 transfer: the clipping kernel against hand-computed overlaps, then the transfer
// by its properties: identity, nesting (exact values), constants kept, mass conserved to 1e-12 on
// unrelated meshes of the same square, domains that differ reported.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "remesh/adapt2d.hpp"
#include "remesh/polygon_clip.hpp"
#include "remesh/polyhedron_clip.hpp"
#include "remesh/transfer.hpp"

using namespace riemesh;

namespace {

Field random_p0(const Mesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 3.0);
  Field f{"rho", FieldKind::kScalar, {}};
  const std::size_t n = m.tets.empty() ? m.num_triangles() : m.num_tets();
  for (std::size_t t = 0; t < n; ++t) f.values.push_back(u(rng));
  return f;
}

double rel(double a, double b) { return std::abs(a - b) / std::max(std::abs(b), 1e-300); }

}  // namespace

TEST(PolygonClip, HandComputedOverlaps) {
  const Vec2 t[3] = {{0, 0}, {1, 0}, {0, 1}};
  EXPECT_DOUBLE_EQ(clip::overlap_area(t, t), 0.5);  // identical
  // Shifted by (0.5, 0): the overlap is the triangle (0.5,0) (1,0) (0.5,0.5), area 1/8.
  const Vec2 s[3] = {{0.5, 0}, {1.5, 0}, {0.5, 1}};
  EXPECT_NEAR(clip::overlap_area(t, s), 0.125, 1e-16);
  // Sharing the edge (1,0)-(0,1) from the other side, or only the vertex (1,0): area 0.
  const Vec2 n[3] = {{1, 0}, {1, 1}, {0, 1}};
  const Vec2 p[3] = {{1, 0}, {2, 0}, {2, 1}};
  EXPECT_EQ(clip::overlap_area(t, n), 0.0);
  EXPECT_EQ(clip::overlap_area(t, p), 0.0);
  // A triangle and its copy turned by 180° about the centroid: a hexagon of 2/3 the area
  // (the star of David removes three corner triangles of 1/9 each).
  const Vec2 c{1.0 / 3.0, 1.0 / 3.0};
  const Vec2 r[3] = {2.0 * c - t[0], 2.0 * c - t[1], 2.0 * c - t[2]};
  const clip::Polygon hex = clip::intersect_triangles(t, r);
  EXPECT_EQ(hex.n, 6);
  EXPECT_NEAR(clip::overlap_area(t, r), 0.5 * 2.0 / 3.0, 1e-15);
}

TEST(TransferP0, IdentityKeepsEveryValue) {
  const Mesh m = perturbed_unit_square(9, 7, 0.2, 1);
  const Field f = random_p0(m, 2);
  P0TransferReport r;
  const std::vector<Field> out = transfer_p0(m, {f}, m, &r);
  ASSERT_EQ(out[0].values.size(), f.values.size());
  for (std::size_t t = 0; t < f.values.size(); ++t)
    EXPECT_NEAR(out[0].values[t], f.values[t], 1e-14 * std::abs(f.values[t]) + 1e-15);
  EXPECT_EQ(r.pairs, m.num_triangles());  // neighbours only touch: no positive overlap
  EXPECT_LT(rel(r.new_integral[0], r.old_integral[0]), 1e-14);
}

TEST(TransferP0, NestedMeshesAreExact) {
  // unit_square(8, 8) refines unit_square(4, 4) with the same diagonals: every fine triangle lies
  // in one coarse triangle (coarse → fine copies its value), and each coarse triangle is four fine
  // ones (fine → coarse is their mean).
  const Mesh coarse = unit_square(4, 4), fine = unit_square(8, 8);
  const Field c = random_p0(coarse, 3);
  const std::vector<Field> down = transfer_p0(coarse, {c}, fine);
  const std::vector<Field> up = transfer_p0(fine, down, coarse);
  for (std::size_t t = 0; t < coarse.num_triangles(); ++t)
    EXPECT_NEAR(up[0].values[t], c.values[t], 1e-14);
  for (double v : down[0].values) {
    bool found = false;
    for (double w : c.values) found |= std::abs(v - w) < 1e-14;
    EXPECT_TRUE(found) << v;
  }
}

TEST(TransferP0, MassConservedOnUnrelatedMeshes) {
  const Mesh from = perturbed_unit_square(37, 23, 0.2, 4);
  for (const Mesh& to : {perturbed_unit_square(19, 41, 0.2, 5), perturbed_unit_square(60, 60, 0.2, 6)}) {
    Field f = random_p0(from, 7);
    Field w{"w", FieldKind::kVector, {}};
    for (std::size_t t = 0; t < from.num_triangles(); ++t) w.values.insert(w.values.end(), {1.0, -2.0});
    P0TransferReport r;
    const std::vector<Field> out = transfer_p0(from, {f, w}, to, &r);
    ASSERT_EQ(r.old_integral.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_LT(rel(r.new_integral[k], r.old_integral[k]), 1e-12) << k;
    EXPECT_NEAR(r.overlap_measure, 1.0, 1e-13);
    EXPECT_LT(std::abs(r.uncovered_new), 1e-13);
    EXPECT_LT(std::abs(r.uncovered_old), 1e-13);
    EXPECT_EQ(r.unmatched_elements, 0u);
    for (std::size_t t = 0; t < to.num_triangles(); ++t) {  // constants kept
      EXPECT_NEAR(out[1].values[2 * t], 1.0, 1e-14);
      EXPECT_NEAR(out[1].values[2 * t + 1], -2.0, 1e-14);
    }
  }
}

TEST(TransferP0, MassConservedOntoAnAdaptedMesh) {
  const Mesh from = perturbed_unit_square(30, 30, 0.2, 8);
  // An anisotropic unit mesh of the square by riemesh's own remesher.
  const std::vector<SymMat2> met(from.num_vertices(), SymMat2{{900.0, 300.0, 4000.0}});
  const Mesh to = adapt2d(from, met, {}).mesh;
  const Field f = random_p0(from, 9);
  P0TransferReport r;
  const std::vector<Field> there = transfer_p0(from, {f}, to, &r);
  EXPECT_LT(rel(r.new_integral[0], r.old_integral[0]), 1e-12);
  P0TransferReport back_r;
  transfer_p0(to, there, from, &back_r);
  EXPECT_LT(rel(back_r.new_integral[0], r.old_integral[0]), 1e-12);
}

TEST(TransferP0, DifferentDomainsAreReported) {
  const Mesh from = unit_square(10, 10);
  Mesh wider = unit_square(12, 10);  // [0, 1.1] × [0, 1]
  for (std::size_t v = 0; v < wider.num_vertices(); ++v) wider.coords[2 * v] *= 1.1;
  const Field one{"one", FieldKind::kScalar, std::vector<double>(from.num_triangles(), 2.0)};
  P0TransferReport r;
  const std::vector<Field> out = transfer_p0(from, {one}, wider, &r);
  EXPECT_NEAR(r.uncovered_new, 0.1, 1e-12);
  EXPECT_NEAR(r.uncovered_old, 0.0, 1e-12);
  EXPECT_EQ(r.unmatched_elements, 20u);  // the last column of cells lies beyond x = 1
  for (double v : out[0].values) EXPECT_NEAR(v, 2.0, 1e-13);  // the mean over the covered part
  // Back: the old mesh's part beyond x = 1 is lost, and the report says how much.
  const std::vector<Field> back = transfer_p0(wider, out, from, &r);
  EXPECT_NEAR(r.uncovered_old, 0.1, 1e-12);
  EXPECT_NEAR(r.old_integral[0] - r.new_integral[0], 2.0 * 0.1, 1e-12);
}

TEST(PolyhedronClip, HandComputedOverlaps) {
  const Vec3 t[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_NEAR(clip::overlap_volume(t, t), 1.0 / 6.0, 1e-16);
  // Shifted by (0.5, 0, 0): the overlap is t scaled by 1/2 about (1, 0, 0), volume 1/48.
  const Vec3 s[4] = {{0.5, 0, 0}, {1.5, 0, 0}, {0.5, 1, 0}, {0.5, 0, 1}};
  EXPECT_NEAR(clip::overlap_volume(t, s), 1.0 / 48.0, 1e-16);
  // Across the face x + y + z = 1 (the reflection of the origin through it): 0 up to round-off
  // (the piece is the shared face, two faces only, which the transfer does not count); apart: 0.
  const Vec3 r[4] = {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {2.0 / 3, 2.0 / 3, 2.0 / 3}};
  EXPECT_NEAR(clip::overlap_volume(t, r), 0.0, 1e-16);
  EXPECT_LT(clip::intersect_tetrahedra(t, r).n, 4);
  const Vec3 far[4] = {{3, 0, 0}, {4, 0, 0}, {3, 1, 0}, {3, 0, 1}};
  EXPECT_EQ(clip::overlap_volume(t, far), 0.0);
  // A tetrahedron inside the unit cube against the six Kuhn tetrahedra of the cube: the overlaps
  // add up to its volume (each piece found once).
  const Mesh cube = unit_cube(1);
  const Vec3 q[4] = {{0.1, 0.2, 0.15}, {0.9, 0.3, 0.2}, {0.4, 0.8, 0.3}, {0.5, 0.4, 0.95}};
  double sum = 0.0;
  for (std::size_t k = 0; k < cube.num_tets(); ++k) {
    Vec3 y[4];
    for (int i = 0; i < 4; ++i)
      for (int a = 0; a < 3; ++a) y[i][a] = cube.coords[3 * cube.tets[4 * k + i] + a];
    sum += clip::overlap_volume(q, y);
  }
  const double vol = std::abs(dot(q[1] - q[0], cross(q[2] - q[0], q[3] - q[0]))) / 6.0;
  EXPECT_NEAR(sum, vol, 1e-15);
}

TEST(TransferP0, TetrahedraIdentityAndMass) {
  const Mesh a = perturbed_unit_cube(5, 0.1, 11), b = perturbed_unit_cube(7, 0.1, 12);
  const Field f = random_p0(a, 13);
  P0TransferReport r;
  const std::vector<Field> same = transfer_p0(a, {f}, a, &r);
  for (std::size_t t = 0; t < f.values.size(); ++t)
    EXPECT_NEAR(same[0].values[t], f.values[t], 1e-13 * std::abs(f.values[t]) + 1e-14);
  EXPECT_EQ(r.pairs, a.num_tets());
  const Field one{"one", FieldKind::kScalar, std::vector<double>(a.num_tets(), 1.5)};
  const std::vector<Field> out = transfer_p0(a, {f, one}, b, &r);
  EXPECT_LT(rel(r.new_integral[0], r.old_integral[0]), 1e-12);
  EXPECT_LT(rel(r.new_integral[1], r.old_integral[1]), 1e-12);
  EXPECT_NEAR(r.overlap_measure, 1.0, 1e-12);
  EXPECT_LT(std::abs(r.uncovered_new), 1e-12);
  EXPECT_EQ(r.unmatched_elements, 0u);
  for (double v : out[1].values) EXPECT_NEAR(v, 1.5, 1e-13);
  // Back onto the first mesh: still conserved.
  transfer_p0(b, out, a, &r);
  EXPECT_LT(rel(r.new_integral[0], r.old_integral[0]), 1e-12);
}

TEST(TransferP0, RejectsBadInput) {
  const Mesh m = unit_square(2, 2);
  EXPECT_THROW(transfer_p0(m, {Field{"u", FieldKind::kScalar, {1.0, 2.0}}}, m), InputError);
  const Mesh cube = unit_cube(1);
  EXPECT_THROW(transfer_p0(m, {}, cube), InputError);
  EXPECT_THROW(transfer_p0(cube, {Field{"u", FieldKind::kScalar, {1.0}}}, cube), InputError);
}
