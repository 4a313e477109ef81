#pragma once
// The progress line of one remeshing pass, for the commands that run the remesher (adapt, mesh).
#include "remesh/adapt2d.hpp"  // PassStats

namespace riemesh::cli {

/// "pass N: V vertices E elements, lengths in [1/√2, √2] P%, q_min Q (S s)" on stderr, then with
/// verbosity > 0 the operator counts and the length and quality summary. `label` prefixes the
/// line ("" or e.g. "fill ").
void print_pass(const PassStats& s, int verbosity, const char* elements = "triangles",
                const char* label = "");

}  // namespace riemesh::cli
