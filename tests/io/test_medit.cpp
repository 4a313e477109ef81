// Medit .mesh / .meshb: round trips of meshes built in code, and the ASCII dialect features.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/medit.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

using test::expect_same_mesh;
using test::ScratchDir;

struct Case {
  const char* name;
  Mesh (*make)();
};

const Case kMeshes[] = {{"square_2d", test::square_2d},
                        {"tetra_surface", test::tetra_surface},
                        {"cube_volume", test::cube_volume}};

TEST(Medit, AsciiRoundTripIsIdentical) {
  ScratchDir dir;
  for (const Case& c : kMeshes) {
    SCOPED_TRACE(c.name);
    const Mesh m = c.make();
    const std::string path = dir.file(std::string(c.name) + ".mesh");
    write_medit(m, path);
    expect_same_mesh(m, read_medit(path));
  }
}

TEST(Medit, BinaryRoundTripIsIdenticalForVersions2To4) {
  ScratchDir dir;
  for (const Case& c : kMeshes) {
    for (int version : {0, 2, 3, 4}) {
      SCOPED_TRACE(std::string(c.name) + " version " + std::to_string(version));
      const Mesh m = c.make();
      const std::string path = dir.file(std::string(c.name) + ".meshb");
      MeditWriteOptions options;
      options.binary_version = version;
      write_medit(m, path, options);
      expect_same_mesh(m, read_medit(path));
    }
  }
}

TEST(Medit, BinaryVersion1StoresFloats) {
  // Version 1 holds 32-bit reals: the cube's coordinates (0 and 1) survive, 0.1/3 is rounded.
  ScratchDir dir;
  MeditWriteOptions options;
  options.binary_version = 1;
  const Mesh cube = test::cube_volume();
  write_medit(cube, dir.file("cube.meshb"), options);
  expect_same_mesh(cube, read_medit(dir.file("cube.meshb")));

  const Mesh square = test::square_2d();
  write_medit(square, dir.file("square.meshb"), options);
  const Mesh back = read_medit(dir.file("square.meshb"));
  EXPECT_EQ(back.coords[9], static_cast<double>(static_cast<float>(square.coords[9])));
  EXPECT_EQ(back.triangles, square.triangles);
}

TEST(Medit, DefaultBinaryIsVersion2) {
  ScratchDir dir;
  write_medit(test::cube_volume(), dir.file("cube.meshb"));
  const std::string bytes = test::read_text(dir.file("cube.meshb"));
  ASSERT_GE(bytes.size(), 20u);
  std::int32_t header[5];
  std::memcpy(header, bytes.data(), sizeof header);
  EXPECT_EQ(header[0], 1);   // endianness marker
  EXPECT_EQ(header[1], 2);   // version
  EXPECT_EQ(header[2], 3);   // GmfDimension
  EXPECT_EQ(header[3], 20);  // next keyword right after the dimension value
  EXPECT_EQ(header[4], 3);
}

TEST(Medit, AsciiAndBinaryAgree) {
  ScratchDir dir;
  const Mesh m = test::tetra_surface();
  write_medit(m, dir.file("a.mesh"));
  write_medit(read_medit(dir.file("a.mesh")), dir.file("b.meshb"));
  write_medit(read_medit(dir.file("b.meshb")), dir.file("c.mesh"));
  EXPECT_EQ(test::read_text(dir.file("a.mesh")), test::read_text(dir.file("c.mesh")));
}

TEST(Medit, AsciiRealsAreExact) {
  // Shortest round-trip output: awkward doubles come back bit for bit.
  Mesh m;
  m.dim = 3;
  m.coords = {0.1, 1.0 / 3.0, -2.5e-310, 1e300, -0.0, 6.02214076e23, 5e-324, 1.7976931348623157e308,
              1};
  ScratchDir dir;
  write_medit(m, dir.file("reals.mesh"));
  const Mesh back = read_medit(dir.file("reals.mesh"));
  ASSERT_EQ(back.coords.size(), m.coords.size());
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    EXPECT_EQ(std::memcmp(&back.coords[i], &m.coords[i], sizeof(double)), 0) << i;
}

