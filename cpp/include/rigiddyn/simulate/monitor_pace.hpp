// When a run calls SimulationOptions::monitor (simulate/simulate.hpp): about every monitor_period_seconds
// of wall time, whatever a step costs (a one-body step of ~0.1 µs, a scene of many bodies of ~1 ms, a
// Python force of any time), so that Ctrl-C and a stop request are answered as fast for an expensive step
// as for a cheap one. The stepping loops (run_loop.hpp, simulate/closed_form.cpp, batch/simd_rigid_body.cpp) count
// steps between two calls; MonitorPace adapts that count to the wall time the steps took, one clock read
// before and one after each call, never per step.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>

namespace rigiddyn {

// Wall time between two calls of SimulationOptions::monitor [s]: long beside a clock read (~20 ns, two per
// call), short beside the 0.05 s in which Python's monitor answers Ctrl-C (cpp/bindings/python_run.hpp).
inline constexpr double monitor_period_seconds = 0.01;

// The count of steps between two monitor calls. It starts at one step (the first call comes after the
// first step: a step of any cost is never run twice before one), doubles while the steps of an interval
// take less than half the period and shrinks in proportion when they take more than the period, so that
// the calls settle between half the period and the period apart; a step slower than the period gets a
// call after each step. Bounded by max_interval (no overflow however cheap a step).
class MonitorPace {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::int64_t max_interval = std::int64_t{1} << 30;

  // Steps from the last call (or the start) to the next one, >= 1.
  std::int64_t interval() const { return interval_; }

  // At the end of an interval: adapts it to the wall time its steps took, then returns monitor(steps_done)
  // (the time of the call itself, a Python callback or a wait for the GIL, is not counted as the steps').
  template <class Monitor>
  bool check(const Monitor& monitor, std::int64_t steps_done) {
    adapt(std::chrono::duration<double>(Clock::now() - lap_start_).count());
    const bool stop = monitor(steps_done);
    lap_start_ = Clock::now();
    return stop;
  }

 private:
  void adapt(double seconds) {
    if (seconds < 0.5 * monitor_period_seconds) {
      interval_ = std::min(2 * interval_, max_interval);
    } else if (seconds > monitor_period_seconds) {
      const double shrunk = static_cast<double>(interval_) * (monitor_period_seconds / seconds);  // < interval_
      interval_ = std::max<std::int64_t>(1, static_cast<std::int64_t>(shrunk));
    }
  }

  Clock::time_point lap_start_ = Clock::now();
  std::int64_t interval_ = 1;
};

}  // namespace rigiddyn
