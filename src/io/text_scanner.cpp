#include "io/text_scanner.hpp"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace riemesh::io_detail {

void TextScanner::skip_blanks() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++line_;
      ++pos_;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++pos_;
    } else if (c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

bool TextScanner::next(std::string_view& token) {
  skip_blanks();
  if (pos_ >= text_.size()) {
    token = {};  // line() stays that of the last token: where the file was cut short
    return false;
  }
  token_line_ = line_;
  const std::size_t begin = pos_;
  if (text_[pos_] == '"') {
    // A quoted string runs to the closing quote, or to the end of the line if unterminated.
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '"') ++pos_;
  } else {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v') break;
      ++pos_;
    }
  }
  token = text_.substr(begin, pos_ - begin);
  return true;
}

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
