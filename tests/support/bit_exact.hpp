#pragma once
// Helpers of the bit-exact round-trip tests (export_serialize, trim_serialize): doubles a lossy
// encoding would change, and an equality that compares bits, not values (NaN == NaN, −0 ≠ +0).
#include <cstdint>
#include <cstring>
#include <limits>

namespace whirl::test {

/// The i-th of eight doubles whose bits a lossy encoding would change: NaN with a payload and sign,
/// −0, denormals, infinity, values without a short decimal form, a float's value, the extremes.
inline double trickyDouble(int i) {
  const std::uint64_t nan_bits = 0xfff8'0000'dead'beefULL;
  double nan;
  std::memcpy(&nan, &nan_bits, sizeof nan);
  const double v[] = {0.1 * i - 1,
                      -0.0,
                      std::numeric_limits<double>::denorm_min() * (i + 1),
                      nan,
                      std::numeric_limits<double>::infinity(),
                      1.0 / 3 + i,
                      0.5f,
                      -1e300 * i};
  return v[i % 8];
}

/// True when `a` and `b` have the same bits.
inline bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace whirl::test
