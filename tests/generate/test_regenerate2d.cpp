// Uniform refinement by meshing the domain afresh (adapt_or_regenerate2d), tested by properties:
// the regions keep their input triangle refs and areas, holes stay empty, the edge refs and
// corners are kept, the boundary stays within hausd of the input's, the lengths and qualities of
// a unit mesh, determinism; and adapt2d itself whenever the conditions do not hold (same mesh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "core/error.hpp"
#include "core/predicates.hpp"
#include "generate/mesh2d.hpp"
#include "generate/regenerate2d.hpp"
#include "generate/square_loop.hpp"
#include "io/mesh_file.hpp"
#include "mesh/check.hpp"
#include "mesh/fixtures.hpp"
#include "metric/metric.hpp"
#include "remesh/boundary_distance.hpp"

using namespace riemesh;
using test::add_square;

namespace {

/// [0, 4]² (edge ref 1) with the subdomain [0.5, 1.5]² (ref 2 on its sides, triangle ref 20,
/// the rest 10) and the hole [2.5, 3.5]² (ref 3), meshed at size 0.5.
Mesh two_regions_and_a_hole() {
  Mesh b;
  b.dim = 2;
  add_square(b, 0, 4, 8, true, 1);
  add_square(b, 0.5, 1, 2, true, 2);
  add_square(b, 2.5, 1, 2, false, 3);
  Mesh2dOptions o;
  o.hsiz = 0.5;
  o.adapt.hgrad = 0;
  Mesh m = mesh_domain2d(b, o).mesh;
  for (auto& r : m.tri_ref) r = r == 1 ? 10 : 20;
  m.vert_tag.assign(m.num_vertices(), kTagNone);  // (kept boundary vertices were tagged corners)
  return m;
}

std::map<int, double> ref_areas(const Mesh& m) {
  std::map<int, double> out;
  for (std::size_t t = 0; t < m.num_triangles(); ++t) {
    const double o =
        orient2d(&m.coords[2 * m.triangles[3 * t]], &m.coords[2 * m.triangles[3 * t + 1]],
                 &m.coords[2 * m.triangles[3 * t + 2]]);
    EXPECT_GT(o, 0);
    out[m.tri_ref[t]] += 0.5 * o;
  }
  return out;
}

std::vector<SymMat2> uniform(const Mesh& m, double h) {
  return std::vector<SymMat2>(m.num_vertices(), isotropic_metric<2>(h));
}

bool regenerated(const Adapt2dResult& r) {
  return std::any_of(r.report.notes.begin(), r.report.notes.end(), [](const std::string& s) {
    return s.find("meshed afresh") != std::string::npos;
  });
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  return a.coords == b.coords && a.triangles == b.triangles && a.tri_ref == b.tri_ref &&
         a.edges == b.edges && a.edge_ref == b.edge_ref && a.vert_tag == b.vert_tag;
}

}  // namespace

