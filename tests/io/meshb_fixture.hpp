#pragma once
// An encoder of libMeshb binary files written for the tests only, from the layout in
// libmeshb7.c (GmfOpenMesh, GmfSetKwd), independent of src/io: any file version, either byte
// order. Codes are spelled out as numbers on purpose (libmeshb7.h, enum GmfKwdCod).
#include <cstdint>
#include <cstring>
#include <string>

namespace riemesh::test {

class MeshbFixture {
 public:
  MeshbFixture(int version, bool swapped, int dim) : version_(version), swapped_(swapped) {
    put<std::int32_t>(1);
    put<std::int32_t>(version);
    keyword(3);  // GmfDimension: no count
    put<std::int32_t>(dim);
  }
  /// Starts a keyword; count < 0 for none.
  MeshbFixture& keyword(int code, std::int64_t count = -1) {
    patch_next(bytes_.size());
    put<std::int32_t>(code);
    slot_ = bytes_.size();
    if (version_ >= 3)
      put<std::int64_t>(0);
    else
      put<std::int32_t>(0);
    if (count >= 0) integer(count);
    return *this;
  }
  MeshbFixture& integer(std::int64_t v) {
    if (version_ >= 4)
      put<std::int64_t>(v);
    else
      put<std::int32_t>(static_cast<std::int32_t>(v));
    return *this;
  }
  MeshbFixture& i32(std::int32_t v) {
    put(v);
    return *this;
  }
  MeshbFixture& real(double v) {
    if (version_ == 1)
      put<float>(static_cast<float>(v));
    else
      put<double>(v);
    return *this;
  }
  std::string finish() {
    keyword(54);  // GmfEnd, next position 0
    return bytes_;
  }
  /// The bytes so far, without End (the last keyword has next position 0).
  const std::string& bytes() const { return bytes_; }

 private:
  template <class T>
  void put(T v) {
    put_at(bytes_.size(), v);
  }
  template <class T>
  void put_at(std::size_t at, T v) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (swapped_)
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    if (bytes_.size() < at + sizeof(T)) bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, b, sizeof(T));
  }
  void patch_next(std::size_t here) {
    if (slot_ == 0) return;
    if (version_ >= 3)
      put_at<std::int64_t>(slot_, static_cast<std::int64_t>(here));
    else
      put_at<std::int32_t>(slot_, static_cast<std::int32_t>(here));
  }

  int version_;
  bool swapped_;
  std::string bytes_;
  std::size_t slot_ = 0;
};

}  // namespace riemesh::test
