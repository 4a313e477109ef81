#pragma once
// Numbers in messages: the shortest "%g" form (1e-06, 0.5, 1e+100), as the errors quote values.
#include <cstdio>
#include <string>

namespace riemesh {

inline std::string format_g(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

}  // namespace riemesh
