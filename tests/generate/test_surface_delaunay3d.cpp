// Volumes from closed surfaces: validation of the surface, Delaunay tetrahedralisation of its
// vertices, missing boundary counts and the tets inside.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "generate/boundary_recovery3d.hpp"
#include "generate/surface_delaunay3d.hpp"
#include "io/mesh_file.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "mesh/stats.hpp"
#include "twisted_prism.hpp"

namespace riemesh {
namespace {

using test::twisted_prism;

/// The boundary of the tetrahedron (0,0,0), (s,0,0), (0,s,0), (0,0,s) shifted by o, outward when
/// `outward`, starting at vertex id `first`.
void add_tet_surface(Mesh& m, double s, double o, bool outward) {
  const Id f = static_cast<Id>(m.num_vertices());
  m.coords.insert(m.coords.end(), {o, o, o, o + s, o, o, o, o + s, o, o, o, o + s});
  std::vector<Id> t = {f, f + 2, f + 1, f, f + 1, f + 3, f, f + 3, f + 2, f + 1, f + 2, f + 3};
  if (!outward)
    for (std::size_t k = 0; k < t.size(); k += 3) std::swap(t[k + 1], t[k + 2]);
  m.triangles.insert(m.triangles.end(), t.begin(), t.end());
  m.vert_ref.resize(m.num_vertices(), 0);
  m.vert_tag.resize(m.num_vertices(), 0);
  m.tri_ref.resize(m.num_triangles(), 1);
  m.tri_tag.resize(m.num_triangles(), 0);
}

double volume(const Mesh& m) {
  double sum = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const double* p[4];
    for (int i = 0; i < 4; ++i) p[i] = &m.coords[3 * static_cast<std::size_t>(m.tets[4 * t + i])];
    double e[3][3];
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) e[i][k] = p[i + 1][k] - p[0][k];
    sum += (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
            e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
            e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
  }
  return sum;
}

TEST(SurfaceDelaunay3d, TetrahedronSurfaceGivesOneTet) {
  Mesh s;
  s.dim = 3;
  add_tet_surface(s, 1.0, 0.0, true);
  const SurfaceDelaunay d = delaunay_of_surface(s);
  EXPECT_EQ(d.num_faces, 4u);
  EXPECT_EQ(d.num_edges, 6u);
  EXPECT_TRUE(d.conforming());
  const Mesh v = volume_inside(s, d);
  EXPECT_EQ(v.num_tets(), 1u);
  EXPECT_TRUE(check_mesh(v).valid());
}

TEST(SurfaceDelaunay3d, ConvexIcosphereIsFilled) {
  // A strictly convex polyhedron: its triangles are the hull's facets, all Delaunay faces.
  const Mesh s = sphere_surface(3);
  const SurfaceDelaunay d = delaunay_of_surface(s);
  EXPECT_EQ(d.missing_faces, 0u);
  EXPECT_EQ(d.missing_edges, 0u);
  const Mesh v = volume_inside(s, d);
  EXPECT_EQ(v.num_tets(), d.tz.num_tets());  // nothing outside a convex surface
  EXPECT_TRUE(check_mesh(v).valid());
  EXPECT_GT(volume(v), 0.95 * 4.0 / 3 * M_PI);
  EXPECT_LT(volume(v), 4.0 / 3 * M_PI);
}

/// Volume of the tets with ref `ref`.
double region_volume(const Mesh& v, int ref) {
  Mesh part = v;
  part.tets.clear();
  part.tet_ref.clear();
  for (std::size_t t = 0; t < v.num_tets(); ++t)
    if (v.tet_ref[t] == ref) {
      part.tets.insert(part.tets.end(), v.tets.begin() + static_cast<std::ptrdiff_t>(4 * t),
                       v.tets.begin() + static_cast<std::ptrdiff_t>(4 * t + 4));
      part.tet_ref.push_back(ref);
    }
  return volume(part);
}

TEST(SurfaceDelaunay3d, NestedShellsKeepTheSpaceBetweenThem) {
  // An outer tetrahedron of side 10 and an inner one of side 1, inward: the volume between.
  Mesh s;
  s.dim = 3;
  add_tet_surface(s, 10.0, 0.0, true);
  add_tet_surface(s, 1.0, 1.0, false);
  const SurfaceDelaunay d = delaunay_of_surface(s);
  ASSERT_TRUE(d.conforming());
  const Mesh v = volume_inside(s, d);
  EXPECT_NEAR(volume(v), (1000.0 - 1.0) / 6, 1e-9);
  EXPECT_TRUE(check_mesh(v).valid());
  EXPECT_EQ(v.tet_ref, std::vector<int>(v.num_tets(), 1));
  // The whole surface turned inside out: the inner shell still against the outer one.
  Mesh r = s;
  for (std::size_t k = 0; k < r.triangles.size(); k += 3)
    std::swap(r.triangles[k + 1], r.triangles[k + 2]);
  EXPECT_NEAR(volume(volume_inside(r, delaunay_of_surface(r))), (1000.0 - 1.0) / 6, 1e-9);
  // No holes: the inner shell bounds a solid of its own, whatever its orientation.
  const Mesh n = volume_inside(s, d, {}, true);
  EXPECT_NEAR(region_volume(n, 1), (1000.0 - 1.0) / 6, 1e-9);
  EXPECT_NEAR(region_volume(n, 2), 1.0 / 6, 1e-12);
  BoundaryRecoveryOptions ro;
  ro.no_holes = true;
  EXPECT_NEAR(volume(recover_volume(s, ro).volume), 1000.0 / 6, 1e-9);
  ro.hole_points = {1.1, 1.1, 1.1};
  EXPECT_THROW(recover_volume(s, ro), InputError);  // they contradict
}

TEST(SurfaceDelaunay3d, InnerShellOrientedLikeTheOuterIsASolidOfItsOwn) {
  // As gmsh writes a solid inside another: both shells outward. Two regions, refs in the order
  // of their first triangle (the outer shell's first).
  Mesh s;
  s.dim = 3;
  add_tet_surface(s, 10.0, 0.0, true);
  add_tet_surface(s, 1.0, 1.0, true);
  const SurfaceDelaunay d = delaunay_of_surface(s);
  ASSERT_TRUE(d.conforming());
  const Mesh v = volume_inside(s, d);
  EXPECT_NEAR(volume(v), 1000.0 / 6, 1e-9);
  EXPECT_NEAR(region_volume(v, 1), (1000.0 - 1.0) / 6, 1e-9);
  EXPECT_NEAR(region_volume(v, 2), 1.0 / 6, 1e-12);
  EXPECT_TRUE(check_mesh(v).valid());
  // A hole point in the inner one makes it a hole again; outside or on the surface: refused.
  const std::vector<double> in = {1.1, 1.1, 1.1}, out = {20, 1, 1}, on = {1.2, 1.2, 1.0};
  EXPECT_NEAR(volume(volume_inside(s, d, in)), (1000.0 - 1.0) / 6, 1e-9);
  EXPECT_THROW(volume_inside(s, d, out), InputError);
  EXPECT_THROW(volume_inside(s, d, on), InputError);
  // A hole point in the outer region (next to the outside: its shell would bound nothing), or
  // one in each of two regions side by side: refused by name.
  try {
    volume_inside(s, d, std::vector<double>{5, 1, 1});
    ADD_FAILURE() << "a hole next to the outside was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("hole point (5, 1, 1) is in a region next to the outside"),
              std::string::npos)
        << e.what();
  }
  Mesh three = s;  // a third shell inside the inner one, outward: three nested regions
  add_tet_surface(three, 0.25, 1.05, true);
  BoundaryRecoveryOptions ro;
  EXPECT_NEAR(volume(recover_volume(three, ro).volume), 1000.0 / 6, 1e-9);
  ro.hole_points = {1.1, 1.1, 1.5, 1.08, 1.08, 1.08};
  try {
    recover_volume(three, ro);
    ADD_FAILURE() << "two holes side by side were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("are in regions next to each other"), std::string::npos)
        << e.what();
  }
}

