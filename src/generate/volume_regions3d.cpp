#include "generate/volume_regions3d.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/predicates.hpp"

namespace riemesh {

namespace {

using detail::Face;
using detail::sorted_face;

/// Face i of a positive tet, oriented with its normal away from the tet.
constexpr int kOutward[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

std::string place(const double* p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%g, %g, %g)", p[0], p[1], p[2]);
  return buf;
}

/// Per tet face (4 t + i): the surface triangle on it, or kNoId.
std::vector<Id> surface_faces(const Tetrahedralization& tz, std::span<const Id> triangles) {
  std::vector<std::pair<Face, Id>> faces(triangles.size() / 3);
  for (std::size_t k = 0; k < faces.size(); ++k)
    faces[k] = {sorted_face(triangles[3 * k], triangles[3 * k + 1], triangles[3 * k + 2]),
                static_cast<Id>(k)};
  std::sort(faces.begin(), faces.end());
  std::vector<Id> out(tz.tets.size(), kNoId);
  for (std::size_t t = 0; t < tz.num_tets(); ++t) {
    const Id* v = &tz.tets[4 * t];
    for (int i = 0; i < 4; ++i) {
      const Face f = sorted_face(v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4]);
      const auto it = std::lower_bound(faces.begin(), faces.end(), std::pair<Face, Id>{f, -1});
      if (it != faces.end() && it->first == f)
        out[4 * t + static_cast<std::size_t>(i)] = it->second;
    }
  }
  return out;
}

/// Does surface triangle (a, b, c) face away from tet v across its face i?
bool faces_away(const Id* v, int i, const Id* abc) {
  const Id f0 = v[kOutward[i][0]], f1 = v[kOutward[i][1]], f2 = v[kOutward[i][2]];
  return abc[0] == f0 ? abc[1] == f1 : abc[0] == f1 ? abc[1] == f2 : abc[1] == f0;
}

/// The tet whose closure holds p and whose region is not the outside (ties: the first), or kNoId;
/// on_surface is set when p lies on a surface triangle.
Id locate(const Tetrahedralization& tz, std::span<const double> coords,
          const std::vector<Id>& on_face, const double* p, bool* on_surface) {
  const auto xyz = [&](Id v) { return coords.data() + 3 * static_cast<std::size_t>(v); };
  for (std::size_t t = 0; t < tz.num_tets(); ++t) {
    const Id* v = &tz.tets[4 * t];
    bool inside = true, on = false;
    for (int i = 0; i < 4 && inside; ++i) {
      const double* q[4] = {xyz(v[0]), xyz(v[1]), xyz(v[2]), xyz(v[3])};
      q[i] = p;
      const double s = orient3d(q[0], q[1], q[2], q[3]);
      inside = s >= 0.0;
      if (s == 0.0 && on_face[4 * t + static_cast<std::size_t>(i)] != kNoId) on = true;
    }
    if (!inside) continue;
    *on_surface = on;
    return static_cast<Id>(t);
  }
  return kNoId;
}

}  // namespace

