#include "rigiddyn/so3/slerp.hpp"

#include "rigiddyn/check.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace rigiddyn {

KeyedSlerp::KeyedSlerp(std::vector<double> times, std::vector<Eigen::Quaterniond> q)
    : times_(std::move(times)), q_(std::move(q)) {
  if (times_.size() < 2) throw_invalid("times", "at least 2 key times", times_.size());
  if (q_.size() != times_.size()) {
    throw_invalid("q", std::to_string(times_.size()) + " key rotations (one per key time)", q_.size());
  }
  for (size_t k = 0; k < times_.size(); ++k) {
    require_finite(times_[k], "times");
    if (k > 0 && !(times_[k] > times_[k - 1])) {
      throw_invalid("times", "strictly increasing key times",
                    "times[" + std::to_string(k - 1) + "] = " + format_value(times_[k - 1]) + " >= times[" +
                        std::to_string(k) + "] = " + format_value(times_[k]));
    }
  }
  rotvec_.reserve(q_.size() - 1);
  for (size_t k = 0; k + 1 < q_.size(); ++k) rotvec_.push_back(quat_to_rotvec(q_[k].conjugate() * q_[k + 1]));
}

Eigen::Quaterniond KeyedSlerp::operator()(double t, const char* name) const {
  if (!(t >= times_.front() && t <= times_.back())) {
    throw_invalid(name, "times within the key times [" + format_value(times_.front()) + ", " +
                            format_value(times_.back()) + "]",
                  t);
  }
  // the segment [times[k], times[k+1]] with times[k] < t <= times[k+1] (k = 0 at t = times[0])
  const auto after = std::lower_bound(times_.begin(), times_.end(), t);
  const size_t k = after == times_.begin() ? 0 : static_cast<size_t>(after - times_.begin()) - 1;
  const double alpha = (t - times_[k]) / (times_[k + 1] - times_[k]);
  return q_[k] * rotvec_to_quat(alpha * rotvec_[k]);
}

}  // namespace rigiddyn
