// Reader bugs found by the fuzz targets (fuzz/, scripts/fuzz.sh), one test each, named after the
// bug. The fuzzer's own inputs are replayed by test_fuzz_crashers.cpp.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "io/sol.hpp"
#include "io_test_util.hpp"
#include "meshb_fixture.hpp"

namespace riemesh {
namespace {

// The error line of reading `name` (holding `bytes`) with `read`, from the file name on.
template <class Read>
std::string error_of(const std::string& name, const std::string& bytes, Read read) {
  test::ScratchDir dir;
  test::write_text(dir.file(name), bytes);
  try {
    read(dir.file(name));
  } catch (const InputError& e) {
    const std::string what = e.what();
    return what.substr(what.find(name));
  }
  return "no error";
}

// Found by fuzz_medit_ascii and fuzz_meshb: a second Dimension keyword with another value, after
// Vertices were read with the first, gave a mesh whose coords did not match its dim (3 reals
// per vertex read, then split as 2): vert_ref of another size, tets in a 2D mesh, .sol fields
// with the component count of the other dimension. A file has one dimension: now an error.
TEST(MeditRegressions, DimensionChangeAfterVerticesIsAnError) {
  const auto mesh = [](const std::string& path) { read_medit(path); };
  EXPECT_EQ(error_of("a.mesh",
                     "MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 0 0 1\n"
                     "Dimension 2\nEnd\n",
                     mesh),
            "a.mesh:5: Dimension: dimension 2 after dimension 3");
  // Header 8 bytes, Dimension 8..20, Vertices 20..60 (v2: 12 + 3 doubles + 1 int), then the
  // second Dimension: code and next position, its value at byte 68.
  test::MeshbFixture bin(2, false, 3);
  bin.keyword(4, 1).real(0).real(0).real(0).integer(1).keyword(3).i32(2);
  EXPECT_EQ(error_of("a.meshb", bin.finish(), mesh),
            "a.meshb: byte 68: Dimension: dimension 2 after dimension 3");

  // A 3D tensor then a 2D scalar: read as dimension 2, the tensor had 6 values per vertex
  // where 3 were expected. (For a 3D mesh: for a planar one the tensor section is refused
  // first, SolTensorOfAnotherDimensionIsNamedFirst.)
  const auto sol = [](const std::string& path) { read_sol(path, 1, 3); };
  EXPECT_EQ(error_of("a.sol",
                     "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n1\n1 3\n1 0 1 0 0 1\n"
                     "Dimension 2\nSolAtVertices\n1\n1 1\n5\nEnd\n",
                     sol),
            "a.sol:7: Dimension: dimension 2 after dimension 3");
  test::MeshbFixture solb(2, false, 3);
  solb.keyword(62, 1).i32(1).i32(3);
  for (double x : {1, 0, 1, 0, 0, 1}) solb.real(x);
  solb.keyword(3).i32(2);  // at 88 (8 + 12 + 12 + 8 + 48), value at 96
  EXPECT_EQ(error_of("a.solb", solb.finish(), sol),
            "a.solb: byte 96: Dimension: dimension 2 after dimension 3");
}

TEST(MeditRegressions, SolTensorOfAnotherDimensionIsNamedFirst) {
  // A Dimension 3 metric (6 values per vertex) written with 3 values per line for a planar
  // mesh: "expected a real number, found 'End'" at the end of the file; now the section.
  const auto sol2 = [](const std::string& path) { read_sol(path, 2, 2); };
  EXPECT_EQ(
      error_of("a.sol",
               "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n2\n1 3\n1 0 1\n1 0 1\nEnd\n",
               sol2),
      "a.sol:5: SolAtVertices: the file is in dimension 3 but the mesh in dimension 2");
  // Scalars serve any dimension.
  EXPECT_EQ(
      error_of("b.sol", "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n2\n1 1\n1\n2\nEnd\n",
               sol2),
      "no error");
}

TEST(MeditRegressions, RepeatedSameDimensionIsFine) {
  test::ScratchDir dir;
  test::write_text(dir.file("a.mesh"),
                   "Dimension 2\nVertices 1\n0 0 1\nDimension 2\nVertices 1\n1 0 2\nEnd\n");
  const Mesh m = read_medit(dir.file("a.mesh"));
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.coords, (std::vector<double>{0, 0, 1, 0}));
  EXPECT_EQ(m.vert_ref, (std::vector<std::int32_t>{1, 2}));
}

}  // namespace
}  // namespace riemesh
