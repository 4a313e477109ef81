// Throughput of one 2D adaptation run, library only (no file I/O), on the PEERS.md linear2d
// field scaled to about 1.75 M triangles (s = 0.025) and on a uniform refinement of the square
// (as the tool does it, the domain meshed afresh, and by adapt2d's passes alone).
// Setup: the square is adapted 3 times to the field (as the UGAWG benchmark iterates), then each
// benchmark iteration re-adapts that mesh once, as the harness's later passes do.
//   build/bench/riemesh_bench_adapt2d --benchmark_repetitions=3 --benchmark_report_aggregates_only
#include <benchmark/benchmark.h>

#include <vector>

#include "generate/regenerate2d.hpp"
#include "mesh/fixtures.hpp"
#include "metric/analytic.hpp"
#include "remesh/adapt2d.hpp"

using namespace riemesh;

namespace {


Adapt2dOptions options() {
  Adapt2dOptions o;
  o.hgrad = 0.0;
  return o;
}

void run(benchmark::State& state, const AnalyticCase& c, int setup_runs) {
  Mesh m = unit_square(20, 20);
  for (int i = 0; i < setup_runs; ++i) m = adapt2d(m, analytic_metrics(c, m), options()).mesh;
  const std::vector<SymMat2> met = analytic_metrics(c, m);
  std::size_t triangles = 0;
  for (auto _ : state) {
    const Adapt2dResult r = adapt2d(m, met, options());
    triangles = r.mesh.num_triangles();
    benchmark::DoNotOptimize(r.mesh.coords.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["tri_per_s"] =
      benchmark::Counter(static_cast<double>(triangles), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Linear2dScaled(benchmark::State& state) {
  AnalyticCase c = analytic_case("linear2d");
  c.scale = 0.025;
  run(state, c, 3);
}
BENCHMARK(BM_Linear2dScaled)->Name("adapt2d/linear2d:s=0.025")->Unit(benchmark::kSecond)->Iterations(1);

/// From the 20 x 20 square straight to a uniform size of 0.001: about 2.3 M triangles. `fresh`:
/// as `riemesh adapt --hsiz` does it, meshing the domain afresh (generate/regenerate2d.hpp);
/// otherwise adapt2d's passes alone.
void uniform_refinement(benchmark::State& state, bool fresh) {
  const Mesh m = unit_square(20, 20);
  const std::vector<SymMat2> met(m.num_vertices(), isotropic_metric<2>(0.001));
  std::size_t triangles = 0;
  for (auto _ : state) {
    const Adapt2dResult r =
        fresh ? adapt_or_regenerate2d(m, met, options()) : adapt2d(m, met, options());
    triangles = r.mesh.num_triangles();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["tri_per_s"] =
      benchmark::Counter(static_cast<double>(triangles), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_UniformRefinement(benchmark::State& state) { uniform_refinement(state, true); }
BENCHMARK(BM_UniformRefinement)->Name("adapt2d/uniform_h0.001")->Unit(benchmark::kSecond)->Iterations(1);

void BM_UniformRefinementByPasses(benchmark::State& state) { uniform_refinement(state, false); }
BENCHMARK(BM_UniformRefinementByPasses)
    ->Name("adapt2d/uniform_h0.001_passes")
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
