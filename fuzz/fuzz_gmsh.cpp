// libFuzzer target: the Gmsh reader (.msh 4.1 and 2.2, ASCII and binary, $NodeData) on arbitrary
// bytes, in memory (read_gmsh_bytes).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fuzz_common.hpp"
#include "io/gmsh.hpp"

namespace {

// Fields read from $NodeData must have a value set per vertex of the mesh.
void expect_fields_sized(const riemesh::Mesh& mesh) {
  for (const riemesh::Field& f : mesh.fields) {
    const std::size_t c = static_cast<std::size_t>(field_components(f.kind, mesh.dim));
    if (f.values.size() != mesh.num_vertices() * c) {
      std::fprintf(stderr, "field %s has %zu values for %zu vertices\n", f.name.c_str(),
                   f.values.size(), mesh.num_vertices());
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  for (bool planar : {true, false}) {
    riemesh::fuzz::run_reader([&] {
      riemesh::GmshReadOptions options;
      options.planar_as_2d = planar;
      riemesh::GmshReadInfo info;
      const riemesh::Mesh mesh = riemesh::read_gmsh_bytes("fuzz.msh", bytes, options, &info);
      riemesh::fuzz::expect_writable(mesh);
      expect_fields_sized(mesh);
    });
  }
  return 0;
}
