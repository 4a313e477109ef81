#include "io/text_scanner.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace riemesh::io_detail {

std::string_view TextScanner::peek() {
  const Mark m = mark();
  const std::size_t saved_line = token_line_;
  std::string_view token;
  next(token);
  reset(m);
  token_line_ = saved_line;
  return token;
}

bool parse_int(std::string_view token, std::int64_t& value) {
  // Plain digits (what mesh files hold), at most 18 of them: no overflow possible.
  if (!token.empty() && token.size() <= 18) {
    std::int64_t v = 0;
    std::size_t i = 0;
    for (; i < token.size(); ++i) {
      const unsigned d = static_cast<unsigned>(token[i]) - '0';
      if (d > 9) break;
      v = 10 * v + static_cast<std::int64_t>(d);
    }
    if (i == token.size()) {
      value = v;
      return true;
    }
  }
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, value);
  return result.ec == std::errc() && result.ptr == end && !token.empty();
}

bool parse_real(std::string_view token, double& value) {
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  auto result = std::from_chars(token.data(), end, value);
  if (result.ec == std::errc() && result.ptr == end) return true;
  if (result.ec == std::errc::result_out_of_range && result.ptr == end && token.size() < 64) {
    // Subnormal or overflowing values: strtod gives the nearest double (or +-inf, which the
    // callers reject as non-finite).
    const std::string copy(token);
    char* stop = nullptr;
    value = std::strtod(copy.c_str(), &stop);
    return stop == copy.c_str() + copy.size();
  }
  // Fortran writers use 'D' for the exponent (1.0D+00).
  const std::size_t d = token.find_first_of("dD");
  if (d == std::string_view::npos || token.size() > 64) return false;
  std::string copy(token);
  copy[d] = 'e';
  result = std::from_chars(copy.data(), copy.data() + copy.size(), value);
  return result.ec == std::errc() && result.ptr == copy.data() + copy.size();
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

}  // namespace riemesh::io_detail
