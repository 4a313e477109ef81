// The A -> B check of the surface remesher (surface_cover.hpp) and the check points it keeps.
#include "remesh/surface_cover.hpp"

#include <algorithm>

namespace riemesh::surface_detail {
namespace {

std::size_t us(Id i) { return static_cast<std::size_t>(i); }

}  // namespace

bool new_triangles_cover(const State& s, std::span<const Id> old_ids,
                         const std::vector<Tri3>& new_t, std::span<const Id> new_ids,
                         CoverScratch& c) {
  const double h = kCheckMargin * s.opt->hausd, h2 = h * h;
  c.pts.clear();
  c.by.clear();
  c.run.clear();
  c.probe.clear();
  for (const Tri3& t : new_t) c.probe.emplace_back(t);
  const int nn = static_cast<int>(new_t.size());
  int last = 0;
  for (Id t : old_ids) {
    c.run.push_back(c.pts.size());
    int own = -1;  // the new triangle that keeps t's id
    for (int k = 0; k < nn; ++k)
      if (new_ids[us(k)] == t) own = k;
    if (own >= 0) last = own;
    for (Id p = s.cover_head[us(t)]; p != kNoId; p = s.cover_next[us(p)]) {
      const Vec3& x = s.check_pts[us(p)];
      int k = -1;
      if (nn > 0) {
        // Cheap answers first (inside a triangle's prism near its plane), the exact distance of
        // the edge bands only when no triangle says yes cheaply.
        int maybe = 0;
        const int a = c.probe[us(last)].quick(x, h);
        if (a == 1) k = last;
        maybe |= a == 2;
        for (int j = 0; k < 0 && j < nn; ++j) {
          if (j == last) continue;
          const int b = c.probe[us(j)].quick(x, h);
          if (b == 1) k = j;
          maybe |= b == 2;
        }
        if (k < 0 && maybe) {
          for (int j = 0; k < 0 && j < nn; ++j) {
            const int jj = j == 0 ? last : (j == last ? 0 : j);
            if (c.probe[us(jj)].exact(x, h2)) k = jj;
          }
        }
      }
      if (k < 0) return false;
      last = k;
      if (k != own) {
        c.pts.push_back(p);
        c.by.push_back(k);
      }
    }
  }
  c.run.push_back(c.pts.size());
  return true;
}

void hand_over(State& s, std::span<const Id> old_ids, std::span<const Id> new_ids,
               const CoverScratch& c) {
  s.cover_head.resize(s.num_triangles(), kNoId);
  for (std::size_t j = 0; j < old_ids.size(); ++j) {
    const Id t = old_ids[j];
    const bool kept = std::find(new_ids.begin(), new_ids.end(), t) != new_ids.end();
    if (!kept) {
      s.cover_head[us(t)] = kNoId;
      continue;
    }
    // Unlink the moved points: they are met in list order.
    std::size_t r = c.run[j];
    const std::size_t end = c.run[j + 1];
    Id* link = &s.cover_head[us(t)];
    while (r < end && *link != kNoId) {
      if (*link == c.pts[r]) {
        *link = s.cover_next[us(*link)];
        ++r;
      } else {
        link = &s.cover_next[us(*link)];
      }
    }
  }
  for (std::size_t k = 0; k < c.pts.size(); ++k) {
    const auto t = us(new_ids[us(c.by[k])]);
    s.cover_next[us(c.pts[k])] = s.cover_head[t];
    s.cover_head[t] = c.pts[k];
  }
}

void State::init_cover(const SurfaceProjection& projection) {
  std::vector<Vec3> pts;
  std::vector<Id> owner;
  projection.check_points_by_triangle(pts, &owner);
  // Numbered triangle by triangle (each list in the lattice's order): a list is one run of
  // memory, and the runs stay together as the lists merge.
  std::vector<Id> start(num_triangles() + 1, 0);
  for (Id t : owner) ++start[us(t) + 1];
  for (std::size_t t = 0; t < num_triangles(); ++t) start[t + 1] += start[t];
  check_pts.resize(pts.size());
  cover_head.assign(num_triangles(), kNoId);
  cover_next.assign(pts.size(), kNoId);
  std::vector<Id> fill(start.begin(), start.end() - 1);
  for (std::size_t p = 0; p < pts.size(); ++p) {
    const auto t = us(owner[p]);
    const Id id = fill[t]++;
    check_pts[us(id)] = pts[p];
    if (id > start[t]) cover_next[us(id - 1)] = id;
  }
  for (std::size_t t = 0; t < num_triangles(); ++t)
    if (start[t + 1] > start[t]) cover_head[t] = start[t];
}

}  // namespace riemesh::surface_detail
