// .meshb reading of every file version and byte order, from fixtures encoded by the test, and
// robustness of both readers against truncated and corrupted files.
#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "io/medit_detail.hpp"
#include "io_test_util.hpp"
#include "meshb_fixture.hpp"

namespace riemesh {
namespace {

using test::MeshbFixture;

// A mesh with every keyword Riemesh reads plus two it skips (an empty Quadrilaterals section and
// an unknown code), all values exact in float so that version 1 reads them back exactly.
std::string fixture(int version, bool swapped) {
  MeshbFixture f(version, swapped, 3);
  f.keyword(4, 5);  // Vertices
  const double xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, -2.25, 1e3}};
  for (int v = 0; v < 5; ++v) {
    for (double x : xyz[v]) f.real(x);
    f.integer(v + 10);
  }
  f.keyword(7, 0);  // Quadrilaterals
  f.keyword(5, 2).integer(1).integer(2).integer(3).integer(3).integer(4).integer(-1);  // Edges
  f.keyword(6, 2);                                                                     // Triangles
  for (int t : {1, 3, 2, 7, 1, 2, 4, 8}) f.integer(t);
  f.keyword(8, 2);  // Tetrahedra
  for (int t : {1, 2, 3, 4, 2, 1, 2, 5, 3, 5}) f.integer(t);
  f.keyword(13, 2).integer(1).integer(4);       // Corners
  f.keyword(14, 1).integer(2);                  // Ridges
  f.keyword(15, 1).integer(5);                  // RequiredVertices
  f.keyword(16, 2).integer(1).integer(2);       // RequiredEdges
  f.keyword(17, 1).integer(2);                  // RequiredTriangles
  f.keyword(999, 2).integer(123).integer(456);  // not a libMeshb keyword: jumped over
  f.keyword(60, 2).real(0).real(0).real(-1).real(0.5).real(0.25).real(0.75);  // Normals
  f.keyword(20, 2).integer(1).integer(1).integer(5).integer(2);               // NormalAtVertices
  f.keyword(59, 1).real(1).real(0).real(0);                                   // Tangents
  f.keyword(61, 1).integer(2).integer(1);                                     // TangentAtVertices
  return f.finish();
}

Mesh expected() {
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, -2.25, 1e3};
  m.vert_ref = {10, 11, 12, 13, 14};
  m.vert_tag = {kTagCorner, 0, 0, kTagCorner, kTagRequired};
  m.edges = {0, 1, 2, 3};
  m.edge_ref = {3, -1};
  m.edge_tag = {kTagRequired, kTagRidge | kTagRequired};
  m.triangles = {0, 2, 1, 0, 1, 3};
  m.tri_ref = {7, 8};
  m.tri_tag = {0, kTagRequired};
  m.tets = {0, 1, 2, 3, 0, 1, 4, 2};
  m.tet_ref = {2, 5};
  m.normals = {0, 0, -1, 0.5, 0.25, 0.75};
  m.normal_at_vertex = {0, 0, 4, 1};
  m.tangents = {1, 0, 0};
  m.tangent_at_vertex = {1, 0};
  return m;
}

TEST(MeshbVersions, EveryVersionAndByteOrderReads) {
  test::ScratchDir dir;
  for (int version = 1; version <= 4; ++version) {
    for (bool swapped : {false, true}) {
      SCOPED_TRACE("version " + std::to_string(version) + (swapped ? " swapped" : ""));
      // (Built with append: GCC 12 warns wrongly on "literal" + std::string here, PR 105329.)
      std::string name = "v";
      name.append(std::to_string(version)).append(".meshb");
      const std::string path = dir.file(name);
      test::write_text(path, fixture(version, swapped));
      test::expect_same_mesh(expected(), read_medit(path));
    }
  }
}

TEST(MeshbVersions, ElementsRiemeshDoesNotReadAreRefused) {
  // libMeshb codes (GmfKwdCod) and integers per entry; they were jumped over without a word (a
  // quad mesh read as empty and valid). A RequiredQuadrilaterals list is skipped.
  struct Case {
    int code, ints;
    const char* name;
  };
  test::ScratchDir dir;
  for (const Case& c :
       {Case{7, 5, "Quadrilaterals"}, Case{9, 7, "Prisms"}, Case{10, 9, "Hexahedra"},
        Case{49, 6, "Pyramids"}, Case{24, 7, "TrianglesP2"}, Case{30, 11, "TetrahedraP2"}}) {
    for (int version : {2, 4}) {
      SCOPED_TRACE(std::string(c.name) + " version " + std::to_string(version));
      MeshbFixture f(version, false, 3);
      f.keyword(4, 4);
      for (int v = 0; v < 4; ++v) f.real(v == 1).real(v == 2).real(v == 3).integer(0);
      f.keyword(c.code, 2);
      for (int i = 0; i < 2 * c.ints; ++i) f.integer(1 + i % 4);
      const std::string path = dir.file("e.meshb");
      test::write_text(path, f.finish());
      try {
        read_medit(path);
        ADD_FAILURE() << "no error";
      } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(std::string(c.name) + ": 2 elements of a kind riemesh does not read"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("e.meshb: byte "), std::string::npos) << what;
      }
    }
  }
  MeshbFixture f(2, false, 3);
  f.keyword(4, 1).real(0).real(0).real(0).integer(0);
  f.keyword(18, 1).integer(1);  // RequiredQuadrilaterals
  const std::string path = dir.file("rq.meshb");
  test::write_text(path, f.finish());
  EXPECT_EQ(read_medit(path).num_vertices(), 1u);
}

