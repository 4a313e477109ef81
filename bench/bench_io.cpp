// Medit I/O throughput on unit_cube(55): 175,616 vertices, 998,250 tetrahedra, 36,300 boundary
// triangles. The mesh is written once to a scratch folder (.meshb version 2 and .mesh); reads
// and writes then report bytes of file per second. "Parse" is the read without the file system
// (bytes already in memory), to tell parsing from I/O. Issue #3 targets: .meshb read >= 300 MB/s,
// .mesh read >= 50 MB/s.
// Run: build/bench/riemesh_bench_io --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true     (quote the medians)
#include <benchmark/benchmark.h>
#include <stdlib.h>

#include <filesystem>
#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"
#include "io/medit.hpp"
#include "io/medit_detail.hpp"
#include "mesh/fixtures.hpp"

using namespace riemesh;

namespace {

constexpr int kCubeCells = 55;

/// unit_cube(55) and its two files, made on first use, removed at exit.
class Fixture {
 public:
  static const Fixture& get() {
    static const Fixture fixture;
    return fixture;
  }
  ~Fixture() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  const Mesh& mesh() const { return mesh_; }
  std::string file(const char* name) const { return (dir_ / name).string(); }
  std::size_t size(const char* name) const { return std::filesystem::file_size(file(name)); }

 private:
  Fixture() : mesh_(unit_cube(kCubeCells)) {
    std::string pattern =
        (std::filesystem::temp_directory_path() / "riemesh_bench_io_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    dir_ = pattern;
    write_medit(mesh_, file("cube.meshb"));
    write_medit(mesh_, file("cube.mesh"));
  }
  Mesh mesh_;
  std::filesystem::path dir_;
};

void set_counters(benchmark::State& state, std::size_t file_bytes, const Mesh& m) {
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * file_bytes));
  state.counters["file_MB"] = static_cast<double>(file_bytes) / 1e6;
  state.counters["tets"] = static_cast<double>(m.num_tets());
}

void read_bench(benchmark::State& state, const char* name) {
  const Fixture& f = Fixture::get();
  const std::string path = f.file(name);
  for (auto _ : state) {
    Mesh m = read_medit(path);
    benchmark::DoNotOptimize(m.tets.data());
  }
  set_counters(state, f.size(name), f.mesh());
}

void parse_bench(benchmark::State& state, const char* name) {
  const Fixture& f = Fixture::get();
  const std::string bytes = read_file_bytes(f.file(name));
  const bool binary = medit_detail::ends_with(name, ".meshb");
  for (auto _ : state) {
    Mesh m = binary ? medit_detail::read_medit_binary(name, bytes, {})
                    : medit_detail::read_medit_ascii(name, bytes, {});
    benchmark::DoNotOptimize(m.tets.data());
  }
  set_counters(state, bytes.size(), f.mesh());
}

void write_bench(benchmark::State& state, const char* name) {
  const Fixture& f = Fixture::get();
  const std::string path = f.file(name);
  for (auto _ : state) write_medit(f.mesh(), path);
  set_counters(state, f.size(name), f.mesh());
}

void BM_MeshbRead(benchmark::State& state) { read_bench(state, "cube.meshb"); }
void BM_MeshbParse(benchmark::State& state) { parse_bench(state, "cube.meshb"); }
void BM_MeshbWrite(benchmark::State& state) { write_bench(state, "cube.meshb"); }
void BM_MeshRead(benchmark::State& state) { read_bench(state, "cube.mesh"); }
void BM_MeshParse(benchmark::State& state) { parse_bench(state, "cube.mesh"); }
void BM_MeshWrite(benchmark::State& state) { write_bench(state, "cube.mesh"); }

// Real time: writes spend part of their time in the kernel (and the rename).
BENCHMARK(BM_MeshbRead)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MeshbParse)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MeshbWrite)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MeshRead)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MeshParse)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MeshWrite)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
