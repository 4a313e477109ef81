// Conservative P0 transfer between planar meshes of the unit square, about 1 M triangles each:
//   same:    perturbed unit_square(700, 700) (980,000 triangles) onto perturbed
//            unit_square(690, 720) (993,600 triangles): unrelated meshes of the same resolution;
//   coarse:  perturbed unit_square(350, 350) (245,000) onto the 993,600-triangle mesh;
//   fine:    the 993,600-triangle mesh onto perturbed unit_square(350, 350);
//   tets:    perturbed unit_cube(55) (998,250 tetrahedra) onto perturbed unit_cube(50) (750,000).
// Interior vertices are moved at random by up to 0.2 cell (all triangles stay valid), so no
// edge is shared by accident.
// The time includes building the background mesh (grid, adjacency) of the old mesh.
// Run: build/bench/riemesh_bench_transfer_p0 --benchmark_repetitions=3
//        --benchmark_report_aggregates_only=true
// Counters: overlapping pairs per new element, ns per new element (tri), relative mass error.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "mesh/fixtures.hpp"
#include "remesh/transfer.hpp"

using namespace riemesh;

namespace {

const Mesh& mesh(int which) {
  if (which >= 3) {
    static const Mesh d = perturbed_unit_cube(55, 0.1, 4), e = perturbed_unit_cube(50, 0.1, 5);
    return which == 3 ? d : e;
  }
  static const Mesh a = perturbed_unit_square(700, 700, 0.2, 1), b = perturbed_unit_square(690, 720, 0.2, 2),
                    c = perturbed_unit_square(350, 350, 0.2, 3);
  return which == 0 ? a : which == 1 ? b : c;
}

void run(benchmark::State& state, int from_id, int to_id) {
  const Mesh& from = mesh(from_id);
  const Mesh& to = mesh(to_id);
  Field f{"rho", FieldKind::kScalar, {}};
  const std::size_t ne = from.tets.empty() ? from.num_triangles() : from.num_tets();
  for (std::size_t t = 0; t < ne; ++t) f.values.push_back(1.0 + (t % 7));
  P0TransferReport r;
  for (auto _ : state) {
    std::vector<Field> out = transfer_p0(from, {f}, to, &r);
    benchmark::DoNotOptimize(out.data());
  }
  const double nt = static_cast<double>(to.tets.empty() ? to.num_triangles() : to.num_tets());
  state.counters["pairs/tri"] = static_cast<double>(r.pairs) / nt;
  state.counters["ns/tri"] =
      benchmark::Counter(nt, benchmark::Counter::kIsIterationInvariantRate |
                                 benchmark::Counter::kInvert);
  state.counters["mass_rel_err"] =
      std::abs(r.new_integral[0] - r.old_integral[0]) / std::abs(r.old_integral[0]);
}

void BM_Same(benchmark::State& s) { run(s, 0, 1); }
void BM_CoarseToFine(benchmark::State& s) { run(s, 2, 1); }
void BM_FineToCoarse(benchmark::State& s) { run(s, 1, 2); }
void BM_Tets(benchmark::State& s) { run(s, 3, 4); }

}  // namespace

BENCHMARK(BM_Same)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_CoarseToFine)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_FineToCoarse)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Tets)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
