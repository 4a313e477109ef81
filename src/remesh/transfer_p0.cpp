// Conservative transfer of P0 fields between planar triangle meshes (BOOK.md §8): every new
// triangle is intersected with the old triangles it overlaps.
//
// Candidates: the new triangle's centroid is located in the old mesh by walking from the
// previous answer (remesh/background.hpp), then old triangles are visited across edges while
// their overlap with the new one is not empty. The pieces old ∩ new tile the new triangle, and
// two pieces with a common boundary of positive length come from old triangles sharing an edge,
// so the search reaches every overlapping old triangle (the tiling of a convex set is connected
// through its edges). If rounding hides a piece, or the domains differ, the vertices and edge
// midpoints of the new triangle are located too and the search restarts from them.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "remesh/background.hpp"
#include "remesh/polygon_clip.hpp"
#include "remesh/simplex_geometry.hpp"
#include "remesh/transfer.hpp"

namespace riemesh {
namespace {

/// The corners of triangle t of a mesh, translated by −origin, counter-clockwise.
void corners(const std::vector<double>& coords, const Id* t, const Vec2& origin, Vec2 x[3]) {
  for (int i = 0; i < 3; ++i) {
    const auto v = static_cast<std::size_t>(t[i]);
    x[i] = Vec2{coords[2 * v] - origin[0], coords[2 * v + 1] - origin[1]};
  }
  if (simplex::signed_volume(x) < 0.0) std::swap(x[1], x[2]);
}

struct Components {
  std::vector<int> per_field;
  int total = 0;
};

Components check_fields(const Mesh& from, const std::vector<Field>& fields) {
  Components c;
  for (const Field& f : fields) {
    const int n = field_components(f.kind, from.dim);
    if (f.values.size() != from.num_triangles() * static_cast<std::size_t>(n))
      throw InputError("field '" + f.name + "' does not have one value set per triangle (" +
                       std::to_string(f.values.size()) + " values for " +
                       std::to_string(from.num_triangles()) + " triangles)");
    c.per_field.push_back(n);
    c.total += n;
  }
  return c;
}

/// The per-element values of all fields of old triangle s, concatenated.
void gather(const std::vector<Field>& fields, const Components& c, std::size_t s, double* out) {
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const auto n = static_cast<std::size_t>(c.per_field[f]);
    for (std::size_t k = 0; k < n; ++k) *out++ = fields[f].values[n * s + k];
  }
}

/// The walk needs a background mesh; its metric is not used here (identity).
std::vector<double> identity_metrics(std::size_t n) {
  std::vector<double> m;
  m.reserve(3 * n);
  for (std::size_t v = 0; v < n; ++v) m.insert(m.end(), {1.0, 0.0, 1.0});
  return m;
}

class P0Transfer {
 public:
  P0Transfer(const Mesh& from, const std::vector<Field>& fields, const Mesh& to)
      : from_(from), fields_(fields), to_(to), comps_(check_fields(from, fields)),
        bg_(from, identity_metrics(from.num_vertices()), InterpScheme::kLinear),
        stamp_(from.num_triangles(), -1) {}

  std::vector<Field> run(P0TransferReport& r);

 private:
  /// Visits the old triangles reachable from `seed` through overlapping neighbours; adds the
  /// overlaps with new triangle e (corners x, translated by origin) to acc and covered.
  void search(Id seed, Id e, const Vec2 x[3], const Vec2& origin, std::vector<double>& acc,
              double& covered, P0TransferReport& r);

