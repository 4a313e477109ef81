#include "io/meshb_stream.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"
#include "io/medit_detail.hpp"

namespace riemesh::medit_detail {

MeshbReader::MeshbReader(const std::string& path, std::string_view bytes)
    : path_(path), bytes_(bytes) {
  if (bytes_.size() < 8) fail_at(0, "file too short for a .meshb/.solb header");
  const std::int32_t marker = raw<std::int32_t>();
  if (marker == 0x01000000) {
    swap_ = true;
  } else if (marker != 1) {
    fail_at(0, "bad endianness marker " + std::to_string(marker) + " (not a binary Medit file?)");
  }
  const std::int32_t version = raw<std::int32_t>();
  if (version < 1 || version > 4) fail_at(4, "unknown file version " + std::to_string(version));
  version_ = version;
}

void MeshbReader::fail_at(std::size_t offset, const std::string& what) const {
  fail(where(offset), code_ ? keyword() : std::string(), what);
}

std::string MeshbReader::keyword() const {
  const std::string name = keyword_name(code_);
  return name == "keyword" ? "keyword " + std::to_string(code_) : name;
}

void MeshbReader::need(std::size_t bytes) {
  if (bytes > bytes_.size() - pos_)
    fail_at(pos_, "file truncated (" + std::to_string(bytes) + " bytes needed, " +
                      std::to_string(bytes_.size() - pos_) + " left)");
}

bool MeshbReader::next_keyword(int& code) {
  while (!stop_ && pos_ < bytes_.size()) {
    keyword_pos_ = pos_;
    code_ = 0;
    const std::size_t position_size = version_ >= 3 ? 8 : 4;
    need(4 + position_size);
    code_ = raw<std::int32_t>();
    next_ = version_ >= 3 ? raw<std::uint64_t>() : raw<std::uint32_t>();
    // Positions only go forward: this also rules out loops in a corrupt file.
    if (next_ != 0 && (next_ <= keyword_pos_ || next_ > bytes_.size()))
      fail_at(keyword_pos_ + 4, "next keyword position " + std::to_string(next_) +
                                    " outside the file (" + std::to_string(bytes_.size()) +
                                    " bytes)");
    if (code_ == kEnd) return false;
    if (code_ == kDimension) {
      need(4);
      const std::int32_t d = raw<std::int32_t>();
      if (d != 2 && d != 3)
        fail_at(pos_ - 4, "dimension " + std::to_string(d) + " (2 or 3 expected)");
      // Sections already read used the first dimension: a file has one.
      if (dim_ != 0 && d != dim_)
        fail_at(pos_ - 4,
                "dimension " + std::to_string(d) + " after dimension " + std::to_string(dim_));
      dim_ = d;
      end_keyword(true);
      continue;
    }
    code = code_;
    return true;
  }
  return false;
}

void MeshbReader::end_keyword(bool data_read) {
  if (next_ == 0) {
    // Without a next position, only a keyword whose data was read tells where the next starts.
    if (!data_read) stop_ = true;
    return;
  }
  if (data_read && pos_ > next_)
    fail_at(keyword_pos_, "data runs past the next keyword at byte " + std::to_string(next_));
  pos_ = static_cast<std::size_t>(next_);
}

int MeshbReader::require_dim() {
  if (dim_ == 0) fail_at(keyword_pos_, "no Dimension keyword before this section");
  return dim_;
}

std::size_t MeshbReader::count(std::size_t entry_bytes) {
  const std::size_t at = pos_;
  need(static_cast<std::size_t>(int_size()));
  const std::int64_t n = version_ >= 4 ? raw<std::int64_t>() : raw<std::int32_t>();
  if (n < 0) fail_at(at, "negative count " + std::to_string(n));
  count_pos_ = at;
  check_room(static_cast<std::size_t>(n), entry_bytes);
  return static_cast<std::size_t>(n);
}

void MeshbReader::check_room(std::size_t n, std::size_t entry_bytes) {
  const std::size_t left = bytes_.size() - pos_;
  if (entry_bytes > 0 && n > left / entry_bytes)
    fail_at(count_pos_, "count " + std::to_string(n) + " needs more bytes than the " +
                            std::to_string(left) + " left in the file");
}

std::int32_t MeshbReader::i32() {
  need(4);
  return raw<std::int32_t>();
}

std::int64_t MeshbReader::integer() {
  need(static_cast<std::size_t>(int_size()));
  return version_ >= 4 ? raw<std::int64_t>() : raw<std::int32_t>();
}

std::int32_t MeshbReader::id() {
  const std::size_t at = pos_;
  const std::int64_t v = integer();
  if (v < 1 || v > std::numeric_limits<std::int32_t>::max())
    fail_at(at, "id " + std::to_string(v) + " out of range (ids start at 1)");
  return static_cast<std::int32_t>(v - 1);
}

std::int32_t MeshbReader::ref() {
  const std::size_t at = pos_;
  const std::int64_t v = integer();
  if (v < std::numeric_limits<std::int32_t>::min() || v > std::numeric_limits<std::int32_t>::max())
    fail_at(at, "reference " + std::to_string(v) + " does not fit in 32 bits");
  return static_cast<std::int32_t>(v);
}

double MeshbReader::real() {
  const std::size_t at = pos_;
  need(static_cast<std::size_t>(real_size()));
  const double v = version_ == 1 ? static_cast<double>(raw<float>()) : raw<double>();
  if (!std::isfinite(v)) fail_at(at, "non-finite value");
  return v;
}

MeshbWriter::MeshbWriter(int version, int dim, std::size_t expected_bytes) : version_(version) {
  bytes_.reserve(expected_bytes);
  put(std::int32_t{1});
  put(std::int32_t{version});
  keyword(kDimension, -1);
  put(std::int32_t{dim});
}

void MeshbWriter::put_position(std::uint64_t value) {
  if (version_ >= 3)
    put(value);
  else
    put(static_cast<std::uint32_t>(value));
}

void MeshbWriter::keyword(int code, std::int64_t count) {
  const std::uint64_t here = bytes_.size();
  if (next_slot_ != 0) {
    if (version_ >= 3) {
      std::memcpy(bytes_.data() + next_slot_, &here, 8);
    } else {
      const auto here32 = static_cast<std::uint32_t>(here);
      std::memcpy(bytes_.data() + next_slot_, &here32, 4);
    }
  }
  put(std::int32_t{code});
  next_slot_ = bytes_.size();
  put_position(0);
  if (count >= 0) integer(count);
}

const std::string& MeshbWriter::finish() {
  keyword(kEnd, -1);
  return bytes_;
}

int choose_meshb_version(int requested, std::uint64_t estimated_bytes, std::uint64_t max_count,
                         const std::string& path) {
  constexpr std::uint64_t kMax32 = std::numeric_limits<std::int32_t>::max();
  if (requested == 0) return max_count > kMax32 ? 4 : estimated_bytes > kMax32 ? 3 : 2;
  if (requested < 1 || requested > 4)
    throw Error(path + ": unknown .meshb version " + std::to_string(requested));
  if (requested < 4 && max_count > kMax32)
    throw Error(path + ": ids or counts over 2^31 need .meshb version 4");
  if (requested < 3 && estimated_bytes > kMax32)
    throw Error(path + ": a file over 2 GB needs .meshb version 3 or 4");
  return requested;
}

}  // namespace riemesh::medit_detail