TEST(Regenerate2d, RegionsKeepTheirRefsAndAreasAndTheHoleStaysEmpty) {
  const Mesh in = two_regions_and_a_hole();
  const std::vector<SymMat2> met = uniform(in, 0.05);
  Adapt2dOptions o;
  ASSERT_TRUE(regeneration_applies(in, met, o));
  const Adapt2dResult r = adapt_or_regenerate2d(in, met, o);
  EXPECT_TRUE(regenerated(r));
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  const auto areas = ref_areas(r.mesh);
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_NEAR(areas.at(10), 14.0, 1e-9);
  EXPECT_NEAR(areas.at(20), 1.0, 1e-9);
  EXPECT_EQ(std::set<int>(r.mesh.edge_ref.begin(), r.mesh.edge_ref.end()),
            (std::set<int>{1, 2, 3}));
  // The 12 corners of the three squares, at their places.
  int corners = 0;
  for (std::size_t v = 0; v < r.mesh.num_vertices(); ++v)
    if (r.mesh.vert_tag[v] & kTagCorner) {
      ++corners;
      const double x = r.mesh.coords[2 * v], y = r.mesh.coords[2 * v + 1];
      EXPECT_EQ(x, std::round(2 * x) / 2);
      EXPECT_EQ(y, std::round(2 * y) / 2);
    }
  EXPECT_EQ(corners, 12);
  // A unit mesh: (4/√3) C triangles within 10%, good lengths and qualities.
  const double expected = 4.0 / std::sqrt(3.0) * 15.0 / (0.05 * 0.05);
  EXPECT_NEAR(static_cast<double>(r.mesh.num_triangles()), expected, 0.1 * expected);
  const PassStats& last = r.report.passes.back();
  EXPECT_GE(last.len_in, 0.98);
  EXPECT_GE(last.len_min, 0.5);
  EXPECT_LE(last.len_max, 1.7);
  EXPECT_GE(last.q_min, 0.6);
  EXPECT_GE(last.q_mean, 0.97);
  ASSERT_EQ(r.metrics.size(), r.mesh.num_vertices());
  EXPECT_TRUE(same_metric<2>(r.metrics).has_value());
  // Deterministic.
  EXPECT_TRUE(same_mesh(adapt_or_regenerate2d(in, met, o).mesh, r.mesh));
}

TEST(Regenerate2d, AnUnlistedInterfaceComesFromTheTriangleRefs) {
  Mesh in = two_regions_and_a_hole();
  // Without the subdomain's listed edges, its sides are an interface by the triangle refs alone
  // (edge ref 0), as adapt2d finds them.
  Mesh kept = in;
  kept.edges.clear(), kept.edge_ref.clear(), kept.edge_tag.clear();
  for (std::size_t e = 0; e < in.num_edges(); ++e)
    if (in.edge_ref[e] != 2) {
      kept.edges.insert(kept.edges.end(), {in.edges[2 * e], in.edges[2 * e + 1]});
      kept.edge_ref.push_back(in.edge_ref[e]);
      kept.edge_tag.push_back(in.edge_tag.empty() ? std::uint8_t{kTagNone} : in.edge_tag[e]);
    }
  const Adapt2dResult r = adapt_or_regenerate2d(kept, uniform(kept, 0.05), Adapt2dOptions{});
  EXPECT_TRUE(regenerated(r));
  const auto areas = ref_areas(r.mesh);
  ASSERT_EQ(areas.size(), 2u);
  EXPECT_NEAR(areas.at(10), 14.0, 1e-9);
  EXPECT_NEAR(areas.at(20), 1.0, 1e-9);
  EXPECT_EQ(std::set<int>(r.mesh.edge_ref.begin(), r.mesh.edge_ref.end()),
            (std::set<int>{0, 1, 3}));
}

TEST(Regenerate2d, CurvedBoundaryWithinHausd) {
  const Mesh in = read_mesh(RIEMESH_SHARED_DATA "/2d/naca0012.mesh");
  double xmin = 1e300, xmax = -1e300;
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    xmin = std::min(xmin, in.coords[2 * v]), xmax = std::max(xmax, in.coords[2 * v]);
  Adapt2dOptions o;
  o.hausd = 1e-3 * (xmax - xmin);
  const std::vector<SymMat2> met = uniform(in, (xmax - xmin) / 150.0);
  ASSERT_TRUE(regeneration_applies(in, met, o));
  const Adapt2dResult r = adapt_or_regenerate2d(in, met, o);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  const double d = test::boundary_distance(r.mesh, in, 4);
  EXPECT_LE(d, o.hausd) << "Hausdorff distance " << d << " for hausd " << o.hausd;
  EXPECT_EQ(std::set<int>(r.mesh.edge_ref.begin(), r.mesh.edge_ref.end()),
            std::set<int>(in.edge_ref.begin(), in.edge_ref.end()));
  EXPECT_GE(r.report.passes.back().q_min, 0.5);
}

