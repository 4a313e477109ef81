// What the surface adapter refuses before any work (surface_input.hpp): a surface `riemesh
// check` calls invalid came out invalid, exit 0 (hunt 6, G3 and G13).
#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "io/mesh_file.hpp"
#include "mesh/fixtures.hpp"
#include "remesh/surface_adapt.hpp"
#include "remesh/surface_input.hpp"

namespace riemesh {
namespace {

std::string refusal(const Mesh& m) {
  try {
    require_adaptable_surface(m);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(SurfaceInput, ValidSurfacesAreAccepted) {
  EXPECT_EQ(refusal(sphere_surface(2)), "accepted");
  for (const char* name : {"bunny", "elephant", "fandisk", "rotor"})
    EXPECT_EQ(refusal(read_mesh(std::string(RIEMESH_SHARED_DATA) + "/surf/" + name + ".mesh")),
              "accepted")
        << name;
}

TEST(SurfaceInput, TurnedTriangleIsRefusedAndNamed) {
  Mesh s = sphere_surface(2);
  std::swap(s.triangles[3 * 5 + 1], s.triangles[3 * 5 + 2]);  // triangle 6 turned over
  EXPECT_EQ(refusal(s),
            "the surface is not consistently oriented: 3 edges traversed the same way by both "
            "their triangles (first: triangle 6); turn the triangles of one side");
  SurfaceAdaptOptions o;
  o.hsiz = 0.3;
  EXPECT_THROW(adapt_surface(s, o), InputError);
}

TEST(SurfaceInput, SeamNotMergedIsRefusedAndNamed) {
  Mesh s = sphere_surface(2);
  const Id v = s.triangles[0];
  s.coords.insert(s.coords.end(), s.coords.begin() + 3 * v, s.coords.begin() + 3 * v + 3);
  s.vert_ref.push_back(0);
  s.vert_tag.push_back(0);
  s.triangles[0] = static_cast<Id>(s.num_vertices() - 1);
  EXPECT_EQ(refusal(s), "vertices " + std::to_string(v + 1) + " and " +
                            std::to_string(s.num_vertices()) +
                            " are at the same place (1 pair; merge them)");
}

TEST(SurfaceInput, CrossingSheetsAreRefused) {
  // Two unit spheres 1 apart: their surfaces cross along a circle.
  Mesh s = sphere_surface(2);
  const Mesh b = sphere_surface(2);
  const Id n = static_cast<Id>(s.num_vertices());
  for (std::size_t k = 0; k < b.coords.size(); ++k)
    s.coords.push_back(b.coords[k] + (k % 3 == 0 ? 1.0 : 0.0));
  for (const Id v : b.triangles) s.triangles.push_back(v + n);
  s.tri_ref.insert(s.tri_ref.end(), b.tri_ref.begin(), b.tri_ref.end());
  s.tri_tag.insert(s.tri_tag.end(), b.tri_tag.begin(), b.tri_tag.end());
  s.vert_ref.insert(s.vert_ref.end(), b.vert_ref.begin(), b.vert_ref.end());
  s.vert_tag.insert(s.vert_tag.end(), b.vert_tag.begin(), b.vert_tag.end());
  EXPECT_EQ(refusal(s).rfind("the surface intersects itself: triangles ", 0), 0u) << refusal(s);
}

}  // namespace
}  // namespace riemesh
