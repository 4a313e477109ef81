// Malformed Medit input: each snippet gives one InputError line naming the file, the keyword and
// the line (ASCII) or byte offset (binary).
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "io/sol.hpp"
#include "io_test_util.hpp"
#include "meshb_fixture.hpp"

namespace riemesh {
namespace {

struct BadInput {
  bool head;  // prefixed with kHead
  const char* text;
  const char* message;  // expected to start the error, after "<dir>/"; null: no error
};

const char kHead[] = "MeshVersionFormatted 2\nDimension 2\n";  // lines 1-2

const BadInput kBadAscii[] = {
    {false, "", "bad.mesh: Dimension: missing"},
    {false, "MeshVersionFormatted 7\n", "bad.mesh:1: MeshVersionFormatted: unknown version 7"},
    {false, "MeshVersionFormatted\n", "bad.mesh:1: MeshVersionFormatted: unexpected end of file"},
    {false, "Dimension 4\n", "bad.mesh:1: Dimension: dimension 4 (2 or 3 expected)"},
    {false, "Dimension two\n", "bad.mesh:1: Dimension: expected an integer, found 'two'"},
    {false, "Vertices 1\n0 0 0\n", "bad.mesh:1: Vertices: no Dimension keyword"},
    {false, "@Dimension 2\n", "bad.mesh:1: expected a keyword, found '@Dimension'"},
    // Lines below count from 3 (after kHead).
    {true, "Vertices\n-1\n", "bad.mesh:4: Vertices: negative count -1"},
    {true, "Vertices\n1000000000\n0 0 1\n",
     "bad.mesh:4: Vertices: count 1000000000 is larger than"},
    {true, "Vertices\n2\n0 0 1\n", "bad.mesh:4: Vertices: count 2 is larger than the rest"},
    {true, "Vertices\n2\n0 0 1\n# cut short here\n",
     "bad.mesh:5: Vertices: unexpected end of file, expected a real"},
    {true, "Vertices\n2\n0 0 1\n1 1 2\nEnd", nullptr},  // fine
    {true, "Vertices\n2\n0 0 1\n1 nan 2\n", "bad.mesh:6: Vertices: non-finite value 'nan'"},
    {true, "Vertices\n2\n0 0 1\n1 inf 2\n", "bad.mesh:6: Vertices: non-finite value 'inf'"},
    {true, "Vertices\n2\n0 0 1\n1 1e999 2\n", "bad.mesh:6: Vertices: non-finite value '1e999'"},
    {true, "Vertices\n2\n0 0 1\n1 0x1 2\n",
     "bad.mesh:6: Vertices: expected a real number, found '0x1'"},
    {true, "Vertices\n2\n0 0 1\n1 1 2.5\n",
     "bad.mesh:6: Vertices: expected an integer, found '2.5'"},
    {true, "Vertices\n1\n0 0 99999999999\n",
     "bad.mesh:5: Vertices: reference 99999999999 does not fit"},
    {true, "Vertices\n1\n0 0 1\n2 2 2\n",
     "bad.mesh:6: Vertices: expected a keyword after the Vertices section, found '2'"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n1\n1 2 0 1\n",
     "bad.mesh:9: Triangles: id 0 out of range (ids start at 1)"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n2\n1 2 3 1\n\n1 2\n4 1\n",
     "bad.mesh:12: Triangles: vertex id 4 out of range (the file has 3 vertices)"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n1\n1 2 3\n",
     "bad.mesh:9: Triangles: unexpected end of file, expected an integer"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nTriangles\n2\n1 2 3 0\nEnd # one triangle short\n",
     "bad.mesh:10: Triangles: expected an integer, found 'End'"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nTetrahedra 1\n1 2 3 3 0\n",
     "bad.mesh:7: Tetrahedra: tetrahedra in a 2D mesh"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nEdges 1\n1 2 0\nRidges 1\n2\n",
     "bad.mesh:10: Ridges: edge id 2 out of range (the file has 1 edge)"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nCorners 1\n4\n",
     "bad.mesh:8: Corners: vertex id 4 out of range (the file has 3 vertices)"},
    {true, "Vertices 3\n0 0 0\n1 0 0\n0 1 0\nRequiredTriangles 1 1\n",
     "bad.mesh:7: RequiredTriangles: triangle id 1 out of range (the file has 0 triangles)"},
    {true, "Vertices 1\n0 0 0\nNormals 1\n0 1\nNormalAtVertices 1\n1 2\n",
     "bad.mesh:8: NormalAtVertices: normal id 2 out of range (the file has 1 normal)"},
    {true, "Quadrilaterals 2\n1 2 3 4 0\n", "bad.mesh:3: Quadrilaterals: count 2 is larger than"},
    {true, "Quadrilaterals 2\n1 2 3 4 0\n# padding padding padding\n",
     "bad.mesh:3: Quadrilaterals: 2 elements of a kind riemesh does not read (it reads linear "
     "Edges, Triangles and Tetrahedra only)"},
    {true, "TrianglesP2 1\n1 2 3 4 5 6 0\n# padding padding padding\n",
     "bad.mesh:3: TrianglesP2: 1 elements of a kind riemesh does not read"},
};

TEST(MeditErrors, AsciiTable) {
  test::ScratchDir dir;
  const std::string path = dir.file("bad.mesh");
  const std::string prefix = dir.path().string() + "/";
  for (const BadInput& bad : kBadAscii) {
    const std::string text = (bad.head ? std::string(kHead) : std::string()) + bad.text;
    SCOPED_TRACE(text);
    test::write_text(path, text);
    if (!bad.message) {
      EXPECT_NO_THROW(read_medit(path));
      continue;
    }
    try {
      read_medit(path);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(prefix + bad.message, 0), 0u) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos);
    }
  }
}

