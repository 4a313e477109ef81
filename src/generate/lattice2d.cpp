#include "generate/lattice2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "core/huge_pages.hpp"

namespace riemesh {

namespace {

constexpr double kRow = 0.86602540378443864676;  // √3/2: the distance between lattice rows

/// The Edges (and lone vertices, as edges of zero length) in unit-space cells of side `side`,
/// for the distance test of the lattice points: each segment is listed in the cells of its
/// points at spacing 1/2, so a point within 1/2 of it lies in one of the 3 × 3 cells around one
/// of those cells.
class SegmentGrid {
 public:
  SegmentGrid(std::vector<double> ends, const double lo[2], const double hi[2])
      : ends_(std::move(ends)) {
    const std::size_t n = ends_.size() / 4;
    double samples = 0;
    for (std::size_t s = 0; s < n; ++s) samples += 1.0 + 2.0 * length(s);
    // About four cells per sample (and never fewer than unit cells).
    const double area = (hi[0] - lo[0] + 2) * (hi[1] - lo[1] + 2);
    side_ = std::max(1.0, std::sqrt(area / std::max(1024.0, 4.0 * samples)));
    lo_[0] = lo[0] - 1, lo_[1] = lo[1] - 1;
    nx_ = static_cast<std::int64_t>((hi[0] - lo_[0] + 1) / side_) + 1;
    ny_ = static_cast<std::int64_t>((hi[1] - lo_[1] + 1) / side_) + 1;
    std::vector<std::pair<std::int64_t, Id>> pairs;
    for (std::size_t s = 0; s < n; ++s) {
      const double* e = &ends_[4 * s];
      const auto steps = static_cast<std::int64_t>(std::ceil(2.0 * length(s)));
      std::int64_t last = -1;
      for (std::int64_t k = 0; k <= steps; ++k) {
        const double t = steps > 0 ? static_cast<double>(k) / static_cast<double>(steps) : 0.0;
        const std::int64_t c = cell(e[0] + t * (e[2] - e[0]), e[1] + t * (e[3] - e[1]));
        if (c != last) pairs.emplace_back(c, static_cast<Id>(s));
        last = c;
      }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    for (const auto& [c, s] : pairs) ++start_[static_cast<std::size_t>(c) + 1];
    for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
    for (const auto& [c, s] : pairs) segment_.push_back(s);
  }

  /// Whether u is closer than `clearance` (≤ 1/2) to a segment.
  bool near(const double* u, double clearance) const {
    const auto cx = static_cast<std::int64_t>((u[0] - lo_[0]) / side_);
    const auto cy = static_cast<std::int64_t>((u[1] - lo_[1]) / side_);
    const double c2 = clearance * clearance;
    for (std::int64_t y = std::max<std::int64_t>(cy - 1, 0); y <= std::min(cy + 1, ny_ - 1); ++y)
      for (std::int64_t x = std::max<std::int64_t>(cx - 1, 0); x <= std::min(cx + 1, nx_ - 1);
           ++x) {
        const auto c = static_cast<std::size_t>(y * nx_ + x);
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k)
          if (distance2(segment_[k], u) < c2) return true;
      }
    return false;
  }

 private:
  double length(std::size_t s) const {
    const double* e = &ends_[4 * s];
    return std::hypot(e[2] - e[0], e[3] - e[1]);
  }
  std::int64_t cell(double x, double y) const {
    const auto cx =
        std::clamp<std::int64_t>(static_cast<std::int64_t>((x - lo_[0]) / side_), 0, nx_ - 1);
    const auto cy =
        std::clamp<std::int64_t>(static_cast<std::int64_t>((y - lo_[1]) / side_), 0, ny_ - 1);
    return cy * nx_ + cx;
  }
  double distance2(Id s, const double* u) const {
    const double* e = &ends_[4 * static_cast<std::size_t>(s)];
    const double dx = e[2] - e[0], dy = e[3] - e[1], wx = u[0] - e[0], wy = u[1] - e[1];
    const double dd = dx * dx + dy * dy;
    const double t = dd > 0 ? std::clamp((dx * wx + dy * wy) / dd, 0.0, 1.0) : 0.0;
    const double rx = wx - t * dx, ry = wy - t * dy;
    return rx * rx + ry * ry;
  }

