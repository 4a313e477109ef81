// Gmsh .msh: round trips through MSH 4.1 ASCII and binary, the shared data files (4.1 and 2.2,
// and gmsh's own binary output when gmsh is installed), fields as $NodeData.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <set>

#include "core/error.hpp"
#include "external_tools.hpp"
#include "io/gmsh.hpp"
#include "io/medit.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

// Stable sort of elements (stride ids each) by ref: the order write_gmsh writes them in.
void sort_by_ref(std::vector<Id>& ids, std::vector<std::int32_t>& refs, int stride) {
  std::vector<std::size_t> order(refs.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return refs[a] < refs[b]; });
  std::vector<Id> sorted_ids;
  std::vector<std::int32_t> sorted_refs;
  for (std::size_t e : order) {
    sorted_refs.push_back(refs[e]);
    for (int k = 0; k < stride; ++k) sorted_ids.push_back(ids[e * stride + k]);
  }
  ids = std::move(sorted_ids);
  refs = std::move(sorted_refs);
}

// What a .msh file keeps of a mesh: elements grouped by ref, corner tags with their vertex
// refs; no other vertex refs, no ridge/required tags, no normals or tangents.
Mesh gmsh_view(Mesh m) {
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    m.vert_tag[v] &= kTagCorner;
    if (!m.vert_tag[v]) m.vert_ref[v] = 0;
  }
  sort_by_ref(m.edges, m.edge_ref, 2);
  sort_by_ref(m.triangles, m.tri_ref, 3);
  sort_by_ref(m.tets, m.tet_ref, 4);
  m.edge_tag.assign(m.num_edges(), kTagNone);
  m.tri_tag.assign(m.num_triangles(), kTagNone);
  m.normals.clear();
  m.normal_at_vertex.clear();
  m.tangents.clear();
  m.tangent_at_vertex.clear();
  return m;
}

// Adds a scalar, a vector and a metric field (non-short reals) to m.
Mesh with_fields(Mesh m) {
  const std::size_t nv = m.num_vertices();
  Field s{"u", FieldKind::kScalar, {}}, v{"velocity", FieldKind::kVector, {}},
      t{"metric", FieldKind::kSymTensor, {}};
  for (std::size_t i = 0; i < nv; ++i) {
    s.values.push_back(1.0 / (3.0 + i));
    for (int k = 0; k < m.dim; ++k) v.values.push_back(k - 0.1 * i);
    for (int k = 0; k < field_components(FieldKind::kSymTensor, m.dim); ++k)
      t.values.push_back(k % 2 ? 0.1 / (1 + i) : 2.0 + i + k);
  }
  m.fields = {s, v, t};
  return m;
}

void expect_same_fields(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.fields.size(), b.fields.size());
  for (std::size_t i = 0; i < a.fields.size(); ++i) {
    EXPECT_EQ(a.fields[i].name, b.fields[i].name);
    EXPECT_EQ(a.fields[i].kind, b.fields[i].kind);
    EXPECT_EQ(a.fields[i].values, b.fields[i].values) << a.fields[i].name;
  }
}

TEST(Gmsh, RoundTripsAsciiAndBinary) {
  test::ScratchDir dir;
  const Mesh meshes[] = {test::square_2d(), test::tetra_surface(), test::cube_volume()};
  for (const Mesh& m : meshes)
    for (bool binary : {false, true}) {
      SCOPED_TRACE(binary ? "binary" : "ascii");
      GmshWriteOptions options;
      options.binary = binary;
      write_gmsh(m, dir.file("a.msh"), options);
      GmshReadInfo info;
      const Mesh back = read_gmsh(dir.file("a.msh"), {}, &info);
      EXPECT_EQ(info.version, 4.1);
      EXPECT_EQ(info.binary, binary);
      EXPECT_TRUE(info.skipped_elements.empty());
      test::expect_same_mesh(gmsh_view(m), back);
      // Written again, the file is the same byte for byte.
      write_gmsh(back, dir.file("b.msh"), options);
      EXPECT_EQ(test::read_text(dir.file("a.msh")), test::read_text(dir.file("b.msh")));
    }
}

