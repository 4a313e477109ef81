// Edge swap n -> 2n - 4 (the best triangulation of the shell's ring) and face swap 2 -> 3.
#include <algorithm>

#include "mesh/adjacency.hpp"
#include "remesh/ops3d.hpp"

namespace riemesh {
namespace {

constexpr int kMaxShell = 7;

/// The ring of the closed shell of (a, b): p[0..n-1] with each (a, b, p[i], p[i+1]) a tet of
/// the shell, positively oriented. False when the shell is open, holds a listed face on the
/// edge, mixes tet refs, or is not a single ring.
bool shell_ring(const TetMesh& m, const std::vector<Id>& shell, Id a, Id b, Id* p) {
  const int n = static_cast<int>(shell.size());
  Id from[kMaxShell], to[kMaxShell];
  for (int k = 0; k < n; ++k) {
    const Id t = shell[k];
    if (m.tref[t] != m.tref[shell[0]]) return false;
    const int ia = tet_index(m, t, a), ib = tet_index(m, t, b);
    int others[2], c = 0;
    for (int i = 0; i < 4; ++i) {
      if (i == ia || i == ib) continue;
      others[c++] = i;
    }
    // Faces holding the edge are those opposite the two other vertices.
    for (const int i : others)
      if (m.tadj[4 * t + i] == kNoId || m.fbdy[4 * t + i]) return false;
    // Orientation of (a, b, c, d) relative to the tet's: parity of the index permutation.
    const int perm[4] = {ia, ib, others[0], others[1]};
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
    Id c0 = m.tv[4 * t + others[0]], d0 = m.tv[4 * t + others[1]];
    if (inversions % 2) std::swap(c0, d0);
    from[k] = c0, to[k] = d0;
  }
  p[0] = from[0];
  for (int k = 1; k <= n; ++k) {
    int next = -1;
    for (int j = 0; j < n; ++j)
      if (from[j] == p[k - 1]) next = j;
    if (next < 0) return false;
    if (k == n) return to[next] == p[0];
    p[k] = to[next];
    for (int j = 0; j < k; ++j)
      if (p[j] == p[k]) return false;
  }
  return false;
}

struct RingTriangulation {
  double q[kMaxShell][kMaxShell];
  int split[kMaxShell][kMaxShell];
};

void emit(const RingTriangulation& r, const Id* p, Id a, Id b, std::int32_t ref, int i, int j,
          std::vector<NewTet>& out) {
  if (j - i < 2) return;
  const int k = r.split[i][j];
  out.push_back({{a, p[i], p[k], p[j]}, ref});
  out.push_back({{b, p[i], p[j], p[k]}, ref});
  emit(r, p, a, b, ref, i, k, out);
  emit(r, p, a, b, ref, k, j, out);
}

}  // namespace

Outcome swap_edge(TetMesh& m, Id a, Id b, double min_gain, double max_length, Id hint) {
  thread_local std::vector<Id> shell;
  thread_local std::vector<NewTet> tets;
  collect_shell(m, a, b, shell, hint);
  const int n = static_cast<int>(shell.size());
  if (n < 3 || n > kMaxShell) return Outcome::kRejectedTopology;
  Id p[kMaxShell];
  if (!shell_ring(m, shell, a, b, p)) return Outcome::kRejectedTopology;
  double old_worst = 1.0;
  for (const Id t : shell) old_worst = std::min(old_worst, cached_quality(m, t));
  // Best triangulation of the ring polygon: maximise the worst tet (dynamic programming), with
  // no diagonal of the ring longer than max_length. A sub-polygon's triangulations at or below
  // `floor` cannot be part of an accepted one, so their tets are not measured (the measure is
  // the cost: an exponential per tet where the metric turns); the optimum above floor and its
  // choice among equals are the same.
  const double floor = std::max(0.0, old_worst + min_gain);
  bool ok[kMaxShell][kMaxShell];
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      ok[i][j] = j == i + 1 || (i == 0 && j == n - 1) || edge_length(m, p[i], p[j]) <= max_length;
  RingTriangulation r;
  for (int len = 1; len < n; ++len)
    for (int i = 0; i + len < n; ++i) {
      const int j = i + len;
      r.q[i][j] = len == 1 ? 2.0 : floor;
      for (int k = i + 1; k < j; ++k) {
        if (!ok[i][k] || !ok[k][j]) continue;
        double q = std::min(r.q[i][k], r.q[k][j]);
        if (q <= r.q[i][j]) continue;
        q = std::min(q, tet_quality(m, a, p[i], p[k], p[j]));
        if (q <= r.q[i][j]) continue;
        q = std::min(q, tet_quality(m, b, p[i], p[j], p[k]));
        if (q > r.q[i][j]) r.q[i][j] = q, r.split[i][j] = k;
      }
    }
  const double best = r.q[0][n - 1];
  if (!(best > floor)) return floor > 0.0 ? Outcome::kRejectedQuality : Outcome::kRejectedGeometry;
  tets.clear();
  emit(r, p, a, b, m.tref[shell[0]], 0, n - 1, tets);
  if (!replace_cavity(m, shell, tets, {})) return Outcome::kRejectedTopology;
  return Outcome::kApplied;
}

Outcome swap_face(TetMesh& m, Id slot, double min_gain, double max_length) {
  const Id r = m.tadj[slot];
  if (r == kNoId || m.fbdy[slot]) return Outcome::kRejectedTopology;
  const Id t = slot / 4, u = r / 4;
  if (m.tref[t] != m.tref[u]) return Outcome::kRejectedTopology;
  const int i = slot % 4;
  const Id d = m.tv[4 * t + i], e = m.tv[4 * u + r % 4];
  const Id f[3] = {m.tv[4 * t + kTetFace[i][0]], m.tv[4 * t + kTetFace[i][1]],
                   m.tv[4 * t + kTetFace[i][2]]};
  if (edge_length(m, d, e) > max_length) return Outcome::kRejectedQuality;
  const double old_worst = std::min(cached_quality(m, t), cached_quality(m, u));
  NewTet tets[3];
  double worst = 1.0;
  for (int k = 0; k < 3; ++k) {
    tets[k] = {{f[k], f[(k + 1) % 3], d, e}, m.tref[t]};
    worst = std::min(worst, tet_quality(m, tets[k].v));
  }
  if (!(worst > 0.0)) return Outcome::kRejectedGeometry;
  if (worst <= old_worst + min_gain) return Outcome::kRejectedQuality;
  const Id cavity[2] = {t, u};
  if (!replace_cavity(m, cavity, tets, {})) return Outcome::kRejectedTopology;
  return Outcome::kApplied;
}

}  // namespace riemesh
