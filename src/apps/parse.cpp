#include "apps/parse.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace riemesh::cli {

std::vector<double> parse_numbers(const std::string& text, const std::string& what) {
  std::vector<double> values;
  const char* p = text.c_str();
  bool comma = false;  // a comma since the last number: an empty item ("100," "1,,2") is refused
  while (*p != '\0') {
    while (*p == ' ') ++p;
    if (*p == ',') {
      if (comma || values.empty())
        throw InputError(what + ": '" + text + "' " +
                         (values.empty() ? "starts with a comma" : "has two commas in a row"));
      comma = true;
      ++p;
      continue;
    }
    if (*p == '\0') break;
    comma = false;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(p, &end);
    if (end == p) throw InputError(what + ": '" + text + "' is not a list of numbers");
    if (errno == ERANGE || !std::isfinite(v))
      throw InputError(what + ": '" + text + "' has a NaN, infinite or out-of-range number");
    if (*end != '\0' && *end != ',' && *end != ' ')
      throw InputError(what + ": '" + text + "' is not a list of numbers");
    values.push_back(v);
    p = end;
  }
  if (comma) throw InputError(what + ": '" + text + "' ends with a comma");
  if (values.empty()) throw InputError(what + ": no numbers given");
  return values;
}

void require_size_option(const std::string& option, double size) {
  if (size > 0.0 && std::isnormal(1.0 / (size * size)) && std::isfinite(size * size)) return;
  char msg[120];
  std::snprintf(msg, sizeof msg, " must be a finite size > 0 (from 1e-150 to 1e150), got %g", size);
  throw InputError(option + msg);
}

void require_image_output(const std::string& path) {
  auto ends = [&path](const char* e) {
    const std::string ext = e;
    if (path.size() < ext.size()) return false;
    for (std::size_t i = 0; i < ext.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i])
        return false;
    return true;
  };
  if (!ends(".png") && !ends(".svg"))
    throw InputError(path + ": unknown image extension (expected .png or .svg)");
  require_writable(path);
}

void require_verbosity(int verbosity, bool quiet) {
  if (quiet && verbosity > 0)
    throw InputError("-v " + std::to_string(verbosity) + " and -q contradict: give one of them");
}

}  // namespace riemesh::cli