TEST(SurfaceDelaunay3d, SolidsSharingAFaceAreTwoRegions) {
  // Tets (0, a, b, c) and (d, a, b, c) on either side of the shared face abc, listed once: its
  // edges are on three triangles each. Either orientation of the shared face gives two regions.
  for (const bool flip : {false, true}) {
    Mesh s;
    s.dim = 3;
    s.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1.5, 1.5, 1.5};
    s.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 4, 1, 2, 4, 3, 1, 4, 2, 3, 1, 2, 3};
    if (flip) std::swap(s.triangles[19], s.triangles[20]);
    s.vert_ref.assign(5, 0);
    s.vert_tag.assign(5, 0);
    s.tri_ref = {1, 1, 1, 2, 2, 2, 3};
    s.tri_tag.assign(7, 0);
    ASSERT_NO_THROW(require_closed_surface(s));
    const SurfaceDelaunay d = delaunay_of_surface(s);
    ASSERT_TRUE(d.conforming());
    const Mesh v = volume_inside(s, d);
    EXPECT_NEAR(region_volume(v, 1), 1.0 / 6, 1e-12);
    EXPECT_NEAR(region_volume(v, 2), 3.5 / 6, 1e-12);  // height 3.5 / sqrt(3) over abc
    EXPECT_TRUE(check_mesh(v).valid());
  }
}

