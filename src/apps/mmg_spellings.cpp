#include "apps/mmg_spellings.hpp"

#include <array>
#include <cstdlib>
#include <string_view>

#include "core/error.hpp"

namespace riemesh::cli {
namespace {

constexpr std::array<std::string_view, 16> kLongWithOneDash = {
    "-in",    "-out", "-met",   "-sol",      "-hmin",   "-hmax",   "-hsiz",  "-hgrad",
    "-hausd", "-ar",  "-nr",    "-optim",    "-noinsert", "-noswap", "-nomove", "-nosurf"};

// MMG options Riemesh has no counterpart for: refused by name rather than misread (a
// single-dash word is a cluster of short flags to CLI11, and "-hgradreq" began with -h, the help).
constexpr std::array<std::string_view, 20> kMmgUnsupported = {
    "-hgradreq", "-A",        "-m",   "-d",       "-ls",    "-lssurf", "-lag",
    "-opnbdy",   "-rmc",      "-rn",  "-nofem",   "-nreg",  "-xreg",   "-nsd",
    "-octree",   "-optimLES", "-val", "-default", "-noout", "-3dMedit"};

bool is_integer(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtol(s.c_str(), &end, 10);
  return *end == '\0';
}

}  // namespace

void translate_mmg_spellings(std::vector<std::string>& args) {
  std::vector<std::string> out;
  out.reserve(args.size());
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    bool long_one_dash = false;
    for (std::string_view k : kLongWithOneDash) long_one_dash = long_one_dash || a == k;
    for (std::string_view k : kMmgUnsupported)
      if (a == k)
        throw InputError("the MMG option " + a +
                         " is not supported by riemesh (its options: riemesh COMMAND -h)");
    // -h takes no value and clusters with nothing: "-hmax0.1", "-hausd=0.01" or a typo would
    // print the help and exit 0 as if the run had succeeded.
    if (a.size() > 2 && a[0] == '-' && a[1] == 'h' && !long_one_dash)
      throw InputError("unknown option " + a + " (see -h)");
    if (long_one_dash) {
      out.push_back("-" + a);
    } else if (a == "-v" && i + 1 < args.size() && is_integer(args[i + 1])) {
      out.push_back("--verbose=" + args[++i]);
    } else if (a == "-v") {
      out.push_back("--verbose=1");
    } else {
      out.push_back(a);
    }
  }
  args.swap(out);
}

}  // namespace riemesh::cli