TEST(Regenerate2d, OtherwiseAdapt2dItself) {
  const Mesh in = unit_square(10, 10);
  Adapt2dOptions o;
  // Not fine enough (about 2.3 times the triangles), a metric that varies, an operator off.
  std::vector<SymMat2> met = uniform(in, 0.1);
  std::vector<SymMat2> varied = uniform(in, 0.02);
  varied[7] = isotropic_metric<2>(0.03);
  Adapt2dOptions noswap = o;
  noswap.swap = false;
  EXPECT_FALSE(regeneration_applies(in, met, o));
  EXPECT_FALSE(regeneration_applies(in, varied, o));
  EXPECT_FALSE(regeneration_applies(in, uniform(in, 0.02), noswap));
  EXPECT_TRUE(regeneration_applies(in, uniform(in, 0.02), o));
  EXPECT_TRUE(same_mesh(adapt_or_regenerate2d(in, met, o).mesh, adapt2d(in, met, o).mesh));
  EXPECT_TRUE(same_mesh(adapt_or_regenerate2d(in, varied, o).mesh, adapt2d(in, varied, o).mesh));
  const std::vector<SymMat2> fine = uniform(in, 0.02);
  EXPECT_TRUE(
      same_mesh(adapt_or_regenerate2d(in, fine, noswap).mesh, adapt2d(in, fine, noswap).mesh));
  // A required vertex inside stays: adapt2d.
  Mesh pinned = in;
  pinned.vert_tag.assign(pinned.num_vertices(), kTagNone);
  pinned.vert_tag[5 * 11 + 5] |= kTagRequired;
  EXPECT_FALSE(regeneration_applies(pinned, fine, o));
}

TEST(Regenerate2d, ACrackIsLeftToAdapt2d) {
  // The unit square cut along x = 0.5 from y = 0 to 0.5: the triangles right of the cut use
  // copies of its vertices (the tip shared). Meshed afresh, the lips would be merged.
  Mesh in = unit_square(8, 8);
  const std::size_t nv = in.num_vertices();
  std::vector<Id> copy(nv, kNoId);
  for (std::size_t t = 0; t < in.num_triangles(); ++t) {
    double cx = 0.0;
    for (int i = 0; i < 3; ++i) cx += in.coords[2 * in.triangles[3 * t + i]] / 3.0;
    if (cx < 0.5) continue;
    for (int i = 0; i < 3; ++i) {
      const Id v = in.triangles[3 * t + i];
      if (in.coords[2 * v] != 0.5 || !(in.coords[2 * v + 1] < 0.5)) continue;
      if (copy[v] == kNoId) {
        copy[v] = static_cast<Id>(in.num_vertices());
        in.coords.insert(in.coords.end(), {in.coords[2 * v], in.coords[2 * v + 1]});
        in.vert_ref.push_back(0);
        in.vert_tag.push_back(kTagNone);
      }
      in.triangles[3 * t + i] = copy[v];
    }
  }
  for (std::size_t e = 0; e < in.num_edges(); ++e)  // the bottom side right of the cut
    for (int i = 0; i < 2; ++i) {
      const Id v = in.edges[2 * e + i], w = in.edges[2 * e + 1 - i];
      if (copy[v] != kNoId && in.coords[2 * w] > 0.5) in.edges[2 * e + i] = copy[v];
    }
  ASSERT_EQ(in.num_vertices(), nv + 4);
  const std::vector<SymMat2> met = uniform(in, 0.02);
  EXPECT_FALSE(regeneration_applies(in, met, Adapt2dOptions{}));
  const Adapt2dResult r = adapt_or_regenerate2d(in, met, Adapt2dOptions{});
  EXPECT_FALSE(regenerated(r));
  // The lips stay apart: boundary edges on x = 0.5 below the tip, on both sides.
  double lips = 0.0;
  for (std::size_t e = 0; e < r.mesh.num_edges(); ++e) {
    const double* a = &r.mesh.coords[2 * r.mesh.edges[2 * e]];
    const double* b = &r.mesh.coords[2 * r.mesh.edges[2 * e + 1]];
    if (a[0] == 0.5 && b[0] == 0.5) lips += std::abs(b[1] - a[1]);
  }
  EXPECT_NEAR(lips, 1.0, 1e-9);
}

