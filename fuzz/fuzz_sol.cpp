// libFuzzer target: the Medit solution readers (.sol and .solb) on arbitrary bytes, in memory.
// The input starts with the format, dimension and vertex count (sol_input.hpp).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_common.hpp"
#include "sol_input.hpp"

namespace {

// What read_sol promises: at least one field, each of a known kind with num_vertices times its
// component count of finite values.
void expect_consistent(const std::vector<riemesh::Field>& fields,
                       const riemesh::fuzz::SolInput& in) {
  if (fields.empty()) {
    std::fprintf(stderr, "read_sol returned no field\n");
    std::abort();
  }
  for (const riemesh::Field& f : fields) {
    const int kind = static_cast<int>(f.kind);
    bool ok = kind >= 1 && kind <= 3 &&
              f.values.size() ==
                  in.num_vertices * static_cast<std::size_t>(field_components(f.kind, in.dim));
    for (double x : f.values) ok = ok && std::isfinite(x);
    if (!ok) {
      std::fprintf(stderr, "read_sol returned field %s of kind %d with %zu values\n",
                   f.name.c_str(), kind, f.values.size());
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  riemesh::fuzz::SolInput in;
  if (!riemesh::fuzz::decode_sol_input(data, size, in)) return 0;
  riemesh::fuzz::run_reader([&] {
    expect_consistent(
        riemesh::medit_detail::read_sol_bytes(in.path, in.bytes, in.num_vertices, in.dim), in);
  });
  return 0;
}
