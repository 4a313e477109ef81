// Mesh layer timings on unit_cube(n): n = 55 gives 998,250 tetrahedra and 175,616 vertices.
// Run: build-mesh/bench/riemesh_bench_mesh --benchmark_repetitions=3
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "mesh/adjacency.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/hilbert.hpp"

using namespace riemesh;

namespace {

const Mesh& cube(int n) {
  static int cached_n = -1;
  static Mesh mesh;
  if (cached_n != n) mesh = unit_cube(n), cached_n = n;
  return mesh;
}

/// unit_cube(n) with randomly relabelled vertices and shuffled tets (a badly ordered input),
/// and the same after renumber_hilbert.
const Mesh& scrambled_cube(int n, bool renumbered) {
  static int cached_n = -1;
  static Mesh scrambled, hilbert;
  if (cached_n != n) {
    scrambled = unit_cube(n);
    std::mt19937 rng(1);
    std::vector<Id> perm(scrambled.num_vertices());
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), rng);
    permute_vertices(scrambled, perm);
    std::vector<Id> order(scrambled.num_tets());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Id> tets(scrambled.tets.size());
    for (std::size_t t = 0; t < order.size(); ++t)
      std::copy_n(scrambled.tets.begin() + 4 * order[t], 4, tets.begin() + 4 * t);
    scrambled.tets = std::move(tets);
    hilbert = scrambled;
    renumber_hilbert(hilbert);
    cached_n = n;
  }
  return renumbered ? hilbert : scrambled;
}

void BM_AdjacencyScrambled(benchmark::State& state) {
  const Mesh& m = scrambled_cube(static_cast<int>(state.range(0)), state.range(1) != 0);
  for (auto _ : state) {
    Adjacency adj = build_adjacency(m.tets, 4, m.num_vertices());
    benchmark::DoNotOptimize(adj.elem2elem.data());
  }
  state.counters["tets"] = static_cast<double>(m.num_tets());
}
// Arg pair (n, renumbered): random order, then the same mesh after renumber_hilbert.
BENCHMARK(BM_AdjacencyScrambled)->Args({55, 0})->Args({55, 1})->Unit(benchmark::kMillisecond);

void BM_AdjacencyTets(benchmark::State& state) {
  const Mesh& m = cube(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Adjacency adj = build_adjacency(m.tets, 4, m.num_vertices());
    benchmark::DoNotOptimize(adj.elem2elem.data());
  }
  state.counters["tets"] = static_cast<double>(m.num_tets());
  state.SetItemsProcessed(state.iterations() * static_cast<long>(m.num_tets()));
}
BENCHMARK(BM_AdjacencyTets)->Arg(20)->Arg(55)->Unit(benchmark::kMillisecond);

void BM_HilbertRenumber(benchmark::State& state) {
  const Mesh& m = scrambled_cube(static_cast<int>(state.range(0)), false);
  for (auto _ : state) {
    state.PauseTiming();
    Mesh copy = m;
    state.ResumeTiming();
    renumber_hilbert(copy);
    benchmark::DoNotOptimize(copy.tets.data());
  }
  state.counters["tets"] = static_cast<double>(m.num_tets());
}
BENCHMARK(BM_HilbertRenumber)->Arg(55)->Unit(benchmark::kMillisecond);

void BM_HilbertOrderVertices(benchmark::State& state) {
  const Mesh& m = scrambled_cube(static_cast<int>(state.range(0)), false);
  for (auto _ : state) {
    std::vector<Id> order = hilbert_order(m.coords, m.dim);
    benchmark::DoNotOptimize(order.data());
  }
  state.counters["vertices"] = static_cast<double>(m.num_vertices());
}
BENCHMARK(BM_HilbertOrderVertices)->Arg(55)->Unit(benchmark::kMillisecond);

void BM_CheckMesh(benchmark::State& state) {
  const Mesh& m = cube(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    CheckReport r = check_mesh(m);
    benchmark::DoNotOptimize(r.issues.data());
  }
  state.counters["tets"] = static_cast<double>(m.num_tets());
}
BENCHMARK(BM_CheckMesh)->Arg(55)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
