// P1 transfer: exact for fields linear in the coordinates, on the adapted square.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "remesh/adapt2d.hpp"
#include "remesh/transfer.hpp"

using namespace riemesh;

TEST(Transfer, LinearFieldsAreExact) {
  const Mesh from = unit_square(7, 5);
  const std::vector<SymMat2> met(from.num_vertices(), SymMat2{{400.0, 0.0, 2500.0}});
  const Mesh to = adapt2d(from, met, {}).mesh;
  Field s{"u", FieldKind::kScalar, {}}, w{"w", FieldKind::kVector, {}};
  for (std::size_t v = 0; v < from.num_vertices(); ++v) {
    const double x = from.coords[2 * v], y = from.coords[2 * v + 1];
    s.values.push_back(1.0 + 2.0 * x - 3.0 * y);
    w.values.insert(w.values.end(), {x, x + y});
  }
  const std::vector<Field> out = transfer_p1(from, {s, w}, to);
  ASSERT_EQ(out.size(), 2u);
  for (std::size_t v = 0; v < to.num_vertices(); ++v) {
    const double x = to.coords[2 * v], y = to.coords[2 * v + 1];
    EXPECT_NEAR(out[0].values[v], 1.0 + 2.0 * x - 3.0 * y, 1e-12);
    EXPECT_NEAR(out[1].values[2 * v], x, 1e-12);
    EXPECT_NEAR(out[1].values[2 * v + 1], x + y, 1e-12);
  }
}

TEST(Transfer, RejectsMismatchedFields) {
  const Mesh m = unit_square(2, 2);
  Field bad{"u", FieldKind::kScalar, {1.0, 2.0}};
  EXPECT_THROW(transfer_p1(m, {bad}, m), InputError);
}

TEST(Transfer, VerticesOutsideTheOldMeshAreReported) {
  // The same square shifted by 0.5 in x: the vertices beyond x = 1 are outside, up to 0.5 away
  // (the transfer said nothing of them before).
  const Mesh from = unit_square(4, 4);
  Mesh to = from;
  for (std::size_t v = 0; v < to.num_vertices(); ++v) to.coords[2 * v] += 0.5;
  const std::vector<Field> f = {
      {"u", FieldKind::kScalar, std::vector<double>(from.num_vertices(), 1.0)}};
  P1TransferReport report;
  transfer_p1(from, f, to, &report);
  EXPECT_EQ(report.outside, 10u);  // the columns x = 1.25 and 1.5
  EXPECT_NEAR(report.farthest, 0.5, 1e-12);
  transfer_p1(from, f, from, &report);
  EXPECT_EQ(report.outside, 0u);
  EXPECT_EQ(report.farthest, 0.0);
}
