// Background mesh: construction (validation, volumes, adjacency, log-metrics, search grid) and
// the interpolation of metrics and vertex fields at located points. Location is in
// background_locate.cpp.
#include "remesh/background.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/huge_pages.hpp"
#include "core/spd.hpp"
#include "mesh/adjacency.hpp"
#include "remesh/simplex_geometry.hpp"

namespace riemesh {
namespace {

std::string prefix() { return "background mesh: "; }

template <int D>
std::span<const Id> mesh_simplices(const Mesh& mesh) {
  if (mesh.dim != D) {
    std::string msg = prefix();
    msg += "a " + std::to_string(D) + "D background needs a mesh of dimension " +
           std::to_string(D) + ", got " + std::to_string(mesh.dim);
    throw InputError(msg);
  }
  if (D == 3 && mesh.tets.empty())
    throw InputError(prefix() + "a 3D background needs tetrahedra (the mesh has none)");
  return D == 2 ? std::span<const Id>(mesh.triangles) : std::span<const Id>(mesh.tets);
}

/// Cells per axis of a grid of about `target` cells over a box of sides `extent`, cells about
/// square: an axis shorter than the cell side gets one cell and the rest share the target.
template <int D>
void grid_shape(const Vec<D>& extent, double target, int n[D]) {
  bool active[D];
  for (int a = 0; a < D; ++a) active[a] = true;
  for (int pass = 0; pass < D; ++pass) {
    double prod = 1.0;
    int count = 0;
    for (int a = 0; a < D; ++a)
      if (active[a]) prod *= extent[a], ++count;
    if (count == 0) break;
    const double h = std::pow(prod / target, 1.0 / count);
    bool changed = false;
    for (int a = 0; a < D; ++a) {
      if (!active[a]) continue;
      if (extent[a] < h) {
        active[a] = false, n[a] = 1, changed = true;
      } else {
        n[a] = static_cast<int>(std::min(std::ceil(extent[a] / h), 1e6));
      }
    }
    if (!changed) break;
  }
}

/// Calls f(cell index) for every cell of the box [lo, hi] (inclusive, per axis) of a grid n.
template <int D, class F>
void for_box(const int lo[D], const int hi[D], const int n[D], F&& f) {
  int c[D];
  for (int a = 0; a < D; ++a) c[a] = lo[a];
  while (true) {
    std::size_t index = 0;
    for (int a = D - 1; a >= 0; --a) index = index * static_cast<std::size_t>(n[a]) + c[a];
    f(index);
    int a = 0;
    while (a < D && ++c[a] > hi[a]) c[a] = lo[a], ++a;
    if (a == D) return;
  }
}

}  // namespace

template <int D>
BackgroundMesh<D>::BackgroundMesh(std::span<const double> coords, std::span<const Id> simplices,
                                  std::span<const double> metrics, InterpScheme scheme)
    : scheme_(scheme) {
  build(coords, simplices, metrics);
}

template <int D>
BackgroundMesh<D>::BackgroundMesh(std::vector<Vec<D>>&& coords, std::vector<Id>&& simplices,
                                  std::vector<SymMat<D>>&& metrics, InterpScheme scheme,
                                  std::vector<Id>&& elem2elem)
    : scheme_(scheme), coords_(std::move(coords)), simplices_(std::move(simplices)),
      metrics_(std::move(metrics)) {
  const std::size_t nv = coords_.size();
  if (simplices_.size() % kVerts != 0 || simplices_.empty())
    throw InputError(prefix() + "coordinate or simplex array of a bad size (" +
                     std::to_string(D * nv) + " coordinates, " +
                     std::to_string(simplices_.size()) + " simplex ids)");
  if (nv >= static_cast<std::size_t>(std::numeric_limits<Id>::max()) ||
      simplices_.size() >= static_cast<std::size_t>(std::numeric_limits<Id>::max()))
    throw InputError(prefix() + "too many entities for 32-bit ids");
  if (metrics_.size() != nv)
    throw InputError(prefix() + std::to_string(metrics_.size() * SymMat<D>::kSize) +
                     " metric coefficients for " + std::to_string(nv) + " vertices (expected " +
                     std::to_string(nv * SymMat<D>::kSize) + ")");
  if (!elem2elem.empty() && elem2elem.size() != simplices_.size())
    throw InputError(prefix() + "neighbour array of a bad size");
  finish(std::move(elem2elem));
}

template <int D>
BackgroundMesh<D>::BackgroundMesh(const Mesh& mesh, std::span<const double> metrics,
                                  InterpScheme scheme, const Adjacency* adjacency)
    : scheme_(scheme) {
  build(mesh.coords, mesh_simplices<D>(mesh), metrics, adjacency);
}

template <int D>
void BackgroundMesh<D>::build(std::span<const double> coords, std::span<const Id> simplices,
                              std::span<const double> metrics, const Adjacency* adjacency) {
  constexpr int kSize = SymMat<D>::kSize;
  if (coords.size() % D != 0 || simplices.size() % kVerts != 0 || simplices.empty())
    throw InputError(prefix() + "coordinate or simplex array of a bad size (" +
                     std::to_string(coords.size()) + " coordinates, " +
                     std::to_string(simplices.size()) + " simplex ids)");
  const std::size_t nv = coords.size() / D;
  if (nv >= static_cast<std::size_t>(std::numeric_limits<Id>::max()) ||
      simplices.size() >= static_cast<std::size_t>(std::numeric_limits<Id>::max()))
    throw InputError(prefix() + "too many entities for 32-bit ids");
  if (metrics.size() != nv * kSize)
    throw InputError(prefix() + std::to_string(metrics.size()) + " metric coefficients for " +
                     std::to_string(nv) + " vertices (expected " + std::to_string(nv * kSize) +
                     ")");
  coords_.resize(nv);
  for (std::size_t v = 0; v < nv; ++v)
    for (int a = 0; a < D; ++a) coords_[v][a] = coords[D * v + a];
  simplices_.assign(simplices.begin(), simplices.end());
  metrics_.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) std::copy_n(metrics.begin() + kSize * v, kSize, metrics_[v].c);
  finish(adjacency ? std::vector<Id>(adjacency->elem2elem) : std::vector<Id>{});
}

