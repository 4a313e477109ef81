#include "io/mesh_file.hpp"

#include "core/error.hpp"
#include "io/gmsh.hpp"
#include "io/medit.hpp"
#include "io/medit_detail.hpp"
#include "io/vtu.hpp"

namespace riemesh {

MeshFormat mesh_format(const std::string& path) {
  using medit_detail::ends_with;
  if (ends_with(path, ".mesh")) return MeshFormat::kMedit;
  if (ends_with(path, ".meshb")) return MeshFormat::kMeditBinary;
  if (ends_with(path, ".msh")) return MeshFormat::kGmsh;
  if (ends_with(path, ".vtu")) return MeshFormat::kVtu;
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  std::string what = path + ": unknown mesh file extension";
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    what += ' ';
    what += medit_detail::quote(std::string_view(path).substr(dot));
  }
  what += " (.mesh, .meshb, .msh or .vtu expected)";
  throw InputError(what);
}

Mesh read_mesh(const std::string& path, std::vector<std::string>* unknown_keywords) {
  switch (mesh_format(path)) {
    case MeshFormat::kMedit:
    case MeshFormat::kMeditBinary: {
      MeditReadOptions options;
      options.unknown_keywords = unknown_keywords;
      return read_medit(path, options);
    }
    case MeshFormat::kGmsh:
      return read_gmsh(path);
    case MeshFormat::kVtu:
      break;
  }
  throw InputError(path + ": reading .vtu files is not supported (Riemesh writes them only)");
}

void write_mesh(const Mesh& mesh, const std::string& path, const MeshWriteOptions& options) {
  switch (mesh_format(path)) {
    case MeshFormat::kMedit:
    case MeshFormat::kMeditBinary: {
      MeditWriteOptions medit;
      medit.sync = options.sync;
      write_medit(mesh, path, medit);
      return;
    }
    case MeshFormat::kGmsh: {
      GmshWriteOptions gmsh;
      gmsh.binary = options.gmsh_binary;
      gmsh.sync = options.sync;
      write_gmsh(mesh, path, gmsh);
      return;
    }
    case MeshFormat::kVtu: {
      VtuWriteOptions vtu;
      vtu.sync = options.sync;
      write_vtu(mesh, path, vtu);
      return;
    }
  }
}

}  // namespace riemesh
