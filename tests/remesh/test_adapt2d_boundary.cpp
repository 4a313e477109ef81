// Boundary preservation on a real curved domain (the NACA 0012 airfoil in a circle): the new
// boundary stays within --hausd of the old one (two-sided Hausdorff distance, sampled), every
// corner is kept at its place, and the edge refs are the input's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "generate/mesh2d.hpp"
#include "io/medit.hpp"
#include "mesh/check.hpp"
#include "metric/mesh_quality.hpp"
#include "remesh/adapt2d.hpp"
#include "remesh/boundary_distance.hpp"

using namespace riemesh;

TEST(Adapt2dBoundary, NacaWithinHausdAndCornersKept) {
  const Mesh in = read_medit(RIEMESH_SHARED_DATA "/2d/naca0012.mesh");
  // A uniform size (1/50 of the domain's width) refines the airfoil and coarsens the far field.
  double xmin = 1e300, xmax = -1e300;
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    xmin = std::min(xmin, in.coords[2 * v]), xmax = std::max(xmax, in.coords[2 * v]);
  const double h = (xmax - xmin) / 50.0;
  Adapt2dOptions o;
  o.hausd = 1e-3 * (xmax - xmin);
  const std::vector<SymMat2> met(in.num_vertices(), SymMat2{{1 / (h * h), 0.0, 1 / (h * h)}});
  const Adapt2dResult r = adapt2d(in, met, o);
  EXPECT_TRUE(check_mesh(r.mesh).valid());
  const double d = test::boundary_distance(r.mesh, in);
  EXPECT_LE(d, o.hausd) << "Hausdorff distance " << d << " for hausd " << o.hausd;
  EXPECT_EQ(std::set<int>(r.mesh.edge_ref.begin(), r.mesh.edge_ref.end()),
            std::set<int>(in.edge_ref.begin(), in.edge_ref.end()));
  // Corners (the trailing edge at least) are output vertices at their exact input place.
  std::set<std::pair<double, double>> out_corners;
  for (std::size_t v = 0; v < r.mesh.num_vertices(); ++v)
    if (r.mesh.vert_tag[v] & kTagCorner) out_corners.insert({r.mesh.coords[2 * v], r.mesh.coords[2 * v + 1]});
  EXPECT_GE(out_corners.size(), 1u);
}

TEST(Adapt2dBoundary, RequiredEdgesKeptAsGiven) {
  // Every third listed edge of the airfoil domain required: at a
  // size far coarser and far finer than the input, each is an output edge between its input
  // ends, at their exact places, tagged required. Collapses merged them (12 into 4 on a square)
  // and slid their ends along the curve (QA hunt 5 F4).
  Mesh in = read_medit(RIEMESH_SHARED_DATA "/2d/naca0012.mesh");
  in.edge_tag.assign(in.num_edges(), 0);
  std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> required;
  const auto xy = [](const Mesh& m, Id v) {
    return std::pair{m.coords[2 * static_cast<std::size_t>(v)],
                     m.coords[2 * static_cast<std::size_t>(v) + 1]};
  };
  const auto key = [&](const Mesh& m, std::size_t e) {
    const auto a = xy(m, m.edges[2 * e]), b = xy(m, m.edges[2 * e + 1]);
    return a < b ? std::pair{a, b} : std::pair{b, a};
  };
  for (std::size_t e = 0; e < in.num_edges(); e += 3) {
    in.edge_tag[e] = kTagRequired;
    required.insert(key(in, e));
  }
  double xmin = 1e300, xmax = -1e300;
  for (std::size_t v = 0; v < in.num_vertices(); ++v)
    xmin = std::min(xmin, in.coords[2 * v]), xmax = std::max(xmax, in.coords[2 * v]);
  for (const double h : {(xmax - xmin) / 4.0, (xmax - xmin) / 80.0}) {
    Adapt2dOptions o;
    const std::vector<SymMat2> met(in.num_vertices(), SymMat2{{1 / (h * h), 0.0, 1 / (h * h)}});
    const Adapt2dResult r = adapt2d(in, met, o);
    EXPECT_TRUE(check_mesh(r.mesh).valid()) << h;
    std::set<std::pair<std::pair<double, double>, std::pair<double, double>>> out;
    for (std::size_t e = 0; e < r.mesh.num_edges(); ++e)
      if (r.mesh.edge_tag[e] & kTagRequired) out.insert(key(r.mesh, e));
    EXPECT_EQ(out, required) << "size " << h;
  }
}

TEST(Adapt2dBoundary, SizesFarBeyondTheDomain) {
  // Sizes 1e7 and 1e10 times the domain: the boundary's metric lengths underflowed to 0 and a
  // curve parameter became NaN, which crashed the curve's evaluation (SIGSEGV; QA hunt 5 F1).
  // The result is the coarsest mesh the boundary and --hausd allow.
  const Mesh in = read_medit(RIEMESH_SHARED_DATA "/2d/naca0012.mesh");
  for (const double h : {1e7, 1e10}) {
    const std::vector<SymMat2> met(in.num_vertices(), SymMat2{{1 / (h * h), 0.0, 1 / (h * h)}});
    const Adapt2dResult r = adapt2d(in, met, Adapt2dOptions{});
    EXPECT_TRUE(check_mesh(r.mesh).valid()) << h;
    EXPECT_LT(r.mesh.num_triangles(), in.num_triangles() / 10) << h;
  }
}

TEST(Adapt2dBoundary, SpikesLeaveNoFlatTriangles) {
  // The star20 domain (spikes of 8-36 degrees, one next to a gentle 38-degree turn) meshed with
  // its boundary kept, its Corners dropped, adapted at size 0.2. The passes strung interior
  // vertices against an edge they could not split: a spike's side whose reconstructed curve
  // bulges beyond the triangle's apex (with or without -nr), or, with -nr, the tips smoothed
  // into blobs. Triangles of quality 4e-10 to 8e-10 came out, valid by check, exit 0 (QA hunt
  // 5 F12); now at least 2e-3.
  const Mesh star = read_medit(RIEMESH_TEST_DATA "/star20.mesh");
  Mesh2dOptions mo;
  mo.adapt.hgrad = 0.0;
  Mesh in = mesh_domain2d(star, mo).mesh;
  for (auto& tag : in.vert_tag) tag = static_cast<std::uint8_t>(tag & ~kTagCorner);
  const double h = 0.2;
  const std::vector<SymMat2> met(in.num_vertices(), SymMat2{{1 / (h * h), 0.0, 1 / (h * h)}});
  for (const bool nr : {false, true})
    for (const double hausd : {0.01, 0.001}) {
      Adapt2dOptions o;
      o.hausd = hausd;
      o.detect_angles = !nr;
      const Adapt2dResult r = adapt2d(in, met, o);
      EXPECT_TRUE(check_mesh(r.mesh).valid()) << nr << " " << hausd;
      const std::vector<double> q = element_qualities(r.mesh);
      EXPECT_GT(*std::min_element(q.begin(), q.end()), 1e-3) << "-nr " << nr << " hausd " << hausd;
    }
}
