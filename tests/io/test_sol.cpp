// Medit .sol / .solb: several fields per file, types 1-3, versions, errors.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/sol.hpp"
#include "io_test_util.hpp"
#include "meshb_fixture.hpp"

namespace riemesh {
namespace {

std::vector<Field> three_fields_2d() {
  // 3 vertices: a scalar, a vector (2 values) and a tensor (m11 m12 m22) per vertex.
  return {Field{"a", FieldKind::kScalar, {1.5, -2, 0.1}},
          Field{"b", FieldKind::kVector, {1, 2, 3, 4, 5, 6}},
          Field{"c", FieldKind::kSymTensor, {10, 0.5, 20, 11, -0.5, 21, 12, 0, 1.0 / 3.0}}};
}

TEST(Sol, RoundTripOfSeveralFields) {
  test::ScratchDir dir;
  for (const char* name : {"f.sol", "f.solb"}) {
    for (int version : {0, 2, 3, 4}) {
      SolWriteOptions options;
      options.binary_version = version;
      write_sol(dir.file(name), three_fields_2d(), 2, options);
      const std::vector<Field> back = read_sol(dir.file(name), 3, 2);
      ASSERT_EQ(back.size(), 3u);
      const std::vector<Field> in = three_fields_2d();
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(back[k].name, "sol" + std::to_string(k));
        EXPECT_EQ(back[k].kind, in[k].kind);
        EXPECT_EQ(back[k].values, in[k].values) << name << " field " << k;
      }
    }
  }
}

TEST(Sol, AsciiLayoutIsInterleavedPerVertex) {
  test::ScratchDir dir;
  write_sol(dir.file("f.sol"), three_fields_2d(), 2);
  EXPECT_EQ(test::read_text(dir.file("f.sol")),
            "MeshVersionFormatted 2\n\nDimension 2\n\nSolAtVertices\n3\n3 1 2 3\n"
            "1.5 1 2 10 0.5 20\n-2 3 4 11 -0.5 21\n0.1 5 6 12 0 0.3333333333333333\n\nEnd\n");
}

TEST(Sol, SingleTensorIsTheMetric3d) {
  test::ScratchDir dir;
  const std::vector<Field> m = {Field{"metric", FieldKind::kSymTensor, {1, 2, 3, 4, 5, 6}}};
  write_sol(dir.file("m.solb"), m, 3);
  const std::vector<Field> back = read_sol(dir.file("m.solb"), 1, 3);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].name, "metric");
  EXPECT_EQ(back[0].values, m[0].values);  // m11 m12 m22 m13 m23 m33, as stored
}

TEST(Sol, BinaryFixturesOfEveryVersionAndByteOrder) {
  test::ScratchDir dir;
  for (int version = 1; version <= 4; ++version) {
    for (bool swapped : {false, true}) {
      test::MeshbFixture f(version, swapped, 3);
      f.keyword(62, 2).i32(2).i32(1).i32(2);  // SolAtVertices: 2 vertices, scalar + vector
      for (double x : {1.0, 2.0, 3.0, 4.0, 0.5, 0.25, -8.0, 16.0}) f.real(x);
      test::write_text(dir.file("f.solb"), f.finish());
      const std::vector<Field> fields = read_sol(dir.file("f.solb"), 2, 3);
      ASSERT_EQ(fields.size(), 2u);
      EXPECT_EQ(fields[0].values, (std::vector<double>{1, 0.5}));
      EXPECT_EQ(fields[1].values, (std::vector<double>{2, 3, 4, 0.25, -8, 16}));
    }
  }
}

TEST(Sol, ScalarFieldsOfAnotherDimensionAreAccepted) {
  // A Dimension 3 .sol of a mesh read as planar: scalars are usable, vectors are not.
  test::ScratchDir dir;
  test::write_text(dir.file("s.sol"),
                   "MeshVersionFormatted 2\nDimension 3\nSolAtVertices\n2\n1 1\n5\n6\nEnd\n");
  EXPECT_EQ(read_sol(dir.file("s.sol"), 2, 2)[0].values, (std::vector<double>{5, 6}));
  test::write_text(dir.file("v.sol"), "Dimension 3\nSolAtVertices 1 1 2 1 2 3\n");
  EXPECT_THROW(read_sol(dir.file("v.sol"), 1, 2), InputError);
}

struct BadSol {
  const char* text;
  const char* message;
};

