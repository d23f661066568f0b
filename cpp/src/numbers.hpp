// The floating-point constants the library's sources share (C++17 has no <numbers>), defined once: the sources of a
// layer compile as one translation unit (cpp/CMakeLists.txt), where a constant of each file would be defined twice.
#pragma once
#include <limits>

namespace rigiddyn::detail {

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double infinity = std::numeric_limits<double>::infinity();
inline constexpr double epsilon = std::numeric_limits<double>::epsilon();  // 2⁻⁵²
inline constexpr double pi = 3.141592653589793;                            // π rounded to the nearest double
inline constexpr double two_pi = 6.283185307179586;                        // 2π rounded to the nearest double
inline constexpr double ln_4 = 1.3862943611198906;                         // ln 4 rounded to the nearest double

}  // namespace rigiddyn::detail
