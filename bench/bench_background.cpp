// Background mesh queries: locate + metric_at (log-Euclidean) per query, on unit_square(300)
// (180,000 triangles) and unit_cube(30) (162,000 tetrahedra), for 65,536 random points visited
//   - in random order, hinted by the previous answer (long walks across the mesh),
//   - in Hilbert order, hinted by the previous answer (the remesher's case: short walks),
//   - in random order without a hint (the walk starts from the point's grid cell).
// Run: build-bg/bench/riemesh_bench_background --benchmark_repetitions=3
//        --benchmark_report_aggregates_only=true
// Counters: ns per query (ns/q) and mean walk steps per query.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "core/spd.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/hilbert.hpp"
#include "remesh/background.hpp"

using namespace riemesh;

namespace {

constexpr int kQueries = 1 << 16;

enum Order { kRandomHinted = 0, kHilbertHinted = 1, kRandomNoHint = 2 };

/// An anisotropic field, log M linear in x (ratios up to e^4 ≈ 55, rotating).
template <int D>
std::vector<double> field(const Mesh& m) {
  std::vector<double> out;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    SymMat<D> l = SymMat<D>::zero();
    for (int i = 0; i < D; ++i) l.at(i, i) = 4.0 + 4.0 * m.coords[D * v + i];
    l.at(0, 1) = 1.5 * m.coords[D * v + D - 1] - 0.5;
    const SymMat<D> s = exp_sym(l);
    out.insert(out.end(), s.c, s.c + SymMat<D>::kSize);
  }
  return out;
}

template <int D>
struct Setup {
  std::unique_ptr<BackgroundMesh<D>> bg;
  std::vector<Vec<D>> random, hilbert;
};

template <int D>
const Setup<D>& setup() {
  static const Setup<D> s = [] {
    Setup<D> r;
    const Mesh m = D == 2 ? unit_square(300, 300) : unit_cube(30);
    r.bg = std::make_unique<BackgroundMesh<D>>(m, field<D>(m));
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> flat;
    for (int q = 0; q < kQueries; ++q) {
      Vec<D> p{};
      for (int a = 0; a < D; ++a) p[a] = u(rng);
      r.random.push_back(p);
      flat.insert(flat.end(), p.x, p.x + D);
    }
    for (Id k : hilbert_order(flat, D)) r.hilbert.push_back(r.random[k]);
    return r;
  }();
  return s;
}

template <int D>
void BM_LocateMetric(benchmark::State& state) {
  const Setup<D>& s = setup<D>();
  const auto order = static_cast<Order>(state.range(0));
  const bool with_metric = state.range(1) != 0;
  const std::vector<Vec<D>>& pts = order == kHilbertHinted ? s.hilbert : s.random;
  LocateStats stats;
  Id hint = 0;
  double sink = 0.0;
  for (auto _ : state) {
    for (const Vec<D>& p : pts) {
      const Location<D> loc = s.bg->locate(p, order == kRandomNoHint ? kNoId : hint, &stats);
      hint = loc.simplex;
      if (with_metric) sink += s.bg->metric_at(loc).c[0];
    }
  }
  benchmark::DoNotOptimize(sink);
  const double queries = static_cast<double>(state.iterations()) * kQueries;
  state.counters["ns/q"] =
      benchmark::Counter(queries, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["steps/q"] = static_cast<double>(stats.walk_steps) / queries;
  state.counters["simplices"] = static_cast<double>(s.bg->num_simplices());
}

void orders(benchmark::internal::Benchmark* b) {
  b->ArgNames({"order", "metric"});
  for (int order : {kRandomHinted, kHilbertHinted, kRandomNoHint})
    for (int metric : {0, 1}) b->Args({order, metric});
  b->Unit(benchmark::kMillisecond);
}

/// Construction: validation, logs, adjacency and grid.
template <int D>
void BM_Build(benchmark::State& state) {
  const Mesh m = D == 2 ? unit_square(300, 300) : unit_cube(30);
  const std::vector<double> metrics = field<D>(m);
  for (auto _ : state) {
    BackgroundMesh<D> bg(m, metrics);
    benchmark::DoNotOptimize(&bg);
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(D == 2 ? m.num_triangles() : m.num_tets()));
  state.SetLabel("items = simplices");
}

}  // namespace

// order: 0 random hinted by the previous answer, 1 Hilbert hinted, 2 random without hint;
// metric: 0 locate only, 1 locate + metric_at.
BENCHMARK(BM_LocateMetric<2>)->Apply(orders);
BENCHMARK(BM_LocateMetric<3>)->Apply(orders);
BENCHMARK(BM_Build<2>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Build<3>)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
