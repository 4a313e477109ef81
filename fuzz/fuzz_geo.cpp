// libFuzzer target: the Gmsh .geo reader (parse_geo) on arbitrary text, then the geometry's
// curves and domain meshed as `riemesh mesh IN.geo` does (geo_input.hpp).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.hpp"
#include "geo_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  riemesh::fuzz::run_reader([&] {
    riemesh::fuzz::mesh_geo_text(text,
                                 [](const riemesh::Mesh& m) { riemesh::fuzz::expect_writable(m); });
  });
  return 0;
}
