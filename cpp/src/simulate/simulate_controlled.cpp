// simulate under a controller (scene/controller.hpp): the generic model's run of simulate_scene.cpp
// (detail::run_generic_scene, compiled there once for every method), its pieces set by the controlled run's hooks,
// which sample the law at the sample times.
#include "rigiddyn/scene/controller.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <cmath>
#include <string>
#include <utility>

namespace rigiddyn {

namespace detail {

void check_controller(const Controller& controller) {
  require_positive(controller.period, "controller.period");
  if (!controller.law) throw std::invalid_argument("controller.law: expected a law to call at each sample, got none");
}

std::vector<AppliedLoad> with_sample_times(std::vector<AppliedLoad> schedule, double period, double t0, double t_end) {
  constexpr double max_samples = 1e8;  // a period far below any step's: a mistaken unit, refused before it fills memory
  const double samples = std::floor((t_end - t0) / period);
  if (samples > max_samples) {
    throw_invalid("controller.period", "a period [s] giving at most 1e8 samples over the run (" + format_value(t_end - t0) +
                                           " s)", period);
  }
  for (std::int64_t k = 1; k <= static_cast<std::int64_t>(samples); ++k) {
    AppliedLoad sample;
    sample.t_start = t0 + static_cast<double>(k) * period;  // t_k, as ControlRun computes it
    schedule.push_back(sample);
  }
  return schedule;
}

}  // namespace detail

SceneSimulation simulate(const CompiledScene& compiled, const std::vector<BodyState>& initial, const SimulationOptions& o,
                         const Controller& controller) {
  detail::check_controller(controller);
  const std::vector<BodyState> states =
      detail::checked_scene_input(compiled.scene(), compiled.method(), initial, o, true, "initial");
  detail::check_masses_over_run(compiled.scene(), o, o.steps);
  const SceneModel& model = compiled.model();
  const Eigen::VectorXd y0 = model.coordinates(states, o.t0);
  const std::vector<AppliedLoad> schedule =
      detail::with_sample_times(compiled.switch_schedule(), controller.period, o.t0, detail::grid_time(o, o.steps));
  std::vector<std::string> element_types;
  for (const Element& element : compiled.scene().elements) element_types.push_back(element_type_name(element));
  detail::ControlRun control(controller, o, y0, std::move(element_types), model.wheel_count());
  return detail::run_generic_scene(model, y0, o, schedule, &control);
}

}  // namespace rigiddyn