TEST(Medit, PlanarMeshWrittenCounterClockwise) {
  Mesh m = test::square_2d();
  std::swap(m.triangles[1], m.triangles[2]);  // make triangle 0 clockwise
  ScratchDir dir;
  write_medit(m, dir.file("cw.mesh"));
  const std::string text = test::read_text(dir.file("cw.mesh"));
  EXPECT_NE(text.find("Dimension 2\n"), std::string::npos);
  const Mesh back = read_medit(dir.file("cw.mesh"));
  EXPECT_EQ(back.triangles, test::square_2d().triangles);

  MeditWriteOptions keep;
  keep.ccw_2d = false;
  write_medit(m, dir.file("kept.mesh"), keep);
  EXPECT_EQ(read_medit(dir.file("kept.mesh")).triangles, m.triangles);
}

TEST(Medit, EmptyArraysOfRefsAndTagsWriteZeros) {
  Mesh m = test::cube_volume();
  m.vert_ref.clear();
  m.tet_ref.clear();
  m.vert_tag.clear();
  m.edge_tag.clear();
  ScratchDir dir;
  write_medit(m, dir.file("bare.mesh"));
  const Mesh back = read_medit(dir.file("bare.mesh"));
  EXPECT_EQ(back.vert_ref, std::vector<std::int32_t>(8, 0));
  EXPECT_EQ(back.tet_ref, std::vector<std::int32_t>(6, 0));
  EXPECT_EQ(back.vert_tag, std::vector<std::uint8_t>(8, kTagNone));
}

