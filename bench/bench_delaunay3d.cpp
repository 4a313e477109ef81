// The 3D Delaunay kernel: random points in the unit cube.
//   Sorted/N    points already in Hilbert order, inserted as given (the target: ≥ 1.5 M/s)
//   Hilbert/N   unsorted points; the Hilbert sort is included in the time
//   Brio/N      unsorted points; BRIO ordering (Hilbert sort per round) included in the time
// "points/s" counts the points over the whole call (ordering, insertion, compaction of the result).
// Run: build/bench/riemesh_bench_delaunay3d --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "generate/delaunay3d.hpp"
#include "mesh/hilbert.hpp"

using namespace riemesh;

namespace {

std::vector<double> random_cube(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> xyz(3 * n);
  for (double& x : xyz) x = u(rng);
  return xyz;
}

std::vector<double> hilbert_sorted(const std::vector<double>& xyz) {
  const std::vector<Id> order = hilbert_order(xyz, 3);
  std::vector<double> out(xyz.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    for (int i = 0; i < 3; ++i) out[3 * k + i] = xyz[3 * static_cast<std::size_t>(order[k]) + i];
  return out;
}

void run(benchmark::State& state, const std::vector<double>& xyz, InsertionOrder order) {
  std::size_t tets = 0;
  for (auto _ : state) {
    Tetrahedralization t = delaunay3d(xyz, order);
    tets = t.num_tets();
    benchmark::DoNotOptimize(t.tets.data());
  }
  state.counters["points/s"] =
      benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["tets"] = double(tets);
}

void Sorted(benchmark::State& state) {
  run(state, hilbert_sorted(random_cube(state.range(0))), InsertionOrder::kAsGiven);
}
BENCHMARK(Sorted)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Hilbert(benchmark::State& state) {
  run(state, random_cube(state.range(0)), InsertionOrder::kHilbert);
}
BENCHMARK(Hilbert)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Brio(benchmark::State& state) {
  run(state, random_cube(state.range(0)), InsertionOrder::kBrio);
}
BENCHMARK(Brio)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