const BadSol kBadSol[] = {
    {"Dimension 2\nSolAtVertices\n3\n1 1\n1\n2\n3\n",
     "s.sol:3: SolAtVertices: 3 values for a mesh of 2 vertices"},
    {"Dimension 2\nSolAtVertices\n2\n1 4\n1 2 3 4\n5 6 7 8\n",
     "s.sol:4: SolAtVertices: unsupported solution type 4 (1 scalar, 2 vector, 3 symmetric "
     "tensor)"},
    {"Dimension 2\nSolAtVertices\n2\n0\n",
     "s.sol:4: SolAtVertices: bad number of solution types 0"},
    {"Dimension 2\nSolAtVertices\n2\n1 3\n1 2 3\n",
     "s.sol:4: SolAtVertices: count 2 is larger than"},
    {"Dimension 2\nSolAtVertices\n2\n1 1\n1\nnan\n",
     "s.sol:6: SolAtVertices: non-finite value 'nan'"},
    {"SolAtVertices\n2\n1 1\n1\n2\n", "s.sol:1: SolAtVertices: no Dimension keyword"},
    {"Dimension 2\nEnd\n", "s.sol: SolAtVertices: no solution at vertices in the file"},
};

TEST(Sol, Errors) {
  test::ScratchDir dir;
  const std::string prefix = dir.path().string() + "/";
  for (const BadSol& bad : kBadSol) {
    SCOPED_TRACE(bad.text);
    test::write_text(dir.file("s.sol"), bad.text);
    try {
      read_sol(dir.file("s.sol"), 2, 2);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(prefix + bad.message, 0), 0u) << e.what();
    }
  }
  test::MeshbFixture f(2, false, 2);
  f.keyword(62, 1000000).i32(1).i32(1).real(1);
  test::write_text(dir.file("s.solb"), f.finish());
  try {
    read_sol(dir.file("s.solb"), 1000000, 2);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(
                  prefix + "s.solb: byte 28: SolAtVertices: count 1000000 needs more bytes", 0),
              0u)
        << e.what();
  }
}

TEST(Sol, PerElementSectionsRoundTrip) {
  // A mesh of 4 vertices, 3 triangles and 2 tetrahedra (counts only matter to the reader).
  Mesh mesh;
  mesh.coords.assign(12, 0.0);
  mesh.triangles.assign(9, 0);
  mesh.tets.assign(8, 0);
  test::ScratchDir dir;
  struct Case {
    SolLocation at;
    const char* keyword;
    std::size_t n;
  };
  for (const Case c : {Case{SolLocation::kTriangles, "SolAtTriangles", 3},
                       Case{SolLocation::kTetrahedra, "SolAtTetrahedra", 2},
                       Case{SolLocation::kVertices, "SolAtVertices", 4}}) {
    const std::vector<Field> in = {
        Field{"a", FieldKind::kScalar, std::vector<double>(c.n, 0.25)},
        Field{"b", FieldKind::kVector, std::vector<double>(3 * c.n, -1.5)}};
    for (const char* name : {"p.sol", "p.solb"}) {
      SolWriteOptions o;
      o.location = c.at;
      write_sol(dir.file(name), in, 3, o);
      const SolData back = read_sol_any(dir.file(name), mesh);
      EXPECT_EQ(back.location, c.at) << name;
      ASSERT_EQ(back.fields.size(), 2u);
      EXPECT_EQ(back.fields[0].values, in[0].values);
      EXPECT_EQ(back.fields[1].values, in[1].values);
    }
    EXPECT_NE(test::read_text(dir.file("p.sol")).find(c.keyword), std::string::npos);
    EXPECT_EQ(std::string(sol_keyword(c.at)), c.keyword);
  }
}

TEST(Sol, PerElementCountsAreChecked) {
  test::ScratchDir dir;
  Mesh mesh;
  mesh.dim = 2;
  mesh.coords.assign(8, 0.0);
  mesh.triangles.assign(6, 0);  // 2 triangles
  test::write_text(dir.file("t.sol"), "Dimension 2\nSolAtTriangles\n3\n1 1\n1\n2\n3\nEnd\n");
  try {
    read_sol_any(dir.file("t.sol"), mesh);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("3 values for a mesh of 2 triangles"), std::string::npos)
        << e.what();
  }
  // A per-vertex read of a per-element file says there is no vertex solution.
  EXPECT_THROW(read_sol(dir.file("t.sol"), mesh), InputError);
  test::write_text(dir.file("e.sol"), "Dimension 2\nEnd\n");
  EXPECT_THROW(read_sol_any(dir.file("e.sol"), mesh), InputError);
}

TEST(Sol, WriteRejectsInconsistentFields) {
  test::ScratchDir dir;
  std::vector<Field> fields = three_fields_2d();
  fields[1].values.pop_back();
  EXPECT_THROW(write_sol(dir.file("x.sol"), fields, 2), Error);
  EXPECT_THROW(write_sol(dir.file("x.sol"), {}, 2), Error);
  EXPECT_THROW(write_sol(dir.file("x.sol"), three_fields_2d(), 4), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace riemesh