template <int D>
void BackgroundMesh<D>::set_metrics(std::vector<SymMat<D>>&& metrics) {
  if (metrics.size() != coords_.size())
    throw InputError(prefix() + std::to_string(metrics.size()) + " metrics for " +
                     std::to_string(coords_.size()) + " vertices");
  for (std::size_t v = 0; v < metrics.size(); ++v)
    if (!is_spd(metrics[v]))
      throw InputError(prefix() + "the metric of vertex " + std::to_string(v + 1) +
                       " is not symmetric positive definite");
  metrics_ = std::move(metrics);
  if (scheme_ == InterpScheme::kLogEuclidean)
    for (std::size_t v = 0; v < metrics_.size(); ++v) logs_[v] = log_spd(metrics_[v]);
}

template <int D>
void BackgroundMesh<D>::finish(std::vector<Id>&& elem2elem) {
  const std::size_t nv = coords_.size(), ns = simplices_.size() / kVerts;
  for (std::size_t v = 0; v < nv; ++v)
    for (int a = 0; a < D; ++a)
      if (!std::isfinite(coords_[v][a]))
        throw InputError(prefix() + "vertex " + std::to_string(v + 1) +
                         " has a non-finite coordinate");
  for (Id v : simplices_)
    if (v < 0 || static_cast<std::size_t>(v) >= nv)
      throw InputError(prefix() + "vertex id " + std::to_string(v) + " out of range [0, " +
                       std::to_string(nv) + ")");
  for (std::size_t s = 0; s < ns; ++s) {
    Vec<D> x[kVerts];
    for (int i = 0; i < kVerts; ++i) x[i] = coords_[simplices_[kVerts * s + i]];
    // A tet whose volume rounds to zero is decided by the exact orientation: a flat sliver of a
    // Delaunay tetrahedralisation is valid (no walk stops in it: its barycentric coordinates are
    // not finite, and the searches pass it by).
    const double volume = simplex::signed_volume(x);
    if (!std::isfinite(volume) ||
        (volume == 0.0 && (D == 2 || simplex::exact_orientation(x) == 0.0)))
      throw InputError(prefix() + "simplex " + std::to_string(s + 1) + " has zero measure");
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (!is_spd(metrics_[v]))
      throw InputError(prefix() + "the metric of vertex " + std::to_string(v + 1) +
                       " is not symmetric positive definite");
  }
  if (scheme_ == InterpScheme::kLogEuclidean) {
    reserve_huge(logs_, nv);
    logs_.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) logs_[v] = log_spd(metrics_[v]);
  }
  elem2elem_ = !elem2elem.empty() ? std::move(elem2elem)
                                  : build_face_adjacency(simplices_, kVerts, nv).elem2elem;
  // Walks from a hint crossing a uniform mesh take O(ns^(1/D)) steps; beyond a generous multiple
  // of that, the grid search is cheaper than walking on (and a cycle cannot run forever).
  max_walk_steps_ =
      64 + 8 * static_cast<int>(std::ceil(std::pow(static_cast<double>(ns), 1.0 / D)));
  build_grid();
}

