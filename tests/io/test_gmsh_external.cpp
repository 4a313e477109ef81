// Independent readers of the .msh files Riemesh writes: meshio (python3-meshio) and gmsh itself
// (which re-saves them; Riemesh reads its output back). Skipped when not installed.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "external_tools.hpp"
#include "io/gmsh.hpp"
#include "io/medit.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

Mesh with_fields(Mesh m) {
  const std::size_t nv = m.num_vertices();
  m.fields.push_back({"u", FieldKind::kScalar, std::vector<double>(nv, 1.5)});
  m.fields.push_back({"v", FieldKind::kVector, std::vector<double>(nv * m.dim, 0.25)});
  m.fields.push_back({"metric", FieldKind::kSymTensor,
                      std::vector<double>(nv * field_components(FieldKind::kSymTensor, m.dim), 1)});
  return m;
}

// meshio's summary of a .msh written by write_gmsh: one cell block per (dimension, ref), in
// increasing dimension and ref, each with its ref as gmsh:physical.
std::string expected_msh_summary(const Mesh& m) {
  const char* names[4] = {"vertex", "line", "triangle", "tetra"};
  std::map<std::int32_t, std::size_t> by_ref[4];
  for (std::size_t v = 0; v < m.num_vertices(); ++v)
    if (m.vert_tag[v] & kTagCorner) ++by_ref[0][m.vert_ref[v]];
  for (std::int32_t r : m.edge_ref) ++by_ref[1][r];
  for (std::int32_t r : m.tri_ref) ++by_ref[2][r];
  for (std::int32_t r : m.tet_ref) ++by_ref[3][r];
  std::string counts = std::to_string(m.num_vertices()), physical;
  for (int d = 0; d < 4; ++d)
    for (const auto& [ref, n] : by_ref[d]) {
      counts += ' ';
      counts += names[d];
      counts += ':';
      counts += std::to_string(n);
      physical += " gmsh:physical[";
      physical += names[d];
      physical += "]=";
      physical += std::to_string(ref);
    }
  std::string points;
  for (const char* p : {" point:metric:9", " point:u:1", " point:v:3"})
    if (!m.fields.empty()) points += p;
  return counts + physical + points;
}

TEST(GmshExternal, MeshioReadsOurMshFiles) {
  if (!test::meshio_available()) GTEST_SKIP() << "python3-meshio not installed";
  test::ScratchDir dir;
  Mesh zero_ref = test::square_2d();
  zero_ref.tri_ref.assign(8, 0);
  zero_ref.edge_ref = {-1, -1, 2, 2, 3, 3, 0, 0};
  for (const Mesh& m : {with_fields(test::square_2d()), test::tetra_surface(),
                        with_fields(test::cube_volume()), zero_ref})
    for (bool binary : {false, true}) {
      SCOPED_TRACE(binary ? "binary" : "ascii");
      GmshWriteOptions options;
      options.binary = binary;
      write_gmsh(m, dir.file("m.msh"), options);
      EXPECT_EQ(test::meshio_summary(dir.file("m.msh")), expected_msh_summary(m));
    }
}

// Counts and refs of a mesh, to compare what gmsh re-saved with what we wrote.
std::string census(const Mesh& m) {
  auto refs = [](const std::vector<std::int32_t>& r) {
    std::string s;
    for (std::int32_t x : std::set<std::int32_t>(r.begin(), r.end())) s += ' ' + std::to_string(x);
    return s;
  };
  std::size_t corners = 0;
  for (std::uint8_t t : m.vert_tag) corners += (t & kTagCorner) != 0;
  return "dim " + std::to_string(m.dim) + " nv " + std::to_string(m.num_vertices()) + " corners " +
         std::to_string(corners) + " edges " + std::to_string(m.num_edges()) + refs(m.edge_ref) +
         " triangles " + std::to_string(m.num_triangles()) + refs(m.tri_ref) + " tets " +
         std::to_string(m.num_tets()) + refs(m.tet_ref);
}

bool gmsh_resave(const std::string& in, const std::string& out, const char* flags = "") {
  const std::string command = "gmsh '" + in + "' -0 " + flags + " -o '" + out + "' >/dev/null 2>&1";
  return std::system(command.c_str()) == 0;
}

TEST(GmshExternal, GmshReadsOurMshFiles) {
  if (!test::gmsh_available()) GTEST_SKIP() << "gmsh not installed";
  test::ScratchDir dir;
  for (const Mesh& m : {test::square_2d(), test::tetra_surface(), test::cube_volume()})
    for (bool binary : {false, true}) {
      SCOPED_TRACE(binary ? "binary" : "ascii");
      GmshWriteOptions options;
      options.binary = binary;
      write_gmsh(m, dir.file("m.msh"), options);
      ASSERT_TRUE(gmsh_resave(dir.file("m.msh"), dir.file("g.msh")));
      const Mesh back = read_gmsh(dir.file("g.msh"));
      EXPECT_EQ(census(back), census(m));
      EXPECT_EQ(back.coords, m.coords);
    }
}

TEST(GmshExternal, GmshKeepsRefZeroWithSaveAll) {
  // gmsh drops elements of physical tag 0 when re-saving (SOURCES.md) unless told to save all;
  // then it still reads them, with their entity tags.
  if (!test::gmsh_available()) GTEST_SKIP() << "gmsh not installed";
  test::ScratchDir dir;
  Mesh m = test::square_2d();
  m.tri_ref.assign(8, 0);
  write_gmsh(m, dir.file("m.msh"));
  ASSERT_TRUE(gmsh_resave(dir.file("m.msh"), dir.file("g.msh"), "-save_all"));
  const Mesh back = read_gmsh(dir.file("g.msh"));
  EXPECT_EQ(back.num_triangles(), 8u);
  EXPECT_EQ(back.num_edges(), 8u);
}

TEST(GmshExternal, GmshReadsOur3dMeditFiles) {
  if (!test::gmsh_available()) GTEST_SKIP() << "gmsh not installed";
  test::ScratchDir dir;
  for (const Mesh& m : {test::tetra_surface(), test::cube_volume()}) {
    write_medit(m, dir.file("m.mesh"));
    ASSERT_TRUE(gmsh_resave(dir.file("m.mesh"), dir.file("g.msh")));
    const Mesh back = read_gmsh(dir.file("g.msh"));
    EXPECT_EQ(back.num_vertices(), m.num_vertices());
    EXPECT_EQ(back.num_tets(), m.num_tets());
    EXPECT_EQ(back.num_triangles(), m.num_triangles());
    EXPECT_EQ(back.num_edges(), m.num_edges());
    EXPECT_EQ(back.tri_ref, m.tri_ref);
    EXPECT_EQ(back.coords, m.coords);
  }
}

}  // namespace
}  // namespace riemesh
