#pragma once
// Reading a trivially copyable value from unaligned bytes, byte-swapped when the file's byte
// order differs from the machine's (Medit .meshb and Gmsh binary .msh).
#include <cstring>
#include <type_traits>
#include <utility>

namespace riemesh::io_detail {

template <class T>
T load_value(const char* p, bool swap) {
  static_assert(std::is_trivially_copyable_v<T>);
  T value;
  std::memcpy(&value, p, sizeof(T));
  if (swap) {
    unsigned char* b = reinterpret_cast<unsigned char*>(&value);
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  }
  return value;
}

}  // namespace riemesh::io_detail
