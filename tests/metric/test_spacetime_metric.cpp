// Space–time metrics (BOOK.md §8): samples combined in time, and the global Lp normalisation
// over sub-intervals checked against the closed forms of spacetime_metric.hpp.
#include <gtest/gtest.h>

#include <cmath>

#include "core/eigen.hpp"
#include "core/error.hpp"
#include "mesh/fixtures.hpp"
#include "metric/recovery.hpp"
#include "metric/spacetime_metric.hpp"

using namespace riemesh;

namespace {

/// Hessians of a front tanh(k (x − c)) + a y² bump on unit_square(n, n), recovered.
std::vector<SymMat2> front_hessians(const Mesh& m, double c) {
  std::vector<double> u(m.num_vertices());
  for (std::size_t v = 0; v < u.size(); ++v) {
    const double x = m.coords[2 * v], y = m.coords[2 * v + 1];
    u[v] = std::tanh(20.0 * (x + 0.3 * y - c)) + 0.5 * y * y;
  }
  return recover_hessian<2>(m, u, RecoveryMethod::kLeastSquares);
}

/// Smallest eigenvalue of a − b relative to the size of a (>= −tol: a contains b's unit ball).
double min_gap(const SymMat2& a, const SymMat2& b) {
  const SymEigen<2> e = eigen(a - b);
  const SymEigen<2> s = eigen(a);
  return e.values[0] / std::max(std::abs(s.values[1]), 1e-300);
}

}  // namespace

TEST(SpaceTime, MaxInTimeContainsEverySample) {
  const Mesh m = unit_square(12, 12);
  std::vector<std::vector<SymMat2>> samples;
  for (double c : {0.2, 0.5, 0.8}) samples.push_back(front_hessians(m, c));
  const double length = 0.25;
  const std::vector<SymMat2> h = combine_in_time<2>(samples, length, TimeCombination::kMax);
  for (std::size_t v = 0; v < h.size(); ++v)
    for (const auto& s : samples)
      EXPECT_GE(min_gap(h[v], length * abs_hessian<2>(s[v], 0.0)), -1e-9) << v;
}

TEST(SpaceTime, IntegralOfAConstantSampleIsLengthTimesIt) {
  const Mesh m = unit_square(6, 6);
  const std::vector<SymMat2> h = front_hessians(m, 0.5);
  const std::vector<std::vector<SymMat2>> same = {h, h, h, h};
  const std::vector<SymMat2> i = combine_in_time<2>(same, 0.3, TimeCombination::kIntegral);
  for (std::size_t v = 0; v < h.size(); ++v) {
    const SymMat2 want = 0.3 * abs_hessian<2>(h[v], 0.0);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(i[v].c[k], want.c[k], 1e-9 * (1 + std::abs(want.c[k])));
  }
  // Trapezoid weights: samples 0 and 1 of a linear-in-time field |H|(t) = (1 + t) A.
  const SymMat2 a{{2.0, 0.5, 1.0}};
  const std::vector<std::vector<SymMat2>> lin = {{a}, {1.5 * a}, {2.0 * a}};
  const std::vector<SymMat2> li = combine_in_time<2>(lin, 1.0, TimeCombination::kIntegral);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(li[0].c[k], 1.5 * a.c[k], 1e-14);  // ∫₀¹ (1 + t) dt
}

TEST(SpaceTime, ComplexitiesFollowTheClosedForm) {
  // Two sub-intervals on the same mesh, H_2 = 8 H_1, equal time steps: N_2 / N_1 = I_2 / I_1 =
  // 8^{d p/(2p+d)} = 8^{4/6} = 4 (d = 2, p = 2), and the mean of N_1, N_2 is N̄.
  const Mesh m = unit_square(10, 10);
  const std::vector<SymMat2> h1 = combine_in_time<2>(
      std::vector<std::vector<SymMat2>>{front_hessians(m, 0.4)}, 1.0, TimeCombination::kMax);
  std::vector<SymMat2> h2 = h1;
  for (SymMat2& h : h2) h = 8.0 * h;
  std::vector<SpaceTimeInterval<2>> in = {{&m, h1, 1.0}, {&m, h2, 1.0}};
  std::vector<double> n = spacetime_complexities<2>(in, 1000.0, 2.0);
  EXPECT_NEAR(n[1] / n[0], 4.0, 1e-12);
  EXPECT_NEAR(0.5 * (n[0] + n[1]), 1000.0, 1e-9);
  // Same H, time steps n_1 = 3 n_2: N_1 / N_2 = 3^{-d/(2p+d)} = 3^{-1/3}, Σ n_i N_i = N̄ Σ n_i.
  in = {{&m, h1, 3.0}, {&m, h1, 1.0}};
  n = spacetime_complexities<2>(in, 1000.0, 2.0);
  EXPECT_NEAR(n[0] / n[1], std::pow(3.0, -1.0 / 3.0), 1e-12);
  EXPECT_NEAR((3.0 * n[0] + n[1]) / 4.0, 1000.0, 1e-9);
}

