#pragma once
// MMG's single-dash long options (-in, -met, -hmax, -v 5, ...) rewritten to Riemesh's spellings
// before parsing, so that scripts written for mmg2d/mmgs/mmg3d run unchanged.
#include <string>
#include <vector>

namespace riemesh::cli {

/// Rewrites args (argv[1..], in order) in place: "-hmax" -> "--hmax", "-v N" -> "--verbose=N",
/// a lone "-v" -> "--verbose=1". Other arguments are left as they are. Throws InputError on the
/// MMG options Riemesh does not have (-hgradreq, -ls, -m, ...) and on single-dash words beginning
/// with -h (CLI11 would read "-hgradreq" as -h, print the help and exit 0).
void translate_mmg_spellings(std::vector<std::string>& args);

}  // namespace riemesh::cli