TEST(Gmsh, SortedElementsKeepTheirOrder) {
  // cube_volume's elements are sorted by ref already: nothing moves.
  const Mesh m = test::cube_volume();
  test::ScratchDir dir;
  write_gmsh(m, dir.file("c.msh"));
  const Mesh back = read_gmsh(dir.file("c.msh"));
  EXPECT_EQ(back.tets, m.tets);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.edges, m.edges);
  EXPECT_EQ(back.coords, m.coords);
}

TEST(Gmsh, ZeroAndNegativeRefsRoundTrip) {
  Mesh m = test::square_2d();
  m.tri_ref = {0, 0, -3, -3, 5, 5, 0, 0};
  m.edge_ref = {0, 0, 2, 2, -1, -1, 7, 7};
  m.vert_ref[0] = 0;
  m.vert_ref[8] = -2;
  test::ScratchDir dir;
  for (bool binary : {false, true}) {
    GmshWriteOptions options;
    options.binary = binary;
    write_gmsh(m, dir.file("z.msh"), options);
    test::expect_same_mesh(gmsh_view(m), read_gmsh(dir.file("z.msh")));
  }
}

TEST(Gmsh, FieldsRoundTripAsNodeData) {
  test::ScratchDir dir;
  for (const Mesh& m : {with_fields(test::square_2d()), with_fields(test::cube_volume())})
    for (bool binary : {false, true}) {
      GmshWriteOptions options;
      options.binary = binary;
      write_gmsh(m, dir.file("f.msh"), options);
      const Mesh back = read_gmsh(dir.file("f.msh"));
      test::expect_same_mesh(gmsh_view(m), back);
      expect_same_fields(m, back);
      options.fields = false;
      write_gmsh(m, dir.file("g.msh"), options);
      EXPECT_TRUE(read_gmsh(dir.file("g.msh")).fields.empty());
    }
}

TEST(Gmsh, EmptyAndVertexOnlyMeshes) {
  test::ScratchDir dir;
  Mesh empty;
  write_gmsh(empty, dir.file("e.msh"));
  const Mesh e = read_gmsh(dir.file("e.msh"));
  EXPECT_EQ(e.num_vertices(), 0u);
  Mesh points;
  points.dim = 3;
  points.coords = {0, 0, 1, 2, 3, 4};
  for (bool binary : {false, true}) {
    GmshWriteOptions options;
    options.binary = binary;
    write_gmsh(points, dir.file("p.msh"), options);
    const Mesh p = read_gmsh(dir.file("p.msh"));
    EXPECT_EQ(p.coords, points.coords);
    EXPECT_EQ(p.num_triangles(), 0u);
  }
}

TEST(Gmsh, Msh22CopiesPerPhysicalGroupAreOneElement) {
  // gmsh writes a 2.2 element once per physical group of its entity (here triangle 1 of entity
  // 1 in groups 7 and 8, edge 1-2 of entity 2 in groups 10 and 30): every element was doubled.
  test::ScratchDir dir;
  test::write_text(dir.file("m.msh"),
                   "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n"
                   "3 1 1 0\n4 0 1 0\n$EndNodes\n$Elements\n6\n"
                   "1 1 2 10 2 1 2\n2 1 2 30 2 1 2\n"
                   "3 2 2 7 1 1 2 3\n4 2 2 8 1 1 2 3\n5 2 2 7 1 1 3 4\n6 2 2 8 1 1 3 4\n"
                   "$EndElements\n");
  const Mesh m = read_gmsh(dir.file("m.msh"));
  EXPECT_EQ(m.num_triangles(), 2u);
  EXPECT_EQ(m.tri_ref, (std::vector<std::int32_t>{7, 7}));
  EXPECT_EQ(m.edge_ref, (std::vector<std::int32_t>{10}));
}

TEST(Gmsh, PlanarOptionKeepsZ) {
  test::ScratchDir dir;
  write_gmsh(test::square_2d(), dir.file("s.msh"));
  GmshReadOptions options;
  options.planar_as_2d = false;
  const Mesh m = read_gmsh(dir.file("s.msh"), options);
  EXPECT_EQ(m.dim, 3);
  EXPECT_EQ(m.num_vertices(), 9u);
}

