#include "remesh/surface_input.hpp"

#include <string>

#include "core/error.hpp"
#include "mesh/check.hpp"
#include "mesh/self_intersection.hpp"

namespace riemesh {

void require_adaptable_surface(const Mesh& s) {
  const CoincidentVertices same = find_coincident_vertices(s);
  if (same.pairs > 0)
    throw InputError("vertices " + std::to_string(same.first_a + 1) + " and " +
                     std::to_string(same.first_b + 1) + " are at the same place (" +
                     std::to_string(same.pairs) + (same.pairs == 1 ? " pair" : " pairs") +
                     "; merge them)");
  const CheckReport report = check_mesh(s);
  for (const CheckIssue& issue : report.issues)  // not the notes: regions meet there
    if (issue.category == CheckCategory::kInconsistentOrientation)
      throw InputError("the surface is not consistently oriented: " + std::to_string(issue.count) +
                       " edges traversed the same way by both their triangles (first: triangle " +
                       std::to_string(issue.example + 1) + "); turn the triangles of one side");
  const SelfIntersections x = find_self_intersections(s, 1, /*coplanar=*/true);
  if (x.pairs > 0)
    throw InputError("the surface intersects itself: triangles " + std::to_string(x.first_a + 1) +
                     " and " + std::to_string(x.first_b + 1) + " cross or overlap");
}

}  // namespace riemesh
