// Interior points of a volume by the 3D remesher with the boundary kept (volume_fill3d.hpp).
#include "generate/volume_fill3d.hpp"

#include <cmath>

#include "core/error.hpp"
#include "metric/metric.hpp"

namespace riemesh {

std::vector<double> boundary_sizes(const Mesh& volume) {
  const std::size_t nv = volume.num_vertices();
  std::vector<double> sum(nv, 0.0), count(nv, 0.0);
  double total = 0.0, edges = 0.0;
  auto at = [&](Id v, int c) { return volume.coords[3 * static_cast<std::size_t>(v) + c]; };
  for (std::size_t t = 0; t < volume.num_triangles(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Id a = volume.triangles[3 * t + i], b = volume.triangles[3 * t + (i + 1) % 3];
      double l2 = 0.0;
      for (int c = 0; c < 3; ++c) l2 += (at(a, c) - at(b, c)) * (at(a, c) - at(b, c));
      const double l = std::sqrt(l2);
      for (Id v : {a, b}) {
        sum[static_cast<std::size_t>(v)] += l;
        count[static_cast<std::size_t>(v)] += 1.0;
      }
      total += l;
      edges += 1.0;
    }
  if (!(edges > 0.0)) throw InputError("boundary sizes: the volume has no boundary triangles");
  std::vector<double> h(nv, total / edges);
  for (std::size_t v = 0; v < nv; ++v)
    if (count[v] > 0.0) h[v] = sum[v] / count[v];
  return h;
}

Adapt3dResult fill_volume(Mesh&& volume, double hsiz, Adapt3dOptions options,
                          const PassCallback& on_pass) {
  if (!(hsiz >= 0.0) || !std::isfinite(hsiz)) throw InputError("fill_volume: hsiz must be >= 0");
  std::vector<SymMat3> metrics;
  if (hsiz > 0.0) {
    metrics.assign(volume.num_vertices(), isotropic_metric<3>(hsiz));
  } else {
    for (double h : boundary_sizes(volume)) metrics.push_back(isotropic_metric<3>(h));
  }
  options.keep_surface = true;
  return adapt3d(std::move(volume), metrics, options, on_pass);
}

}  // namespace riemesh
