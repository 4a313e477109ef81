// Conservative transfer of P0 fields between planar triangle meshes or tetrahedral volumes
// (BOOK.md §8): every new element is intersected with the old elements it overlaps.
//
// Candidates: the new element's centroid is located in the old mesh by walking from the
// previous answer (remesh/background.hpp), then old elements are visited across faces while
// their overlap with the new one is not empty. The pieces old ∩ new tile the new element, and
// two pieces with a common boundary of positive (D−1)-measure come from old elements sharing a
// face, so the search reaches every overlapping old element (the tiling of a convex set is
// connected through its faces). If rounding hides a piece, or the domains differ, points near
// the vertices and the edge midpoints of the new element are located too and the search restarts
// from them.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "remesh/background.hpp"
#include "remesh/polygon_clip.hpp"
#include "remesh/polyhedron_clip.hpp"
#include "remesh/simplex_geometry.hpp"
#include "remesh/transfer.hpp"

namespace riemesh {
namespace {

/// The corners of simplex t of a mesh, translated by −origin, positively oriented.
template <int D>
void corners(const std::vector<double>& coords, const Id* t, const Vec<D>& origin,
             Vec<D> x[D + 1]) {
  for (int i = 0; i <= D; ++i) {
    const auto v = static_cast<std::size_t>(t[i]);
    for (int a = 0; a < D; ++a) x[i][a] = coords[D * v + a] - origin[a];
  }
  if (simplex::signed_volume(x) < 0.0) std::swap(x[1], x[2]);
}

template <int D>
const std::vector<Id>& elements(const Mesh& m) {
  return D == 2 ? m.triangles : m.tets;
}

constexpr double kFactorial[4] = {1.0, 1.0, 2.0, 6.0};

/// The measure of the intersection; `touching` is false when the two are apart.
inline double overlap(const Vec2 t[3], const Vec2 s[3], bool& touching) {
  const clip::Polygon piece = clip::intersect_triangles(t, s);
  touching = piece.n >= 3;
  return touching ? std::max(0.0, 0.5 * clip::twice_area(piece)) : 0.0;
}
inline double overlap(const Vec3 t[4], const Vec3 s[4], bool& touching) {
  // Bounding boxes first: most neighbours visited by the search only touch or are apart.
  for (int a = 0; a < 3; ++a) {
    const double t_lo = std::min({t[0][a], t[1][a], t[2][a], t[3][a]});
    const double t_hi = std::max({t[0][a], t[1][a], t[2][a], t[3][a]});
    const double s_lo = std::min({s[0][a], s[1][a], s[2][a], s[3][a]});
    const double s_hi = std::max({s[0][a], s[1][a], s[2][a], s[3][a]});
    if (t_hi < s_lo || s_hi < t_lo) {
      touching = false;
      return 0.0;
    }
  }
  const clip::Polyhedron piece = clip::intersect_tetrahedra(t, s);
  touching = piece.n >= 4;
  return touching ? clip::volume(piece) : 0.0;
}

struct Components {
  std::vector<int> per_field;
  int total = 0;
};

template <int D>
Components check_fields(const Mesh& from, const std::vector<Field>& fields) {
  Components c;
  const std::size_t ne = elements<D>(from).size() / (D + 1);
  for (const Field& f : fields) {
    const int n = field_components(f.kind, from.dim);
    if (f.values.size() != ne * static_cast<std::size_t>(n))
      throw InputError("field '" + f.name + "' does not have one value set per element (" +
                       std::to_string(f.values.size()) + " values for " + std::to_string(ne) +
                       (D == 2 ? " triangles)" : " tetrahedra)"));
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
template <int D>
std::vector<double> identity_metrics(std::size_t n) {
  std::vector<double> m;
  m.reserve(SymMat<D>::kSize * n);
  const SymMat<D> id = SymMat<D>::identity();
  for (std::size_t v = 0; v < n; ++v) m.insert(m.end(), id.c, id.c + SymMat<D>::kSize);
  return m;
}

template <int D>
class P0Transfer {
 public:
  P0Transfer(const Mesh& from, const std::vector<Field>& fields, const Mesh& to)
      : from_(from), fields_(fields), to_(to), comps_(check_fields<D>(from, fields)),
        bg_(from, identity_metrics<D>(from.num_vertices()), InterpScheme::kLinear),
        stamp_(elements<D>(from).size() / (D + 1), -1) {}

  std::vector<Field> run(P0TransferReport& r);

 private:
  /// Visits the old elements reachable from `seed` through overlapping neighbours; adds the
  /// overlaps with new element e (corners x, translated by origin) to acc and covered.
  void search(Id seed, Id e, const Vec<D> x[D + 1], const Vec<D>& origin,
              std::vector<double>& acc, double& covered, P0TransferReport& r);

  const Mesh& from_;
  const std::vector<Field>& fields_;
  const Mesh& to_;
  Components comps_;
  BackgroundMesh<D> bg_;
  std::vector<Id> stamp_;  // the last new triangle that visited each old one
  std::vector<Id> stack_;
  std::vector<double> values_;
};

template <int D>
void P0Transfer<D>::search(Id seed, Id e, const Vec<D> x[D + 1], const Vec<D>& origin,
                           std::vector<double>& acc, double& covered, P0TransferReport& r) {
  if (stamp_[static_cast<std::size_t>(seed)] == e) return;
  stamp_[static_cast<std::size_t>(seed)] = e;
  stack_.assign(1, seed);
  values_.resize(static_cast<std::size_t>(comps_.total));
  while (!stack_.empty()) {
    const Id s = stack_.back();
    stack_.pop_back();
    Vec<D> y[D + 1];
    corners<D>(from_.coords, &elements<D>(from_)[(D + 1) * static_cast<std::size_t>(s)], origin,
               y);
    bool touching = false;
    const double area = overlap(x, y, touching);
    if (!touching) continue;  // apart, or touching along a face, an edge or at a vertex
    if (area > 0.0) {
      ++r.pairs;
      covered += area;
      gather(fields_, comps_, static_cast<std::size_t>(s), values_.data());
      for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += area * values_[k];
    }
    for (int i = 0; i <= D; ++i) {
      const Id n = bg_.neighbour(s, i);
      if (n == kNoId || stamp_[static_cast<std::size_t>(n)] == e) continue;
      stamp_[static_cast<std::size_t>(n)] = e;
      stack_.push_back(n);
    }
  }
}

template <int D>
std::vector<Field> P0Transfer<D>::run(P0TransferReport& r) {
  const std::vector<Id>& elems = elements<D>(to_);
  const std::size_t nt = elems.size() / (D + 1);
  const auto total = static_cast<std::size_t>(comps_.total);
  std::vector<double> out(nt * total, 0.0);
  std::vector<double> acc(total);
  Id hint = kNoId;
  for (std::size_t t = 0; t < nt; ++t) {
    const Id* tv = &elems[(D + 1) * t];
    Vec<D> origin{};
    for (int a = 0; a < D; ++a) origin[a] = to_.coords[D * static_cast<std::size_t>(tv[0]) + a];
    Vec<D> x[D + 1];
    corners<D>(to_.coords, tv, origin, x);
    const double area = simplex::signed_volume(x) / kFactorial[D];
    std::fill(acc.begin(), acc.end(), 0.0);
    double covered = 0.0;
    const Id e = static_cast<Id>(t);
    Vec<D> centroid = Vec<D>::zero();
    for (int i = 0; i <= D; ++i) centroid += x[i];
    centroid *= 1.0 / (D + 1);
    const Location<D> loc = bg_.locate(origin + centroid, hint);
    hint = loc.simplex;
    search(loc.simplex, e, x, origin, acc, covered, r);
    if (covered < area * (1.0 - 1e-12)) {
      // Rounding hid a piece, or the domains differ: more seeds, near the corners (a thousandth
      // of the way to the centroid) and at the edge midpoints.
      for (int i = 0; i <= D; ++i) {
        for (int j = i; j <= D; ++j) {
          const Vec<D> p = i == j ? x[i] + 0.001 * (centroid - x[i]) : 0.5 * (x[i] + x[j]);
          const Location<D> l = bg_.locate(origin + p, loc.simplex);
          if (l.inside) search(l.simplex, e, x, origin, acc, covered, r);
        }
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

/// Σ value × measure per component of the fields on a mesh's elements; adds the measures to
/// *measure.
template <int D>
std::vector<double> integrals(const Mesh& m, const std::vector<Field>& fields, double* measure) {
  std::vector<double> out;
  const std::vector<Id>& elems = elements<D>(m);
  for (std::size_t t = 0; t < elems.size() / (D + 1); ++t) {
    Vec<D> x[D + 1];
    corners<D>(m.coords, &elems[(D + 1) * t], Vec<D>::zero(), x);
    const double area = simplex::signed_volume(x) / kFactorial[D];
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

template <int D>
std::vector<Field> transfer(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                            P0TransferReport& r) {
  std::vector<Field> out;
  {
    P0Transfer<D> transfer(from, fields, to);
    out = transfer.run(r);
  }
  r.old_integral = integrals<D>(from, fields, &r.old_measure);
  r.new_integral = integrals<D>(to, out, &r.new_measure);
  return out;
}

}  // namespace

std::vector<Field> transfer_p0(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                               P0TransferReport* report) {
  if (from.dim != to.dim || from.kind() != to.kind())
    throw InputError("field transfer needs two meshes of the same kind");
  if (from.kind() != MeshKind::kPlanar && from.kind() != MeshKind::kVolume)
    throw InputError("conservative transfer works on planar triangle meshes and tetrahedral "
                     "volumes");
  P0TransferReport r;
  std::vector<Field> out = from.kind() == MeshKind::kPlanar ? transfer<2>(from, fields, to, r)
                                                            : transfer<3>(from, fields, to, r);
  r.uncovered_new = r.new_measure - r.overlap_measure;
  r.uncovered_old = r.old_measure - r.overlap_measure;
  if (report) *report = std::move(r);
  return out;
}

}  // namespace riemesh
