// The Hausdorff checks of the surface operators (surface_hausdorff.hpp).
#include "remesh/surface_hausdorff.hpp"

#include <algorithm>

#include "mesh/distance.hpp"

namespace riemesh {
namespace {

/// Lattice order of the points of a new triangle checked against the input (corners excluded):
/// the order `riemesh distance` samples by default, so the check bounds what is measured.
constexpr int kProbeOrder = 4;

/// "Is p within hausd of one of these triangles?", with per-triangle rejections computed once:
/// the triangle's box grown by hausd, then its plane (a point farther than hausd from the plane
/// is farther from the triangle), then the exact point-triangle distance. The triangle that
/// answered yes last is tried first (consecutive points come from the same grid cell).
class NearTest {
 public:
  NearTest(const std::vector<Tri3>& tris, double hausd) : hausd_(hausd), h2_(hausd * hausd) {
    items_.reserve(tris.size());
    for (const Tri3& t : tris) {
      Item it{TriangleProbe(t[0], t[1], t[2]), t[0], t[0]};
      for (const Vec3& p : t)
        for (int c = 0; c < 3; ++c) {
          it.lo[c] = std::min(it.lo[c], p[c] - hausd);
          it.hi[c] = std::max(it.hi[c], p[c] + hausd);
        }
      items_.push_back(it);
    }
  }
  bool operator()(const Vec3& p) {
    const std::size_t n = items_.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = last_ + k < n ? last_ + k : last_ + k - n;
      if (close(p, items_[i])) {
        last_ = i;
        return true;
      }
    }
    return false;
  }

 private:
  struct Item {
    TriangleProbe probe;
    Vec3 lo, hi;  // the triangle's box grown by hausd
  };
  bool close(const Vec3& p, const Item& it) const {
    for (int c = 0; c < 3; ++c)
      if (p[c] < it.lo[c] || p[c] > it.hi[c]) return false;
    return it.probe.within(p, hausd_, h2_);
  }
  std::vector<Item> items_;
  double hausd_, h2_;
  std::size_t last_ = 0;
};

}  // namespace

bool keeps_input_close(const SurfaceProjection& geo, double hausd, const std::vector<Tri3>& old_t,
                       const std::vector<Tri3>& new_t) {
  if (old_t.empty()) return true;
  Vec3 lo = old_t[0][0], hi = old_t[0][0];
  for (const Tri3& t : old_t)
    for (const Vec3& p : t)
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], p[c] - hausd);
        hi[c] = std::max(hi[c], p[c] + hausd);
      }
  thread_local std::vector<Vec3> pts;  // scratch reused across calls (no shared state)
  pts.clear();
  geo.check_points(lo, hi, pts);
  NearTest near_new(new_t, hausd), near_old(old_t, hausd);
  for (const Vec3& p : pts)
    if (!near_new(p) && near_old(p)) return false;  // covered before, not any more
  return true;
}

bool new_triangles_close(const SurfaceProjection& geo, double hausd, const std::vector<Tri3>& new_t,
                         Id hint) {
  // Row by row, alternately forward and backward: each point next to the previous one, so that
  // the walk of SurfaceProjection::within from the last answer has few steps to make.
  for (const Tri3& t : new_t)
    for (int i = 0; i <= kProbeOrder; ++i)
      for (int jj = 0; i + jj <= kProbeOrder; ++jj) {
        const int j = i % 2 == 0 ? jj : kProbeOrder - i - jj;
        if ((i == 0 && j == 0) || i == kProbeOrder || j == kProbeOrder) continue;  // corners
        const Vec3 q = t[0] + (static_cast<double>(i) / kProbeOrder) * (t[1] - t[0]) +
                       (static_cast<double>(j) / kProbeOrder) * (t[2] - t[0]);
        if (!geo.within(q, hausd, &hint)) return false;
      }
  return true;
}

}  // namespace riemesh