  const Mesh& from_;
  const std::vector<Field>& fields_;
  const Mesh& to_;
  Components comps_;
  BackgroundMesh<2> bg_;
  std::vector<Id> stamp_;  // the last new triangle that visited each old one
  std::vector<Id> stack_;
  std::vector<double> values_;
};

void P0Transfer::search(Id seed, Id e, const Vec2 x[3], const Vec2& origin,
                        std::vector<double>& acc, double& covered, P0TransferReport& r) {
  if (stamp_[static_cast<std::size_t>(seed)] == e) return;
  stamp_[static_cast<std::size_t>(seed)] = e;
  stack_.assign(1, seed);
  values_.resize(static_cast<std::size_t>(comps_.total));
  while (!stack_.empty()) {
    const Id s = stack_.back();
    stack_.pop_back();
    Vec2 y[3];
    corners(from_.coords, &from_.triangles[3 * static_cast<std::size_t>(s)], origin, y);
    const clip::Polygon piece = clip::intersect_triangles(x, y);
    if (piece.n < 3) continue;  // apart, or touching along an edge or at a vertex
    const double area = std::max(0.0, 0.5 * clip::twice_area(piece));
    if (area > 0.0) {
      ++r.pairs;
      covered += area;
      gather(fields_, comps_, static_cast<std::size_t>(s), values_.data());
      for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += area * values_[k];
    }
    for (int i = 0; i < 3; ++i) {
      const Id n = bg_.neighbour(s, i);
      if (n == kNoId || stamp_[static_cast<std::size_t>(n)] == e) continue;
      stamp_[static_cast<std::size_t>(n)] = e;
      stack_.push_back(n);
    }
  }
}

std::vector<Field> P0Transfer::run(P0TransferReport& r) {
  const std::size_t nt = to_.num_triangles();
  const auto total = static_cast<std::size_t>(comps_.total);
  std::vector<double> out(nt * total, 0.0);
  std::vector<double> acc(total);
  Id hint = kNoId;
  for (std::size_t t = 0; t < nt; ++t) {
    const Id* tv = &to_.triangles[3 * t];
    const Vec2 origin{to_.coords[2 * static_cast<std::size_t>(tv[0])],
                      to_.coords[2 * static_cast<std::size_t>(tv[0]) + 1]};
    Vec2 x[3];
    corners(to_.coords, tv, origin, x);
    const double area = 0.5 * simplex::signed_volume(x);
    std::fill(acc.begin(), acc.end(), 0.0);
    double covered = 0.0;
    const Id e = static_cast<Id>(t);
    const Vec2 centroid = origin + (1.0 / 3.0) * (x[0] + x[1] + x[2]);
    const Location<2> loc = bg_.locate(centroid, hint);
    hint = loc.simplex;
    search(loc.simplex, e, x, origin, acc, covered, r);
    if (covered < area * (1.0 - 1e-12)) {
      // Rounding hid a piece, or the domains differ: more seeds, from the corners inwards.
      for (int k = 0; k < 6; ++k) {
        const Vec2 p = k < 3 ? 0.999 * x[k] + 0.0005 * (x[(k + 1) % 3] + x[(k + 2) % 3])
                             : 0.5 * (x[k - 3] + x[(k - 2) % 3]);
        const Location<2> l = bg_.locate(origin + p, loc.simplex);
        if (l.inside) search(l.simplex, e, x, origin, acc, covered, r);
      }
    }
    r.overlap_measure += covered;
    double* v = &out[total * t];
    if (covered > 0.0) {
      for (std::size_t k = 0; k < total; ++k) v[k] = acc[k] / covered;
    } else {
      ++r.unmatched_elements;  // outside the old mesh: the nearest old element's value
      gather(fields_, comps_, static_cast<std::size_t>(loc.simplex), v);
    }
  }
  std::vector<Field> result;
  std::size_t offset = 0;
  for (std::size_t f = 0; f < fields_.size(); ++f) {
    const auto n = static_cast<std::size_t>(comps_.per_field[f]);
    Field g{fields_[f].name, fields_[f].kind, std::vector<double>(nt * n)};
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t k = 0; k < n; ++k) g.values[n * t + k] = out[total * t + offset + k];
    offset += n;
    result.push_back(std::move(g));
  }
  return result;
}

/// Σ value × area per component of the fields on a mesh's triangles; adds the areas to *measure.
std::vector<double> integrals(const Mesh& m, const std::vector<Field>& fields, double* measure) {
  std::vector<double> out;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    Vec2 x[3];
    corners(m.coords, &m.triangles[3 * t], Vec2{0.0, 0.0}, x);
    const double area = 0.5 * simplex::signed_volume(x);
    if (measure) *measure += area;
    std::size_t k = 0;
    for (const Field& f : fields) {
      const auto n = static_cast<std::size_t>(field_components(f.kind, m.dim));
      for (std::size_t c = 0; c < n; ++c, ++k) {
        if (out.size() <= k) out.push_back(0.0);
        out[k] += area * f.values[n * t + c];
      }
    }
  }
  return out;
}

}  // namespace

std::vector<Field> transfer_p0(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                               P0TransferReport* report) {
  if (from.dim != to.dim || from.kind() != to.kind())
    throw InputError("field transfer needs two meshes of the same kind");
  if (from.kind() == MeshKind::kVolume)
    throw InputError("conservative transfer of tetrahedral P0 fields is not implemented yet");
  if (from.kind() != MeshKind::kPlanar)
    throw InputError("conservative transfer works on planar triangle meshes");
  P0TransferReport r;
  std::vector<Field> out;
  {
    P0Transfer transfer(from, fields, to);
    out = transfer.run(r);
  }
  r.old_integral = integrals(from, fields, &r.old_measure);
  r.new_integral = integrals(to, out, &r.new_measure);
  r.uncovered_new = r.new_measure - r.overlap_measure;
  r.uncovered_old = r.old_measure - r.overlap_measure;
  if (report) *report = std::move(r);
  return out;
}

}  // namespace riemesh
