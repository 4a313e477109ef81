// Interior points of a volume: field points, then the 3D remesher with the boundary kept
// (volume_fill3d.hpp).
#include "generate/volume_fill3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/error.hpp"
#include "mesh/distance.hpp"
#include "metric/metric.hpp"
#include "remesh/prepare_metrics.hpp"
#include "remesh/simplex_geometry.hpp"

namespace riemesh {

std::vector<double> boundary_sizes(const Mesh& volume) {
  const std::size_t nv = volume.num_vertices();
  std::vector<double> sum(nv, 0.0), count(nv, 0.0);
  double total = 0.0, edges = 0.0;
  auto at = [&](Id v, int c) { return volume.coords[3 * static_cast<std::size_t>(v) + c]; };
  for (std::size_t t = 0; t < volume.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id a = volume.triangles[3 * t + i], b = volume.triangles[3 * t + (i + 1) % 3];
      double l2 = 0.0;
      for (int c = 0; c < 3; ++c) l2 += (at(a, c) - at(b, c)) * (at(a, c) - at(b, c));
      const double l = std::sqrt(l2);
      for (Id v : {a, b}) {
        sum[static_cast<std::size_t>(v)] += l;
        count[static_cast<std::size_t>(v)] += 1.0;
      }
      total += l;
      edges += 1.0;
    }
  if (!(edges > 0.0)) throw InputError("boundary sizes: the volume has no boundary triangles");
  std::vector<double> h(nv, total / edges);
  for (std::size_t v = 0; v < nv; ++v)
    if (count[v] > 0.0) h[v] = sum[v] / count[v];
  return h;
}

namespace {

/// A deterministic offset in [-0.5, 0.5) from integer cell coordinates (splitmix64).
double jitter(std::uint64_t key, int axis) {
  std::uint64_t z = key + 0x9e3779b97f4a7c15ULL * static_cast<std::uint64_t>(axis + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53 - 0.5;
}

/// Calls f on each point of the body-centred cubic lattice lo + a (i, j, k), lo + a (i + ½, j +
/// ½, k + ½) in the octree cell of integer corner ijk and side s, in a fixed order. A point is in
/// the cell when its index is at or above the cell's lower face and below its upper face, the
/// faces computed as lo + n s (n an integer) by every cell that has them — the same doubles on
/// both sides, at any depth (s halves exactly) — so each point is in exactly one cell.
template <class F>
void lattice_points(const std::array<std::uint32_t, 3>& ijk, double s, const Vec3& lo, double a,
                    F&& f) {
  for (const double shift : {0.0, 0.5}) {
    std::int64_t first[3], end[3];
    for (int c = 0; c < 3; ++c) {
      const auto n = static_cast<double>(ijk[static_cast<std::size_t>(c)]);
      first[c] = static_cast<std::int64_t>(std::ceil((lo[c] + n * s - lo[c]) / a - shift));
      end[c] = static_cast<std::int64_t>(std::ceil((lo[c] + (n + 1.0) * s - lo[c]) / a - shift));
    }
    for (std::int64_t k = first[2]; k < end[2]; ++k)
      for (std::int64_t j = first[1]; j < end[1]; ++j)
        for (std::int64_t i = first[0]; i < end[0]; ++i)
          f(Vec3{lo[0] + a * (static_cast<double>(i) + shift),
                 lo[1] + a * (static_cast<double>(j) + shift),
                 lo[2] + a * (static_cast<double>(k) + shift)});
  }
}

constexpr double kJitter = 0.2;      // of the cell size
constexpr double kClearance = 1.5;   // of the size: distance kept from the surface
constexpr int kMaxDepth = 21;        // 2^21 cells per axis: far below any sensible size

}  // namespace

FieldPoints3 field_points3d(const Mesh& volume, std::span<const double> sizes) {
  const std::size_t nv = volume.num_vertices(), nt = volume.num_tets();
  if (sizes.size() != nv) throw InputError("field points: one size per vertex expected");
  for (double h : sizes)
    if (!(h > 0.0) || !std::isfinite(h)) throw InputError("field points: sizes must be > 0");
  if (nt == 0) return {};
  const auto vertex = [&](Id v) {
    const std::size_t i = 3 * static_cast<std::size_t>(v);
    return Vec3{volume.coords[i], volume.coords[i + 1], volume.coords[i + 2]};
  };
  // Per tet: its bounding box, to pass the tets overlapping a cell down to its children.
  std::vector<Vec3> tlo(nt), thi(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    tlo[t] = thi[t] = vertex(volume.tets[4 * t]);
    for (int i = 1; i < 4; ++i) {
      const Vec3 x = vertex(volume.tets[4 * t + i]);
      for (int c = 0; c < 3; ++c) {
        tlo[t][c] = std::min(tlo[t][c], x[c]);
        thi[t][c] = std::max(thi[t][c], x[c]);
      }
    }
  }
  // The size at p, interpolated in the first listed tet holding p; 0 when none does.
  const auto size_at = [&](const Vec3& p, const std::vector<Id>& tets) {
    for (Id t : tets) {
      const std::size_t k = static_cast<std::size_t>(t);
      bool in_box = true;
      for (int c = 0; c < 3; ++c) in_box = in_box && p[c] >= tlo[k][c] && p[c] <= thi[k][c];
      if (!in_box) continue;
      Vec3 x[4];
      for (int i = 0; i < 4; ++i) x[i] = vertex(volume.tets[4 * k + i]);
      const double vol = simplex::signed_volume(x);
      if (!(vol > 0.0)) continue;
      double w[4];
      simplex::sub_volumes(x, p, w);
      // (A lattice point on a face shared by two tets may round slightly outside both.)
      if (*std::min_element(w, w + 4) < -1e-12 * vol) continue;
      double h = 0.0;
      for (int i = 0; i < 4; ++i) h += w[i] / vol * sizes[static_cast<std::size_t>(volume.tets[4 * k + i])];
      return h;
    }
    return 0.0;
  };
  const TriangleTree surface(volume);

  Vec3 lo = vertex(0), hi = vertex(0);
  for (std::size_t v = 0; v < nv; ++v)
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], volume.coords[3 * v + c]);
      hi[c] = std::max(hi[c], volume.coords[3 * v + c]);
    }
  const double side = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});

  // A uniform size gets the body-centred cubic lattice of spacing a = h √(6/5): its Delaunay
  // tetrahedra are congruent (two edges a, four a √3/2: root-mean-square length h, mean-ratio
  // quality 0.95) and unique (four Voronoi cells meet at each Voronoi vertex), so no jitter is
  // needed. The octree then stops at cells between a and 2a, each holding the lattice points in
  // it (half-open: each point in one cell).
  const bool uniform =
      std::all_of(sizes.begin(), sizes.end(), [&](double h) { return h == sizes[0]; });
  const double spacing = sizes[0] * std::sqrt(1.2);

  FieldPoints3 out;
  struct Cell {
    std::array<std::uint32_t, 3> ijk;  // integer corner at depth `depth`
    int depth;
    std::vector<Id> tets;  // the tets whose boxes overlap the cell
  };
  std::vector<Cell> stack;
  stack.push_back({{0, 0, 0}, 0, {}});
  stack.back().tets.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) stack.back().tets[t] = static_cast<Id>(t);
  Id tri_hint = kNoId;
  while (!stack.empty()) {
    Cell cell = std::move(stack.back());
    stack.pop_back();
    const double s = side / static_cast<double>(1u << cell.depth);
    Vec3 corner{}, centre{};
    for (int c = 0; c < 3; ++c) {
      corner[c] = lo[c] + cell.ijk[static_cast<std::size_t>(c)] * s;
      centre[c] = corner[c] + 0.5 * s;
    }
    // Size at the centre; when the centre is outside, the smallest size of the listed tets.
    double h = size_at(centre, cell.tets);
    if (h == 0.0) {
      h = std::numeric_limits<double>::infinity();
      for (Id t : cell.tets)
        for (int i = 0; i < 4; ++i)
          h = std::min(h, sizes[static_cast<std::size_t>(volume.tets[4 * static_cast<std::size_t>(t) + i])]);
    }
    if (s > (uniform ? 2.0 * spacing : h) && cell.depth < kMaxDepth) {
      // Children in a fixed order (last pushed first popped: x fastest), each with the tets
      // overlapping it; children overlapping none are outside.
      for (int k = 7; k >= 0; --k) {
        Cell child{{2 * cell.ijk[0] + (k & 1), 2 * cell.ijk[1] + ((k >> 1) & 1),
                    2 * cell.ijk[2] + ((k >> 2) & 1)},
                   cell.depth + 1,
                   {}};
        Vec3 clo{}, chi{};
        for (int c = 0; c < 3; ++c) {
          clo[c] = lo[c] + child.ijk[static_cast<std::size_t>(c)] * (0.5 * s);
          chi[c] = clo[c] + 0.5 * s;
        }
        for (Id t : cell.tets) {
          const std::size_t q = static_cast<std::size_t>(t);
          bool overlap = true;
          for (int c = 0; c < 3; ++c) overlap = overlap && tlo[q][c] <= chi[c] && thi[q][c] >= clo[c];
          if (overlap) child.tets.push_back(t);
        }
        if (!child.tets.empty()) stack.push_back(std::move(child));
      }
      continue;
    }
    if (uniform) {
      lattice_points(cell.ijk, s, lo, spacing, [&](const Vec3& p) {
        if (size_at(p, cell.tets) == 0.0 || surface.within(p, kClearance * sizes[0], &tri_hint))
          return;
        out.coords.insert(out.coords.end(), {p[0], p[1], p[2]});
        out.sizes.push_back(sizes[0]);  // exactly: the field stays constant
      });
      continue;
    }
    const std::uint64_t key = (static_cast<std::uint64_t>(cell.ijk[0]) << 42) ^
                              (static_cast<std::uint64_t>(cell.ijk[1]) << 21) ^ cell.ijk[2] ^
                              (static_cast<std::uint64_t>(cell.depth) << 58);
    Vec3 p = centre;
    for (int c = 0; c < 3; ++c) p[c] += kJitter * s * jitter(key, c);
    const double hp = size_at(p, cell.tets);
    if (hp == 0.0) continue;  // outside
    if (surface.within(p, kClearance * hp, &tri_hint)) continue;
    out.coords.insert(out.coords.end(), {p[0], p[1], p[2]});
    out.sizes.push_back(hp);
  }
  return out;
}

