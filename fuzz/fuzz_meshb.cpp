// libFuzzer target: the binary Medit reader (.meshb, versions 1-4, both byte orders) on
// arbitrary bytes, in memory.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (bool planar : {true, false}) {
    riemesh::fuzz::run_reader([&] {
      riemesh::MeditReadOptions options;
      options.planar_as_2d = planar;
      const riemesh::Mesh mesh =
          riemesh::medit_detail::read_medit_binary("fuzz.meshb", bytes, options);
      riemesh::fuzz::expect_writable(mesh);
      riemesh::fuzz::expect_round_trip(mesh, "round_trip.mesh", options);
    });
  }
  return 0;
}
