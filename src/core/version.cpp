#include "core/version.hpp"

namespace riemesh {
const char* version() { return "0.1.0"; }
}  // namespace riemesh