TEST(SpaceTime, LpMetricsHaveTheRequestedMeanComplexity) {
  const Mesh a = unit_square(16, 16), b = unit_square(11, 13);
  std::vector<std::vector<SymMat2>> ha, hb;
  for (double c : {0.1, 0.3}) ha.push_back(front_hessians(a, c));
  for (double c : {0.3, 0.5, 0.7}) hb.push_back(front_hessians(b, c));
  const std::vector<SymMat2> h1 = combine_in_time<2>(ha, 0.5, TimeCombination::kMax);
  const std::vector<SymMat2> h2 = combine_in_time<2>(hb, 0.5, TimeCombination::kIntegral);
  const std::vector<SpaceTimeInterval<2>> in = {{&a, h1, 2.0}, {&b, h2, 1.0}};
  HessianMetricOptions o;
  o.norm = 1.0;
  o.complexity = 3000.0;
  o.hmin = 1e-3;
  o.hmax = 0.3;  // clipping: each N_i is still reached by hessian_metric's refinement
  std::vector<MetricReport> r;
  const auto m = spacetime_lp_metrics<2>(in, o, &r);
  ASSERT_EQ(m.size(), 2u);
  const double mean = (2.0 * field_complexity<2>(a, m[0]) + field_complexity<2>(b, m[1])) / 3.0;
  EXPECT_NEAR(mean / 3000.0, 1.0, 0.05);
  EXPECT_NEAR((2.0 * r[0].complexity + r[1].complexity) / 3.0 / 3000.0, 1.0, 0.05);
}

TEST(SpaceTime, AnIntervalWithoutErrorTakesNoComplexity) {
  // Sub-interval 1: a linear solution (zero Hessians); 2: a small one (1e-6). Floored to the
  // identity, interval 1 took 1999.8 of 2000; now the whole budget goes where the error is,
  // whatever its scale.
  const Mesh m = unit_square(10, 10);
  const std::vector<std::vector<SymMat2>> zero = {
      std::vector<SymMat2>(m.num_vertices(), SymMat2::zero())};
  const std::vector<std::vector<SymMat2>> small = {
      std::vector<SymMat2>(m.num_vertices(), SymMat2::diagonal(1e-6))};
  for (const TimeCombination how : {TimeCombination::kMax, TimeCombination::kIntegral}) {
    const std::vector<SymMat2> h0 = combine_in_time<2>(zero, 0.5, how);
    for (const SymMat2& h : h0) EXPECT_EQ(h, SymMat2::zero());
    const std::vector<SymMat2> h1 = combine_in_time<2>(small, 0.5, how);
    const std::vector<SpaceTimeInterval<2>> in = {{&m, h0, 0.5}, {&m, h1, 0.5}};
    const std::vector<double> n = spacetime_complexities<2>(in, 1000.0, 2.0);
    EXPECT_EQ(n[0], 0.0);
    EXPECT_NEAR(n[1], 2000.0, 1e-9);
    HessianMetricOptions o;
    o.complexity = 1000.0;
    o.hmax = 0.5;
    std::vector<MetricReport> r;
    const auto metrics = spacetime_lp_metrics<2>(in, o, &r);
    for (const SymMat2& x : metrics[0]) EXPECT_NEAR(x(0, 0), 4.0, 1e-9);  // hmax everywhere
    EXPECT_NEAR(r[1].complexity, 2000.0, 1e-6);
  }
}

TEST(SpaceTime, OneIntervalIsTheSteadyMetric) {
  const Mesh m = unit_square(9, 9);
  const std::vector<SymMat2> h = front_hessians(m, 0.5);
  const std::vector<SpaceTimeInterval<2>> in = {{&m, h, 7.0}};
  HessianMetricOptions o;
  o.complexity = 500.0;
  const auto st = spacetime_lp_metrics<2>(in, o);
  const auto steady = hessian_metric<2>(m, h, o);
  for (std::size_t v = 0; v < h.size(); ++v)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(st[0][v].c[k], steady[v].c[k], 1e-9 * std::abs(steady[v].c[k]) + 1e-12);
}

TEST(SpaceTime, RejectsBadInput) {
  const Mesh m = unit_square(3, 3);
  const std::vector<SymMat2> h = front_hessians(m, 0.5);
  EXPECT_THROW(combine_in_time<2>(std::vector<std::vector<SymMat2>>{}, 1.0, TimeCombination::kMax),
               InputError);
  EXPECT_THROW(combine_in_time<2>(std::vector<std::vector<SymMat2>>{h}, 0.0, TimeCombination::kMax),
               InputError);
  const std::vector<SpaceTimeInterval<2>> bad = {{&m, h, 0.0}};
  EXPECT_THROW(spacetime_complexities<2>(bad, 100.0, 2.0), InputError);
  const std::vector<SpaceTimeInterval<2>> good = {{&m, h, 1.0}};
  EXPECT_THROW(spacetime_complexities<2>(good, 100.0, INFINITY), InputError);
}
