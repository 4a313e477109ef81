// The 2D Delaunay kernel: random points in the unit square.
//   Sorted/N    points already in Hilbert order, inserted as given (the target: ≥ 5 M/s)
//   SortedRounds/N  the same points in BRIO's rounds over their order (kRounds: no sort)
//   SortedCoarseFirst/N  the same points, every 64th first, then the rest (kCoarseFirst: no sort)
//   Brio/N      unsorted points; BRIO ordering (Hilbert sort per round) included in the time
// Run: build/bench/riemesh_bench_delaunay2d --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
// Or one delaunay2d call on the same N points, Hilbert-sorted (as Sorted/N) or unsorted with BRIO
// (as Brio/N), for valgrind --tool=callgrind --toggle-collect='riemesh::delaunay2d*' (counts the
// load does not disturb); prints the triangle count and a hash of tri and nbr (same hash = same
// triangulation, triangle order included): build/bench/riemesh_bench_delaunay2d --once N
// [--order brio|coarse] (coarse: Hilbert-sorted, as SortedCoarseFirst/N)
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <span>
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

/// Triangulates xy with `order` in the timed loop; "points/s" over the whole call.
void run(benchmark::State& state, const std::vector<double>& xy, InsertionOrder order) {
  for (auto _ : state) {
    Triangulation2d t = delaunay2d(xy, order);
    benchmark::DoNotOptimize(t.tri.data());
  }
  state.counters["points/s"] =
      benchmark::Counter(double(state.range(0)), benchmark::Counter::kIsIterationInvariantRate);
}

void Sorted(benchmark::State& state) {
  run(state, hilbert_sorted(random_square(state.range(0))), InsertionOrder::kAsGiven);
}
BENCHMARK(Sorted)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void SortedRounds(benchmark::State& state) {
  run(state, hilbert_sorted(random_square(state.range(0))), InsertionOrder::kRounds);
}
BENCHMARK(SortedRounds)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void SortedCoarseFirst(benchmark::State& state) {
  run(state, hilbert_sorted(random_square(state.range(0))), InsertionOrder::kCoarseFirst);
}
BENCHMARK(SortedCoarseFirst)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Brio(benchmark::State& state) {
  run(state, random_square(state.range(0)), InsertionOrder::kBrio);
}
BENCHMARK(Brio)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

/// FNV-1a over the ids.
std::uint64_t hash_ids(std::span<const Id> ids, std::uint64_t h) {
  for (const Id v : ids) {
    h ^= static_cast<std::uint32_t>(v);
    h *= 0x100000001b3ULL;
  }
  return h;
}

int run_once(std::size_t n, InsertionOrder order) {
  const bool brio = order == InsertionOrder::kBrio;
  const std::vector<double> xy = brio ? random_square(n) : hilbert_sorted(random_square(n));
  const Triangulation2d t = delaunay2d(xy, order);
  const std::uint64_t h = hash_ids(t.nbr, hash_ids(t.tri, 0xcbf29ce484222325ULL));
  std::printf("points %zu triangles %zu hash %016llx\n", n, t.num_triangles(),
              static_cast<unsigned long long>(h));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t once = 0;
  InsertionOrder order = InsertionOrder::kAsGiven;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--once") == 0) once = std::strtoull(argv[i + 1], nullptr, 10);
    if (std::strcmp(argv[i], "--order") == 0 && std::strcmp(argv[i + 1], "brio") == 0)
      order = InsertionOrder::kBrio;
    if (std::strcmp(argv[i], "--order") == 0 && std::strcmp(argv[i + 1], "coarse") == 0)
      order = InsertionOrder::kCoarseFirst;
  }
  if (once > 0) return run_once(once, order);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
