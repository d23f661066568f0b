#include "rigiddyn/so3/quaternion.hpp"

#include "rigiddyn/check.hpp"

#include <cmath>

namespace rigiddyn {

namespace {
// the coefficients in the Python default order (x, y, z, w), for error messages
Eigen::Vector4d xyzw(const Eigen::Quaterniond& q) { return q.coeffs(); }

// "(x, y, z, w) = [...] with |q| = ..."
std::string describe(const Eigen::Quaterniond& q) {
  return "(x, y, z, w) = " + format_value(xyzw(q).transpose()) + " with |q| = " + format_value(q.norm());
}
}  // namespace

void throw_not_unit_quaternion(const Eigen::Quaterniond& q, const std::string& name) {
  if (!q.coeffs().allFinite()) throw_invalid(name, "a quaternion of finite numbers", describe(q));
  throw_invalid(name, "a unit quaternion (| |q| - 1 | <= 1e-6; normalise it first, e.g. with quat_normalize)",
                describe(q));
}

Eigen::Quaterniond quat_normalize(const Eigen::Quaterniond& q, const std::string& name) {
  if (!q.coeffs().allFinite()) throw_invalid(name, "a quaternion of finite numbers", describe(q));
  const double norm = q.norm();
  if (!(norm > 0.0)) throw_invalid(name, "a non-zero quaternion", describe(q));
  return Eigen::Quaterniond(q.coeffs() / norm);
}

}  // namespace rigiddyn
