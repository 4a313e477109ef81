#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "io/gmsh_detail.hpp"
#include "io/medit_detail.hpp"

namespace riemesh::gmsh_detail {

int nodes_per_element(int type) {
  // elm-type table of the MSH specification (first- to fifth-order Lagrange elements).
  static constexpr int kNodes[] = {
      0, 2,  3,  4,  4,  8,  6, 5, 3, 6,  9,  10, 27, 18, 14, 1, 8,  20, 15, 13,  // 0-19
      9, 10, 12, 15, 15, 21, 4, 5, 6, 20, 35, 56, 0,  0,  0,  0, 16, 25, 36, 0,   // 20-39
  };
  if (type == 92) return 64;   // 64-node third-order hexahedron
  if (type == 93) return 125;  // 125-node fourth-order hexahedron
  if (type < 0 || type >= static_cast<int>(std::size(kNodes))) return 0;
  return kNodes[type];
}

std::string unsupported_elements(int type, std::uint64_t count) {
  const char* kind = "";
  switch (type) {
    case 3:
      kind = " (4-node quadrangle)";
      break;
    case 5:
      kind = " (8-node hexahedron)";
      break;
    case 6:
      kind = " (6-node prism)";
      break;
    case 7:
      kind = " (5-node pyramid)";
      break;
    case 8:
      kind = " (3-node line)";
      break;
    case 9:
      kind = " (6-node triangle)";
      break;
    case 11:
      kind = " (10-node tetrahedron)";
      break;
    default:
      break;
  }
  return std::to_string(count) + (count == 1 ? " element" : " elements") + " of type " +
         std::to_string(type) + kind +
         ": riemesh reads 2-node lines, 3-node triangles and 4-node tetrahedra only";
}

GmshInput::GmshInput(std::string name, std::string_view bytes)
    : name_(std::move(name)), bytes_(bytes), scanner_(bytes) {}

bool GmshInput::next_token(std::string_view& token) {
  if (!scanner_.next(token)) {
    last_pos_ = bytes_.size();
    return false;
  }
  last_pos_ = scanner_.mark().pos - token.size();
  return true;
}

std::string_view GmshInput::token(const char* what) {
  std::string_view t;
  if (!next_token(t)) fail(std::string("unexpected end of file, expected ") + what);
  return t;
}

void GmshInput::set_binary(int size_bytes, bool swap) {
  binary_ = true;
  size_bytes_ = size_bytes;
  swap_ = swap;
}

void GmshInput::begin_data() {
  if (!binary_) return;
  std::size_t at = scanner_.mark().pos;
  const std::size_t eol = bytes_.find('\n', at);
  pos_ = eol == std::string_view::npos ? bytes_.size() : eol + 1;
  last_pos_ = pos_;
  in_data_ = true;
}

void GmshInput::end_data() {
  if (!binary_) return;
  scanner_.reset({pos_, 1});
  in_data_ = false;
}

void GmshInput::need(std::size_t bytes, const char* what) {
  last_pos_ = pos_;
  if (bytes > bytes_.size() - pos_) fail(std::string("unexpected end of file, expected ") + what);
}

std::string_view GmshInput::value_token(const char* what) {
  std::string_view t = token(what);
  if (!t.empty() && t[0] == '$')
    fail(std::string("expected ") + what + ", got " + medit_detail::quote(t));
  return t;
}

std::int32_t GmshInput::int32(const char* what) {
  if (in_data_) {
    need(4, what);
    return raw<std::int32_t>();
  }
  const std::string_view t = value_token(what);
  std::int64_t v = 0;
  if (!io_detail::parse_int(t, v) || v < std::numeric_limits<std::int32_t>::min() ||
      v > std::numeric_limits<std::int32_t>::max())
    fail(std::string("expected ") + what + " (an integer), got " + medit_detail::quote(t));
  return static_cast<std::int32_t>(v);
}

std::uint64_t GmshInput::size(const char* what) {
  if (in_data_) {
    need(static_cast<std::size_t>(size_bytes_), what);
    if (size_bytes_ == 4) return raw<std::uint32_t>();
    return raw<std::uint64_t>();
  }
  const std::string_view t = value_token(what);
  std::int64_t v = 0;
  if (!io_detail::parse_int(t, v) || v < 0)
    fail(std::string("expected ") + what + " (a non-negative integer), got " +
         medit_detail::quote(t));
  return static_cast<std::uint64_t>(v);
}

double GmshInput::real(const char* what) {
  double v = 0;
  if (in_data_) {
    need(8, what);
    v = raw<double>();
    if (!std::isfinite(v)) fail(std::string("non-finite ") + what);
    return v;
  }
  const std::string_view t = value_token(what);
  if (!io_detail::parse_real(t, v) || !std::isfinite(v))
    fail(std::string("expected ") + what + " (a finite real), got " + medit_detail::quote(t));
  return v;
}

std::int32_t GmshInput::raw_int32() {
  need(4, "the binary byte-order marker");
  return raw<std::int32_t>();
}

void GmshInput::check_room(std::uint64_t n, std::size_t binary_bytes, std::size_t ascii_tokens,
                           const char* what) {
  // An ASCII token takes at least 2 bytes (a character and a separator).
  const std::size_t at = in_data_ ? pos_ : scanner_.mark().pos;
  const std::size_t per = in_data_ ? binary_bytes : 2 * ascii_tokens;
  const std::size_t room = bytes_.size() - std::min(at, bytes_.size()) + 1;
  if (per > 0 && n > room / per)
    fail(std::to_string(n) + " " + what + " cannot fit in the " + std::to_string(room - 1) +
         " bytes left in the file");
}

void GmshInput::skip_section(std::string_view name) {
  std::string end = "$End";
  end += name;
  const std::size_t from = in_data_ ? pos_ : scanner_.mark().pos;
  std::size_t at = bytes_.find(end, from);
  while (at != std::string_view::npos) {
    // The marker must be a whole token (not "$EndNodesX").
    const std::size_t after = at + end.size();
    if (after == bytes_.size() || std::isspace(static_cast<unsigned char>(bytes_[after]))) break;
    at = bytes_.find(end, after);
  }
  if (at == std::string_view::npos) fail("no " + end + " before the end of the file");
  const std::size_t line =
      scanner_.line() +
      static_cast<std::size_t>(std::count(bytes_.begin() + static_cast<std::ptrdiff_t>(from),
                                          bytes_.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
  scanner_.reset({at + end.size(), line});
  in_data_ = false;
}

void GmshInput::expect_end(std::string_view name) {
  std::string end = "$End";
  end += name;
  const std::string_view t = token(end.c_str());
  if (t != end) fail("expected " + end + ", got " + medit_detail::quote(t));
}

std::string GmshInput::where() const {
  if (binary_) return name_ + ": byte " + std::to_string(last_pos_);
  return name_ + ":" + std::to_string(scanner_.line());
}

void GmshInput::fail(const std::string& what) const { medit_detail::fail(where(), section, what); }

// ---- NodeMap ---------------------------------------------------------------------------------

void NodeMap::build(const std::vector<std::uint64_t>& tags, const GmshInput& input) {
  dense_.clear();
  sparse_.clear();
  std::uint64_t max_tag = 0;
  for (std::uint64_t t : tags) max_tag = std::max(max_tag, t);
  auto duplicate = [&](std::uint64_t t) {
    input.fail(t == 0 ? std::string("node tag 0 (tags start at 1)")
                      : "node tag " + std::to_string(t) + " given twice");
  };
  if (max_tag <= 4 * static_cast<std::uint64_t>(tags.size()) + 1024) {
    dense_.assign(static_cast<std::size_t>(max_tag) + 1, kNoId);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      if (tags[i] == 0 || dense_[tags[i]] != kNoId) duplicate(tags[i]);
      dense_[tags[i]] = static_cast<Id>(i);
    }
    return;
  }
  sparse_.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) {
    if (tags[i] == 0) duplicate(0);
    sparse_.emplace_back(tags[i], static_cast<Id>(i));
  }
  std::sort(sparse_.begin(), sparse_.end());
  for (std::size_t i = 1; i < sparse_.size(); ++i)
    if (sparse_[i].first == sparse_[i - 1].first) duplicate(sparse_[i].first);
}

Id NodeMap::find(std::uint64_t tag) const {
  if (!dense_.empty()) return tag < dense_.size() ? dense_[tag] : kNoId;
  const auto it = std::lower_bound(sparse_.begin(), sparse_.end(), std::make_pair(tag, Id{0}));
  return it != sparse_.end() && it->first == tag ? it->second : kNoId;
}

}  // namespace riemesh::gmsh_detail
