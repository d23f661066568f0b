// x 2^e for the exact layer's scaled arithmetic. Private to cpp/src/exact.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

namespace rigiddyn {

// x 2^e, equal to std::ldexp(x, e) (exact, or rounded once where the result is subnormal or
// overflows), by one multiplication when 2^e is a normal double: std::ldexp costs ~60 instructions,
// a multiplication by a power of two is correctly rounded and so gives the same result.
inline double times_pow2(double x, int e) {
  if (e >= -1022 && e <= 1023) {
    const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
    double pow2;
    std::memcpy(&pow2, &bits, sizeof pow2);
    return x * pow2;
  }
  return std::ldexp(x, e);
}

// The exponent of |x| > 0, floor(log2 |x|), equal to std::ilogb(x), read from the bits for normal x.
inline int exponent_of(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  return biased != 0 && biased != 0x7ff ? biased - 1023 : std::ilogb(x);
}

}  // namespace rigiddyn
