// The records of a run of one body as the global error estimate reads them (ErrorRecords, simulate/global_error.hpp),
// built record by record for the estimate's tests: the attitude and the position given, every other quantity the
// same in every run (ω, v zero, the energy 1 J, |L| zero).
#pragma once
#include "rigiddyn/simulate/global_error.hpp"

#include <array>
#include <vector>

namespace rigiddyn::test {

class OneBodyErrorRecords {
 public:
  // records 4 dt apart (the common records of a run at dt recording every 4th step)
  explicit OneBodyErrorRecords(double dt) : dt_(dt) {}

  // Appends a record whose attitude is q (x, y, z, w; any norm) and position p_W [m].
  void push_back(const std::array<double, 4>& q, const std::array<double, 3>& p_W) {
    t_.push_back(4.0 * dt_ * static_cast<double>(t_.size()));
    q_.insert(q_.end(), q.begin(), q.end());
    p_.insert(p_.end(), p_W.begin(), p_W.end());
    for (int k = 0; k < 3; ++k) w_.push_back(0.0), v_.push_back(0.0);
    energy_.push_back(1.0), kinetic_.push_back(1.0);
  }

  // The records pushed so far (their columns' pointers valid while this object lives and grows no more).
  ErrorRecords records() const {
    ErrorRecords r;
    r.n = t_.size(), r.bodies = 1, r.t = t_.data(), r.q_WB = q_.data();
    r.w_B = w_.data(), r.p_W = p_.data(), r.v_W = v_.data();
    r.energy = energy_.data(), r.energy_scale = kinetic_.data();
    r.momentum.assign(r.n, 0.0);
    return r;
  }

 private:
  double dt_;
  std::vector<double> t_, q_, w_, p_, v_, energy_, kinetic_;
};

}  // namespace rigiddyn::test