  std::vector<double> ends_;  // 4 per segment: x0 y0 x1 y1 (unit space)
  double lo_[2] = {0, 0}, side_ = 1;
  std::int64_t nx_ = 1, ny_ = 1;
  std::vector<std::size_t> start_;
  std::vector<Id> segment_;
};

}  // namespace

MetricMap2d::MetricMap2d(const SymMat2& m) {
  const double a = m.c[0], b = m.c[1], c = m.c[2];
  if (!(std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && a > 0 && a * c - b * b > 0))
    throw InputError("lattice: the metric is not positive definite");
  l11 = std::sqrt(a);
  l12 = b / l11;
  l22 = std::sqrt(c - l12 * l12);
  if (!(l22 > 0)) throw InputError("lattice: the metric is not positive definite");
}

std::vector<double> lattice_points2d(const Mesh& domain, const SymMat2& m, double clearance) {
  RIEMESH_CHECK(domain.dim == 2 && clearance > 0 && clearance <= 0.5);
  const MetricMap2d map(m);
  const std::size_t nv = domain.num_vertices();
  if (nv == 0 || domain.num_triangles() == 0) return {};
  std::vector<double> u(2 * nv);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (std::size_t v = 0; v < nv; ++v) {
    map.to_unit(&domain.coords[2 * v], &u[2 * v]);
    for (int c = 0; c < 2; ++c)
      lo[c] = std::min(lo[c], u[2 * v + c]), hi[c] = std::max(hi[c], u[2 * v + c]);
  }
  // Row and column numbers fit 31 bits (a box wider than that asks for more points than the
  // callers allow anyway: the field point rounds are left to fill it).
  if (!(hi[0] - lo[0] < 1e9 && hi[1] - lo[1] < 1e9)) return {};
  // The segments to keep clear of: the Edges and the vertices on none.
  std::vector<double> ends;
  std::vector<std::uint8_t> on_edge(nv, 0);
  for (std::size_t e = 0; e < domain.num_edges(); ++e) {
    const Id a = domain.edges[2 * e], b = domain.edges[2 * e + 1];
    on_edge[a] = on_edge[b] = 1;
    ends.insert(ends.end(), {u[2 * a], u[2 * a + 1], u[2 * b], u[2 * b + 1]});
  }
  for (std::size_t v = 0; v < nv; ++v)
    if (!on_edge[v]) ends.insert(ends.end(), {u[2 * v], u[2 * v + 1], u[2 * v], u[2 * v + 1]});
  const SegmentGrid grid(std::move(ends), lo, hi);

  // Row j of the lattice: v = lo[1] + j·√3/2, points at u = lo[0] + i + (j odd ? 1/2 : 0). Each
  // triangle's rows by its edges' crossings; a point on an edge shared by two triangles comes
  // twice (the same doubles, from the same (i, j)) and is kept once.
  std::vector<std::int64_t> keys;  // (j << 32) + i
  for (std::size_t t = 0; t < domain.num_triangles(); ++t) {
    const double* p[3];
    for (int k = 0; k < 3; ++k)
      p[k] = &u[2 * static_cast<std::size_t>(domain.triangles[3 * t + k])];
    const double vmin = std::min({p[0][1], p[1][1], p[2][1]}),
                 vmax = std::max({p[0][1], p[1][1], p[2][1]});
    const auto j0 = static_cast<std::int64_t>(std::ceil((vmin - lo[1]) / kRow));
    const auto j1 = static_cast<std::int64_t>(std::floor((vmax - lo[1]) / kRow));
    for (std::int64_t j = j0; j <= j1; ++j) {
      const double v = lo[1] + static_cast<double>(j) * kRow;
      double left = INFINITY, right = -INFINITY;
      for (int k = 0; k < 3; ++k) {
        const double* a = p[k];
        const double* b = p[(k + 1) % 3];
        if ((a[1] - v) * (b[1] - v) > 0 || a[1] == b[1]) continue;
        const double x = a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
        left = std::min(left, x), right = std::max(right, x);
      }
      if (!(left <= right)) continue;
      const double shift = lo[0] + ((j & 1) ? 0.5 : 0.0);
      const auto i0 = static_cast<std::int64_t>(std::ceil(left - shift));
      const auto i1 = static_cast<std::int64_t>(std::floor(right - shift));
      for (std::int64_t i = i0; i <= i1; ++i) keys.push_back((j << 32) + i);
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<double> out;
  reserve_huge(out, 2 * keys.size());
  for (const std::int64_t key : keys) {
    const std::int64_t j = key >> 32, i = key - (j << 32);
    const double q[2] = {lo[0] + static_cast<double>(i) + ((j & 1) ? 0.5 : 0.0),
                         lo[1] + static_cast<double>(j) * kRow};
    if (grid.near(q, clearance)) continue;
    double x[2];
    map.from_unit(q, x);
    out.insert(out.end(), {x[0], x[1]});
  }
  return out;
}

}  // namespace riemesh