TEST(MeshbVersions, LibraryWriterMatchesTheIndependentEncoder) {
  // Written by write_medit and by the fixture encoder with the same sections: same bytes.
  Mesh m;
  m.dim = 2;
  m.coords = {0, 0, 1, 0, 0, 1};
  m.vert_ref = {1, 2, 3};
  m.triangles = {0, 1, 2};
  m.tri_ref = {4};
  for (int version = 1; version <= 4; ++version) {
    MeshbFixture f(version, false, 2);
    f.keyword(4, 3);
    for (int v = 0; v < 3; ++v) f.real(m.coords[2 * v]).real(m.coords[2 * v + 1]).integer(v + 1);
    f.keyword(6, 1).integer(1).integer(2).integer(3).integer(4);
    test::ScratchDir dir;
    MeditWriteOptions options;
    options.binary_version = version;
    write_medit(m, dir.file("t.meshb"), options);
    EXPECT_EQ(test::read_text(dir.file("t.meshb")), f.finish()) << "version " << version;
  }
}

// Reading must end in a mesh or an InputError, whatever the bytes: never a crash, a hang, a
// huge allocation or another exception. (Run under ASan/UBSan in the sanitizer build.)
template <class Read>
void expect_mesh_or_input_error(const std::string& bytes, Read read) {
  try {
    read(bytes);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_EQ(what.rfind("f.mesh", 0), 0u) << what;
  }
}

TEST(MeshbVersions, TruncatedAndCorruptedFilesFailCleanly) {
  auto read = [](const std::string& bytes) {
    return medit_detail::read_medit_binary("f.meshb", bytes, {});
  };
  for (int version = 1; version <= 4; ++version) {
    const std::string good = fixture(version, version % 2 == 0);
    for (std::size_t n = 0; n < good.size(); ++n)
      expect_mesh_or_input_error(good.substr(0, n), read);
    std::mt19937 gen(version);
    for (std::size_t i = 0; i < good.size(); ++i) {
      const unsigned values[] = {0x00, 0x01, 0x7f, 0x80, 0xff, static_cast<unsigned>(gen() & 0xff)};
      for (unsigned value : values) {
        std::string bad = good;
        bad[i] = static_cast<char>(value);
        expect_mesh_or_input_error(bad, read);
      }
    }
  }
}

TEST(MeshbVersions, AsciiTruncationsAndCorruptionsFailCleanly) {
  auto read = [](const std::string& text) {
    return medit_detail::read_medit_ascii("f.mesh", text, {});
  };
  test::ScratchDir dir;
  write_medit(expected(), dir.file("e.mesh"));
  const std::string good = test::read_text(dir.file("e.mesh"));
  for (std::size_t n = 0; n < good.size(); ++n) expect_mesh_or_input_error(good.substr(0, n), read);
  for (std::size_t i = 0; i < good.size(); ++i) {
    for (char c : {'0', '9', '-', ' ', '\n', '#', 'x', '"', '\0'}) {
      std::string bad = good;
      bad[i] = c;
      expect_mesh_or_input_error(bad, read);
    }
  }
}

TEST(MeshbVersions, HugeCountsAreRejectedBeforeAllocating) {
  for (int version = 1; version <= 4; ++version) {
    MeshbFixture f(version, false, 3);
    f.keyword(4, version == 4 ? (std::int64_t{1} << 60) : 2147483647)
        .real(0)
        .real(0)
        .real(0)
        .integer(1);
    try {
      medit_detail::read_medit_binary("big.meshb", f.finish(), {});
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      // The count follows the header (8 bytes), Dimension (12 or 16) and the keyword's code and
      // next position (8 or 12).
      const std::string where = version < 3 ? "big.meshb: byte 28: " : "big.meshb: byte 36: ";
      EXPECT_EQ(std::string(e.what()).rfind(where + "Vertices: count ", 0), 0u) << e.what();
    }
  }
}

}  // namespace
}  // namespace riemesh
