#pragma once
// Input layout of fuzz_sol (also used to replay its crashers in tests/io): read_sol needs the
// vertex count and dimension of the mesh, so the fuzz input starts with them.
//   byte 0     bit 0: dimension 3 (else 2); bit 1: binary .solb (else ASCII .sol)
//   bytes 1-4  vertex count, little-endian uint32 (4 raw bytes so that libFuzzer's comparison
//              tracing can copy the count read from the file into it)
//   bytes 5-   the file
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace riemesh::fuzz {

struct SolInput {
  std::string path;  // "fuzz.sol" or "fuzz.solb": picks the format, appears in messages
  int dim = 2;
  std::size_t num_vertices = 0;
  std::string_view bytes;
};

constexpr std::size_t kSolHeader = 5;

/// Splits a fuzz_sol input; false if it is shorter than the header.
inline bool decode_sol_input(const std::uint8_t* data, std::size_t size, SolInput& in) {
  if (size < kSolHeader) return false;
  in.dim = (data[0] & 1) ? 3 : 2;
  in.path = (data[0] & 2) ? "fuzz.solb" : "fuzz.sol";
  in.num_vertices = std::size_t{data[1]} | std::size_t{data[2]} << 8 | std::size_t{data[3]} << 16 |
                    std::size_t{data[4]} << 24;
  in.bytes = std::string_view(reinterpret_cast<const char*>(data) + kSolHeader, size - kSolHeader);
  return true;
}

/// The header for a file of that kind (to build seeds).
inline std::string sol_input_header(int dim, bool binary, std::uint32_t num_vertices) {
  std::string h(kSolHeader, '\0');
  h[0] = static_cast<char>((dim == 3 ? 1 : 0) | (binary ? 2 : 0));
  for (int i = 0; i < 4; ++i) h[1 + i] = static_cast<char>((num_vertices >> (8 * i)) & 0xff);
  return h;
}

}  // namespace riemesh::fuzz