std::string binary_error(const std::string& bytes) {
  test::ScratchDir dir;
  test::write_text(dir.file("bad.meshb"), bytes);
  try {
    read_medit(dir.file("bad.meshb"));
  } catch (const InputError& e) {
    const std::string what = e.what();
    return what.substr(what.find("bad.meshb"));
  }
  return "no error";
}

TEST(MeditErrors, Binary) {
  using test::MeshbFixture;
  EXPECT_EQ(binary_error(""), "bad.meshb: byte 0: file too short for a .meshb/.solb header");
  EXPECT_EQ(binary_error(std::string("\x02\0\0\0\x02\0\0\0", 8)),
            "bad.meshb: byte 0: bad endianness marker 2 (not a binary Medit file?)");
  EXPECT_EQ(binary_error(std::string("\x01\0\0\0\x05\0\0\0", 8)),
            "bad.meshb: byte 4: unknown file version 5");
  // Dimension 4.
  EXPECT_EQ(binary_error(MeshbFixture(2, false, 4).finish()),
            "bad.meshb: byte 16: Dimension: dimension 4 (2 or 3 expected)");
  // Vertices cut in the middle.
  MeshbFixture two(2, false, 2);
  two.keyword(4, 2).real(0).real(0).integer(1).real(1).real(1).integer(1);  // data 32..72
  std::string cut = two.bytes().substr(0, 60);
  EXPECT_EQ(binary_error(cut),
            "bad.meshb: byte 28: Vertices: count 2 needs more bytes than the 28 left in the file");
  EXPECT_EQ(binary_error(two.bytes() + "\x36"),
            "bad.meshb: byte 72: file truncated (8 bytes needed, 1 left)");
  // A NaN coordinate.
  EXPECT_EQ(
      binary_error(MeshbFixture(2, false, 2).keyword(4, 1).real(0).real(NAN).integer(1).finish()),
      "bad.meshb: byte 40: Vertices: non-finite value");
  // A triangle naming vertex 3 of 2, then vertex 0.
  MeshbFixture tri(3, true, 2);
  tri.keyword(4, 2).real(0).real(0).integer(1).real(1).real(0).integer(1);
  tri.keyword(6, 1).integer(1).integer(2).integer(3).integer(0);
  EXPECT_EQ(binary_error(tri.finish()),
            "bad.meshb: byte 104: Triangles: vertex id 3 out of range (the file has 2 vertices)");
  MeshbFixture zero(2, false, 2);
  zero.keyword(4, 1).real(0).real(0).integer(1).keyword(13, 1).integer(0);
  EXPECT_EQ(binary_error(zero.finish()),
            "bad.meshb: byte 64: Corners: id 0 out of range (ids start at 1)");
  // Negative count.
  EXPECT_EQ(binary_error(MeshbFixture(4, false, 3).keyword(6).integer(-3).finish()),
            "bad.meshb: byte 36: Triangles: negative count -3");
  // A next-keyword position pointing backwards (would loop) or past the end.
  std::string loop = MeshbFixture(2, false, 3).keyword(999, 0).finish();
  loop[24] = 8;
  EXPECT_EQ(binary_error(loop),
            "bad.meshb: byte 24: keyword 999: next keyword position 8 outside the file (40 bytes)");
}

TEST(MeditErrors, FileNames) {
  EXPECT_THROW(read_medit("/nonexistent/x.mesh"), InputError);
  EXPECT_THROW(read_medit("x.stl"), InputError);
  try {
    read_medit("/nonexistent/x.meshb");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent/x.meshb: cannot open", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace riemesh