template <int D>
void BackgroundMesh<D>::build_grid() {
  Vec<D> lo = coords_[0], hi = coords_[0];
  for (const Vec<D>& x : coords_)
    for (int a = 0; a < D; ++a) lo[a] = std::min(lo[a], x[a]), hi[a] = std::max(hi[a], x[a]);
  // About 4 triangles or 64 tetrahedra per cell: a simplex overlaps a few cells, so a cell lists
  // ~12 triangles or a few hundred tetrahedra, the cost of one containment scan in the robust
  // search. In 3D one cell per 2x2x2 block of the 8-tetrahedra grid used before: its cell
  // lists took 16-36 bytes per tetrahedron, now 8x fewer cells hold ~2x fewer entries (memory,
  // issue #7); the remesher's queries walk from nearby hints and hardly use the grid.
  const double ns = static_cast<double>(num_simplices());
  grid_.lo = lo;
  grid_shape<D>(hi - lo, std::max(1.0, ns / (D == 2 ? 4 : 64)), grid_.n);
  // Hints are walked from within 3 cells of the 4-triangle / 8-tetrahedron grid, as before the
  // 3D grid was coarsened (the same walks, hence the same answers on shared faces).
  int fine[D];
  grid_shape<D>(hi - lo, std::max(1.0, ns / (D == 2 ? 4 : 8)), fine);
  std::size_t cells = 1;
  for (int a = 0; a < D; ++a) {
    grid_.cell[a] = (hi[a] - lo[a]) / grid_.n[a];
    hint_reach_ = std::max(hint_reach_, 3.0 * ((hi[a] - lo[a]) / fine[a]));
    grid_.inv_cell[a] = grid_.n[a] / (hi[a] - lo[a]);
    cells *= static_cast<std::size_t>(grid_.n[a]);
  }
  grid_.cells = cells;
}

template <int D>
void BackgroundMesh<D>::simplex_cells(std::size_t s, int c_lo[D], int c_hi[D]) const {
  Vec<D> b_lo = coords_[simplices_[kVerts * s]], b_hi = b_lo;
  for (int i = 1; i < kVerts; ++i) {
    const Vec<D>& x = coords_[simplices_[kVerts * s + i]];
    for (int a = 0; a < D; ++a) b_lo[a] = std::min(b_lo[a], x[a]), b_hi[a] = std::max(b_hi[a], x[a]);
  }
  cell_of(b_lo, c_lo);
  cell_of(b_hi, c_hi);
}

