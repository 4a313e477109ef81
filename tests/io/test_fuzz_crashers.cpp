// Replays the inputs on which a fuzz target (fuzz/fuzz_<target>.cpp) once failed, kept in
// tests/io/crashers/<target>/: each must now be read, or rejected with a riemesh::Error, through
// the same entry point the target calls; a mesh that is read must pass the writers' check.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../../fuzz/geo_input.hpp"
#include "../../fuzz/sol_input.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/medit_detail.hpp"

namespace riemesh {
namespace {

namespace fs = std::filesystem;

fs::path crasher_root() { return fs::path(RIEMESH_TEST_DIR) / "io" / "crashers"; }

// Reads an input the way fuzz/fuzz_<target>.cpp does; false if there is no such target.
bool replay(const std::string& target, const std::string& bytes) {
  if (target == "medit_ascii" || target == "meshb") {
    for (bool planar : {true, false}) {
      MeditReadOptions options;
      options.planar_as_2d = planar;
      try {
        const Mesh m = target == "meshb"
                           ? medit_detail::read_medit_binary("crasher.meshb", bytes, options)
                           : medit_detail::read_medit_ascii("crasher.mesh", bytes, options);
        EXPECT_NO_THROW(medit_detail::check_writable(m, "crasher"));
      } catch (const Error&) {
      }
    }
    return true;
  }
  if (target == "sol") {
    fuzz::SolInput in;
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    if (!fuzz::decode_sol_input(data, bytes.size(), in)) return true;
    try {
      for (const Field& f :
           medit_detail::read_sol_bytes(in.path, in.bytes, in.num_vertices, in.dim))
        EXPECT_EQ(f.values.size(),
                  in.num_vertices * static_cast<std::size_t>(field_components(f.kind, in.dim)));
    } catch (const Error&) {
    }
    return true;
  }
  if (target == "geo") {
    try {
      fuzz::mesh_geo_text(bytes, [](const Mesh& m) {
        EXPECT_NO_THROW(medit_detail::check_writable(m, "crasher"));
      });
    } catch (const Error&) {
    }
    return true;
  }
  return false;
}

TEST(FuzzCrashers, ReadOrRejectedWithAnError) {
  ASSERT_TRUE(fs::is_directory(crasher_root())) << crasher_root();
  int replayed = 0;
  for (const fs::directory_entry& dir : fs::directory_iterator(crasher_root())) {
    if (!dir.is_directory()) continue;
    const std::string target = dir.path().filename().string();
    for (const fs::directory_entry& file : fs::directory_iterator(dir.path())) {
      SCOPED_TRACE(file.path().string());
      try {
        EXPECT_TRUE(replay(target, read_file_bytes(file.path().string())))
            << "no replay for the fuzz target " << target << ": add it to replay()";
      } catch (const std::exception& e) {
        ADD_FAILURE() << "unexpected exception: " << e.what();
      }
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0);
}

}  // namespace
}  // namespace riemesh
