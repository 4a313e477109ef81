// Boundary preservation on a real curved domain (the NACA 0012 airfoil in a circle): the new
// boundary stays within --hausd of the old one (two-sided Hausdorff distance, sampled), every
// corner is kept at its place, and the edge refs are the input's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "io/medit.hpp"
#include "mesh/check.hpp"
#include "remesh/adapt2d.hpp"
#include "remesh/boundary_distance.hpp"

using namespace riemesh;

TEST(Adapt2dBoundary, NacaWithinHausdAndCornersKept) {
  const Mesh in = read_medit(std::string(RIEMESH_SHARED_DATA) + "/2d/naca0012.mesh");
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
