#include "mesh/check.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "core/vec.hpp"
#include "mesh/check_detail.hpp"

namespace riemesh {
namespace {

using check_detail::Collector;
using check_detail::Elements;

void check_sizes(const Mesh& m, Collector& col) {
  auto expect = [&col](std::size_t got, std::size_t want, EntityKind kind, bool may_be_empty) {
    if (got != want && !(may_be_empty && got == 0))
      col.add_count(CheckCategory::kArraySize, kind, got > want ? got - want : want - got);
  };
  if (m.dim != 2 && m.dim != 3) {
    col.add_count(CheckCategory::kArraySize, EntityKind::kNone, 1);
    return;
  }
  expect(m.coords.size() % m.dim, 0, EntityKind::kVertex, false);
  expect(m.edges.size() % 2, 0, EntityKind::kEdge, false);
  expect(m.triangles.size() % 3, 0, EntityKind::kTriangle, false);
  expect(m.tets.size() % 4, 0, EntityKind::kTet, false);
  if (m.dim == 2) expect(m.tets.size(), 0, EntityKind::kTet, false);
  expect(m.vert_ref.size(), m.num_vertices(), EntityKind::kVertex, false);
  expect(m.vert_tag.size(), m.num_vertices(), EntityKind::kVertex, true);
  expect(m.edge_ref.size(), m.num_edges(), EntityKind::kEdge, false);
  expect(m.edge_tag.size(), m.num_edges(), EntityKind::kEdge, true);
  expect(m.tri_ref.size(), m.num_triangles(), EntityKind::kTriangle, false);
  expect(m.tri_tag.size(), m.num_triangles(), EntityKind::kTriangle, true);
  expect(m.tet_ref.size(), m.num_tets(), EntityKind::kTet, false);
  for (const Field& f : m.fields)
    expect(f.values.size(), m.num_vertices() * field_components(f.kind, m.dim), EntityKind::kVertex,
           false);
}

/// Ids in range and no repeated vertex, for one connectivity array; false if an id is bad.
bool check_ids(const std::vector<Id>& conn, int k, EntityKind kind, std::size_t nv,
               Collector& col) {
  bool ok = true;
  for (std::size_t e = 0; e < conn.size() / k; ++e) {
    const std::span<const Id> v(conn.data() + k * e, k);
    bool in_range = true;
    for (Id x : v) in_range = in_range && x >= 0 && static_cast<std::size_t>(x) < nv;
    if (!in_range) {
      col.add(CheckCategory::kIdOutOfRange, kind, static_cast<Id>(e), v);
      ok = false;
      continue;
    }
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j)
        if (v[i] == v[j]) {
          col.add(CheckCategory::kRepeatedVertex, kind, static_cast<Id>(e), v);
          i = j = k;
        }
  }
  return ok;
}

void check_vertices(const Mesh& m, const Elements& el, Collector& col) {
  const std::size_t nv = m.num_vertices();
  for (std::size_t v = 0; v < nv; ++v)
    for (int c = 0; c < m.dim; ++c)
      if (!std::isfinite(m.coords[m.dim * v + c])) {
        const Id id = static_cast<Id>(v);
        col.add(CheckCategory::kNonFiniteCoordinate, EntityKind::kVertex, id, {&id, 1});
        break;
      }
  std::vector<char> used(nv, 0);
  for (Id v : *el.verts) used[v] = 1;
  for (std::size_t v = 0; v < nv; ++v)
    if (!used[v]) {
      const Id id = static_cast<Id>(v);
      col.add(CheckCategory::kUnusedVertex, EntityKind::kVertex, id, {&id, 1});
    }
}

template <int D>
Vec<D> point(const Mesh& m, Id v) {
  Vec<D> p{};
  for (int c = 0; c < D; ++c) p[c] = m.coords[static_cast<std::size_t>(D) * v + c];
  return p;
}

/// Signed measure of element v (area, or volume; unsigned area on surfaces) and the tolerance.
double measure(const Mesh& m, std::span<const Id> v, double& tol) {
  double lmax2 = 0.0;
  auto edge2 = [&](Id a, Id b) {
    double s = 0.0;
    for (int c = 0; c < m.dim; ++c) {
      const double d = m.coords[m.dim * b + c] - m.coords[m.dim * a + c];
      s += d * d;
    }
    lmax2 = std::max(lmax2, s);
  };
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j) edge2(v[i], v[j]);
  if (v.size() == 4) {
    const Vec3 p0 = point<3>(m, v[0]);
    tol = kMeasureTolerance * lmax2 * std::sqrt(lmax2);
    const Vec3 a = point<3>(m, v[1]) - p0, b = point<3>(m, v[2]) - p0, c = point<3>(m, v[3]) - p0;
    return dot(a, cross(b, c)) / 6.0;
  }
  tol = kMeasureTolerance * lmax2;
  if (m.dim == 2) {
    const Vec2 p0 = point<2>(m, v[0]);
    return 0.5 * cross(point<2>(m, v[1]) - p0, point<2>(m, v[2]) - p0);
  }
  const Vec3 p0 = point<3>(m, v[0]);
  return 0.5 * norm(cross(point<3>(m, v[1]) - p0, point<3>(m, v[2]) - p0));
}

