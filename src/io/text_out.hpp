#pragma once
// Buffered text output for the ASCII writers: reals in the shortest form that reads back to the
// same double (std::to_chars), so ASCII round trips are bit-identical like %.17g but shorter.
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>

#include "io/atomic_file.hpp"

namespace riemesh::io_detail {

class TextOut {
 public:
  explicit TextOut(AtomicFile& file) : file_(file) { buffer_.reserve(kChunk + 256); }

  TextOut& text(std::string_view s) {
    buffer_.append(s);
    if (buffer_.size() >= kChunk) flush();
    return *this;
  }
  TextOut& integer(std::int64_t value) {
    char digits[24];
    const auto r = std::to_chars(digits, digits + sizeof digits, value);
    return text(std::string_view(digits, static_cast<std::size_t>(r.ptr - digits)));
  }
  TextOut& real(double value) {
    char digits[32];
    const auto r = std::to_chars(digits, digits + sizeof digits, value);
    return text(std::string_view(digits, static_cast<std::size_t>(r.ptr - digits)));
  }
  void flush() {
    file_.write(buffer_);
    buffer_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 20;
  AtomicFile& file_;
  std::string buffer_;
};

}  // namespace riemesh::io_detail