TetRegions tet_regions(const Tetrahedralization& tz, std::span<const Id> triangles,
                       std::span<const double> coords, std::span<const double> hole_points,
                       bool no_holes) {
  const std::size_t nt = tz.num_tets();
  const std::vector<Id> on_face = surface_faces(tz, triangles);
  // Regions: flooding through the faces that are no surface triangle.
  std::vector<int> region(nt, -1);
  int count = 0;
  std::vector<Id> stack;
  for (std::size_t s = 0; s < nt; ++s) {
    if (region[s] >= 0) continue;
    region[s] = count;
    stack.assign(1, static_cast<Id>(s));
    while (!stack.empty()) {
      const auto t = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      for (std::size_t i = 0; i < 4; ++i) {
        const Id n = tz.tet2tet[4 * t + i];
        if (n == kNoId || on_face[4 * t + i] != kNoId || region[static_cast<std::size_t>(n)] >= 0)
          continue;
        region[static_cast<std::size_t>(n)] = count;
        stack.push_back(n);
      }
    }
    ++count;
  }
  const auto rc = static_cast<std::size_t>(count);
  std::vector<char> outside(rc, 0), by_outside(rc, 0);
  std::vector<std::size_t> away(rc, 0), toward(rc, 0);
  std::vector<Id> first(rc, static_cast<Id>(triangles.size()));
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t i = 0; i < 4; ++i)
      if (tz.tet2tet[4 * t + i] == kNoId && on_face[4 * t + i] == kNoId)
        outside[static_cast<std::size_t>(region[t])] = 1;
  // How the surface triangles face each region, and how the outer boundary faces the outside.
  std::size_t outer_away = 0, outer_toward = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    const auto r = static_cast<std::size_t>(region[t]);
    if (outside[r]) continue;
    for (int i = 0; i < 4; ++i) {
      const std::size_t k = 4 * t + static_cast<std::size_t>(i);
      const Id f = on_face[k];
      if (f == kNoId) continue;
      first[r] = std::min(first[r], f);
      const bool out = faces_away(&tz.tets[4 * t], i, &triangles[3 * static_cast<std::size_t>(f)]);
      ++(out ? away[r] : toward[r]);
      const Id n = tz.tet2tet[k];
      if (n == kNoId || outside[static_cast<std::size_t>(region[static_cast<std::size_t>(n)])]) {
        by_outside[r] = 1;
        ++(out ? outer_away : outer_toward);
      }
    }
  }
  const bool outward = outer_away >= outer_toward;
  std::vector<char> hole(rc, 0);
  TetRegions result;
  if (!hole_points.empty()) {
    // Per region, the first hole point in it + 1 (0: none).
    std::vector<std::size_t> point_of(rc, 0);
    for (std::size_t h = 0; h + 2 < hole_points.size(); h += 3) {
      bool on_surface = false;
      const Id t = locate(tz, coords, on_face, &hole_points[h], &on_surface);
      const std::string where = place(&hole_points[h]);
      if (t == kNoId || outside[static_cast<std::size_t>(region[static_cast<std::size_t>(t)])])
        throw InputError("hole point " + where + " is outside the volume");
      if (on_surface) throw InputError("hole point " + where + " is on the surface");
      const auto r = static_cast<std::size_t>(region[static_cast<std::size_t>(t)]);
      // A hole must be enclosed by meshed regions: the surface around it bounds them.
      if (by_outside[r])
        throw InputError("hole point " + where +
                         " is in a region next to the outside: only regions enclosed by others "
                         "can be holes");
      hole[r] = 1;
      if (!point_of[r]) point_of[r] = h / 3 + 1;
    }
    // Two holes side by side: the triangles between them would bound no tetrahedron.
    for (std::size_t t = 0; t < nt; ++t) {
      const auto r = static_cast<std::size_t>(region[t]);
      for (std::size_t i = 0; hole[r] && i < 4; ++i) {
        const Id n = tz.tet2tet[4 * t + i];
        if (n == kNoId || on_face[4 * t + i] == kNoId) continue;
        const auto q = static_cast<std::size_t>(region[static_cast<std::size_t>(n)]);
        if (q == r || !hole[q]) continue;
        throw InputError("hole points " + place(&hole_points[3 * (point_of[r] - 1)]) + " and " +
                         place(&hole_points[3 * (point_of[q] - 1)]) +
                         " are in regions next to each other: the triangles between them would "
                         "bound no volume");
      }
    }
  } else if (!no_holes) {
    for (std::size_t r = 0; r < rc; ++r)
      hole[r] = !outside[r] && !by_outside[r] && (outward ? away[r] == 0 : toward[r] == 0);
  }
  // Refs in the order of the first surface triangle around each region.
  std::vector<std::pair<Id, std::size_t>> kept;
  for (std::size_t r = 0; r < rc; ++r) {
    if (outside[r]) continue;
    if (hole[r])
      ++result.holes;
    else
      kept.push_back({first[r], r});
  }
  if (kept.empty()) throw InputError("no region is left to mesh: every one is a hole");
  std::sort(kept.begin(), kept.end());
  std::vector<int> ref(rc, 0);
  for (std::size_t k = 0; k < kept.size(); ++k) ref[kept[k].second] = static_cast<int>(k + 1);
  result.regions = static_cast<int>(kept.size());
  result.ref.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) result.ref[t] = ref[static_cast<std::size_t>(region[t])];
  return result;
}

void require_no_pinch(const Mesh& volume) {
  const std::size_t nt = volume.num_tets();
  // Union-find on the corners (4 t + i), joined across the faces two tets share.
  std::vector<std::pair<Face, std::size_t>> faces(4 * nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const Id* v = &volume.tets[4 * t];
    for (std::size_t i = 0; i < 4; ++i)
      faces[4 * t + i] = {sorted_face(v[(i + 1) % 4], v[(i + 2) % 4], v[(i + 3) % 4]), 4 * t + i};
  }
  std::sort(faces.begin(), faces.end());
  std::vector<std::size_t> parent(4 * nt);
  for (std::size_t k = 0; k < parent.size(); ++k) parent[k] = k;
  const auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  const auto corner = [&](std::size_t t, Id w) {
    const Id* v = &volume.tets[4 * t];
    return 4 * t + (v[0] == w ? 0 : v[1] == w ? 1 : v[2] == w ? 2 : 3);
  };
  for (std::size_t k = 0; k + 1 < faces.size(); ++k) {
    if (faces[k].first != faces[k + 1].first) continue;
    const std::size_t t = faces[k].second / 4, u = faces[k + 1].second / 4;
    for (const Id w : faces[k].first) {
      const std::size_t x = root(corner(t, w)), y = root(corner(u, w));
      parent[std::max(x, y)] = std::min(x, y);
    }
  }
  std::vector<std::size_t> seen(volume.num_vertices(), parent.size());
  std::size_t pinched = 0;
  Id first = kNoId;
  for (std::size_t k = 0; k < parent.size(); ++k) {
    const auto v = static_cast<std::size_t>(volume.tets[k]);
    const std::size_t r = root(k);
    if (seen[v] == parent.size()) {
      seen[v] = r;
    } else if (seen[v] != r && seen[v] != parent.size() + 1) {
      seen[v] = parent.size() + 1;  // counted
      if (pinched++ == 0 || static_cast<Id>(v) < first) first = static_cast<Id>(v);
    }
  }
  if (pinched)
    throw InputError(
        "the surface cannot bound a volume: separate solids touch along an edge or "
        "at a point, at " +
        std::to_string(pinched) +
        " vertices (first: " + place(&volume.coords[3 * static_cast<std::size_t>(first)]) + ")");
}

}  // namespace riemesh
