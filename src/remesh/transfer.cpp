#include "remesh/transfer.hpp"

#include <algorithm>
#include <span>
#include <string>

#include "core/error.hpp"
#include "remesh/background.hpp"

namespace riemesh {
namespace {

template <int D>
std::vector<Field> transfer(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                            P1TransferReport* report) {
  // The walk needs a background mesh; its metric is not used here (identity).
  std::vector<double> identity;
  for (std::size_t v = 0; v < from.num_vertices(); ++v)
    for (int k = 0; k < SymMat<D>::kSize; ++k) identity.push_back(SymMat<D>::identity().c[k]);
  const BackgroundMesh<D> bg(from, identity, InterpScheme::kLinear);
  std::vector<Field> out;
  for (const Field& f : fields) {
    const int n = field_components(f.kind, from.dim);
    if (f.values.size() != from.num_vertices() * static_cast<std::size_t>(n))
      throw InputError("field '" + f.name + "' does not have one value set per vertex");
    out.push_back({f.name, f.kind, std::vector<double>(to.num_vertices() * n)});
  }
  Id hint = kNoId;
  for (std::size_t v = 0; v < to.num_vertices(); ++v) {
    Vec<D> p{};
    for (int k = 0; k < D; ++k) p[k] = to.coords[D * v + k];
    const Location<D> loc = bg.locate(p, hint);
    hint = loc.simplex;
    if (report && !loc.inside) {
      Vec<D> q{};  // the projection: the barycentric combination of the simplex's corners
      for (int i = 0; i <= D; ++i) {
        const Id c = (D == 2 ? from.triangles
                             : from.tets)[(D + 1) * static_cast<std::size_t>(loc.simplex) + i];
        for (int k = 0; k < D; ++k)
          q[k] += loc.bary[i] * from.coords[D * static_cast<std::size_t>(c) + k];
      }
      ++report->outside;
      report->farthest = std::max(report->farthest, norm(p - q));
    }
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const int n = field_components(fields[i].kind, from.dim);
      bg.interpolate_fields(loc, fields[i].values, n,
                            std::span<double>(out[i].values).subspan(n * v, n));
    }
  }
  return out;
}

}  // namespace

std::vector<Field> transfer_p1(const Mesh& from, const std::vector<Field>& fields, const Mesh& to,
                               P1TransferReport* report) {
  if (from.dim != to.dim || from.kind() != to.kind())
    throw InputError("field transfer needs two meshes of the same kind");
  if (report) *report = {};
  if (from.kind() == MeshKind::kPlanar) return transfer<2>(from, fields, to, report);
  if (from.kind() == MeshKind::kVolume) return transfer<3>(from, fields, to, report);
  throw InputError("field transfer works on planar triangle meshes and tetrahedral volumes");
}

}  // namespace riemesh