template <int D>
void BackgroundMesh<D>::build_grid_lists() const {
  const std::size_t cells = grid_.cells;
  // Two passes over the simplices' bounding boxes: count, then fill (ids increase per cell).
  grid_.offsets.assign(cells + 1, 0);
  int c_lo[D], c_hi[D];
  for (std::size_t s = 0; s < num_simplices(); ++s) {
    simplex_cells(s, c_lo, c_hi);
    for_box<D>(c_lo, c_hi, grid_.n, [&](std::size_t c) { ++grid_.offsets[c + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) grid_.offsets[c + 1] += grid_.offsets[c];
  grid_.ids.resize(grid_.offsets[cells]);
  std::vector<std::size_t> fill(grid_.offsets.begin(), grid_.offsets.end() - 1);
  for (std::size_t s = 0; s < num_simplices(); ++s) {
    simplex_cells(s, c_lo, c_hi);
    for_box<D>(c_lo, c_hi, grid_.n,
               [&](std::size_t c) { grid_.ids[fill[c]++] = static_cast<Id>(s); });
  }
  build_face_grid();
}

template <int D>
void BackgroundMesh<D>::build_starts() const {
  // Walk starts: the simplex nearest the cell centre among those whose bounding box overlaps
  // the cell (first in id order on ties: simplices in increasing id, strict improvement), so
  // that a hint-free walk crosses about half a cell. One pass over the simplices, the centroid
  // computed once per simplex (the same sums, hence the same bits, as cell by cell).
  const std::size_t cells = grid_.cells;
  grid_.start.assign(cells, kNoId);
  std::vector<double> best(cells, std::numeric_limits<double>::infinity());
  int c_lo[D], c_hi[D];
  for (std::size_t s = 0; s < num_simplices(); ++s) {
    simplex_cells(s, c_lo, c_hi);
    Vec<D> centroid = Vec<D>::zero();
    for (int i = 0; i < kVerts; ++i) centroid += coords_[simplices_[kVerts * s + i]];
    centroid *= 1.0 / kVerts;
    int k[D];  // the cells of the box, axis 0 fastest (as for_box)
    for (int a = 0; a < D; ++a) k[a] = c_lo[a];
    for (;;) {
      const std::size_t cell = cell_index(k);
      Vec<D> centre{};
      for (int a = 0; a < D; ++a) centre[a] = grid_.lo[a] + (k[a] + 0.5) * grid_.cell[a];
      const Vec<D> d = centroid - centre;
      if (dot(d, d) < best[cell]) best[cell] = dot(d, d), grid_.start[cell] = static_cast<Id>(s);
      int a = 0;
      while (a < D && ++k[a] > c_hi[a]) k[a] = c_lo[a], ++a;
      if (a == D) break;
    }
  }
}

template <int D>
void BackgroundMesh<D>::build_face_grid() const {
  const std::size_t cells = grid_.cells;
  grid_.face_offsets.assign(cells + 1, 0);
  auto face_box = [&](std::size_t slot, int c_lo[D], int c_hi[D]) {
    const std::size_t s = slot / kVerts, i = slot % kVerts;
    const Vec<D>& x0 = coords_[simplices_[kVerts * s + (i + 1) % kVerts]];
    Vec<D> b_lo = x0, b_hi = x0;
    for (std::size_t j = 2; j < kVerts; ++j) {
      const Vec<D>& x = coords_[simplices_[kVerts * s + (i + j) % kVerts]];
      for (int a = 0; a < D; ++a)
        b_lo[a] = std::min(b_lo[a], x[a]), b_hi[a] = std::max(b_hi[a], x[a]);
    }
    cell_of(b_lo, c_lo);
    cell_of(b_hi, c_hi);
  };
  int c_lo[D], c_hi[D];
  for (std::size_t slot = 0; slot < elem2elem_.size(); ++slot) {
    if (elem2elem_[slot] != kNoId) continue;
    face_box(slot, c_lo, c_hi);
    for_box<D>(c_lo, c_hi, grid_.n, [&](std::size_t c) { ++grid_.face_offsets[c + 1]; });
  }
  for (std::size_t c = 0; c < cells; ++c) grid_.face_offsets[c + 1] += grid_.face_offsets[c];
  grid_.faces.resize(grid_.face_offsets[cells]);
  std::vector<std::size_t> fill(grid_.face_offsets.begin(), grid_.face_offsets.end() - 1);
  for (std::size_t slot = 0; slot < elem2elem_.size(); ++slot) {
    if (elem2elem_[slot] != kNoId) continue;
    face_box(slot, c_lo, c_hi);
    for_box<D>(c_lo, c_hi, grid_.n,
               [&](std::size_t c) { grid_.faces[fill[c]++] = static_cast<Id>(slot); });
  }
}

template <int D>
SymMat<D> BackgroundMesh<D>::metric_at(const Location<D>& loc) const {
  RIEMESH_CHECK(loc.simplex >= 0 && static_cast<std::size_t>(loc.simplex) < num_simplices());
  const auto v = simplex(loc.simplex);
  // A vertex hit returns the input metric itself (no log/exp rounding).
  for (int i = 0; i < kVerts; ++i)
    if (loc.bary[i] == 1.0) return metrics_[v[i]];
  SymMat<D> m[kVerts];
  if (scheme_ == InterpScheme::kLogEuclidean) {
    for (int i = 0; i < kVerts; ++i) m[i] = logs_[v[i]];
    return interpolate_log_euclidean_logs<D>(m, loc.bary);
  }
  for (int i = 0; i < kVerts; ++i) m[i] = metrics_[v[i]];
  return interpolate<D>(scheme_, std::span<const SymMat<D>>(m), std::span<const double>(loc.bary));
}

template <int D>
SymMat<D> BackgroundMesh<D>::metric_at(const Vec<D>& p, Id hint, Id* found) const {
  const Location<D> loc = locate(p, hint);
  if (found) *found = loc.simplex;
  return metric_at(loc);
}

template <int D>
void BackgroundMesh<D>::interpolate_fields(const Location<D>& loc, std::span<const double> values,
                                           int components, std::span<double> out) const {
  if (components < 1 || values.size() != num_vertices() * static_cast<std::size_t>(components) ||
      out.size() < static_cast<std::size_t>(components)) {
    std::string msg = prefix();
    msg += "field of " + std::to_string(values.size()) + " values with " +
           std::to_string(components) + " components per vertex does not fit " +
           std::to_string(num_vertices()) + " vertices and an output of " +
           std::to_string(out.size());
    throw InputError(msg);
  }
  RIEMESH_CHECK(loc.simplex >= 0 && static_cast<std::size_t>(loc.simplex) < num_simplices());
  const auto v = simplex(loc.simplex);
  const auto k = static_cast<std::size_t>(components);
  for (std::size_t c = 0; c < k; ++c) {
    double s = 0.0;
    for (int i = 0; i < kVerts; ++i)
      s += loc.bary[i] * values[k * static_cast<std::size_t>(v[i]) + c];
    out[c] = s;
  }
}

template class BackgroundMesh<2>;
template class BackgroundMesh<3>;

}  // namespace riemesh
