#include "mesh/fixtures.hpp"

#include <cmath>
#include <random>
#include <string>

#include "core/error.hpp"
#include "core/vec.hpp"
#include "mesh/adjacency.hpp"

namespace riemesh {
namespace {

void add_edge(Mesh& m, Id a, Id b, int ref, std::uint8_t tag) {
  m.edges.push_back(a);
  m.edges.push_back(b);
  m.edge_ref.push_back(ref);
  m.edge_tag.push_back(tag);
}

void add_triangle(Mesh& m, Id a, Id b, Id c, int ref) {
  m.triangles.insert(m.triangles.end(), {a, b, c});
  m.tri_ref.push_back(ref);
  m.tri_tag.push_back(kTagNone);
}

void require_positive(int n, const char* what) {
  if (n < 1) throw InputError(std::string(what) + ": the number of cells must be >= 1");
}

}  // namespace

Mesh unit_square(int nx, int ny) {
  require_positive(nx, "unit_square");
  require_positive(ny, "unit_square");
  Mesh m;
  m.dim = 2;
  const auto id = [nx](int i, int j) { return static_cast<Id>(j * (nx + 1) + i); };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.coords.push_back(static_cast<double>(i) / nx);
      m.coords.push_back(static_cast<double>(j) / ny);
    }
  m.vert_ref.assign(m.num_vertices(), 0);
  m.vert_tag.assign(m.num_vertices(), kTagNone);
  for (Id c : {id(0, 0), id(nx, 0), id(nx, ny), id(0, ny)}) m.vert_tag[c] = kTagCorner;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      add_triangle(m, id(i, j), id(i + 1, j), id(i + 1, j + 1), 1);
      add_triangle(m, id(i, j), id(i + 1, j + 1), id(i, j + 1), 1);
    }
  // Boundary edges, counter-clockwise around the square.
  for (int i = 0; i < nx; ++i) add_edge(m, id(i, 0), id(i + 1, 0), 1, kTagNone);
  for (int j = 0; j < ny; ++j) add_edge(m, id(nx, j), id(nx, j + 1), 2, kTagNone);
  for (int i = nx; i > 0; --i) add_edge(m, id(i, ny), id(i - 1, ny), 3, kTagNone);
  for (int j = ny; j > 0; --j) add_edge(m, id(0, j), id(0, j - 1), 4, kTagNone);
  return m;
}

namespace {

/// The Kuhn tetrahedra of the unit cube: one per permutation p of the axes, walking from
/// (0,0,0) to (1,1,1) along e_p0, e_p1, e_p2. Its edge matrix (e_p0, e_p0+e_p1, 1) has the
/// determinant sign(p), so odd permutations swap their last two vertices. Corner c of the cube
/// is the bit set x + 2y + 4z.
constexpr int kKuhn[6][4] = {{0, 1, 3, 7}, {0, 1, 7, 5}, {0, 2, 7, 3},
                             {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 7, 6}};

/// Which of the cube's 6 sides (refs 1..6) holds all three integer points, or 0.
int cube_side(const int (*p)[3], int n) {
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int value = side * n;
      if (p[0][axis] == value && p[1][axis] == value && p[2][axis] == value)
        return 2 * axis + side + 1;
    }
  return 0;
}

}  // namespace

