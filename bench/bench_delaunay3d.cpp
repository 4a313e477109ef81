// The 3D Delaunay kernel: random points in the unit cube.
//   Sorted/N    points already in Hilbert order, inserted as given (the issue's target: ≥ 1.5 M/s)
//   SortedRounds/N  the same points in BRIO's rounds over their order (kRounds: no sort)
//   SortedCoarseFirst/N  the same points, every 64th first, then the rest (kCoarseFirst: no sort)
//   Hilbert/N   unsorted points; the Hilbert sort is included in the time
//   Brio/N      unsorted points; BRIO ordering (Hilbert sort per round) included in the time
// "points/s" counts the points over the whole call (ordering, insertion, compaction of the result).
// Run: build/bench/riemesh_bench_delaunay3d --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
// Or, on the points of a TetGen .node file (for bench/delaunay3d_vs_tetgen.sh):
//      build/bench/riemesh_bench_delaunay3d --node FILE.node [--runs R] [--order
//      brio|hilbert|given]
//   prints "points N tets T median_seconds S" (median over R runs of delaunay3d, reading excluded).
// Or the kernel's work per point on N random points, Hilbert-sorted beforehand (as Sorted/N) or in
// BRIO order, or Hilbert-sorted in rounds (as SortedRounds/N), with one run only (for valgrind
// --tool=callgrind, whose counts the load does not disturb):
//      build/bench/riemesh_bench_delaunay3d --counts N [--order brio|rounds|coarse]
// With --hash (and --counts N or --node FILE): prints "tets T hash H raw R", H an FNV-1a hash of
// the tets, each with its vertices sorted, in sorted order (the same triangulation), R one of the
// arrays as returned (the same tet numbering and neighbours), to check that a change of the kernel
// leaves its output the same, instead of the timings or counts.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <cstdlib>
#include <string>
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

void SortedRounds(benchmark::State& state) {
  run(state, hilbert_sorted(random_cube(state.range(0))), InsertionOrder::kRounds);
}
BENCHMARK(SortedRounds)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void SortedCoarseFirst(benchmark::State& state) {
  run(state, hilbert_sorted(random_cube(state.range(0))), InsertionOrder::kCoarseFirst);
}
BENCHMARK(SortedCoarseFirst)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Hilbert(benchmark::State& state) {
  run(state, random_cube(state.range(0)), InsertionOrder::kHilbert);
}
BENCHMARK(Hilbert)->Arg(1000000)->Unit(benchmark::kMillisecond);

void Brio(benchmark::State& state) {
  run(state, random_cube(state.range(0)), InsertionOrder::kBrio);
}
BENCHMARK(Brio)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

/// Points of a TetGen .node file: "N 3 attributes markers", then "index x y z ...".
std::vector<double> read_node(const char* path) {
  std::ifstream in(path);
  std::size_t n = 0;
  int dim = 0, attributes = 0, markers = 0;
  in >> n >> dim >> attributes >> markers;
  std::vector<double> xyz(3 * n);
  for (std::size_t i = 0; i < n && in; ++i) {
    double index, extra;
    in >> index >> xyz[3 * i] >> xyz[3 * i + 1] >> xyz[3 * i + 2];
    for (int k = 0; k < attributes + markers; ++k) in >> extra;
  }
  if (!in || dim != 3) {
    std::fprintf(stderr, "%s: not a 3D .node file\n", path);
    std::exit(2);
  }
  return xyz;
}

/// The tets as sets of vertices, sorted, hashed (FNV-1a 64 over the ids).
int print_hash(const std::vector<double>& xyz, InsertionOrder order) {
  const Tetrahedralization t = delaunay3d(xyz, order);
  const auto fnv = [](std::uint64_t h, Id v) { return (h ^ static_cast<std::uint32_t>(v)) * 0x100000001b3ull; };
  std::uint64_t raw = 0xcbf29ce484222325ull;  // the arrays as returned: tet order and neighbours
  for (Id v : t.tets) raw = fnv(raw, v);
  for (Id v : t.tet2tet) raw = fnv(raw, v);
  std::vector<std::array<Id, 4>> tets(t.num_tets());
  for (std::size_t k = 0; k < tets.size(); ++k) {
    std::copy(t.tets.begin() + 4 * k, t.tets.begin() + 4 * k + 4, tets[k].begin());
    std::sort(tets[k].begin(), tets[k].end());
  }
  std::sort(tets.begin(), tets.end());
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const auto& q : tets)
    for (Id v : q) h = fnv(h, v);
  std::printf("tets %zu hash %016llx raw %016llx\n", tets.size(), static_cast<unsigned long long>(h),
              static_cast<unsigned long long>(raw));
  return 0;
}

