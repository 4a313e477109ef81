#pragma once
// Fixtures for the io tests: small meshes built in code, a scratch folder, file helpers.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mesh/mesh.hpp"

namespace riemesh::test {

/// A fresh folder under TMPDIR, removed when the fixture goes away.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "riemesh_io_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The shared data folder (../shared/data of the source tree), or $RIEMESH_SHARED_DATA.
inline std::string shared_data() {
  if (const char* env = std::getenv("RIEMESH_SHARED_DATA")) return env;
#ifdef RIEMESH_SHARED_DATA
  return RIEMESH_SHARED_DATA;
#else
  return "../shared/data";
#endif
}

/// Unit square split into 2 x 2 cells (9 vertices, 8 counter-clockwise triangles), boundary
/// edges with one ref per side, the 4 corners tagged corner + required, side 1 ridges.
inline Mesh square_2d() {
  Mesh m;
  m.dim = 2;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      m.coords.push_back(0.5 * i);
      m.coords.push_back(0.5 * j + (i == 1 && j == 1 ? 0.1 / 3.0 : 0.0));  // a non-short real
      m.vert_ref.push_back(i == 1 && j == 1 ? 0 : 7);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const Id a = j * 3 + i, b = a + 1, c = a + 4, d = a + 3;
      m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
      m.tri_ref.insert(m.tri_ref.end(), {i + 1, i + 1});
    }
  const Id sides[4][3] = {{0, 1, 2}, {2, 5, 8}, {8, 7, 6}, {6, 3, 0}};
  for (int s = 0; s < 4; ++s)
    for (int k = 0; k < 2; ++k) {
      m.edges.insert(m.edges.end(), {sides[s][k], sides[s][k + 1]});
      m.edge_ref.push_back(s + 1);
    }
  m.vert_tag.assign(9, kTagNone);
  for (Id v : {0, 2, 6, 8}) m.vert_tag[v] = kTagCorner | kTagRequired;
  m.edge_tag.assign(8, kTagNone);
  m.edge_tag[0] = m.edge_tag[1] = kTagRidge;
  m.edge_tag[5] = kTagRequired | kTagRidge;
  m.tri_tag.assign(8, kTagNone);
  m.tri_tag[3] = kTagRequired;
  return m;
}

/// Surface of the unit tetrahedron (4 outward triangles), with vertex normals and a tangent.
inline Mesh tetra_surface() {
  Mesh m;
  m.dim = 3;
  m.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.vert_ref = {1, 2, 3, -4};
  m.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  m.tri_ref = {10, 11, 12, 13};
  m.edges = {0, 1, 1, 2, 2, 0};
  m.edge_ref = {5, 5, 6};
  m.vert_tag = {kTagCorner, kTagCorner, kTagNone, kTagRequired};
  m.edge_tag = {kTagRidge, kTagRidge | kTagRequired, kTagNone};
  m.tri_tag = {kTagNone, kTagRequired, kTagNone, kTagNone};
  const double s = 1.0 / std::sqrt(3.0);
  m.normals = {0, 0, -1, s, s, s, -1, 0, 0};
  m.normal_at_vertex = {0, 0, 1, 1, 3, 2};
  m.tangents = {1, 0, 0, 0, -0.6, 0.8};
  m.tangent_at_vertex = {1, 0, 2, 1};
  m.vert_tag.resize(4);
  return m;
}

/// Unit cube split into 6 tetrahedra around the diagonal 0-6, with its 12 boundary triangles
/// (ref = face number) and the 12 cube edges as ridges.
inline Mesh cube_volume() {
  Mesh m;
  m.dim = 3;
  for (int v = 0; v < 8; ++v) {
    const int x = (v == 1 || v == 2 || v == 5 || v == 6),
              y = (v == 2 || v == 3 || v == 6 || v == 7), z = v >= 4;
    m.coords.insert(m.coords.end(), {1.0 * x, 1.0 * y, 1.0 * z});
    m.vert_ref.push_back(v);
  }
  m.tets = {0, 1, 2, 6, 0, 2, 3, 6, 0, 3, 7, 6, 0, 7, 4, 6, 0, 4, 5, 6, 0, 5, 1, 6};
  m.tet_ref = {1, 1, 1, 2, 2, 2};
  m.triangles = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                 2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3};
  for (int f = 0; f < 6; ++f) m.tri_ref.insert(m.tri_ref.end(), {f + 1, f + 1});
  m.edges = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 0, 4, 1, 5, 2, 6, 3, 7};
  m.edge_ref.assign(12, 3);
  m.vert_tag.assign(8, kTagCorner);
  m.edge_tag.assign(12, kTagRidge);
  m.tri_tag.assign(12, kTagNone);
  return m;
}

/// Every array of two meshes equal (reals bit for bit).
inline void expect_same_mesh(const Mesh& a, const Mesh& b) {
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.coords, b.coords);
  EXPECT_EQ(a.vert_ref, b.vert_ref);
  EXPECT_EQ(a.vert_tag, b.vert_tag);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edge_ref, b.edge_ref);
  EXPECT_EQ(a.edge_tag, b.edge_tag);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.tri_ref, b.tri_ref);
  EXPECT_EQ(a.tri_tag, b.tri_tag);
  EXPECT_EQ(a.tets, b.tets);
  EXPECT_EQ(a.tet_ref, b.tet_ref);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.normal_at_vertex, b.normal_at_vertex);
  EXPECT_EQ(a.tangents, b.tangents);
  EXPECT_EQ(a.tangent_at_vertex, b.tangent_at_vertex);
}

}  // namespace riemesh::test
