#include "io/medit.hpp"

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/medit_detail.hpp"

namespace riemesh {

using medit_detail::ends_with;

Mesh read_medit(const std::string& path, const MeditReadOptions& options) {
  const bool binary = ends_with(path, ".meshb");
  if (!binary && !ends_with(path, ".mesh"))
    throw InputError(path + ": not a Medit mesh file name (.mesh or .meshb expected)");
  const std::string bytes = read_file_bytes(path);
  return binary ? medit_detail::read_medit_binary(path, bytes, options)
                : medit_detail::read_medit_ascii(path, bytes, options);
}

void write_medit(const Mesh& mesh, const std::string& path, const MeditWriteOptions& options) {
  const bool binary = ends_with(path, ".meshb");
  if (!binary && !ends_with(path, ".mesh"))
    throw InputError(path + ": not a Medit mesh file name (.mesh or .meshb expected)");
  medit_detail::check_writable(mesh, path);
  AtomicFile file(path, options.sync);
  if (binary) {
    medit_detail::write_medit_binary(mesh, file, options);
  } else {
    medit_detail::write_medit_ascii(mesh, file, options);
  }
  file.commit();
}

}  // namespace riemesh