int run_node_file(const char* path, int runs, InsertionOrder order, bool hash) {
  const std::vector<double> xyz = read_node(path);
  if (hash) return print_hash(xyz, order);
  std::vector<double> seconds;
  std::size_t tets = 0;
  for (int r = 0; r < runs; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const Tetrahedralization t = delaunay3d(xyz, order);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    tets = t.num_tets();
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("points %zu tets %zu median_seconds %.4f\n", xyz.size() / 3, tets, seconds[seconds.size() / 2]);
  return 0;
}

/// order: kBrio on random points, kAsGiven, kRounds or kCoarseFirst on Hilbert-sorted ones.
int run_counts(std::size_t n, InsertionOrder order) {
  const bool brio = order == InsertionOrder::kBrio;
  const std::vector<double> xyz = brio ? random_cube(n) : hilbert_sorted(random_cube(n));
  std::vector<Id> ids = insertion_order(xyz, order);
  Delaunay3d kernel(&xyz, ids);
  kernel.reserve(ids.size());
  for (std::size_t k = 4; k < ids.size(); ++k) kernel.insert(ids[k]);
  const Delaunay3dStats& s = kernel.stats();
  const double per = 1.0 / static_cast<double>(n);
  std::printf("points %zu tets %zu per point: walk steps %.2f, deleted tets %.2f, conflict tests %.2f\n", n,
              kernel.result().num_tets(), per * static_cast<double>(s.walk_steps),
              per * static_cast<double>(s.cavity_tets), per * static_cast<double>(s.insphere_tests));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const char* node = nullptr;
  std::size_t counts = 0;
  bool hash = false;
  bool brio = false;    // --order brio given (for --counts, whose default is Hilbert-sorted points)
  bool rounds = false;  // --order rounds (for --counts: Hilbert-sorted points in rounds)
  bool coarse = false;  // --order coarse (for --counts: Hilbert-sorted points, a sample first)
  int runs = 5;
  InsertionOrder order = InsertionOrder::kBrio;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--hash") == 0) hash = true;
  for (int i = 1; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--node") == 0) node = argv[i + 1];
    if (std::strcmp(argv[i], "--order") == 0 && std::strcmp(argv[i + 1], "brio") == 0) brio = true;
    if (std::strcmp(argv[i], "--order") == 0 && std::strcmp(argv[i + 1], "rounds") == 0)
      rounds = true;
    if (std::strcmp(argv[i], "--order") == 0 && std::strcmp(argv[i + 1], "coarse") == 0)
      coarse = true;
    if (std::strcmp(argv[i], "--counts") == 0) counts = std::strtoull(argv[i + 1], nullptr, 10);
    if (std::strcmp(argv[i], "--runs") == 0) runs = std::max(1, std::atoi(argv[i + 1]));
    if (std::strcmp(argv[i], "--order") == 0)
      order = std::strcmp(argv[i + 1], "hilbert") == 0 ? InsertionOrder::kHilbert
              : std::strcmp(argv[i + 1], "given") == 0 ? InsertionOrder::kAsGiven
                                                        : InsertionOrder::kBrio;
  }
  if (node) return run_node_file(node, runs, order, hash);
  if (counts >= 4 && hash)
    return print_hash(random_cube(counts), brio ? InsertionOrder::kBrio : InsertionOrder::kHilbert);
  if (counts >= 4)
    return run_counts(counts, brio     ? InsertionOrder::kBrio
                              : rounds ? InsertionOrder::kRounds
                              : coarse ? InsertionOrder::kCoarseFirst
                                       : InsertionOrder::kAsGiven);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
