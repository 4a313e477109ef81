// The unsteady fixed-point loop on a moving front, by properties: deterministic, the error falls
// with the complexity, sub-intervals beat one mesh for all time at the same cost, the
// intersection mode asks for more than N̄ and the Lp mode for N̄.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "remesh/unsteady2d.hpp"

using namespace riemesh;

namespace {

UnsteadyOptions small_options() {
  UnsteadyOptions o;
  o.complexities = {300, 1200};
  o.intervals = 4;
  o.samples = 3;
  o.iterations = 2;
  o.start_cells = 12;
  return o;
}

}  // namespace

TEST(Unsteady, Deterministic) {
  const MovingFunction& f = moving_function("tanh-front");
  UnsteadyOptions o = small_options();
  o.iterations = 1;
  std::vector<Mesh> a, b;
  const UnsteadyStep sa = unsteady_run(f, 300, 2, o, a);
  const UnsteadyStep sb = unsteady_run(f, 300, 2, o, b);
  ASSERT_EQ(a.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(a[i].coords, b[i].coords);
    EXPECT_EQ(a[i].triangles, b[i].triangles);
  }
  EXPECT_EQ(sa.error, sb.error);
}

TEST(Unsteady, ErrorFallsAndSubIntervalsBeatOneMesh) {
  const MovingFunction& f = moving_function("tanh-front");
  const UnsteadyOptions o = small_options();
  const UnsteadyResult r = unsteady_loop(f, o);
  ASSERT_EQ(r.multi.size(), 2u);
  ASSERT_EQ(r.single.size(), 2u);
  EXPECT_LT(r.multi[1].error, 0.6 * r.multi[0].error);
  EXPECT_LT(r.single[1].error, r.single[0].error);
  for (int k = 0; k < 2; ++k) {
    // Lp mode: the mean metric complexity is N̄ (hessian_metric reaches each N_i).
    EXPECT_NEAR(r.multi[k].metric_complexity / o.complexities[k], 1.0, 0.05);
    // At the same mean cost, 4 meshes that follow the front beat one mesh for the whole sweep.
    EXPECT_LT(r.multi[k].error, r.single[k].error) << k;
    EXPECT_LT(r.multi[k].mean_vertices, 1.6 * r.single[k].mean_vertices) << k;
  }
}

TEST(Unsteady, IntersectionAsksForMoreThanEachSample) {
  const MovingFunction& f = moving_function("moving-circle");
  UnsteadyOptions o = small_options();
  o.combine = UnsteadyCombine::kIntersect;
  o.iterations = 1;
  std::vector<Mesh> meshes;
  const UnsteadyStep s = unsteady_run(f, 400, 2, o, meshes);
  EXPECT_GT(s.metric_complexity, 400.0);  // the union of the samples' refined regions
  EXPECT_GT(s.error, 0.0);
}

TEST(Unsteady, RejectsBadOptions) {
  UnsteadyOptions o;
  o.intervals = 0;
  EXPECT_THROW(unsteady_loop(moving_function("tanh-front"), o), InputError);
  EXPECT_THROW(moving_function("nope"), InputError);
}