Adapt3dResult fill_volume(Mesh&& volume, std::span<const double> sizes, Adapt3dOptions options,
                          const PassCallback& on_pass) {
  if (sizes.size() != volume.num_vertices())
    throw InputError("fill_volume: one size per vertex expected");
  std::vector<SymMat3> metrics;
  metrics.reserve(sizes.size());
  for (double h : sizes) {
    if (!(h > 0.0) || !std::isfinite(h)) throw InputError("fill_volume: sizes must be > 0");
    metrics.push_back(isotropic_metric<3>(h));
  }
  options.keep_surface = true;
  options.approach_growth = 0.0;  // field points already put the sizes in place
  return adapt3d(std::move(volume), metrics, options, on_pass);
}

Adapt3dResult fill_volume(Mesh&& volume, double hsiz, Adapt3dOptions options,
                          const PassCallback& on_pass) {
  if (!(hsiz >= 0.0) || !std::isfinite(hsiz)) throw InputError("fill_volume: hsiz must be >= 0");
  const std::vector<double> sizes = hsiz > 0.0 ? std::vector<double>(volume.num_vertices(), hsiz)
                                               : boundary_sizes(volume);
  return fill_volume(std::move(volume), sizes, options, on_pass);
}

FilledVolume mesh_volume(const Mesh& surface, double hsiz, Adapt3dOptions options,
                         const PassCallback& on_pass, const BoundaryRecoveryOptions& recovery) {
  if (!(hsiz >= 0.0) || !std::isfinite(hsiz))
    throw InputError("the size must be finite and >= 0 (0: from the boundary edges)");
  options.validate();
  // Near-flat tets are left to fill_volume's sliver sweeps (BoundaryRecoveryOptions::refine_flat).
  BoundaryRecoveryOptions ro = recovery;
  ro.refine_flat = false;
  ro.interior_points.clear();
  RecoveredVolume first = recover_volume(surface, ro);
  // Sizes clipped to [hmin, hmax] (the field points follow them too).
  const auto sizes_of = [&](const Mesh& v) {
    std::vector<double> h =
        hsiz > 0.0 ? std::vector<double>(v.num_vertices(), hsiz) : boundary_sizes(v);
    for (double& x : h) x = std::min(std::max(x, options.hmin), options.hmax);
    return h;
  };
  const std::vector<double> first_sizes = sizes_of(first.volume);
  // A size far too small (a mistyped --hsiz) is refused before any point is added instead of
  // running for hours: at most 3.5e7 vertices (about 2e8 tets).
  std::vector<SymMat3> first_metrics(first_sizes.size());
  for (std::size_t v = 0; v < first_sizes.size(); ++v)
    first_metrics[v] = isotropic_metric<3>(first_sizes[v]);
  require_reachable_complexity<3>(first.volume, first_metrics, kMostVertices3d,
                                  ComplexityBound::kLinearSizes);
  FieldPoints3 points = field_points3d(first.volume, first_sizes);
  first = {};
  ro.interior_points = std::move(points.coords);
  RecoveredVolume r = recover_volume(surface, ro);
  // Sizes: the boundary's at the surface and Steiner vertices, the field points' own.
  std::vector<double> sizes = sizes_of(r.volume);
  const std::size_t first_point = r.stats.surface_vertices;
  for (std::size_t k = 0; k < points.size(); ++k) sizes[first_point + k] = points.sizes[k];
  FilledVolume out;
  out.stats = r.stats;
  out.field_points = points.size();
  out.adapted = fill_volume(std::move(r.volume), sizes, options, on_pass);
  return out;
}

}  // namespace riemesh