TEST(Medit, WriteRejectsBrokenMeshesAndLeavesNoFile) {
  Mesh m = test::cube_volume();
  m.tets[5] = 8;  // out of range
  ScratchDir dir;
  EXPECT_THROW(write_medit(m, dir.file("bad.mesh")), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  EXPECT_THROW(write_medit(test::cube_volume(), dir.file("bad.txt")), InputError);
  EXPECT_THROW(write_medit(test::cube_volume(), dir.file("missing/x.mesh")), Error);
}

TEST(Medit, PlanarAsTwoD) {
  const std::string text =
      "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 1\n1 0 0 2\n0 1 0 3\n"
      "Triangles\n1\n1 2 3 4\nEdges\n1\n1 2 9\nEnd\n";
  ScratchDir dir;
  test::write_text(dir.file("flat.mesh"), text);
  const Mesh m = read_medit(dir.file("flat.mesh"));
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.coords, (std::vector<double>{0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(m.kind(), MeshKind::kPlanar);

  MeditReadOptions keep;
  keep.planar_as_2d = false;
  EXPECT_EQ(read_medit(dir.file("flat.mesh"), keep).dim, 3);

  test::write_text(
      dir.file("bent.mesh"),
      "Dimension 3\nVertices 3\n0 0 0 1\n1 0 0 2\n0 1 1e-300 3\nTriangles 1\n1 2 3 4\n");
  EXPECT_EQ(read_medit(dir.file("bent.mesh")).dim, 3);

  // All clockwise (Gmsh's mesh of a clockwise loop): the same mesh turned over, edges too.
  const std::string square = "Dimension 3\nVertices 4\n0 0 0 0\n1 0 0 0\n1 1 0 0\n0 1 0 0\n";
  test::write_text(dir.file("cw.mesh"), square + "Triangles 2\n1 3 2 1\n1 4 3 1\nEdges 1\n1 4 7\n");
  const Mesh cw = read_medit(dir.file("cw.mesh"));
  EXPECT_EQ(cw.dim, 2);
  EXPECT_EQ(cw.triangles, (std::vector<Id>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(cw.edges, (std::vector<Id>{3, 0}));
  // Both orientations: no planar mesh, a surface lying in z = 0 (it was made planar, and
  // `convert` turned half of it over).
  test::write_text(dir.file("mixed.mesh"), square + "Triangles 2\n1 3 2 1\n1 3 4 1\n");
  const Mesh mixed = read_medit(dir.file("mixed.mesh"));
  EXPECT_EQ(mixed.dim, 3);
  EXPECT_EQ(mixed.triangles, (std::vector<Id>{0, 2, 1, 0, 2, 3}));
  // Each ref its own way (Gmsh's mesh of two surfaces, one loop given clockwise): planar, the
  // clockwise ref turned over (it was a surface in z = 0, adapted as one: QA hunt 5 F11).
  test::write_text(dir.file("by_ref.mesh"), square + "Triangles 2\n1 3 2 1\n1 3 4 2\n");
  const Mesh by_ref = read_medit(dir.file("by_ref.mesh"));
  EXPECT_EQ(by_ref.dim, 2);
  EXPECT_EQ(by_ref.triangles, (std::vector<Id>{0, 1, 2, 0, 2, 3}));
}

TEST(Medit, AsciiDialects) {
  // Mixed case, comments, counts on the keyword line or the next, unknown keywords with and
  // without a known layout, BAMG strings, repeated sections (meshio), no End; an empty section
  // of elements riemesh does not read (a non-empty one is refused: MeditErrors.AsciiTable).
  const std::string text =
      "\xEF\xBB\xBF# header comment (after a UTF-8 byte-order mark)\n"
      "meshversionformatted\n1\n\n"
      "DIMENSION 2 # inline comment\n"
      "Identifier\n\"some name, Date: 1/2/3\"\n"
      "Geometry\n\"side.gmsh\"\n"
      "vertices 2\n0 0 1\n1 0 2\n"
      "Vertices\n  2\n1 1 3\n0 1 4\n"
      "Quadrilaterals 0\n"
      "triangles\n1\n1 2 3 5\n"
      "SubDomainFromGeom\n1\n2 35 1 1\n"
      "Triangles 1 1 3 4 6\n"
      "VertexOnGeometricEdge\n0\n"
      "Corners 2 1 3\n";
  ScratchDir dir;
  test::write_text(dir.file("dialect.mesh"), text);
  const Mesh m = read_medit(dir.file("dialect.mesh"));
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.coords, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1}));
  EXPECT_EQ(m.vert_ref, (std::vector<std::int32_t>{1, 2, 3, 4}));
  EXPECT_EQ(m.triangles, (std::vector<Id>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.tri_ref, (std::vector<std::int32_t>{5, 6}));
  EXPECT_EQ(m.vert_tag, (std::vector<std::uint8_t>{kTagCorner, 0, kTagCorner, 0}));
}

TEST(Medit, SectionsInAnyOrder) {
  // libMeshb files may list elements before vertices: ids are checked once all is read.
  ScratchDir dir;
  test::write_text(dir.file("order.mesh"),
                   "Dimension 3\nRidges 1 1\nEdges 1 1 3 0\nTriangles 1\n1 2 3 0\n"
                   "Vertices 3\n0 0 0 0\n1 0 0 0\n0 1 0.5 0\nEnd\n");
  const Mesh m = read_medit(dir.file("order.mesh"));
  EXPECT_EQ(m.num_triangles(), 1u);
  EXPECT_EQ(m.edge_tag, (std::vector<std::uint8_t>{kTagRidge}));
}

TEST(Medit, TwoDimensionalNormalsAndTangents) {
  Mesh m = test::square_2d();
  m.normals = {0, -1, 0, 1, 0, 0};
  m.normal_at_vertex = {1, 0, 5, 1};
  m.tangents = {1, 0, 0};
  m.tangent_at_vertex = {1, 0};
  ScratchDir dir;
  for (const char* name : {"n.mesh", "n.meshb"}) {
    write_medit(m, dir.file(name));
    expect_same_mesh(m, read_medit(dir.file(name)));
  }
}

}  // namespace
}  // namespace riemesh
