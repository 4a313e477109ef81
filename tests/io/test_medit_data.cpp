// The real meshes of ../shared/data (see its SOURCES.md): each reads with the counts the data
// sheet states, and writes back (.mesh and .meshb) to an identical mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "io/medit.hpp"
#include "io/sol.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

struct DataFile {
  const char* path;
  int dim;
  std::size_t vertices, edges, triangles, tets;
};

// Counts from SOURCES.md; edge counts of the 3D files from their Edges sections.
const DataFile kFiles[] = {
    {"2d/naca0012.mesh", 2, 2028, 190, 3866, 0},
    {"2d/aile.mesh", 2, 112, 40, 184, 0},
    {"2d/lac-leman.mesh", 2, 726, 163, 1287, 0},
    {"surf/bunny.mesh", 3, 1839, 0, 3674, 0},
    {"surf/fandisk.mesh", 3, 6475, 0, 12946, 0},
    {"surf/rotor.mesh", 3, 600, 0, 1200, 0},
    {"surf/elephant.mesh", 3, 2775, 0, 5558, 0},
    {"vol/bunny_vol.mesh", 3, 2868, 0, 3674, 11555},
    {"vol/screw_vol.mesh", 3, 1531, 195, 2162, 5793},
    {"formats/bunny_vol.meshb", 3, 2868, 0, 3674, 11555},
    {"formats/lshape.mesh", 2, 372, 80, 662, 0},
    {"dialects/aile_freefem.mesh", 2, 112, 40, 184, 0},
    {"dialects/t4_gmsh2d.mesh", 2, 787, 159, 1449, 0},  // Dimension 3, z = 0: read as 2D
    {"dialects/dodecaedre01.mesh", 3, 216, 0, 240, 867},
    {"dialects/cgal_sphere.mesh", 3, 757, 0, 694, 3586},
};

std::string data(const char* relative) { return test::shared_data() + "/" + relative; }

TEST(MeditData, EveryFileReadsWithItsCounts) {
  for (const DataFile& f : kFiles) {
    SCOPED_TRACE(f.path);
    const Mesh m = read_medit(data(f.path));
    EXPECT_EQ(m.dim, f.dim);
    EXPECT_EQ(m.num_vertices(), f.vertices);
    EXPECT_EQ(m.num_edges(), f.edges);
    EXPECT_EQ(m.num_triangles(), f.triangles);
    EXPECT_EQ(m.num_tets(), f.tets);
  }
}

TEST(MeditData, EveryFileWritesBackIdentically) {
  test::ScratchDir dir;
  for (const DataFile& f : kFiles) {
    SCOPED_TRACE(f.path);
    const Mesh m = read_medit(data(f.path));
    for (const char* name : {"out.mesh", "out.meshb"}) {
      write_medit(m, dir.file(name));
      test::expect_same_mesh(m, read_medit(dir.file(name)));
    }
  }
}

TEST(MeditData, BinaryBunnyMatchesAscii) {
  // formats/bunny_vol.meshb is FreeFem's binary save of vol/bunny_vol.mesh. FreeFem turns the
  // boundary triangles over (it swaps their first two vertices): compare them as vertex sets.
  const Mesh ascii = read_medit(data("vol/bunny_vol.mesh"));
  const Mesh binary = read_medit(data("formats/bunny_vol.meshb"));
  EXPECT_EQ(binary.tets, ascii.tets);
  auto sorted_triangles = [](std::vector<Id> t) {
    for (std::size_t i = 0; i < t.size(); i += 3) std::sort(t.begin() + i, t.begin() + i + 3);
    return t;
  };
  EXPECT_EQ(sorted_triangles(binary.triangles), sorted_triangles(ascii.triangles));
  EXPECT_EQ(binary.tri_ref, ascii.tri_ref);
  EXPECT_EQ(binary.tet_ref, ascii.tet_ref);
  ASSERT_EQ(binary.coords.size(), ascii.coords.size());
  for (std::size_t i = 0; i < ascii.coords.size(); ++i)
    ASSERT_NEAR(binary.coords[i], ascii.coords[i], 1e-12 * (1 + std::abs(ascii.coords[i]))) << i;
}

TEST(MeditData, FreeFemDialectMatchesPlainFile) {
  // aile_freefem.mesh (with BAMG keywords) and 2d/aile.mesh hold the same mesh.
  const Mesh plain = read_medit(data("2d/aile.mesh"));
  const Mesh dialect = read_medit(data("dialects/aile_freefem.mesh"));
  EXPECT_EQ(dialect.coords, plain.coords);
  EXPECT_EQ(dialect.triangles, plain.triangles);
  EXPECT_EQ(dialect.edges, plain.edges);
}

TEST(MeditData, LShapeSolutionAndMetric) {
  const Mesh mesh = read_medit(data("formats/lshape.mesh"));
  const std::vector<Field> u = read_sol(data("formats/lshape.sol"), mesh);
  ASSERT_EQ(u.size(), 1u);
  EXPECT_EQ(u[0].name, "sol0");
  EXPECT_EQ(u[0].kind, FieldKind::kScalar);
  ASSERT_EQ(u[0].values.size(), 372u);
  EXPECT_EQ(u[0].values[3], 0.037849369836684382);  // 4th value of the file
  const std::vector<Field> metric = read_sol(data("formats/lshape_metric.sol"), mesh);
  ASSERT_EQ(metric.size(), 1u);
  EXPECT_EQ(metric[0].name, "metric");
  EXPECT_EQ(metric[0].kind, FieldKind::kSymTensor);
  ASSERT_EQ(metric[0].values.size(), 3u * 372u);
  EXPECT_EQ(metric[0].values[1], -7847.0588977439884);  // m12 of vertex 1

  test::ScratchDir dir;
  for (const char* name : {"m.sol", "m.solb"}) {
    write_sol(dir.file(name), metric, 2);
    const std::vector<Field> back = read_sol(dir.file(name), mesh);
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].values, metric[0].values);
  }
}

}  // namespace
}  // namespace riemesh
