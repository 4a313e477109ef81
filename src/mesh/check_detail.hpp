#pragma once
// Internals shared by check.cpp (sizes, ids, geometry, duplicates) and check_topology.cpp
// (conformity, orientation of surfaces, boundary). Not part of the public API.
#include <algorithm>
#include <array>
#include <map>
#include <span>
#include <vector>

#include "mesh/check.hpp"

namespace riemesh::check_detail {

/// Gathers issues: the count per category and the first example met.
class Collector {
 public:
  explicit Collector(const Mesh& m) : mesh_(m) {}

  /// One entity with the problem; `verts` locate it (their centroid).
  void add(CheckCategory c, EntityKind kind, Id id, std::span<const Id> verts, int local = -1) {
    CheckIssue& issue = issues_[c];
    if (issue.count++ == 0) {
      issue.category = c;
      issue.entity = kind;
      issue.example = id;
      issue.local_face = local;
      issue.location = centroid(verts);
    }
  }
  /// n entities at once with no single example (array sizes).
  void add_count(CheckCategory c, EntityKind kind, std::size_t n) {
    CheckIssue& issue = issues_[c];
    if (issue.count == 0) issue.category = c, issue.entity = kind;
    issue.count += n;
  }
  bool has(CheckCategory c) const { return issues_.count(c) != 0; }
  CheckReport report() const {
    CheckReport r;
    const bool regions_meet = has(CheckCategory::kRegionsMeet);
    for (const auto& [c, issue] : issues_) {
      const bool note = c == CheckCategory::kRegionsMeet ||
                        (regions_meet && c == CheckCategory::kInconsistentOrientation);
      (note ? r.notes : r.issues).push_back(issue);
    }
    return r;
  }

 private:
  std::array<double, 3> centroid(std::span<const Id> verts) const {
    std::array<double, 3> p{};
    const int d = mesh_.dim;
    const auto nv = mesh_.num_vertices();
    int n = 0;
    for (Id v : verts) {
      if (v < 0 || static_cast<std::size_t>(v) >= nv) continue;
      for (int c = 0; c < d && c < 3; ++c)
        p[c] += mesh_.coords[static_cast<std::size_t>(d) * v + c];
      ++n;
    }
    if (n > 0)
      for (double& x : p) x /= n;
    return p;
  }

  const Mesh& mesh_;
  std::map<CheckCategory, CheckIssue> issues_;  // ordered: the report lists categories in order
};

/// The elements checked: tets of a volume, triangles otherwise.
struct Elements {
  const std::vector<Id>* verts = nullptr;
  int k = 0;
  EntityKind kind = EntityKind::kNone;
  std::size_t size() const { return k ? verts->size() / k : 0; }
  std::span<const Id> of(std::size_t e) const { return {verts->data() + k * e, std::size_t(k)}; }
};

/// Conformity, non-manifold faces, surface orientation and boundary consistency of the elements
/// `el` restricted to `kept`.
void check_topology(const Mesh& m, const Elements& el, const std::vector<Id>& kept, Collector& col);

/// A mesh of edges only (e.g. the boundary of a 2D domain to be meshed): every vertex of an
/// edge is on exactly two of them (closed loops), no edge is listed twice.
void check_edge_loops(const Mesh& m, Collector& col);

}  // namespace riemesh::check_detail
