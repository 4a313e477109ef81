#pragma once
// Volumes with curved boundaries for the tests of the 3D remesher's curved patches: a coarsely
// faceted cylinder and a ball.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "core/symmat.hpp"
#include "core/vec.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::test {

inline Vec3 point(const Mesh& m, Id v) {
  return Vec3{{m.coords[3 * v], m.coords[3 * v + 1], m.coords[3 * v + 2]}};
}

/// Makes every tet positively oriented (swaps two vertices of the negative ones).
inline void orient_tets(Mesh& m) {
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    Id* v = &m.tets[4 * t];
    const Vec3 a = point(m, v[0]), b = point(m, v[1]), c = point(m, v[2]), d = point(m, v[3]);
    if (dot(b - a, cross(c - a, d - a)) < 0.0) std::swap(v[2], v[3]);
  }
}

/// The cylinder of radius r, axis z, z in [0, height], its side made of `facets` flat quads
/// (vertices on the circle), `layers` layers of prisms around the axis (each cut into three
/// tets, diagonals from the lower to the higher ring id so that neighbours match). Refs: side
/// 1, bottom 2, top 3.
inline Mesh faceted_cylinder(int facets, int layers, double r, double height) {
  Mesh m;
  m.dim = 3;
  const int ring = facets + 1;  // 2D id 0: the axis, 1..facets: the circle
  for (int k = 0; k <= layers; ++k) {
    const double z = height * k / layers;
    m.coords.insert(m.coords.end(), {0.0, 0.0, z});
    for (int i = 0; i < facets; ++i) {
      const double a = 2.0 * M_PI * i / facets;
      m.coords.insert(m.coords.end(), {r * std::cos(a), r * std::sin(a), z});
    }
  }
  m.vert_ref.assign(m.num_vertices(), 0);
  m.vert_tag.assign(m.num_vertices(), kTagNone);
  auto id = [&](int k, int i) { return static_cast<Id>(k * ring + i); };
  for (int k = 0; k < layers; ++k)
    for (int i = 0; i < facets; ++i) {
      int t[3] = {0, 1 + i, 1 + (i + 1) % facets};
      std::sort(t, t + 3);
      const Id a = id(k, t[0]), b = id(k, t[1]), c = id(k, t[2]);
      const Id a1 = id(k + 1, t[0]), b1 = id(k + 1, t[1]), c1 = id(k + 1, t[2]);
      m.tets.insert(m.tets.end(), {a, b, c, c1, a, b, b1, c1, a, a1, b1, c1});
      m.tet_ref.insert(m.tet_ref.end(), {1, 1, 1});
      // The side quad (ring ids t[1] < t[2]), split by the diagonal t[1] -> top of t[2].
      m.triangles.insert(m.triangles.end(), {b, c, c1, b, c1, b1});
      m.tri_ref.insert(m.tri_ref.end(), {1, 1});
    }
  for (int i = 0; i < facets; ++i) {
    const int j = 1 + (i + 1) % facets;
    m.triangles.insert(m.triangles.end(), {id(0, 0), id(0, j), id(0, 1 + i)});
    m.triangles.insert(m.triangles.end(), {id(layers, 0), id(layers, 1 + i), id(layers, j)});
    m.tri_ref.insert(m.tri_ref.end(), {2, 3});
  }
  orient_tets(m);
  return m;
}

/// The unit ball: unit_cube(n) centred and pushed out radially (x ‖x‖∞ / ‖x‖₂), every
/// boundary triangle of ref 1 (a smooth surface without features).
inline Mesh unit_ball(int n) {
  Mesh m = unit_cube(n);
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    Vec3 p = point(m, static_cast<Id>(v));
    p = 2.0 * p - Vec3{{1.0, 1.0, 1.0}};
    const double inf = std::max({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
    const double two = norm(p);
    if (two > 0.0) p = (inf / two) * p;
    for (int k = 0; k < 3; ++k) m.coords[3 * v + k] = p[k];
  }
  std::fill(m.tri_ref.begin(), m.tri_ref.end(), 1);
  m.edges.clear(), m.edge_ref.clear(), m.edge_tag.clear();
  std::fill(m.vert_tag.begin(), m.vert_tag.end(), kTagNone);
  orient_tets(m);
  return m;
}

/// Refined in the normal direction: size hn(ρ) = h − (h − hn) ρ / r radially
/// (ρ the distance to the axis), h along the circle and the axis.
inline std::vector<SymMat3> cylinder_metric(const Mesh& m, double r, double h, double hn) {
  std::vector<SymMat3> out;
  for (std::size_t v = 0; v < m.num_vertices(); ++v) {
    const Vec3 p = point(m, static_cast<Id>(v));
    const double rho = std::hypot(p[0], p[1]);
    const double size = h - (h - hn) * std::min(rho / r, 1.0);
    SymMat3 x = SymMat3::diagonal(1.0 / (h * h));
    if (rho > 0.0) {
      const Vec3 e{{p[0] / rho, p[1] / rho, 0.0}};
      x = x + (1.0 / (size * size) - 1.0 / (h * h)) * outer(e);
    }
    out.push_back(x);
  }
  return out;
}

/// m with tet refs region(centroid) (a Vec3 -> int) and the faces between two refs a < b listed
/// with ref 10 a + b.
template <class Region>
inline Mesh with_regions(Mesh m, Region region) {
  std::map<std::array<Id, 3>, std::pair<int, std::array<Id, 3>>> seen;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const Id* v = &m.tets[4 * t];
    Vec3 c{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) c[k] += m.coords[3 * static_cast<std::size_t>(v[i]) + k] / 4;
    m.tet_ref[t] = region(c);
    for (int i = 0; i < 4; ++i) {
      const std::array<Id, 3> f = {v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4]};
      std::array<Id, 3> key = f;
      std::sort(key.begin(), key.end());
      const auto [it, fresh] = seen.try_emplace(key, m.tet_ref[t], f);
      if (fresh || it->second.first == m.tet_ref[t]) continue;
      const int a = std::min(it->second.first, m.tet_ref[t]),
                b = std::max(it->second.first, m.tet_ref[t]);
      m.triangles.insert(m.triangles.end(), f.begin(), f.end());
      m.tri_ref.push_back(10 * a + b);
      m.tri_tag.push_back(0);
    }
  }
  return m;
}

}  // namespace riemesh::test
