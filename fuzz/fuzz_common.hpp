#pragma once
// What every fuzz target shares: the accepted outcomes of a reader and the checks on what it
// returns. A reader may return a mesh or throw riemesh::Error (InputError included); a crash,
// a sanitizer report, a leak, a hang or any other exception is a bug. A returned mesh must also
// be one the writers accept (consistent array sizes, ids in range, finite coordinates): a reader
// that returns anything else has let malformed input through. The Medit targets also write what
// they read in the other Medit format and read it back: the two meshes must be equal.
#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/medit.hpp"
#include "io/medit_detail.hpp"
#include "mesh/mesh.hpp"

namespace riemesh::fuzz {

/// Aborts (a finding) unless the mesh passes the writers' own consistency check.
inline void expect_writable(const Mesh& mesh) {
  try {
    medit_detail::check_writable(mesh, "fuzz input");
  } catch (const Error& e) {
    std::fprintf(stderr, "reader returned an inconsistent mesh: %s\n", e.what());
    std::abort();
  }
}

/// A folder of this process for round-trip files, removed at exit.
class ScratchDir {
 public:
  static const ScratchDir& get() {
    static const ScratchDir dir;
    return dir;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  std::string file(const char* name) const { return path_ + "/" + name; }

 private:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "riemesh_fuzz_XXXXXX").string();
    if (!mkdtemp(pattern.data())) std::abort();
    path_ = pattern;
  }
  std::string path_;
};

/// Writes the mesh to `name` (.mesh or .meshb, triangles as they are) and aborts unless reading
/// it back with the same options gives the same arrays.
inline void expect_round_trip(const Mesh& mesh, const char* name, const MeditReadOptions& options) {
  const std::string path = ScratchDir::get().file(name);
  MeditWriteOptions write_options;
  write_options.ccw_2d = false;
  Mesh back;
  try {
    write_medit(mesh, path, write_options);
    back = read_medit(path, options);
  } catch (const Error& e) {
    std::fprintf(stderr, "round trip through %s failed: %s\n", name, e.what());
    std::abort();
  }
  const bool same =
      back.dim == mesh.dim && back.coords == mesh.coords && back.vert_ref == mesh.vert_ref &&
      back.vert_tag == mesh.vert_tag && back.edges == mesh.edges &&
      back.edge_ref == mesh.edge_ref && back.edge_tag == mesh.edge_tag &&
      back.triangles == mesh.triangles && back.tri_ref == mesh.tri_ref &&
      back.tri_tag == mesh.tri_tag && back.tets == mesh.tets && back.tet_ref == mesh.tet_ref &&
      back.normals == mesh.normals && back.normal_at_vertex == mesh.normal_at_vertex &&
      back.tangents == mesh.tangents && back.tangent_at_vertex == mesh.tangent_at_vertex;
  if (!same) {
    std::fprintf(stderr, "%s read back differs from the mesh written\n", name);
    std::abort();
  }
}

/// Runs read(); a riemesh::Error is an accepted outcome, any other exception aborts.
template <class Read>
void run_reader(Read read) {
  try {
    read();
  } catch (const Error&) {
    // Malformed input rejected with a message: the expected outcome.
  }
}

}  // namespace riemesh::fuzz