// ---- shared data -----------------------------------------------------------------------------

std::set<std::int32_t> distinct(const std::vector<std::int32_t>& refs) {
  return {refs.begin(), refs.end()};
}

void expect_bunny(const Mesh& m, const Mesh& medit) {
  EXPECT_EQ(m.dim, 3);
  ASSERT_EQ(m.num_vertices(), 2868u);
  EXPECT_EQ(m.num_tets(), 11555u);
  EXPECT_EQ(m.num_triangles(), 3674u);
  EXPECT_EQ(m.num_edges(), 0u);
  EXPECT_EQ(distinct(m.tri_ref), std::set<std::int32_t>{1});
  EXPECT_EQ(distinct(m.tet_ref), std::set<std::int32_t>{1});
  // gmsh kept the vertices and elements of the .mesh in order.
  ASSERT_EQ(m.coords.size(), medit.coords.size());
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    ASSERT_NEAR(m.coords[i], medit.coords[i], 1e-12 * (1 + std::abs(medit.coords[i])));
  EXPECT_EQ(m.tets, medit.tets);
  EXPECT_EQ(m.triangles, medit.triangles);
}

TEST(GmshData, BunnyFilesMatchTheMeditFile) {
  const std::string data = test::shared_data();
  const Mesh medit = read_medit(data + "/vol/bunny_vol.mesh");
  GmshReadInfo info;
  expect_bunny(read_gmsh(data + "/formats/bunny_vol.msh", {}, &info), medit);
  EXPECT_EQ(info.version, 4.1);
  expect_bunny(read_gmsh(data + "/formats/bunny_vol_v22.msh", {}, &info), medit);
  EXPECT_EQ(info.version, 2.2);
  EXPECT_FALSE(info.binary);
}

TEST(GmshData, Naca22ReadsAsPlanar) {
  const std::string data = test::shared_data();
  const Mesh m = read_gmsh(data + "/formats/naca0012_v22.msh");
  const Mesh medit = read_medit(data + "/2d/naca0012.mesh");
  EXPECT_EQ(m.dim, 2);
  EXPECT_EQ(m.num_vertices(), 2028u);
  EXPECT_EQ(m.num_triangles(), 3866u);
  EXPECT_EQ(m.num_edges(), 190u);
  EXPECT_EQ(distinct(m.edge_ref), (std::set<std::int32_t>{1, 99}));
  EXPECT_EQ(distinct(m.tri_ref), std::set<std::int32_t>{1});  // ref 0 became 1 (SOURCES.md)
  ASSERT_EQ(m.coords.size(), medit.coords.size());
  for (std::size_t i = 0; i < m.coords.size(); ++i)
    ASSERT_NEAR(m.coords[i], medit.coords[i], 1e-12);
  EXPECT_EQ(m.triangles, medit.triangles);
}

TEST(GmshData, ReadsWhatGmshWritesInEveryEncoding) {
  if (!test::gmsh_available()) GTEST_SKIP() << "gmsh not installed";
  test::ScratchDir dir;
  const std::string data = test::shared_data();
  const Mesh medit = read_medit(data + "/vol/bunny_vol.mesh");
  const char* variants[][2] = {{"-bin -format msh41", "b41.msh"},
                               {"-bin -format msh22", "b22.msh"},
                               {"-format msh41", "a41.msh"}};
  for (const auto& [flags, name] : variants) {
    SCOPED_TRACE(flags);
    const std::string out = dir.file(name);
    ASSERT_EQ(std::system(("gmsh '" + data + "/vol/bunny_vol.mesh' -0 " + flags + " -o '" + out +
                           "' >/dev/null 2>&1")
                              .c_str()),
              0);
    GmshReadInfo info;
    expect_bunny(read_gmsh(out, {}, &info), medit);
    EXPECT_EQ(info.binary, std::string(flags).find("-bin") != std::string::npos);
  }
}

}  // namespace
}  // namespace riemesh
