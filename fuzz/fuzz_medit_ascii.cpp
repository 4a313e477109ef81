// libFuzzer target: the ASCII Medit reader (.mesh) on arbitrary bytes, in memory.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // planar_as_2d flips the dimension of the result: exercise both settings.
  for (bool planar : {true, false}) {
    riemesh::fuzz::run_reader([&] {
      riemesh::MeditReadOptions options;
      options.planar_as_2d = planar;
      const riemesh::Mesh mesh =
          riemesh::medit_detail::read_medit_ascii("fuzz.mesh", text, options);
      riemesh::fuzz::expect_writable(mesh);
      riemesh::fuzz::expect_round_trip(mesh, "round_trip.meshb", options);
    });
  }
  return 0;
}