TEST(Regenerate2d, CurvesThatCrossAreLeftToAdapt2d) {
  // Two unit squares, the second moved by (0.3, 0.3): every triangle is valid, the boundaries
  // cross (a folded mesh), so no domain is made of them and adapt2d runs.
  Mesh in = unit_square(4, 4);
  const Mesh other = unit_square(4, 4);
  const auto shift = static_cast<Id>(in.num_vertices());
  for (std::size_t v = 0; v < other.num_vertices(); ++v)
    in.coords.insert(in.coords.end(), {other.coords[2 * v] + 0.3, other.coords[2 * v + 1] + 0.3});
  in.vert_ref.resize(in.num_vertices(), 0);
  in.vert_tag.resize(in.num_vertices(), kTagNone);
  for (const Id v : other.triangles) in.triangles.push_back(v + shift);
  in.tri_ref.resize(in.num_triangles(), 0);
  in.tri_tag.resize(in.num_triangles(), kTagNone);
  for (const Id v : other.edges) in.edges.push_back(v + shift);
  in.edge_ref.insert(in.edge_ref.end(), other.edge_ref.begin(), other.edge_ref.end());
  in.edge_tag.resize(in.num_edges(), kTagNone);
  const std::vector<SymMat2> met = uniform(in, 0.05);
  const Adapt2dResult r = adapt_or_regenerate2d(in, met, Adapt2dOptions{});
  EXPECT_FALSE(regenerated(r));
  EXPECT_TRUE(same_mesh(r.mesh, adapt2d(in, met, Adapt2dOptions{}).mesh));
}

TEST(Regenerate2d, BadInputGivesAdapt2dsErrors) {
  Mesh in = unit_square(4, 4);
  std::vector<SymMat2> met = uniform(in, 0.01);
  std::swap(in.triangles[3], in.triangles[4]);  // triangle 2 clockwise
  std::string expected, got;
  try {
    adapt2d(in, met, Adapt2dOptions{});
  } catch (const InputError& e) {
    expected = e.what();
  }
  try {
    adapt_or_regenerate2d(in, met, Adapt2dOptions{});
  } catch (const InputError& e) {
    got = e.what();
  }
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(got, expected);
  EXPECT_FALSE(
      regeneration_applies(in, met, Adapt2dOptions{}));  // no throw: not one to mesh afresh
  const Mesh square = unit_square(4, 4);
  std::vector<SymMat2> nan = uniform(square, 0.01);
  for (auto& m : nan) m.c[1] = std::nan("");
  EXPECT_THROW(adapt_or_regenerate2d(square, nan, Adapt2dOptions{}), InputError);
}

TEST(Regenerate2d, FoldedInputRefusedByPlace) {
  // The unit square's centre fan, the centre moved below the square and the triangle on the
  // bottom side listed the other way round: every triangle counter-clockwise, but the mesh folds
  // over itself (riemesh check: overlapping elements). A fine uniform size meshed the outline of
  // its boundary afresh, exit 0; --optim (the passes) ran out of memory.
  Mesh in;
  in.dim = 2;
  in.coords = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, -0.5};
  in.triangles = {1, 0, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  in.tri_ref.assign(4, 1);
  ASSERT_EQ(check_mesh(in).count(CheckCategory::kOverlappingElements), 2u);
  for (const double h : {0.02, 1.0}) {
    const std::vector<SymMat2> met(in.num_vertices(), isotropic_metric<2>(h));
    try {
      adapt_or_regenerate2d(in, met, Adapt2dOptions{});
      ADD_FAILURE() << h;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("the mesh folds over itself at (0.25, -0.25)", 0), 0u)
          << e.what();
    }
  }
}
