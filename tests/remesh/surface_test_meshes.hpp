#pragma once
// Surface meshes of analytic surfaces for the surface tests: parametric grids (cylinder, torus,
// graphs such as the saddle z = x² − y²), the scaled icosphere and the boundary of a cube. Each
// comes with its exact geometry so that tests can compare estimates with the truth.
#include <cmath>
#include <functional>
#include <numbers>

#include "core/vec.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/mesh.hpp"
#include "metric/geometric.hpp"

namespace riemesh::test {

/// σ(u, v) and its first and second derivatives.
struct Param {
  std::function<Vec3(double, double)> point;
  /// σu, σv, σuu, σuv, σvv at (u, v).
  std::function<void(double, double, Vec3 (&)[5])> derivatives;
};

/// Grid of nu x nv cells on [u0, u1] x [v0, v1], periodic in u and/or v (the last row then
/// wraps to the first); each cell split into two triangles oriented like σu × σv. Vertex (i, j)
/// has id j * (number of u columns) + i; its parameters go to `uv`. The cells' diagonals
/// alternate, or all join (i, j) to (i + 1, j + 1) when `alternate` is false.
inline Mesh param_grid(const Param& s, int nu, int nv, double u0, double u1, double v0, double v1,
                       bool periodic_u, bool periodic_v, std::vector<Vec2>* uv = nullptr,
                       bool alternate = true) {
  Mesh m;
  m.dim = 3;
  const int cu = periodic_u ? nu : nu + 1, cv = periodic_v ? nv : nv + 1;
  for (int j = 0; j < cv; ++j)
    for (int i = 0; i < cu; ++i) {
      const double u = u0 + (u1 - u0) * i / nu, v = v0 + (v1 - v0) * j / nv;
      const Vec3 p = s.point(u, v);
      m.coords.insert(m.coords.end(), {p[0], p[1], p[2]});
      m.vert_ref.push_back(0);
      m.vert_tag.push_back(kTagNone);
      if (uv) uv->push_back({{u, v}});
    }
  auto id = [&](int i, int j) { return static_cast<Id>((j % cv) * cu + (i % cu)); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      // Alternate the diagonal so that the grid has no preferred direction.
      if (!alternate || (i + j) % 2 == 0) {
        m.triangles.insert(m.triangles.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        m.triangles.insert(m.triangles.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        m.triangles.insert(m.triangles.end(), {id(i, j), id(i + 1, j), id(i, j + 1)});
        m.triangles.insert(m.triangles.end(), {id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      m.tri_ref.insert(m.tri_ref.end(), {1, 1});
      m.tri_tag.insert(m.tri_tag.end(), {kTagNone, kTagNone});
    }
  return m;
}

inline Param cylinder_param(double r) {
  return {[r](double u, double v) { return Vec3{{r * std::cos(u), r * std::sin(u), v}}; },
          [r](double u, double, Vec3 (&d)[5]) {
            d[0] = {{-r * std::sin(u), r * std::cos(u), 0}};
            d[1] = {{0, 0, 1}};
            d[2] = {{-r * std::cos(u), -r * std::sin(u), 0}};
            d[3] = {{0, 0, 0}};
            d[4] = {{0, 0, 0}};
          }};
}

/// Torus with major radius R and minor radius r (u around the axis z, v around the tube).
inline Param torus_param(double big, double r) {
  return {[=](double u, double v) {
            const double w = big + r * std::cos(v);
            return Vec3{{w * std::cos(u), w * std::sin(u), r * std::sin(v)}};
          },
          [=](double u, double v, Vec3 (&d)[5]) {
            const double w = big + r * std::cos(v), cu = std::cos(u), su = std::sin(u);
            const double cv = std::cos(v), sv = std::sin(v);
            d[0] = {{-w * su, w * cu, 0}};
            d[1] = {{-r * sv * cu, -r * sv * su, r * cv}};
            d[2] = {{-w * cu, -w * su, 0}};
            d[3] = {{r * sv * su, -r * sv * cu, 0}};
            d[4] = {{-r * cv * cu, -r * cv * su, -r * sv}};
          }};
}

/// The saddle z = x² − y² as the graph σ(x, y) = (x, y, x² − y²).
inline Param saddle_param() {
  return {[](double x, double y) { return Vec3{{x, y, x * x - y * y}}; },
          [](double x, double y, Vec3 (&d)[5]) {
            d[0] = {{1, 0, 2 * x}};
            d[1] = {{0, 1, -2 * y}};
            d[2] = {{0, 0, 2}};
            d[3] = {{0, 0, 0}};
            d[4] = {{0, 0, -2}};
          }};
}

inline SurfaceGeometry exact_geometry(const Param& s, double u, double v) {
  Vec3 d[5];
  s.derivatives(u, v, d);
  return surface_geometry(d[0], d[1], d[2], d[3], d[4]);
}

/// The icosphere of radius r (subdivision s).
inline Mesh sphere_mesh(int s, double r) {
  Mesh m = sphere_surface(s);
  for (double& c : m.coords) c *= r;
  return m;
}

/// The boundary of the cube [0,1]³ with n x n cells per face: the boundary triangles of
/// unit_cube(n) (outward), all refs 1, no listed edges or tags, interior vertices unused.
inline Mesh cube_surface(int n) {
  Mesh c = unit_cube(n);
  Mesh m;
  m.dim = 3;
  m.coords = c.coords;
  m.vert_ref.assign(c.num_vertices(), 0);
  m.vert_tag.assign(c.num_vertices(), kTagNone);
  m.triangles = c.triangles;
  m.tri_ref.assign(c.num_triangles(), 1);
  m.tri_tag.assign(c.num_triangles(), kTagNone);
  return m;
}

}  // namespace riemesh::test
