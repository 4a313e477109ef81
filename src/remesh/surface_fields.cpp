// Fields on surfaces: tangent-plane Hessian recovery, the surface Lp metric, P1 transfer
// (surface_fields.hpp).
#include "remesh/surface_fields.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <cmath>
#include <string>

#include "core/dense_solve.hpp"
#include "core/eigen.hpp"
#include "core/error.hpp"
#include "mesh/adjacency.hpp"
#include "mesh/distance.hpp"
#include "remesh/surface_features.hpp"

namespace riemesh {
namespace {

std::size_t us(Id i) { return static_cast<std::size_t>(i); }

void require_surface(const Mesh& mesh, const char* what) {
  if (mesh.kind() != MeshKind::kSurface) {
    std::string msg = what;
    msg += ": the mesh is not a surface (triangles in 3D, no tetrahedra)";
    throw InputError(msg);
  }
}

Vec3 position(const Mesh& mesh, Id v) {
  const std::size_t k = 3 * us(v);
  return Vec3{{mesh.coords[k], mesh.coords[k + 1], mesh.coords[k + 2]}};
}

/// An orthonormal tangent basis (t1, t2) of the plane normal to n (n unit, or zero: then any).
void tangent_basis(const Vec3& n, Vec3& t1, Vec3& t2) {
  const Vec3 axis = std::abs(n[0]) < 0.6 ? Vec3{{1.0, 0.0, 0.0}} : Vec3{{0.0, 1.0, 0.0}};
  t1 = cross(n, axis);
  const double l = norm(t1);
  if (!(l > 0.0)) {
    t1 = Vec3{{1.0, 0.0, 0.0}};
    t2 = Vec3{{0.0, 1.0, 0.0}};
    return;
  }
  t1 = (1.0 / l) * t1;
  t2 = cross(n, t1);
}

/// The vertices of the two rings around v (v excluded), sorted and unique.
void two_rings(const Mesh& mesh, const Adjacency& adj, Id v, std::vector<Id>& ring,
               std::vector<Id>& scratch) {
  scratch.clear();
  for (Id t : ball(adj, v))
    for (int i = 0; i < 3; ++i) scratch.push_back(mesh.triangles[3 * us(t) + i]);
  std::sort(scratch.begin(), scratch.end());
  scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
  ring = scratch;
  for (Id w : scratch)
    for (Id t : ball(adj, w))
      for (int i = 0; i < 3; ++i) ring.push_back(mesh.triangles[3 * us(t) + i]);
  std::sort(ring.begin(), ring.end());
  ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
  ring.erase(std::remove(ring.begin(), ring.end(), v), ring.end());
}

/// The tangent 2x2 block of a 3D tensor in the basis (t1, t2).
SymMat2 tangent_block(const SymMat3& h, const Vec3& t1, const Vec3& t2) {
  const Vec3 h1 = h * t1, h2 = h * t2;
  return SymMat2{{dot(t1, h1), dot(t1, h2), dot(t2, h2)}};
}

/// m11 t1t1ᵀ + m12 (t1t2ᵀ + t2t1ᵀ) + m22 t2t2ᵀ + normal_value n nᵀ.
SymMat3 embed(const SymMat2& m, const Vec3& t1, const Vec3& t2, const Vec3& n, double normal_value) {
  SymMat3 r = m.c[0] * outer(t1) + m.c[2] * outer(t2) + normal_value * outer(n);
  r += m.c[1] * (outer(t1 + t2) - outer(t1) - outer(t2));
  return r;
}

struct Frames {
  std::vector<Vec3> n, t1, t2;
  std::vector<double> area;  // a third of the adjacent triangles' areas
};

Frames frames_of(const Mesh& mesh, const Adjacency& adj) {
  Frames f;
  f.n = vertex_normals(mesh, adj);
  const std::size_t nv = mesh.num_vertices();
  f.t1.resize(nv);
  f.t2.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) tangent_basis(f.n[v], f.t1[v], f.t2[v]);
  f.area.assign(nv, 0.0);
  for (std::size_t t = 0; t < mesh.num_triangles(); ++t) {
    const Id* tri = &mesh.triangles[3 * t];
    const Vec3 a = position(mesh, tri[0]);
    const double third =
        norm(cross(position(mesh, tri[1]) - a, position(mesh, tri[2]) - a)) / 6.0;
    for (int i = 0; i < 3; ++i) f.area[us(tri[i])] += third;
  }
  return f;
}

}  // namespace

