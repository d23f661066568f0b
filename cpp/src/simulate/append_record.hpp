// Private to cpp/src/simulate: reserving a Trajectory's records and appending one recorded state,
// shared by the stepping loop (simulate.cpp) and the exact method (simulate_exact.cpp) so both
// record the same fields.
#pragma once
#include "rigiddyn/simulate/simulate.hpp"

namespace rigiddyn {

// Reserves the records of a run of `steps` steps recorded every `record_every`-th (recording_bytes);
// throws std::invalid_argument naming record_every when they exceed the memory available.
void reserve_records(Trajectory& out, std::int64_t steps, std::int64_t record_every);

// Append the record r at time t [s] to out: one row of every per-record column of Trajectory
// (p_W, v_W [m, m/s] in W; q_WB as (x, y, z, w); w_B [rad/s] in B; energies [J]; |L| [kg m²/s];
// |q| - 1; work [J]).
inline void append_record(Trajectory& out, double t, const RecordedState& r) {
  out.t.push_back(t);
  out.p_W.insert(out.p_W.end(), r.p_W.data(), r.p_W.data() + 3);
  out.q_WB.insert(out.q_WB.end(), r.q_WB.coeffs().data(), r.q_WB.coeffs().data() + 4);
  out.v_W.insert(out.v_W.end(), r.v_W.data(), r.v_W.data() + 3);
  out.w_B.insert(out.w_B.end(), r.w_B.data(), r.w_B.data() + 3);
  out.kinetic_energy.push_back(r.kinetic_energy);
  out.total_energy.push_back(r.kinetic_energy + r.potential_energy);
  out.angular_momentum_norm.push_back(r.angular_momentum_norm);
  out.quaternion_norm_error.push_back(r.q_WB.norm() - 1.0);
  out.work.push_back(r.work);
}

}  // namespace rigiddyn
