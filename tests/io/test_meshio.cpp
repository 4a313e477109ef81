// Independent reader check: Debian's meshio (python3-meshio) reads the .mesh and .meshb files
// Riemesh writes. Skipped when /usr/bin/python3 cannot import meshio.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "io/medit.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

bool meshio_available() {
  return std::system("/usr/bin/python3 -c 'import meshio' >/dev/null 2>&1") == 0;
}

// What meshio reads: "<points> <coords per point> <sum of coords> type:count ...".
std::string meshio_summary(const std::string& path) {
  const std::string command =
      "/usr/bin/python3 -c 'import sys, meshio; m = meshio.read(sys.argv[1]); "
      "print(len(m.points), m.points.shape[1], repr(float(m.points.sum())), "
      "\" \".join(\"%s:%d\" % (c.type, len(c.data)) for c in m.cells))' '" +
      path + "' 2>/dev/null";
  std::FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return "popen failed";
  std::string out;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  return out;
}

// The summary meshio should give for mesh m.
void expect_meshio_reads(const Mesh& m, const std::string& path, double tolerance = 1e-9) {
  SCOPED_TRACE(path);
  const std::string got = meshio_summary(path);
  std::size_t points = 0;
  int dim = 0;
  double sum = 0;
  char cells[256] = {};
  ASSERT_EQ(std::sscanf(got.c_str(), "%zu %d %lf %255[^\n]", &points, &dim, &sum, cells), 4) << got;
  EXPECT_EQ(points, m.num_vertices());
  EXPECT_EQ(dim, m.dim);
  double expected_sum = 0;
  for (double x : m.coords) expected_sum += x;
  EXPECT_NEAR(sum, expected_sum, tolerance * (1 + std::abs(expected_sum)));
  std::string expected;
  auto add = [&](const char* type, std::size_t n) {
    if (n == 0) return;
    if (!expected.empty()) expected += ' ';
    expected.append(type).append(":").append(std::to_string(n));
  };
  add("line", m.num_edges());
  add("triangle", m.num_triangles());
  add("tetra", m.num_tets());
  EXPECT_EQ(std::string(cells), expected);
}

// meshio's ASCII reader stops at keywords it does not know (RequiredEdges, Normals...): give it
// the elements only. Its binary reader skips them by their next-keyword positions.
Mesh elements_only(Mesh m) {
  m.vert_tag.assign(m.vert_tag.size(), 0);
  m.edge_tag.assign(m.edge_tag.size(), 0);
  m.tri_tag.assign(m.tri_tag.size(), 0);
  m.normals.clear();
  m.normal_at_vertex.clear();
  m.tangents.clear();
  m.tangent_at_vertex.clear();
  return m;
}

TEST(Meshio, ReadsWhatWeWrite) {
  if (!meshio_available()) GTEST_SKIP() << "python3-meshio not installed";
  test::ScratchDir dir;
  const Mesh meshes[] = {test::square_2d(), test::tetra_surface(), test::cube_volume()};
  for (const Mesh& m : meshes) {
    write_medit(elements_only(m), dir.file("a.mesh"));
    expect_meshio_reads(m, dir.file("a.mesh"));
    for (int version : {1, 2, 3, 4}) {
      MeditWriteOptions options;
      options.binary_version = version;
      write_medit(m, dir.file("b.meshb"), options);
      expect_meshio_reads(m, dir.file("b.meshb"), version == 1 ? 1e-6 : 1e-9);  // v1: floats
    }
  }
}

TEST(Meshio, ReadsRealMeshesWeWriteBack) {
  if (!meshio_available()) GTEST_SKIP() << "python3-meshio not installed";
  test::ScratchDir dir;
  for (const char* name : {"vol/screw_vol.mesh", "2d/naca0012.mesh", "dialects/t4_gmsh2d.mesh"}) {
    const Mesh m = read_medit(test::shared_data() + "/" + name);
    write_medit(m, dir.file("c.mesh"));
    expect_meshio_reads(m, dir.file("c.mesh"));
    write_medit(m, dir.file("c.meshb"));
    expect_meshio_reads(m, dir.file("c.meshb"));
  }
}

}  // namespace
}  // namespace riemesh
