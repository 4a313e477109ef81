#pragma once
// Parsing of numbers given on the command line, with one-line errors naming the argument.
#include <string>
#include <vector>

namespace riemesh::cli {

/// Parses "a,b,c" (commas or spaces) into finite doubles; throws InputError naming `what`.
std::vector<double> parse_numbers(const std::string& text, const std::string& what);

/// Throws InputError naming `option` unless `size` is a finite size > 0 whose metric 1/size²
/// is a normal double (from about 1e-154 to 1e154): beyond, the error came later, as a metric
/// the user never gave ("not positive definite", "infinite coefficient").
void require_size_option(const std::string& option, double size);

/// Throws InputError when -v N (N > 0) and -q are given together: they contradict (`mesh` took
/// both and printed nothing). MMG's -v -1 (silent) goes with -q.
void require_verbosity(int verbosity, bool quiet);

/// Throws InputError naming `path` unless it ends in .png or .svg (any case) and can be written
/// (its folder exists): checked before the work, not after it.
void require_image_output(const std::string& path);

}  // namespace riemesh::cli