std::vector<SymMat3> recover_surface_hessian(const Mesh& surface, std::span<const double> u) {
  require_surface(surface, "surface Hessian");
  const std::size_t nv = surface.num_vertices();
  if (u.size() != nv)
    throw InputError("surface Hessian: the field has " + std::to_string(u.size()) +
                     " values for " + std::to_string(nv) + " vertices");
  for (std::size_t v = 0; v < nv; ++v)
    if (!std::isfinite(u[v]))
      throw InputError("surface Hessian: the field is not finite at vertex " + std::to_string(v + 1));
  const Adjacency adj = build_adjacency(surface);
  const Frames fr = frames_of(surface, adj);
  std::vector<SymMat3> out(nv, SymMat3::zero());
  std::vector<Id> ring, scratch;
  struct Sample {
    double x, y, f;
  };
  std::vector<Sample> pts;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!(norm(fr.n[v]) > 0.0)) continue;
    two_rings(surface, adj, static_cast<Id>(v), ring, scratch);
    if (ring.size() < 5) continue;
    const Vec3 p = position(surface, static_cast<Id>(v));
    pts.clear();
    double rho2 = 0.0;
    for (Id w : ring) {
      const Vec3 d = position(surface, w) - p;
      const Sample s{dot(d, fr.t1[v]), dot(d, fr.t2[v]), u[us(w)] - u[v]};
      rho2 += s.x * s.x + s.y * s.y;
      pts.push_back(s);
    }
    const double rho = std::sqrt(rho2 / static_cast<double>(pts.size()));
    if (!(rho > 0.0)) continue;
    // u(x, y) - u(0) = a ξ + b η + ½ h11 ξ² + h12 ξη + ½ h22 η² in ξ = x/ρ, η = y/ρ.
    double a[5][5] = {}, b[5] = {};
    for (const Sample& s : pts) {
      const double xi = s.x / rho, eta = s.y / rho;
      const double phi[5] = {xi, eta, 0.5 * xi * xi, xi * eta, 0.5 * eta * eta};
      for (int i = 0; i < 5; ++i) {
        b[i] += phi[i] * s.f;
        for (int j = 0; j < 5; ++j) a[i][j] += phi[i] * phi[j];
      }
    }
    if (!solve_dense(a, b)) continue;
    const double s2 = 1.0 / (rho * rho);
    const SymMat2 h{{b[2] * s2, b[3] * s2, b[4] * s2}};
    out[v] = embed(h, fr.t1[v], fr.t2[v], fr.n[v], 0.0);
  }
  return out;
}

