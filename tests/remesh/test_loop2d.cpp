// The adaptation loop on an analytic function: errors fall as the complexity rises, the meshes
// stay valid and the vertex counts follow N; the [−1,1]² fixture maps unit_square.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "mesh/check.hpp"
#include "remesh/loop2d.hpp"

using namespace riemesh;

TEST(SquareMesh, MapsUnitSquareToMinusOneOne) {
  const Mesh m = square_mesh(4);
  ASSERT_EQ(m.num_vertices(), 25u);
  EXPECT_EQ(m.coords[0], -1.0);
  EXPECT_EQ(m.coords[1], -1.0);
  EXPECT_EQ(m.coords[2 * 24], 1.0);
  EXPECT_EQ(m.coords[2 * 24 + 1], 1.0);
  EXPECT_EQ(m.coords[2 * 1], -0.5);  // vertex (1, 0)
}

TEST(AdaptationLoop, TanhErrorsFallAndMeshesStayValid) {
  LoopOptions o;
  o.complexities = {200, 400, 800};
  o.iterations = 2;
  o.quadrature.levels = 1;
  int steps = 0;
  const LoopResult r = adaptation_loop(analytic_function("tanh"), o,
                                       [&steps](const LoopStep&, bool) { ++steps; });
  ASSERT_EQ(r.adapted.size(), 3u);
  ASSERT_EQ(r.uniform.size(), 3u);
  EXPECT_EQ(steps, 6);
  for (std::size_t i = 1; i < r.adapted.size(); ++i) {
    EXPECT_LT(r.adapted[i].errors.l2, r.adapted[i - 1].errors.l2) << i;
    EXPECT_LT(r.adapted[i].errors.l1, r.adapted[i - 1].errors.l1) << i;
    EXPECT_GT(r.adapted[i].vertices, r.adapted[i - 1].vertices) << i;
  }
  for (const LoopStep& s : r.adapted) {
    // A unit mesh of complexity N has about N vertices (gradation adds some).
    EXPECT_GT(static_cast<double>(s.vertices), 0.5 * s.complexity);
    EXPECT_LT(static_cast<double>(s.vertices), 3.0 * s.complexity);
  }
  // The adapted meshes beat uniform ones of the same size on this steep function.
  for (std::size_t i = 0; i < r.adapted.size(); ++i)
    EXPECT_LT(r.adapted[i].errors.l2, r.uniform[i].errors.l2) << i;
  EXPECT_LT(r.adapted_slopes.l2, -0.5);
  EXPECT_TRUE(check_mesh(r.final_mesh).valid());
}

TEST(AdaptationLoop, RejectsBadOptions) {
  LoopOptions o;
  o.complexities = {};
  EXPECT_THROW(adaptation_loop(analytic_function("tanh"), o), InputError);
  o = LoopOptions{};
  o.iterations = 0;
  EXPECT_THROW(o.validate(), InputError);
  o = LoopOptions{};
  o.norm = std::numeric_limits<double>::infinity();
  EXPECT_THROW(o.validate(), InputError);
  o = LoopOptions{};
  o.hmin = 1.0;
  EXPECT_THROW(o.validate(), InputError);
  // Complexities are rising: `riemesh loop --complexities 100,50` ran and printed nan slopes.
  o = LoopOptions{};
  o.complexities = {100, 50};
  EXPECT_THROW(o.validate(), InputError);
  o.complexities = {100, 100};
  EXPECT_THROW(o.validate(), InputError);
}
