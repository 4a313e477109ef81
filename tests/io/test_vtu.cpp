// VTK .vtu output: the XML header and the raw appended arrays read back by a small parser here,
// then by meshio (and VTK's own reader when python3-vtk9 is installed).
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "core/error.hpp"
#include "external_tools.hpp"
#include "io/vtu.hpp"
#include "io_test_util.hpp"

namespace riemesh {
namespace {

// The arrays of a .vtu written by write_vtu: "Name" (or "Points") -> raw bytes, found through
// each DataArray's offset into the appended data and its UInt64 size header. PointData comes
// first in the file: the CellData array of a name already seen is stored as "cell <name>".
std::map<std::string, std::string> appended_arrays(const std::string& text) {
  std::map<std::string, std::string> arrays;
  const std::size_t base = text.find("<AppendedData encoding=\"raw\">\n_");
  if (base == std::string::npos) return arrays;
  const std::size_t data = base + std::strlen("<AppendedData encoding=\"raw\">\n_");
  std::size_t at = 0;
  while ((at = text.find("<DataArray ", at)) != std::string::npos && at < base) {
    const std::size_t end = text.find("/>", at);
    const std::string element = text.substr(at, end - at);
    std::string name = "Points";
    const std::size_t n = element.find("Name=\"");
    if (n != std::string::npos) name = element.substr(n + 6, element.find('"', n + 6) - n - 6);
    const std::size_t o = element.find("offset=\"");
    const std::size_t offset = std::stoull(element.substr(o + 8));
    std::uint64_t size = 0;
    std::memcpy(&size, text.data() + data + offset, 8);
    arrays[arrays.count(name) ? "cell " + name : name] = text.substr(data + offset + 8, size);
    at = end;
  }
  return arrays;
}

template <class T>
std::vector<T> as(const std::string& bytes) {
  std::vector<T> v(bytes.size() / sizeof(T));
  std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
  return v;
}

TEST(Vtu, ArraysHoldTheMesh) {
  Mesh m = test::cube_volume();
  m.fields.push_back({"metric", FieldKind::kSymTensor, {}});
  for (int v = 0; v < 8; ++v)  // m11 m12 m22 m13 m23 m33 = 1 2 3 4 5 6 (+10 v)
    for (int k = 1; k <= 6; ++k) m.fields.back().values.push_back(k + 10.0 * v);
  test::ScratchDir dir;
  write_vtu(m, dir.file("c.vtu"));
  const std::string text = test::read_text(dir.file("c.vtu"));
  EXPECT_NE(text.find("NumberOfPoints=\"8\" NumberOfCells=\"30\""), std::string::npos);
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  const auto arrays = appended_arrays(text);
  const auto point_ref = as<std::int32_t>(arrays.at("ref"));
  const auto cell_ref = as<std::int32_t>(arrays.at("cell ref"));
  EXPECT_EQ(point_ref, m.vert_ref);
  std::vector<std::int32_t> refs = m.tet_ref;
  refs.insert(refs.end(), m.tri_ref.begin(), m.tri_ref.end());
  refs.insert(refs.end(), m.edge_ref.begin(), m.edge_ref.end());
  EXPECT_EQ(cell_ref, refs);
  const auto dims = as<std::uint8_t>(arrays.at("dim"));
  ASSERT_EQ(dims.size(), 30u);
  EXPECT_EQ(dims[0], 3);
  EXPECT_EQ(dims[6], 2);
  EXPECT_EQ(dims[29], 1);
  EXPECT_EQ(as<double>(arrays.at("Points")), m.coords);
  const auto connectivity = as<std::int64_t>(arrays.at("connectivity"));
  ASSERT_EQ(connectivity.size(), 24u + 36u + 24u);
  for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(connectivity[i], m.tets[i]);
  const auto offsets = as<std::int64_t>(arrays.at("offsets"));
  EXPECT_EQ(offsets.front(), 4);
  EXPECT_EQ(offsets.back(), 84);
  const auto types = as<std::uint8_t>(arrays.at("types"));
  EXPECT_EQ(types.front(), 10);  // VTK_TETRA
  EXPECT_EQ(types[6], 5);        // VTK_TRIANGLE
  EXPECT_EQ(types.back(), 3);    // VTK_LINE
  // Tensor in VTK order XX YY ZZ XY YZ XZ = m11 m22 m33 m12 m23 m13 = 1 3 6 2 5 4 (+10 v).
  const auto metric = as<double>(arrays.at("metric"));
  ASSERT_EQ(metric.size(), 48u);
  const double expected[6] = {1, 3, 6, 2, 5, 4};
  for (int v = 0; v < 8; ++v)
    for (int k = 0; k < 6; ++k) EXPECT_EQ(metric[6 * v + k], expected[k] + 10.0 * v);
}

TEST(Vtu, PlanarMeshGetsZeroZAndPaddedFields) {
  Mesh m = test::square_2d();
  m.fields.push_back({"v", FieldKind::kVector, std::vector<double>(18, 2.0)});
  m.fields.push_back({"m", FieldKind::kSymTensor, {}});
  for (int v = 0; v < 9; ++v)
    m.fields.back().values.insert(m.fields.back().values.end(), {1, 2, 3});
  test::ScratchDir dir;
  write_vtu(m, dir.file("s.vtu"));
  const auto arrays = appended_arrays(test::read_text(dir.file("s.vtu")));
  const auto points = as<double>(arrays.at("Points"));
  ASSERT_EQ(points.size(), 27u);
  for (int v = 0; v < 9; ++v) {
    EXPECT_EQ(points[3 * v], m.coords[2 * v]);
    EXPECT_EQ(points[3 * v + 1], m.coords[2 * v + 1]);
    EXPECT_EQ(points[3 * v + 2], 0.0);
  }
  const auto vec = as<double>(arrays.at("v"));
  ASSERT_EQ(vec.size(), 27u);
  EXPECT_EQ(vec[0], 2.0);
  EXPECT_EQ(vec[2], 0.0);
  const auto tensor = as<double>(arrays.at("m"));
  ASSERT_EQ(tensor.size(), 54u);
  const double expected[6] = {1, 3, 0, 2, 0, 0};  // XX YY ZZ XY YZ XZ from m11 m12 m22 = 1 2 3
  for (int k = 0; k < 6; ++k) EXPECT_EQ(tensor[k], expected[k]);
}

TEST(Vtu, AFieldCalledRefIsRenamed) {
  // The vertex refs are the point array "ref": a field of that name made a second one.
  Mesh m = test::square_2d();
  m.fields.push_back({"ref", FieldKind::kScalar, std::vector<double>(9, 5.0)});
  test::ScratchDir dir;
  write_vtu(m, dir.file("r.vtu"));
  const std::string text = test::read_text(dir.file("r.vtu"));
  EXPECT_NE(text.find("Name=\"ref_field\""), std::string::npos);
  const auto arrays = appended_arrays(text);
  const auto values = as<double>(arrays.at("ref_field"));
  ASSERT_EQ(values.size(), 9u);
  EXPECT_EQ(values[0], 5.0);
}

TEST(Vtu, BadFieldSizeIsAnError) {
  Mesh m = test::square_2d();
  m.fields.push_back({"u", FieldKind::kScalar, {1.0}});
  test::ScratchDir dir;
  EXPECT_THROW(write_vtu(m, dir.file("bad.vtu")), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("bad.vtu")));
}

TEST(Vtu, MeshioReadsIt) {
  if (!test::meshio_available()) GTEST_SKIP() << "python3-meshio not installed";
  test::ScratchDir dir;
  Mesh cube = test::cube_volume();
  cube.fields.push_back({"u", FieldKind::kScalar, std::vector<double>(8, 1.0)});
  cube.fields.push_back({"metric", FieldKind::kSymTensor, std::vector<double>(48, 1.0)});
  write_vtu(cube, dir.file("c.vtu"));
  EXPECT_EQ(test::meshio_summary(dir.file("c.vtu")),
            "8 tetra:6 triangle:12 line:12 dim[tetra]=3 dim[triangle]=2 dim[line]=1 "
            "ref[tetra]=1,2 ref[triangle]=1,2,3,4,5,6 ref[line]=3 point:metric:6 point:ref:1 "
            "point:u:1");
  write_vtu(test::square_2d(), dir.file("s.vtu"));
  EXPECT_EQ(test::meshio_summary(dir.file("s.vtu")),
            "9 triangle:8 line:8 dim[triangle]=2 dim[line]=1 ref[triangle]=1,2 "
            "ref[line]=1,2,3,4 point:ref:1");
}

TEST(Vtu, VtkReadsIt) {
  if (std::system("/usr/bin/python3 -c 'import vtk' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "python3-vtk9 not installed";
  test::ScratchDir dir;
  write_vtu(test::cube_volume(), dir.file("c.vtu"));
  const std::string out = test::run_capture(
      "/usr/bin/python3 -c 'import sys, vtk; r = vtk.vtkXMLUnstructuredGridReader(); "
      "r.SetFileName(sys.argv[1]); r.Update(); g = r.GetOutput(); "
      "print(g.GetNumberOfPoints(), g.GetNumberOfCells(), "
      "g.GetCellData().GetArray(\"ref\").GetRange())' '" +
      dir.file("c.vtu") + "'");
  EXPECT_EQ(out, "8 30 (1.0, 6.0)\n");
}

}  // namespace
}  // namespace riemesh
