#include "io/medit_ascii_reader.hpp"

#include <cmath>
#include <limits>

namespace riemesh::medit_detail {

using io_detail::is_word;

std::string_view AsciiMeditReader::token(std::string_view keyword, const char* expected) {
  std::string_view t;
  if (!in_.next(t)) fail_here(keyword, std::string("unexpected end of file, expected ") + expected);
  return t;
}

std::int64_t AsciiMeditReader::integer(std::string_view keyword) {
  std::int64_t fast = 0;
  if (in_.next_int(fast)) return fast;
  const std::string_view t = token(keyword, "an integer");
  std::int64_t value = 0;
  if (!io_detail::parse_int(t, value)) fail_here(keyword, "expected an integer, found " + quote(t));
  return value;
}

Id AsciiMeditReader::id(std::string_view keyword) {
  const std::int64_t value = integer(keyword);
  if (value < 1 || value > std::numeric_limits<Id>::max())
    fail_here(keyword, "id " + std::to_string(value) + " out of range (ids start at 1)");
  return static_cast<Id>(value - 1);
}

std::int32_t AsciiMeditReader::ref(std::string_view keyword) {
  const std::int64_t value = integer(keyword);
  if (value < std::numeric_limits<std::int32_t>::min() ||
      value > std::numeric_limits<std::int32_t>::max())
    fail_here(keyword, "reference " + std::to_string(value) + " does not fit in 32 bits");
  return static_cast<std::int32_t>(value);
}

double AsciiMeditReader::real(std::string_view keyword) {
  const io_detail::TextScanner::Mark before = in_.mark();
  double fast = 0;
  if (in_.next_real(fast)) {
    if (std::isfinite(fast)) return fast;
    in_.reset(before);  // the message below quotes the token
  }
  const std::string_view t = token(keyword, "a real number");
  double value = 0;
  if (!io_detail::parse_real(t, value))
    fail_here(keyword, "expected a real number, found " + quote(t));
  if (!std::isfinite(value)) fail_here(keyword, "non-finite value " + quote(t));
  return value;
}

std::size_t AsciiMeditReader::count(std::string_view keyword, std::size_t tokens_per_entry) {
  const std::int64_t n = integer(keyword);
  if (n < 0) fail_here(keyword, "negative count " + std::to_string(n));
  check_room(keyword, static_cast<std::size_t>(n), tokens_per_entry);
  return static_cast<std::size_t>(n);
}

void AsciiMeditReader::check_room(std::string_view keyword, std::size_t n,
                                  std::size_t tokens_per_entry) {
  // Each token takes at least one character and one separator.
  const std::size_t room = (in_.remaining() + 1) / 2;
  if (tokens_per_entry > 0 && n > room / tokens_per_entry)
    fail_here(keyword,
              "count " + std::to_string(n) + " is larger than the rest of the file can hold");
}

int AsciiMeditReader::require_dim(std::string_view keyword) {
  if (dim_ == 0) fail_here(keyword, "no Dimension keyword before this section");
  return dim_;
}

Locator AsciiMeditReader::locator(std::size_t tokens_per_entry) const {
  const io_detail::TextScanner::Mark start = in_.mark();
  return [path = path_, text = text_, start, tokens_per_entry](std::size_t entry, int column) {
    // Only called to report an error: re-scan from the start of the section.
    io_detail::TextScanner s(text);
    s.reset(start);
    std::string_view t;
    const std::size_t skip = entry * tokens_per_entry + static_cast<std::size_t>(column) + 1;
    for (std::size_t i = 0; i < skip && s.next(t); ++i) {
    }
    return path + ":" + std::to_string(s.line());
  };
}

void AsciiMeditReader::skip_section(std::string_view name) {
  const int ints = skipped_keyword_ints(name);
  if (ints > 0) {
    const std::size_t n = count(name, static_cast<std::size_t>(ints));
    if (n > 0 && holds_elements(name)) fail_here(name, unread_elements(n));
    for (std::size_t i = 0; i < n * static_cast<std::size_t>(ints); ++i) integer(name);
    return;
  }
  // Unknown layout (FreeFem/BAMG keywords, Identifier, Geometry ...): skip to the next word.
  if (unknown_ && !known_skipped_keyword(name))
    unknown_->push_back(std::string(name) + " (line " + std::to_string(in_.line()) + ")");
  while (true) {
    const std::string_view t = in_.peek();
    if (t.empty() || is_word(t)) return;
    std::string_view skipped;
    in_.next(skipped);
  }
}

bool AsciiMeditReader::next_keyword(std::string_view& name, int& code) {
  while (true) {
    if (!in_.next(name)) return false;
    if (!is_word(name)) {
      fail_here(last_, "expected a keyword" +
                           (last_.empty() ? std::string() : " after the " + last_ + " section") +
                           ", found " + quote(name) + " (count too small?)");
    }
    code = keyword_code(name);
    if (code != 0) name = keyword_name(code);
    last_ = std::string(name);
    if (code == kEnd) return false;
    if (code == kVersionFormatted) {
      const std::int64_t v = integer(name);
      if (v < 1 || v > 4) fail_here(name, "unknown version " + std::to_string(v));
      version_ = static_cast<int>(v);
    } else if (code == kDimension) {
      const std::int64_t d = integer(name);
      if (d != 2 && d != 3)
        fail_here(name, "dimension " + std::to_string(d) + " (2 or 3 expected)");
      // Sections already read used the first dimension: a file has one.
      if (dim_ != 0 && d != dim_)
        fail_here(name,
                  "dimension " + std::to_string(d) + " after dimension " + std::to_string(dim_));
      dim_ = static_cast<int>(d);
    } else if (code == 0) {
      skip_section(name);
    } else {
      return true;
    }
  }
}

}  // namespace riemesh::medit_detail
