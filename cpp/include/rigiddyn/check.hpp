// Input validation shared by every layer: throw std::invalid_argument with a message of the form
// "<name>: expected <what>, got <value>" (the bindings turn it into Python's ValueError).
#pragma once
#include <Eigen/Core>

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace rigiddyn {

// Formats a value for an error message (full precision, Eigen matrices on one line).
template <typename T>
std::string format_value(const T& value) {
  std::ostringstream out;
  out.precision(17);
  if constexpr (std::is_base_of_v<Eigen::DenseBase<T>, T>) {
    out << value.format(Eigen::IOFormat(Eigen::FullPrecision, Eigen::DontAlignCols, ", ", "; ", "", "", "[", "]"));
  } else {
    out << value;
  }
  return out.str();
}

// Throws std::invalid_argument("<name>: expected <expected>, got <value>").
template <typename T>
[[noreturn]] void throw_invalid(const std::string& name, const std::string& expected, const T& got) {
  throw std::invalid_argument(name + ": expected " + expected + ", got " + format_value(got));
}

// Every entry of `value` is finite, else std::invalid_argument naming `name`.
template <typename Derived>
void require_finite(const Eigen::DenseBase<Derived>& value, const std::string& name) {
  if (!value.allFinite()) throw_invalid(name, "finite values", value.derived().eval());
}

// A finite scalar.
inline void require_finite(double value, const std::string& name) {
  if (!std::isfinite(value)) throw_invalid(name, "a finite number", value);
}

// A finite scalar > 0.
inline void require_positive(double value, const std::string& name) {
  if (!(std::isfinite(value) && value > 0.0)) throw_invalid(name, "a finite number > 0", value);
}

}  // namespace rigiddyn
