// The 2D Delaunay kernel: random points in the unit square.
//   Sorted/N    points already in Hilbert order, inserted as given (the target: ≥ 5 M/s)
//   Brio/N      unsorted points; BRIO ordering (Hilbert sort per round) included in the time
// Run: build/bench/riemesh_bench_delaunay2d --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "generate/delaunay2d.hpp"
#include "mesh/hilbert.hpp"

using namespace riemesh;

namespace {

std::vector<double> random_square(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xy(2 * n);
  for (double& x : xy) x = u(rng);
  return xy;
}

std::vector<double> hilbert_sorted(const std::vector<double>& xy) {
  const std::vector<Id> order = hilbert_order(xy, 2);
  std::vector<double> out(xy.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    out[2 * k] = xy[2 * order[k]];
    out[2 * k + 1] = xy[2 * order[k] + 1];
  }
  return out;
}

void Sorted(benchmark::State& state) {
  const std::vector<double> xy = hilbert_sorted(random_square(state.range(0)));
  for (auto _ : state) {
    Triangulation2d t = delaunay2d(xy, InsertionOrder::kAsGiven);
    benchmark::DoNotOptimize(t.tri.data());
  }
  state.counters["points/s"] =
      benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(Sorted)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Brio(benchmark::State& state) {
  const std::vector<double> xy = random_square(state.range(0));
  for (auto _ : state) {
    Triangulation2d t = delaunay2d(xy, InsertionOrder::kBrio);
    benchmark::DoNotOptimize(t.tri.data());
  }
  state.counters["points/s"] =
      benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(Brio)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
