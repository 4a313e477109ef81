#pragma once
// Byte-level reading and writing of libMeshb binary files (.meshb, .solb).
//
// Layout (libmeshb7.c, GmfOpenMesh / GmfSetKwd / ScaKwdTab): int32 endianness marker 1, int32
// file version, then keywords: int32 code, position of the next keyword (int32 for versions 1-2,
// int64 from 3), a count for keywords that have one (int32, int64 from version 4), then the
// data. Reals are float in version 1 and double after; ints are int32 up to version 3 and
// int64 in version 4. The Dimension keyword has no count and one int32; End closes the file
// with next position 0. A reversed marker means the whole file is byte-swapped.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "io/byte_order.hpp"

namespace riemesh::medit_detail {

class MeshbReader {
 public:
  MeshbReader(const std::string& path, std::string_view bytes);

  int version() const { return version_; }
  /// 0 until a Dimension keyword has been read.
  int dim() const { return dim_; }
  int int_size() const { return version_ >= 4 ? 8 : 4; }
  int real_size() const { return version_ == 1 ? 4 : 8; }

  /// Moves to the next keyword other than Dimension (read on the way). False at End, at the
  /// end of the file, or after a keyword the caller skipped that gives no next position.
  bool next_keyword(int& code);
  /// Leaves the current keyword: checks its data stayed within it and jumps to the next one.
  void end_keyword(bool data_read);
  int code() const { return code_; }
  /// The name of the current keyword, for messages.
  std::string keyword() const;
  int require_dim();

  /// Reads a count of entries of entry_bytes each; fails if negative or beyond the file end.
  std::size_t count(std::size_t entry_bytes);
  /// Fails unless n entries of entry_bytes bytes fit in the rest of the file.
  void check_room(std::size_t n, std::size_t entry_bytes);
  std::int32_t i32();
  std::int64_t integer();
  /// A 1-based id, returned 0-based (upper bound checked later).
  std::int32_t id();
  std::int32_t ref();
  double real();

  std::size_t offset() const { return pos_; }
  std::string where(std::size_t offset) const { return path_ + ": byte " + std::to_string(offset); }
  [[noreturn]] void fail_at(std::size_t offset, const std::string& what) const;

 private:
  void need(std::size_t bytes);
  template <class T>
  T raw() {
    const T value = io_detail::load_value<T>(bytes_.data() + pos_, swap_);
    pos_ += sizeof(T);
    return value;
  }

  std::string path_;
  std::string_view bytes_;
  std::size_t pos_ = 0;
  bool swap_ = false;
  int version_ = 0;
  int dim_ = 0;
  int code_ = 0;
  std::size_t keyword_pos_ = 0;
  std::size_t count_pos_ = 0;
  std::uint64_t next_ = 0;
  bool stop_ = false;
};

class MeshbWriter {
 public:
  MeshbWriter(int version, int dim, std::size_t expected_bytes = 0);
  /// Starts a keyword; count < 0 for keywords without a count.
  void keyword(int code, std::int64_t count);
  void i32(std::int32_t value) { put(value); }
  void integer(std::int64_t value) {
    if (version_ >= 4)
      put(value);
    else
      put(static_cast<std::int32_t>(value));
  }
  void real(double value) {
    if (version_ == 1)
      put(static_cast<float>(value));
    else
      put(value);
  }
  /// Writes End and returns the file contents.
  const std::string& finish();

 private:
  template <class T>
  void put(T value) {
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  void put_position(std::uint64_t value);

  int version_;
  std::string bytes_;
  std::size_t next_slot_ = 0;  // where the previous keyword's next position goes; 0 = none
};

/// The file version to write: the requested one, or 2 / 3 (file over 2 GB) / 4 (ids or counts
/// over 2^31) when `requested` is 0. Throws Error if a requested version cannot hold the data.
int choose_meshb_version(int requested, std::uint64_t estimated_bytes, std::uint64_t max_count,
                         const std::string& path);

}  // namespace riemesh::medit_detail
