// Private to cpp/src/simulate: reserving a Trajectory's records and appending one recorded state,
// shared by the stepping loop (simulate.cpp) and the exact method (simulate_exact.cpp) so both
// record the same fields.
#pragma once
#include "rigiddyn/simulate/run_loop.hpp"
#include "rigiddyn/simulate/simulate.hpp"

namespace rigiddyn {

// Throws std::invalid_argument naming the argument for dt <= 0, non-finite t0 or gravity, a bad load,
// and (stepping: simulate, not step) steps < 0 or record_every < 1.
void check_options(const SimulationOptions& o, bool stepping);

// Throws std::invalid_argument naming record_every when a recording of `bytes` [B] (steps recorded every
// record_every-th) exceeds the memory available.
void check_recording_fits(double bytes, std::int64_t steps, std::int64_t record_every);

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

// The record of a one-body model's coordinates y at time t [s] (the stepping loop's hook, run_loop.hpp).
template <class Model>
void append_state(Trajectory& out, double t, const Model& model, const typename Model::Coordinates& y) {
  append_record(out, t, model.record(y));
}

// simulate's run of a rigid body of mass [kg] with the Euler form `euler` from y, under the loads and
// gravity of o (every method, every LoadKind), instantiated per Euler form in simulate.cpp and
// simulate_rigid_full.cpp (built in parallel; run_rigid_body.hpp).
template <class Euler>
Trajectory run_rigid_body(double mass, const Euler& euler, const RigidBodyCoordinates& y, const SimulationOptions& o);
extern template Trajectory run_rigid_body(double, const SphericalEuler&, const RigidBodyCoordinates&, const SimulationOptions&);
extern template Trajectory run_rigid_body(double, const PrincipalEuler&, const RigidBodyCoordinates&, const SimulationOptions&);
extern template Trajectory run_rigid_body(double, const FullEuler&, const RigidBodyCoordinates&, const SimulationOptions&);

// Today's one-body run of Integrator: the loads of options.loads (run_loop.hpp), records into a Trajectory.
template <class Integrator, class Model>
Trajectory run_one_body(const Model& model, const typename Model::Coordinates& y, const SimulationOptions& o) {
  Trajectory out;
  reserve_records(out, o.steps, o.record_every);
  return detail::run<Integrator>(model, y, o, detail::OneBodySchedule{o.loads}, std::move(out));
}

}  // namespace rigiddyn