bool has_repeated(std::span<const Id> v) {
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j)
      if (v[i] == v[j]) return true;
  return false;
}

void check_measures(const Mesh& m, const Elements& el, Collector& col) {
  for (std::size_t e = 0; e < el.size(); ++e) {
    const auto v = el.of(e);
    if (has_repeated(v)) continue;  // reported already
    double tol = 0.0;
    const double vol = measure(m, v, tol);
    const Id id = static_cast<Id>(e);
    if (std::abs(vol) <= tol || !std::isfinite(vol))
      col.add(CheckCategory::kZeroMeasureElement, el.kind, id, v);
    else if (vol < 0.0)
      col.add(CheckCategory::kInvertedElement, el.kind, id, v);
  }
}

/// Sorted vertex tuple of k <= 4 ids, padded.
std::array<Id, 4> sorted_key(std::span<const Id> v) {
  std::array<Id, 4> key{kNoId, kNoId, kNoId, kNoId};
  for (std::size_t i = 0; i < v.size() && i < 4; ++i) {  // insertion sort of <= 4 ids
    std::size_t j = i;
    for (; j > 0 && key[j - 1] > v[i]; --j) key[j] = key[j - 1];
    key[j] = v[i];
  }
  return key;
}

/// Reports duplicated elements; returns the ids of the elements topology is checked on, in
/// order: the first occurrence of each, without the elements with a repeated vertex (reported
/// by check_vertices; the adjacency cannot hold them: a tet "1 1 2 3" made the checker abort
/// with a corrupted heap).
std::vector<Id> find_duplicates(const Elements& el, Collector& col) {
  std::vector<std::pair<std::array<Id, 4>, Id>> keys(el.size());
  for (std::size_t e = 0; e < el.size(); ++e) keys[e] = {sorted_key(el.of(e)), static_cast<Id>(e)};
  std::sort(keys.begin(), keys.end());
  std::vector<char> dup(el.size(), 0);
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (keys[i].first == keys[i - 1].first) dup[keys[i].second] = 1;
  std::vector<Id> kept;
  for (std::size_t e = 0; e < el.size(); ++e) {
    if (dup[e]) col.add(CheckCategory::kDuplicateElement, el.kind, static_cast<Id>(e), el.of(e));
  }
  for (std::size_t e = 0; e < el.size(); ++e) {
    const auto v = el.of(static_cast<Id>(e));
    bool repeated = false;
    for (std::size_t i = 0; i < v.size(); ++i)
      for (std::size_t j = i + 1; j < v.size(); ++j) repeated = repeated || v[i] == v[j];
    if (!dup[e] && !repeated) kept.push_back(static_cast<Id>(e));
  }
  return kept;
}

}  // namespace

const char* to_string(CheckCategory category) {
  switch (category) {
    case CheckCategory::kArraySize:
      return "array size mismatch";
    case CheckCategory::kIdOutOfRange:
      return "vertex id out of range";
    case CheckCategory::kNonFiniteCoordinate:
      return "non-finite coordinate";
    case CheckCategory::kRepeatedVertex:
      return "repeated vertex in an entity";
    case CheckCategory::kUnusedVertex:
      return "unused vertex";
    case CheckCategory::kInvertedElement:
      return "inverted element";
    case CheckCategory::kZeroMeasureElement:
      return "zero-measure element";
    case CheckCategory::kDuplicateElement:
      return "duplicate element";
    case CheckCategory::kNonManifoldFace:
      return "non-manifold face";
    case CheckCategory::kInconsistentOrientation:
      return "inconsistent orientation";
    case CheckCategory::kOverlappingElements:
      return "overlapping elements (the mesh folds over an edge)";
    case CheckCategory::kOpenBoundary:
      return "open boundary";
    case CheckCategory::kNonManifoldBoundary:
      return "non-manifold boundary";
    case CheckCategory::kMissingBoundary:
      return "boundary entity not listed";
    case CheckCategory::kOrphanEntity:
      return "listed entity not in the elements";
    case CheckCategory::kDuplicateBoundaryEntity:
      return "entity listed twice";
    case CheckCategory::kRegionsMeet:
      return "edges on 3 or more triangles (where regions meet)";
  }
  return "unknown";
}

