#pragma once
namespace riemesh {
/// The library's version, "major.minor.patch".
const char* version();
}  // namespace riemesh