TEST(SurfaceDelaunay3d, SolidsTouchingAlongAnEdgeAreRefused) {
  // Two tetrahedra sharing the edge (0, 1) only: each edge's 4 triangles are accepted by the
  // surface check, but the volume would not be a manifold there.
  Mesh s;
  s.dim = 3;
  s.coords = {0, 0, 0, 1, 0, 0, 0.5, 1, 0.2, 0.5, 0.2, 1, 0.5, -1, -0.2, 0.5, -0.2, -1};
  s.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 4, 1, 0, 1, 5, 0, 5, 4, 1, 4, 5};
  for (std::size_t k = 12; k < 24; k += 3)  // the second one outward too
    std::swap(s.triangles[k + 1], s.triangles[k + 2]);
  s.vert_ref.assign(6, 0);
  s.vert_tag.assign(6, 0);
  s.tri_ref.assign(8, 1);
  s.tri_tag.assign(8, 0);
  try {
    const SurfaceDelaunay d = delaunay_of_surface(s);
    ASSERT_TRUE(d.conforming());
    volume_inside(s, d);
    ADD_FAILURE() << "two solids touching along an edge were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("separate solids touch along an edge or at a point"),
              std::string::npos)
        << e.what();
  }
}

TEST(SurfaceDelaunay3d, SchonhardtPrismIsReportedNotFaked) {
  const SurfaceDelaunay d0 = delaunay_of_surface(twisted_prism(false));
  const SurfaceDelaunay d1 = delaunay_of_surface(twisted_prism(true));
  // Same 6 points in convex position, same Delaunay tetrahedralisation (3 or 4 tets).
  EXPECT_GE(d0.tz.num_tets(), 3u);
  EXPECT_LE(d0.tz.num_tets(), 4u);
  EXPECT_EQ(d0.tz.tets, d1.tz.tets);
  ASSERT_NE(d0.conforming(), d1.conforming());  // exactly one is the hull
  const SurfaceDelaunay& hull = d0.conforming() ? d0 : d1;
  const SurfaceDelaunay& schonhardt = d0.conforming() ? d1 : d0;
  EXPECT_GT(schonhardt.missing_faces, 0u);
  EXPECT_GT(schonhardt.missing_edges, 0u);  // its reflex diagonals are no tet edges
  EXPECT_THROW(volume_inside(twisted_prism(&schonhardt == &d1), schonhardt), Error);
  const Mesh v = volume_inside(twisted_prism(&hull == &d1), hull);
  EXPECT_EQ(v.num_tets(), hull.tz.num_tets());  // a convex surface keeps every tet
  EXPECT_TRUE(check_mesh(v).valid());
}

