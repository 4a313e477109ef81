// Nanoseconds per call of the metric kernels (issue #2's targets: 3D eigendecomposition < 0.1 µs,
// 3D log-Euclidean interpolation of 4 metrics < 0.5 µs). Inputs: 1024 random SPD tensors with
// anisotropy up to 1e3, cycled so that the branch predictor sees varied data.
//   build/bench/riemesh_bench_metric --benchmark_repetitions=5 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <array>
#include <random>
#include <vector>

#include "core/spd.hpp"
#include "metric/edge_length.hpp"
#include "metric/element.hpp"
#include "metric/interpolation.hpp"
#include "metric/intersection.hpp"

using namespace riemesh;

namespace {

constexpr std::size_t kCount = 1024;  // power of two: index with a mask

template <int D>
std::vector<SymMat<D>> random_metrics() {
  std::mt19937_64 rng(2026);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<SymMat<D>> out;
  for (std::size_t k = 0; k < kCount; ++k) {
    Mat<D> r{};
    for (int j = 0; j < D; ++j) {
      Vec<D> v{};
      for (int i = 0; i < D; ++i) v[i] = n01(rng);
      for (int pass = 0; pass < 2; ++pass)
        for (int l = 0; l < j; ++l) v -= dot(v, r.column(l)) * r.column(l);
      r.set_column(j, normalize(v));
    }
    Vec<D> lam{};
    for (int i = 0; i < D; ++i) lam[i] = std::pow(1e6, u01(rng));  // sizes ratio up to 1e3
    out.push_back(compose(r, lam));
  }
  return out;
}

template <int D>
void BM_Eigen(benchmark::State& state) {
  const auto m = random_metrics<D>();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(eigen(m[i++ & (kCount - 1)]));
}
BENCHMARK(BM_Eigen<2>)->Name("eigen/2d");
BENCHMARK(BM_Eigen<3>)->Name("eigen/3d");

void BM_Log3(benchmark::State& state) {
  const auto m = random_metrics<3>();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(log_spd(m[i++ & (kCount - 1)]));
}
BENCHMARK(BM_Log3)->Name("log/3d");

void BM_Exp3(benchmark::State& state) {
  auto m = random_metrics<3>();
  for (auto& x : m) x = log_spd(x);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(exp_sym(m[i++ & (kCount - 1)]));
}
BENCHMARK(BM_Exp3)->Name("exp/3d");

void BM_LogEuclidean4(benchmark::State& state) {
  const auto m = random_metrics<3>();
  const std::array<double, 4> w{0.1, 0.2, 0.3, 0.4};
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = (i += 4) & (kCount - 1);
    benchmark::DoNotOptimize(interpolate<3>(InterpScheme::kLogEuclidean,
                                            std::span<const SymMat3>(&m[k], 4), w));
  }
}
BENCHMARK(BM_LogEuclidean4)->Name("interp_log_euclidean_4/3d");

void BM_LogEuclidean4FromLogs(benchmark::State& state) {
  auto m = random_metrics<3>();
  for (auto& x : m) x = log_spd(x);
  const std::array<double, 4> w{0.1, 0.2, 0.3, 0.4};
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = (i += 4) & (kCount - 1);
    benchmark::DoNotOptimize(
        interpolate_log_euclidean_logs<3>(std::span<const SymMat3>(&m[k], 4), w));
  }
}
BENCHMARK(BM_LogEuclidean4FromLogs)->Name("interp_log_euclidean_4_from_logs/3d");

void BM_Intersect3(benchmark::State& state) {
  const auto m = random_metrics<3>();
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = (i += 2) & (kCount - 1);
    benchmark::DoNotOptimize(intersect(m[k], m[k + 1]));
  }
}
BENCHMARK(BM_Intersect3)->Name("intersect_2/3d");

void BM_EdgeLengthGeometric3(benchmark::State& state) {
  const auto m = random_metrics<3>();
  const Vec3 ab{{0.3, -0.2, 0.5}};
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = (i += 2) & (kCount - 1);
    benchmark::DoNotOptimize(edge_length_geometric(m[k], m[k + 1], ab));
  }
}
BENCHMARK(BM_EdgeLengthGeometric3)->Name("edge_length_geometric/3d");

void BM_EdgeLengthQuadrature3(benchmark::State& state) {
  const auto m = random_metrics<3>();
  const Vec3 ab{{0.3, -0.2, 0.5}};
  std::size_t i = 0;
  for (auto _ : state) {
    const std::size_t k = (i += 2) & (kCount - 1);
    benchmark::DoNotOptimize(edge_length_quadrature(m[k], m[k + 1], ab));
  }
}
BENCHMARK(BM_EdgeLengthQuadrature3)->Name("edge_length_quadrature_log5/3d");

void BM_ElementMetric3(benchmark::State& state) {
  const Vec3 p[4] = {{{0, 0, 0}}, {{1, 0.1, 0}}, {{0.2, 1, 0.1}}, {{0.1, 0.3, 0.9}}};
  for (auto _ : state) {
    benchmark::DoNotOptimize(p);
    benchmark::DoNotOptimize(element_metric<3>(p));
  }
}
BENCHMARK(BM_ElementMetric3)->Name("element_metric/3d");

}  // namespace

BENCHMARK_MAIN();
