// read_mesh / write_mesh: the format follows the extension; every format round-trips what it
// can hold; unknown extensions and reading .vtu are one-line InputErrors.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "io/gmsh.hpp"
#include "io/mesh_file.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

TEST(MeshFile, FormatByExtension) {
  EXPECT_EQ(mesh_format("a/b.mesh"), MeshFormat::kMedit);
  EXPECT_EQ(mesh_format("b.meshb"), MeshFormat::kMeditBinary);
  EXPECT_EQ(mesh_format("x.y/b.msh"), MeshFormat::kGmsh);
  EXPECT_EQ(mesh_format("b.vtu"), MeshFormat::kVtu);
  try {
    mesh_format("dir.v2/out.stl");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "dir.v2/out.stl: unknown mesh file extension '.stl' (.mesh, .meshb, .msh or .vtu "
                 "expected)");
  }
  try {
    mesh_format("dir.v2/noext");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_STREQ(
        e.what(),
        "dir.v2/noext: unknown mesh file extension (.mesh, .meshb, .msh or .vtu expected)");
  }
}

TEST(MeshFile, RoundTripsThroughEveryReadableFormat) {
  test::ScratchDir dir;
  const Mesh cube = test::cube_volume();  // elements sorted by ref: .msh keeps their order
  for (const char* name : {"c.mesh", "c.meshb", "c.msh"}) {
    SCOPED_TRACE(name);
    write_mesh(cube, dir.file(name));
    const Mesh back = read_mesh(dir.file(name));
    EXPECT_EQ(back.coords, cube.coords);
    EXPECT_EQ(back.tets, cube.tets);
    EXPECT_EQ(back.tet_ref, cube.tet_ref);
    EXPECT_EQ(back.triangles, cube.triangles);
    EXPECT_EQ(back.tri_ref, cube.tri_ref);
    EXPECT_EQ(back.edges, cube.edges);
    EXPECT_EQ(back.edge_ref, cube.edge_ref);
  }
  MeshWriteOptions options;
  options.gmsh_binary = true;
  write_mesh(cube, dir.file("b.msh"), options);
  GmshReadInfo info;
  read_gmsh(dir.file("b.msh"), {}, &info);
  EXPECT_TRUE(info.binary);
  EXPECT_EQ(read_mesh(dir.file("b.msh")).tets, cube.tets);
  // Medit -> Gmsh -> Medit, as `riemesh convert` does.
  write_mesh(read_mesh(dir.file("c.mesh")), dir.file("d.msh"));
  write_mesh(read_mesh(dir.file("d.msh")), dir.file("d.mesh"));
  EXPECT_EQ(read_mesh(dir.file("d.mesh")).tets, cube.tets);
}

TEST(MeshFile, VtuIsWriteOnly) {
  test::ScratchDir dir;
  write_mesh(test::square_2d(), dir.file("s.vtu"));
  EXPECT_TRUE(std::filesystem::exists(dir.file("s.vtu")));
  try {
    read_mesh(dir.file("s.vtu"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.vtu: reading .vtu files is not supported"),
              std::string::npos);
  }
}

TEST(MeshFile, UnknownExtensionWritesNothing) {
  test::ScratchDir dir;
  EXPECT_THROW(write_mesh(test::square_2d(), dir.file("s.obj")), InputError);
  EXPECT_THROW(read_mesh(dir.file("s.obj")), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(MeshFile, SharedDataThroughEveryFormat) {
  const std::string data = test::shared_data();
  const Mesh medit = read_mesh(data + "/vol/bunny_vol.mesh");
  const Mesh msh = read_mesh(data + "/formats/bunny_vol.msh");
  const Mesh meshb = read_mesh(data + "/formats/bunny_vol.meshb");
  EXPECT_EQ(msh.num_vertices(), medit.num_vertices());
  EXPECT_EQ(msh.tets, medit.tets);
  EXPECT_EQ(meshb.tets, medit.tets);
  const Mesh naca = read_mesh(data + "/formats/naca0012_v22.msh");
  EXPECT_EQ(naca.dim, 2);
  EXPECT_EQ(naca.num_triangles(), 3866u);
}

}  // namespace
}  // namespace riemesh
