#pragma once
// What every fuzz target shares: the accepted outcomes of a reader and the checks on what it
// returns. A reader may return a mesh or throw riemesh::Error (InputError included); a crash,
// a sanitizer report, a leak, a hang or any other exception is a bug. A returned mesh must also
// be one the writers accept (consistent array sizes, ids in range, finite coordinates): a reader
// that returns anything else has let malformed input through.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "core/error.hpp"
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
