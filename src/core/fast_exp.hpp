#pragma once
// e^x inline, for the metric exponentials of the 2D remesher's hottest measures (exp_sym_2d in
// core/spd.hpp: two per triangle quality or Gauss point where the metric turns). libm's exp is a
// call of ~50 instructions; this is ~30, inlined, and its error stays within 2 ulp.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace riemesh {

/// e^x to within 2 ulp of the exact value for |x| <= 700 (tests/core/test_fast_exp.cpp);
/// std::exp beyond (overflow, underflow to subnormals, NaN). x = k ln 2 + r with k the nearest
/// integer to x / ln 2 (rounded by adding 1.5·2^52), r by Cody and Waite's two-part ln 2 (its
/// high part has 21 trailing zero bits, so k·ln2_hi is exact), |r| <= 0.347; e^r by its Taylor
/// series to degree 13 (next term below 5e-18 relative), evaluated in Estrin's scheme; then 2^k
/// is put in the exponent bits. Deterministic: plain double operations in a fixed order.
inline double fast_exp(double x) {
  if (!(std::abs(x) <= 700.0)) return std::exp(x);
  constexpr double kLog2e = 1.4426950408889634, kRound = 0x1.8p52;
  constexpr double kLn2Hi = 6.93147180369123816490e-01, kLn2Lo = 1.90821492927058770002e-10;
  const double k = (x * kLog2e + kRound) - kRound;
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  constexpr double c2 = 1.0 / 2, c3 = 1.0 / 6, c4 = 1.0 / 24, c5 = 1.0 / 120, c6 = 1.0 / 720,
                   c7 = 1.0 / 5040, c8 = 1.0 / 40320, c9 = 1.0 / 362880, c10 = 1.0 / 3628800,
                   c11 = 1.0 / 39916800, c12 = 1.0 / 479001600, c13 = 1.0 / 6227020800;
  const double r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
  const double low = (c2 + r * c3) + r2 * (c4 + r * c5);
  const double mid = (c6 + r * c7) + r2 * (c8 + r * c9);
  const double high = (c10 + r * c11) + r2 * (c12 + r * c13);
  const double p = 1.0 + (r + r2 * (low + r4 * mid + r8 * high));
  const std::uint64_t bits = static_cast<std::uint64_t>(static_cast<std::int64_t>(k) + 1023) << 52;
  double scale;
  std::memcpy(&scale, &bits, sizeof scale);
  return p * scale;
}

}  // namespace riemesh
