// The Hausdorff checks of the surface operators (surface_hausdorff.hpp).
#include "remesh/surface_hausdorff.hpp"

#include <algorithm>

#include "mesh/distance.hpp"

namespace riemesh {
namespace {

/// Lattice order of the points of a new triangle checked against the input (corners excluded):
/// the order `riemesh distance` samples by default, so the check bounds what is measured.
constexpr int kProbeOrder = 4;

/// "Was p within hausd of the old triangles and is it no longer within hausd of the new ones?",
/// with per-triangle rejections computed once: the triangle's box grown by hausd, then its plane
/// (a point farther than hausd from the plane is farther from the triangle), then the exact
/// point-triangle distance. Old triangle i and new triangle i (usually sharing two corners)
/// share a group box, the union of theirs: a point far from both (a third of the points
/// gathered) is rejected by one box test for the pair. The new triangle that answered yes last
/// is tried first (consecutive points come from the same grid cell).
class CoverTest {
 public:
  CoverTest(const std::vector<Tri3>& old_t, const std::vector<Tri3>& new_t, double hausd)
      : hausd_(hausd), h2_(hausd * hausd), num_old_(old_t.size()), num_new_(new_t.size()) {
    groups_.resize(std::max(num_old_, num_new_));
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      Group& gr = groups_[g];
      gr.lo = g < num_new_ ? new_t[g][0] : old_t[g][0];
      gr.hi = gr.lo;
      if (g < num_old_) set(gr.old_item, old_t[g], gr);
      if (g < num_new_) set(gr.new_item, new_t[g], gr);
    }
  }
  /// True unless p is within hausd of an old triangle and of no new one.
  bool keeps(const Vec3& p) {
    if (num_new_ > 0 && close(p, groups_[last_].new_item)) return true;
    bool near_old = false;
    for (std::size_t g = 0; g < groups_.size(); ++g) {
      const Group& gr = groups_[g];
      if (!in_box(p, gr.lo, gr.hi)) continue;
      if (g < num_new_ && g != last_ && close(p, gr.new_item)) {
        last_ = g;
        return true;
      }
      if (!near_old && g < num_old_) near_old = close(p, gr.old_item);
    }
    return !near_old;
  }

 private:
  struct Item {
    TriangleProbe probe;
    Vec3 lo, hi;  // the triangle's box grown by hausd
  };
  struct Group {
    Item old_item, new_item;
    Vec3 lo, hi;  // the union of their boxes
  };
  void set(Item& it, const Tri3& t, Group& gr) const {
    it.probe = TriangleProbe(t[0], t[1], t[2]);
    it.lo = it.hi = t[0];
    for (const Vec3& p : t)
      for (int c = 0; c < 3; ++c) {
        it.lo[c] = std::min(it.lo[c], p[c] - hausd_);
        it.hi[c] = std::max(it.hi[c], p[c] + hausd_);
      }
    for (int c = 0; c < 3; ++c) {
      gr.lo[c] = std::min(gr.lo[c], it.lo[c]);
      gr.hi[c] = std::max(gr.hi[c], it.hi[c]);
    }
  }
  static bool in_box(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    for (int c = 0; c < 3; ++c)
      if (p[c] < lo[c] || p[c] > hi[c]) return false;
    return true;
  }
  bool close(const Vec3& p, const Item& it) const {
    return in_box(p, it.lo, it.hi) && it.probe.within(p, hausd_, h2_);
  }
  std::vector<Group> groups_;
  double hausd_, h2_;
  std::size_t num_old_, num_new_;
  std::size_t last_ = 0;  // the group whose new triangle answered yes last
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
  CoverTest cover(old_t, new_t, hausd);
  for (const Vec3& p : pts)
    if (!cover.keeps(p)) return false;  // covered before, not any more
  return true;
}

bool new_triangles_close(const SurfaceProjection& geo, double hausd, const std::vector<Tri3>& new_t,
                         Id hint, const std::vector<Tri3>* old_t) {
  auto has_corner = [](const Tri3& t, const Vec3& p) { return t[0] == p || t[1] == p || t[2] == p; };
  for (std::size_t k = 0; k < new_t.size(); ++k) {
    const Tri3& t = new_t[k];
    // The points of an edge shared with an earlier new triangle were checked with it, those of
    // an edge of an old triangle when it was made (the same points up to rounding): edges t0 t1
    // (j = 0), t0 t2 (i = 0), t1 t2 (i + j = order).
    bool done[3] = {false, false, false};
    auto mark_shared = [&](const Tri3& u) {
      const bool h0 = has_corner(u, t[0]), h1 = has_corner(u, t[1]), h2 = has_corner(u, t[2]);
      done[0] = done[0] || (h0 && h1);
      done[1] = done[1] || (h0 && h2);
      done[2] = done[2] || (h1 && h2);
    };
    for (std::size_t m = 0; m < k; ++m) mark_shared(new_t[m]);
    if (old_t)
      for (const Tri3& u : *old_t) mark_shared(u);
    // Row by row, alternately forward and backward: each point next to the previous one, so
    // that the walk of SurfaceProjection::within from the last answer has few steps to make.
    for (int i = 0; i <= kProbeOrder; ++i)
      for (int jj = 0; i + jj <= kProbeOrder; ++jj) {
        const int j = i % 2 == 0 ? jj : kProbeOrder - i - jj;
        if ((i == 0 && j == 0) || i == kProbeOrder || j == kProbeOrder) continue;  // corners
        if ((j == 0 && done[0]) || (i == 0 && done[1]) || (i + j == kProbeOrder && done[2])) continue;
        const Vec3 q = t[0] + (static_cast<double>(i) / kProbeOrder) * (t[1] - t[0]) +
                       (static_cast<double>(j) / kProbeOrder) * (t[2] - t[0]);
        if (!geo.within(q, hausd, &hint)) return false;
      }
  }
  return true;
}

}  // namespace riemesh
