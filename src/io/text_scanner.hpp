#pragma once
// Tokenizer for the Medit ASCII formats (.mesh, .sol): whitespace-separated tokens, '#' comments
// to the end of the line, "quoted strings" (FreeFem's Identifier/Geometry) as single tokens.
// Keeps the line number of each token for error messages.
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace riemesh::io_detail {

class TextScanner {
 public:
  /// A UTF-8 byte-order mark (a Windows editor's) is skipped.
  explicit TextScanner(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  /// Moves to the next token; false at the end of the text.
  bool next(std::string_view& token);
  /// The next token without consuming it (empty at the end).
  std::string_view peek();
  /// Line (1-based) of the last token returned by next().
  std::size_t line() const { return token_line_; }
  /// Bytes not yet scanned.
  std::size_t remaining() const { return text_.size() - pos_; }

  /// The next token when it is a plain number (what from_chars reads, up to a blank or the
  /// end): consumed and true. Otherwise false with nothing consumed but blanks and comments, so
  /// that next() then gives the token (signs, 'D' exponents, out-of-range values, errors).
  bool next_real(double& value) { return next_plain(value); }
  bool next_int(std::int64_t& value) { return next_plain(value); }

  struct Mark {
    std::size_t pos, line;
  };
  Mark mark() const { return {pos_, line_}; }
  void reset(Mark m) { pos_ = m.pos, line_ = m.line, token_line_ = m.line; }

 private:
  void skip_blanks();
  template <class T>
  bool next_plain(T& value);

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t token_line_ = 1;
};

inline void TextScanner::skip_blanks() {
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

inline bool TextScanner::next(std::string_view& token) {
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

namespace scanner_detail {
inline bool is_blank(char c) {
  return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
}  // namespace scanner_detail

template <class T>
inline bool TextScanner::next_plain(T& value) {
  skip_blanks();
  const char* b = text_.data() + pos_;
  const char* e = text_.data() + text_.size();
  if (b == e) return false;
  const auto r = std::from_chars(b, e, value);
  if (r.ec != std::errc() || r.ptr == b || (r.ptr != e && !scanner_detail::is_blank(*r.ptr)))
    return false;
  token_line_ = line_;
  pos_ += static_cast<std::size_t>(r.ptr - b);
  return true;
}

/// Whole-token parses; false if the token is not entirely a number of that kind.
bool parse_int(std::string_view token, std::int64_t& value);
bool parse_real(std::string_view token, double& value);

/// True if the token can start a keyword (a letter).
inline bool is_word(std::string_view token) {
  if (token.empty()) return false;
  const char c = token[0];
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

/// ASCII case-insensitive equality.
bool iequals(std::string_view a, std::string_view b);

}  // namespace riemesh::io_detail