TEST(SurfaceDelaunay3d, DefectsAreNamed) {
  const auto message = [](const Mesh& m) {
    try {
      require_closed_surface(m);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const Mesh good = sphere_surface(1);
  EXPECT_EQ(message(good), "no error");
  Mesh open = good;  // one triangle removed: its 3 edges bound one triangle each
  open.triangles.resize(open.triangles.size() - 3);
  open.tri_ref.pop_back();
  open.tri_tag.pop_back();
  EXPECT_NE(message(open).find("3 edges on one triangle only (holes)"), std::string::npos);
  Mesh flipped = good;
  std::swap(flipped.triangles[1], flipped.triangles[2]);
  EXPECT_NE(message(flipped).find("inconsistent orientation"), std::string::npos);
  // A fin on the edge of the first triangle: that edge has 3 triangles (accepted where regions
  // meet), but the fin's two other edges bound it alone.
  Mesh fin = good;
  fin.coords.insert(fin.coords.end(), {5.0, 5.0, 5.0});
  fin.triangles.insert(fin.triangles.end(),
                       {fin.triangles[0], fin.triangles[1], static_cast<Id>(fin.num_vertices() - 1)});
  EXPECT_NE(message(fin).find("2 edges on one triangle only (holes)"), std::string::npos)
      << message(fin);
  Mesh twice = good;  // the first triangle again (its edges then on 3 triangles each)
  twice.triangles.insert(twice.triangles.end(),
                         {good.triangles[0], good.triangles[2], good.triangles[1]});
  EXPECT_NE(message(twice).find(
                "1 triangles listed twice (same three vertices) (first: triangles 1 and "),
            std::string::npos)
      << message(twice);
  // A seam not merged: triangle 1's first vertex replaced by a copy at the same place. Its two
  // edges there bound one triangle each, but the defect is named as what it is (was: "holes").
  Mesh seam = good;
  const Id v0 = seam.triangles[0];
  seam.coords.insert(seam.coords.end(), seam.coords.begin() + 3 * v0,
                     seam.coords.begin() + 3 * v0 + 3);
  seam.vert_ref.push_back(0);
  seam.vert_tag.push_back(0);
  seam.triangles[0] = static_cast<Id>(seam.num_vertices() - 1);
  EXPECT_NE(message(seam).find("1 pairs of vertices at the same place (first: vertices " +
                               std::to_string(v0 + 1) + " and " +
                               std::to_string(seam.num_vertices()) + ")"),
            std::string::npos)
      << message(seam);
  Mesh none;
  EXPECT_NE(message(none).find("no triangles"), std::string::npos);
  // A tetrahedron whose bottom face is split at the middle of an edge, that edge's other side
  // covered by a zero-area triangle (1, 5, 2): it was named as a self-intersection of two other
  // triangles.
  Mesh flat;
  flat.dim = 3;
  flat.coords = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.5, 0, 0};
  flat.triangles = {0, 2, 4, 4, 2, 1, 1, 3, 0, 0, 4, 1, 0, 3, 2, 1, 2, 3};
  flat.tri_ref.assign(6, 1);
  flat.tri_tag.assign(6, 0);
  flat.vert_ref.assign(5, 0);
  flat.vert_tag.assign(5, 0);
  EXPECT_NE(message(flat).find("1 triangles of zero area (collinear vertices) (first: triangle 4)"),
            std::string::npos)
      << message(flat);
}

TEST(SurfaceDelaunay3d, PinchedVerticesAreNamed) {
  // Two tetrahedra sharing vertex 0 only (the second is the first turned about the origin):
  // every edge has two triangles, consistently oriented, but the triangles at the shared
  // vertex form two separate fans. The fill's optimiser failed an internal check on such a
  // surface (two cubes sharing a corner).
  Mesh s;
  s.dim = 3;
  add_tet_surface(s, 1.0, 0.0, true);
  add_tet_surface(s, -1.0, 0.0, true);  // the reflected tet: (0,0,0), (-1,0,0), (0,-1,0), (0,0,-1)
  // The reflection reverses orientation: flip its triangles back to outward.
  for (std::size_t k = 12; k < s.triangles.size(); k += 3)
    std::swap(s.triangles[k + 1], s.triangles[k + 2]);
  // Weld its first vertex (at the origin) to the first tet's.
  for (std::size_t k = 12; k < s.triangles.size(); ++k)
    if (s.triangles[k] == 4) s.triangles[k] = 0;
  try {
    require_closed_surface(s);
    ADD_FAILURE() << "a pinched vertex was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1 non-manifold vertices (where separate sheets of the "
                                         "surface touch) (first: vertex 1)"),
              std::string::npos)
        << e.what();
  }
  // Each tetrahedron alone is fine.
  Mesh one;
  one.dim = 3;
  add_tet_surface(one, 1.0, 0.0, true);
  EXPECT_NO_THROW(require_closed_surface(one));
}

TEST(SurfaceDelaunay3d, CoincidentVerticesAreNamed) {
  Mesh s;
  s.dim = 3;
  add_tet_surface(s, 1.0, 0.0, true);
  add_tet_surface(s, 1.0, 0.0, true);  // a second copy of the same tetrahedron, own vertices
  EXPECT_THROW(delaunay_of_surface(s), InputError);
}

TEST(SurfaceDelaunay3d, SharedSurfacesAreCounted) {
  // The real surfaces: every one is closed and manifold; the counts are consistent. Which faces
  // are missing is what boundary recovery will have to restore.
  for (const char* name : {"bunny", "elephant", "fandisk", "rotor"}) {
    const Mesh s = read_mesh(std::string(RIEMESH_SHARED_DATA) + "/surf/" + name + ".mesh");
    const SurfaceDelaunay d = delaunay_of_surface(s);
    EXPECT_EQ(d.num_faces, s.num_triangles()) << name;
    EXPECT_EQ(2 * d.num_edges, 3 * d.num_faces) << name;  // closed: each edge on 2 triangles
    EXPECT_LE(d.missing_faces, d.num_faces) << name;
    // A face present implies its 3 edges present: missing edges touch missing faces only.
    EXPECT_LE(d.missing_edges, 3 * d.missing_faces) << name;
    if (d.conforming()) {
      EXPECT_TRUE(check_mesh(volume_inside(s, d)).valid()) << name;
    }
    std::printf("%s: %zu of %zu faces and %zu of %zu edges missing\n", name, d.missing_faces,
                d.num_faces, d.missing_edges, d.num_edges);
  }
}

}  // namespace
}  // namespace riemesh