std::size_t CheckReport::count(CheckCategory category) const {
  const CheckIssue* issue = find(category);
  return issue ? issue->count : 0;
}

const CheckIssue* CheckReport::find(CheckCategory category) const {
  for (const auto* list : {&issues, &notes})
    for (const CheckIssue& issue : *list)
      if (issue.category == category) return &issue;
  return nullptr;
}

CheckReport check_mesh(const Mesh& m) {
  Collector col(m);
  check_sizes(m, col);
  if (col.has(CheckCategory::kArraySize)) {
    // Connectivity we cannot even slice: stop there.
    const bool sliceable = (m.dim == 2 || m.dim == 3) && m.coords.size() % m.dim == 0 &&
                           m.edges.size() % 2 == 0 && m.triangles.size() % 3 == 0 &&
                           m.tets.size() % 4 == 0 && (m.dim == 3 || m.tets.empty());
    if (!sliceable) return col.report();
  }
  const std::size_t nv = m.num_vertices();
  bool ids_ok = check_ids(m.edges, 2, EntityKind::kEdge, nv, col);
  ids_ok = check_ids(m.triangles, 3, EntityKind::kTriangle, nv, col) && ids_ok;
  ids_ok = check_ids(m.tets, 4, EntityKind::kTet, nv, col) && ids_ok;
  if (!ids_ok) return col.report();
  if (m.kind() == MeshKind::kEmpty) {
    check_detail::check_edge_loops(m, col);  // a boundary given by its edges only
    return col.report();
  }

  Elements el;
  if (m.kind() == MeshKind::kVolume)
    el = {&m.tets, 4, EntityKind::kTet};
  else
    el = {&m.triangles, 3, EntityKind::kTriangle};
  check_vertices(m, el, col);
  if (col.has(CheckCategory::kNonFiniteCoordinate)) return col.report();
  check_measures(m, el, col);
  const std::vector<Id> kept = find_duplicates(el, col);
  check_detail::check_topology(m, el, kept, col);
  return col.report();
}

CoincidentVertices find_coincident_vertices(const Mesh& m) {
  CoincidentVertices r;
  const std::size_t nv = m.num_vertices(), dim = m.dim;
  if (dim != 2 && dim != 3) return r;
  std::vector<char> used(nv, 0);
  for (const std::vector<Id>* list : {&m.tets, &m.triangles, &m.edges})
    for (const Id v : *list)
      if (v >= 0 && static_cast<std::size_t>(v) < nv) used[static_cast<std::size_t>(v)] = 1;
  const auto xyz = [&](Id v) {
    return std::span<const double>(&m.coords[dim * static_cast<std::size_t>(v)], dim);
  };
  std::vector<Id> ids;  // NaN coordinates left out: they would break the sort's order
  for (std::size_t v = 0; v < nv; ++v) {
    const auto p = xyz(static_cast<Id>(v));
    if (used[v] && std::all_of(p.begin(), p.end(), [](double x) { return std::isfinite(x); }))
      ids.push_back(static_cast<Id>(v));
  }
  const auto less = [&](Id a, Id b) {
    const auto pa = xyz(a), pb = xyz(b);
    return std::lexicographical_compare(pa.begin(), pa.end(), pb.begin(), pb.end()) ||
           (std::equal(pa.begin(), pa.end(), pb.begin()) && a < b);
  };
  std::sort(ids.begin(), ids.end(), less);
  std::size_t run = 0;  // the first of the current run of equal points: its smallest id
  for (std::size_t k = 1; k < ids.size(); ++k) {
    const auto pa = xyz(ids[k - 1]), pb = xyz(ids[k]);
    if (!std::equal(pa.begin(), pa.end(), pb.begin())) {
      run = k;
      continue;
    }
    ++r.pairs;
    const Id a = ids[run], b = ids[k];
    if (r.first_a == kNoId || a < r.first_a || (a == r.first_a && b < r.first_b))
      r.first_a = a, r.first_b = b;
  }
  return r;
}

}  // namespace riemesh