Mesh unit_cube(int n) {
  require_positive(n, "unit_cube");
  Mesh m;
  m.dim = 3;
  const int n1 = n + 1;
  const auto id = [n1](int i, int j, int k) { return static_cast<Id>((k * n1 + j) * n1 + i); };
  m.coords.reserve(3 * static_cast<std::size_t>(n1) * n1 * n1);
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        for (int c : {i, j, k}) m.coords.push_back(static_cast<double>(c) / n);
  m.vert_ref.assign(m.num_vertices(), 0);
  m.vert_tag.assign(m.num_vertices(), kTagNone);

  m.tets.reserve(24 * static_cast<std::size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& t : kKuhn)
          for (int c : t) m.tets.push_back(id(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)));
  m.tet_ref.assign(m.num_tets(), 1);

  // Boundary triangles: the tet faces lying on a side of the cube, outward by kTetFace.
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (const auto& f : kTetFace) {
      int p[3][3];
      Id v[3];
      for (int a = 0; a < 3; ++a) {
        v[a] = m.tets[4 * t + f[a]];
        p[a][0] = v[a] % n1, p[a][1] = (v[a] / n1) % n1, p[a][2] = v[a] / (n1 * n1);
      }
      if (const int ref = cube_side(p, n)) add_triangle(m, v[0], v[1], v[2], ref);
    }

  // Ridges: the 12 edges of the cube, along x, then y, then z.
  int ref = 0;
  for (int axis = 0; axis < 3; ++axis)
    for (int b = 0; b < 4; ++b) {
      ++ref;
      int q[3];
      q[(axis + 1) % 3] = (b & 1) * n;
      q[(axis + 2) % 3] = (b >> 1) * n;
      for (int s = 0; s < n; ++s) {
        q[axis] = s;
        const Id a = id(q[0], q[1], q[2]);
        q[axis] = s + 1;
        const Id c = id(q[0], q[1], q[2]);
        add_edge(m, a, c, ref, kTagRidge);
        m.vert_tag[a] |= kTagRidge;
        m.vert_tag[c] |= kTagRidge;
      }
    }
  for (int c = 0; c < 8; ++c)
    m.vert_tag[id((c & 1) * n, ((c >> 1) & 1) * n, (c >> 2) * n)] |= kTagCorner;
  return m;
}

Mesh sphere_surface(int subdivisions) {
  if (subdivisions < 0) throw InputError("sphere_surface: subdivisions must be >= 0");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double ico[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  Mesh m;
  m.dim = 3;
  for (const auto& p : ico) {
    const Vec3 u = normalize(Vec3{{p[0], p[1], p[2]}});
    m.coords.insert(m.coords.end(), {u[0], u[1], u[2]});
  }
  // Counter-clockwise seen from outside.
  m.triangles = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                 6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  for (int level = 0; level < subdivisions; ++level) {
    // New vertex nv + e at the (projected) midpoint of edge e; each triangle becomes 4.
    const Adjacency adj = build_adjacency(m.triangles, 3, m.num_vertices());
    const auto nv = static_cast<Id>(m.num_vertices());
    for (std::size_t e = 0; e < adj.num_edges(); ++e) {
      const Id a = adj.edges[2 * e], b = adj.edges[2 * e + 1];
      Vec3 mid{};
      for (int c = 0; c < 3; ++c) mid[c] = m.coords[3 * a + c] + m.coords[3 * b + c];
      mid = normalize(mid);
      m.coords.insert(m.coords.end(), {mid[0], mid[1], mid[2]});
    }
    std::vector<Id> fine;
    fine.reserve(4 * m.triangles.size());
    for (std::size_t f = 0; f < m.num_triangles(); ++f) {
      const Id a = m.triangles[3 * f], b = m.triangles[3 * f + 1], c = m.triangles[3 * f + 2];
      // Edge j is opposite vertex j: m0 on (b, c), m1 on (c, a), m2 on (a, b).
      const Id m0 = nv + adj.elem2edge[3 * f], m1 = nv + adj.elem2edge[3 * f + 1],
               m2 = nv + adj.elem2edge[3 * f + 2];
      fine.insert(fine.end(), {a, m2, m1, m2, b, m0, m1, m0, c, m0, m1, m2});
    }
    m.triangles = std::move(fine);
  }
  m.vert_ref.assign(m.num_vertices(), 0);
  m.vert_tag.assign(m.num_vertices(), kTagNone);
  m.tri_ref.assign(m.num_triangles(), 1);
  m.tri_tag.assign(m.num_triangles(), kTagNone);
  return m;
}

}  // namespace riemesh

namespace riemesh {

Mesh perturbed_unit_square(int nx, int ny, double amount, unsigned seed) {
  Mesh mesh = unit_square(nx, ny);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    double& x = mesh.coords[2 * v];
    double& y = mesh.coords[2 * v + 1];
    if (x == 0.0 || x == 1.0 || y == 0.0 || y == 1.0) continue;
    x += u(rng) / nx;
    y += u(rng) / ny;
  }
  return mesh;
}

Mesh perturbed_unit_cube(int n, double amount, unsigned seed) {
  Mesh mesh = unit_cube(n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    bool boundary = false;
    for (int a = 0; a < 3; ++a)
      boundary |= mesh.coords[3 * v + a] == 0.0 || mesh.coords[3 * v + a] == 1.0;
    if (!boundary)
      for (int a = 0; a < 3; ++a) mesh.coords[3 * v + a] += u(rng) / n;
  }
  return mesh;
}

}  // namespace riemesh