std::vector<SymMat3> surface_hessian_metric(const Mesh& surface, std::span<const SymMat3> hessians,
                                            const HessianMetricOptions& options,
                                            MetricReport* report) {
  require_surface(surface, "surface metric");
  options.validate();
  const std::size_t nv = surface.num_vertices();
  if (hessians.size() != nv)
    throw InputError("surface metric: " + std::to_string(hessians.size()) + " Hessians for " +
                     std::to_string(nv) + " vertices");
  const Adjacency adj = build_adjacency(surface);
  const Frames fr = frames_of(surface, adj);
  // |H| in the tangent plane, floored at 1e-12 of the largest eigenvalue over the surface.
  std::vector<SymEigen<2>> e(nv);
  double largest = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!is_finite(hessians[v]))
      throw InputError("surface metric: the Hessian is not finite at vertex " + std::to_string(v + 1));
    e[v] = eigen(tangent_block(hessians[v], fr.t1[v], fr.t2[v]));
    for (int i = 0; i < 2; ++i) {
      e[v].values[i] = std::abs(e[v].values[i]);
      largest = std::max(largest, e[v].values[i]);
    }
  }
  const double floor = largest > 0.0 ? 1e-12 * largest : 1.0;
  const bool lp = options.complexity > 0.0;
  const double p = options.norm;
  // The unscaled metric per vertex: det|H|^{-1/(2p+2)} |H| (Lp) or (2/9) |H| / ε (L∞).
  for (std::size_t v = 0; v < nv; ++v) {
    for (int i = 0; i < 2; ++i) e[v].values[i] = std::max(e[v].values[i], floor);
    const double s = lp ? std::pow(e[v].values[0] * e[v].values[1], -1.0 / (2.0 * p + 2.0))
                        : (2.0 / 9.0) / options.tolerance;
    for (int i = 0; i < 2; ++i) e[v].values[i] *= s;
  }
  const double lmin = 1.0 / (options.hmax * options.hmax);  // hmax = inf gives 0
  const double lmax = options.hmin > 0.0 ? 1.0 / (options.hmin * options.hmin)
                                         : std::numeric_limits<double>::infinity();
  const double aniso2 = options.aniso_max * options.aniso_max;
  auto clipped = [&](const SymEigen<2>& x, double scale) {
    double l0 = std::clamp(scale * x.values[0], lmin, lmax);
    double l1 = std::clamp(scale * x.values[1], lmin, lmax);
    const double hi = std::max(l0, l1);
    l0 = std::max(l0, hi / aniso2);
    l1 = std::max(l1, hi / aniso2);
    return std::array<double, 2>{l0, l1};
  };
  auto complexity = [&](double scale) {
    double c = 0.0;
    for (std::size_t v = 0; v < nv; ++v) {
      const auto l = clipped(e[v], scale);
      c += fr.area[v] * std::sqrt(l[0] * l[1]);
    }
    return c;
  };
  double scale = 1.0;
  if (lp) {
    // C(scale) grows like scale^s, 0 <= s <= 1 (s = 1 where nothing is clipped): the update
    // scale *= N / C approaches N monotonically.
    for (int it = 0; it < 100; ++it) {
      const double c = complexity(scale);
      if (!(c > 0.0)) break;
      const double ratio = options.complexity / c;
      if (std::abs(ratio - 1.0) < 1e-12) break;
      scale *= ratio;
    }
  }
  std::vector<SymMat3> out(nv);
  double total = 0.0;
  for (std::size_t v = 0; v < nv; ++v) {
    const auto l = clipped(e[v], scale);
    total += fr.area[v] * std::sqrt(l[0] * l[1]);
    const Vec2 w0{{e[v].vectors(0, 0), e[v].vectors(1, 0)}};
    const Vec2 w1{{e[v].vectors(0, 1), e[v].vectors(1, 1)}};
    const SymMat2 m = l[0] * outer(w0) + l[1] * outer(w1);
    Vec3 n = fr.n[v];
    Vec3 t1 = fr.t1[v], t2 = fr.t2[v];
    if (!(norm(n) > 0.0)) {  // an isolated vertex: any frame
      n = Vec3{{0.0, 0.0, 1.0}};
      t1 = Vec3{{1.0, 0.0, 0.0}};
      t2 = Vec3{{0.0, 1.0, 0.0}};
    }
    out[v] = embed(m, t1, t2, n, std::min(l[0], l[1]));
  }
  if (report) {
    report->complexity = total;
    report->predicted_vertices = 2.0 / std::sqrt(3.0) * total;
    report->predicted_elements = 4.0 / std::sqrt(3.0) * total;
  }
  return out;
}

std::vector<Field> transfer_surface_p1(const Mesh& from, const std::vector<Field>& fields,
                                       const Mesh& to) {
  require_surface(from, "surface transfer");
  require_surface(to, "surface transfer");
  const std::size_t nv = from.num_vertices();
  for (const Field& f : fields)
    if (f.values.size() != nv * static_cast<std::size_t>(field_components(f.kind, 3)))
      throw InputError("surface transfer: field " + f.name + " does not match the input's " +
                       std::to_string(nv) + " vertices");
  const TriangleTree tree(from);
  std::vector<Field> out = fields;
  for (Field& f : out) f.values.assign(to.num_vertices() * static_cast<std::size_t>(field_components(f.kind, 3)), 0.0);
  Id hint = kNoId;
  for (std::size_t v = 0; v < to.num_vertices(); ++v) {
    const Vec3 p = position(to, static_cast<Id>(v));
    const TriangleTree::Nearest q = tree.nearest(p, hint);
    hint = q.triangle;
    const Id* tri = &from.triangles[3 * us(q.triangle)];
    const Vec3 a = position(from, tri[0]);
    const Vec3 e1 = position(from, tri[1]) - a, e2 = position(from, tri[2]) - a, d = q.point - a;
    // Barycentric coordinates of the closest point (least squares in the triangle's plane).
    const double g11 = dot(e1, e1), g12 = dot(e1, e2), g22 = dot(e2, e2);
    const double det = g11 * g22 - g12 * g12;
    double s = 0.0, t = 0.0;
    if (det > 0.0) {
      s = std::clamp((g22 * dot(d, e1) - g12 * dot(d, e2)) / det, 0.0, 1.0);
      t = std::clamp((g11 * dot(d, e2) - g12 * dot(d, e1)) / det, 0.0, 1.0 - s);
    }
    const double w[3] = {1.0 - s - t, s, t};
    for (std::size_t k = 0; k < out.size(); ++k) {
      const auto nc = static_cast<std::size_t>(field_components(out[k].kind, 3));
      for (std::size_t c = 0; c < nc; ++c) {
        double x = 0.0;
        for (int i = 0; i < 3; ++i) x += w[i] * fields[k].values[nc * us(tri[i]) + c];
        out[k].values[nc * v + c] = x;
      }
    }
  }
  return out;
}

}  // namespace riemesh
