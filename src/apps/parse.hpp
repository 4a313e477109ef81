#pragma once
// Parsing of numbers given on the command line, with one-line errors naming the argument.
#include <string>
#include <vector>

namespace riemesh::cli {

/// Parses "a,b,c" (commas or spaces) into finite doubles; throws InputError naming `what`.
std::vector<double> parse_numbers(const std::string& text, const std::string& what);

}  // namespace riemesh::cli
