// libFuzzer target: the Gmsh .geo reader (parse_geo) on arbitrary text, then what `riemesh mesh
// IN.geo` does with a geometry it accepts: its curves meshed (mesh_geometry_boundary, sizes not
// below 1e-3 of the points' box so that a run stays short) and, for boundaries of at most 2,000
// edges, the domain meshed (mesh_domain2d) and its triangles given their surfaces' refs.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_common.hpp"
#include "generate/geometry2d.hpp"
#include "generate/mesh2d.hpp"
#include "io/geo.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  riemesh::fuzz::run_reader([&] {
    const riemesh::Geometry2d g = riemesh::parse_geo(text);
    if (g.points.empty() || g.points.size() > 200) return;
    double lo[2] = {g.points[0].x, g.points[0].y}, hi[2] = {lo[0], lo[1]};
    for (const riemesh::GeoPoint& p : g.points) {
      lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x);
      lo[1] = std::min(lo[1], p.y), hi[1] = std::max(hi[1], p.y);
    }
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(diagonal > 0.0) || !std::isfinite(diagonal)) return;
    riemesh::GeometryMeshOptions options;
    options.hmin = 1e-3 * diagonal;
    const riemesh::GeometryBoundary b = riemesh::mesh_geometry_boundary(g, options);
    riemesh::fuzz::expect_writable(b.domain);
    if (b.domain.num_edges() > 2000) return;
    riemesh::Mesh2dOptions mesh_options;
    mesh_options.adapt.hgrad = 0.0;
    mesh_options.adapt.max_passes = 3;
    riemesh::Mesh2dResult r = riemesh::mesh_domain2d(b.domain, mesh_options);
    riemesh::assign_surface_refs(b, r.mesh);
    riemesh::fuzz::expect_writable(r.mesh);
  });
  return 0;
}
