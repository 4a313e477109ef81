// Derivative recovery throughput (issue #5: Hessian recovery + metric for 1 M vertices under 1 s).
// Field u = sin(2x) cos(3y) (· e^{z/2} in 3D) on unit_square(700, 700) (491,401 vertices) and
// unit_cube(50) (132,651 vertices); the counter ns/vertex is the time of one call divided by the
// vertex count. Adjacency is built inside each call (Green and least squares), as users pay it.
//   build/bench/riemesh_bench_recovery --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "mesh/fixtures.hpp"
#include "metric/hessian_metric.hpp"
#include "metric/recovery.hpp"

using namespace riemesh;

namespace {

template <int D>
const Mesh& bench_mesh() {
  static const Mesh mesh = D == 2 ? unit_square(700, 700) : unit_cube(50);
  return mesh;
}

template <int D>
std::vector<double> bench_field(const Mesh& mesh) {
  std::vector<double> u(mesh.num_vertices());
  for (std::size_t v = 0; v < u.size(); ++v) {
    const double* x = &mesh.coords[v * D];
    u[v] = std::sin(2 * x[0]) * std::cos(3 * x[1]) * (D == 3 ? std::exp(0.5 * x[D - 1]) : 1.0);
  }
  return u;
}

void per_vertex(benchmark::State& state, std::size_t nv) {
  state.counters["ns/vertex"] =
      benchmark::Counter(static_cast<double>(nv), benchmark::Counter::kIsIterationInvariantRate |
                                                      benchmark::Counter::kInvert);
  state.counters["vertices"] = static_cast<double>(nv);
}

template <int D>
void BM_RecoverHessian(benchmark::State& state) {
  const Mesh& mesh = bench_mesh<D>();
  const std::vector<double> u = bench_field<D>(mesh);
  const auto method = static_cast<RecoveryMethod>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(recover_hessian<D>(mesh, u, method));
  per_vertex(state, mesh.num_vertices());
}

template <int D>
void BM_RecoverGradient(benchmark::State& state) {
  const Mesh& mesh = bench_mesh<D>();
  const std::vector<double> u = bench_field<D>(mesh);
  const auto method = static_cast<RecoveryMethod>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(recover_gradient<D>(mesh, u, method));
  per_vertex(state, mesh.num_vertices());
}

/// The figure: least-squares Hessians, then the L2-optimal metric for N = 10⁴.
template <int D>
void BM_HessianAndMetric(benchmark::State& state) {
  const Mesh& mesh = bench_mesh<D>();
  const std::vector<double> u = bench_field<D>(mesh);
  HessianMetricOptions options;
  options.complexity = 1e4;
  for (auto _ : state) {
    const std::vector<SymMat<D>> h = recover_hessian<D>(mesh, u);
    benchmark::DoNotOptimize(hessian_metric<D>(mesh, h, options));
  }
  per_vertex(state, mesh.num_vertices());
}

// Arguments: 0 = L2 projection, 1 = Green, 2 = least squares (RecoveryMethod order).
BENCHMARK(BM_RecoverHessian<2>)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecoverHessian<3>)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecoverGradient<2>)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HessianAndMetric<2>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HessianAndMetric<3>)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
