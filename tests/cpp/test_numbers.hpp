// The floating-point constants the C++ tests state their error bounds in, defined once: the tests compile as a few
// translation units (tests/CMakeLists.txt), whose files share their anonymous namespaces.
#pragma once
#include <limits>

namespace rigiddyn::test {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();  // unit round-off ×2: 2.2e-16
inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace rigiddyn::test
