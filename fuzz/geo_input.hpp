#pragma once
// What fuzz/fuzz_geo.cpp does with its input, shared with the crasher replay
// (tests/io/test_fuzz_crashers.cpp): the .geo text parsed, then what `riemesh mesh IN.geo` does
// with a geometry it accepts — its curves meshed (sizes not below 1e-2 of the points' box, so
// that a run stays short) and, for boundaries of at most 300 edges, the domain meshed and its
// triangles given their surfaces' refs (the sanitized build is ~50x slower). `check` is called
// on the boundary and on the mesh made; a rejection is a riemesh::Error thrown.
#include <algorithm>
#include <cmath>
#include <string_view>

#include "generate/geometry2d.hpp"
#include "generate/mesh2d.hpp"
#include "io/geo.hpp"

namespace riemesh::fuzz {

template <class Check>
void mesh_geo_text(std::string_view text, Check check) {
  const Geometry2d g = parse_geo(text);
  if (g.points.empty() || g.points.size() > 200) return;
  double lo[2] = {g.points[0].x, g.points[0].y}, hi[2] = {lo[0], lo[1]};
  for (const GeoPoint& p : g.points) {
    lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x);
    lo[1] = std::min(lo[1], p.y), hi[1] = std::max(hi[1], p.y);
  }
  const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  GeometryMeshOptions options;
  if (diagonal > 0.0 && std::isfinite(diagonal)) options.hmin = 1e-2 * diagonal;
  const GeometryBoundary b = mesh_geometry_boundary(g, options);
  check(b.domain);
  if (b.domain.num_edges() > 300) return;
  Mesh2dOptions mesh_options;
  mesh_options.adapt.hgrad = 0.0;
  mesh_options.adapt.max_passes = 3;
  Mesh2dResult r = mesh_domain2d(b.domain, mesh_options);
  assign_surface_refs(b, r.mesh);
  check(r.mesh);
}

}  // namespace riemesh::fuzz
