#pragma once
// Keyword-level reading of Medit ASCII files (.mesh and .sol): the header keywords, counts
// checked against the file size, numbers checked for range and finiteness, unknown keywords
// skipped, and error locations "file:line".
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "io/medit_detail.hpp"
#include "io/text_scanner.hpp"

namespace riemesh::medit_detail {

class AsciiMeditReader {
 public:
  AsciiMeditReader(const std::string& path, std::string_view text)
      : path_(path), text_(text), in_(text) {}

  /// Moves to the next data keyword (MeshVersionFormatted and Dimension are read on the way;
  /// unknown keywords are skipped). False at `End` or at the end of the file.
  bool next_keyword(std::string_view& name, int& code);

  int version() const { return version_; }
  /// 0 until a Dimension keyword has been read.
  int dim() const { return dim_; }
  /// The dimension, or an error if no Dimension keyword came before `keyword`.
  int require_dim(std::string_view keyword);

  /// Count of a section whose entries have tokens_per_entry tokens; fails if negative or larger
  /// than what the rest of the file could hold.
  std::size_t count(std::string_view keyword, std::size_t tokens_per_entry);
  /// Fails unless n entries of tokens_per_entry tokens could still fit in the file.
  void check_room(std::string_view keyword, std::size_t n, std::size_t tokens_per_entry);
  std::int64_t integer(std::string_view keyword);
  /// A 1-based id from the file, returned 0-based (upper bound checked later).
  Id id(std::string_view keyword);
  std::int32_t ref(std::string_view keyword);
  double real(std::string_view keyword);

  /// "file:line" of the last token read.
  std::string where() const { return path_ + ":" + std::to_string(in_.line()); }
  /// Locator of the section whose data starts at the next token.
  Locator locator(std::size_t tokens_per_entry) const;
  /// Skips the data of a keyword the caller does not use.
  void skip_section(std::string_view name);
  /// Where skip_section reports the unknown keywords it skips ("NAME (line N)"), or null.
  void report_unknown(std::vector<std::string>* out) { unknown_ = out; }
  [[noreturn]] void fail_here(std::string_view keyword, const std::string& what) const {
    fail(where(), keyword, what);
  }

 private:
  std::string_view token(std::string_view keyword, const char* expected);

  std::string path_;
  std::string_view text_;
  io_detail::TextScanner in_;
  std::string last_;  // the last keyword, for messages about what follows a section
  int version_ = 0;
  int dim_ = 0;
  std::vector<std::string>* unknown_ = nullptr;
};

}  // namespace riemesh::medit_detail
