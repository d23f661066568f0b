// simulate_batch (batch/simulate_batch.hpp) when a sample fails with anything but its own error: the first such
// failure stops every sample at its next check (about monitor_period_seconds later) and comes out as
// SampleFailure, naming the sample and carrying the exception itself.
#include <gtest/gtest.h>

#include "rigiddyn/batch/simulate_batch.hpp"
#include "rigiddyn/scene/compile.hpp"

#include <atomic>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

// Not one of the standard types of a sample's own error: a user function's failure.
struct Boom : std::exception {
  const char* what() const noexcept override { return "boom"; }
};

// One particle pushed by `f` (a FunctionForce), compiled for RK4 (4 calls of f a step).
CompiledScene pushed_particle(ForceFunction f) {
  Scene scene;
  scene.bodies = {Particle(1.0)};
  FunctionForce push;
  push.f = std::move(f);
  scene.elements = {push};
  return compile_scene(scene, Method::rk4);
}

TEST(BatchFailure, AFunctionsExceptionStopsEverySampleAndNamesItsSample) {
  constexpr std::int64_t steps = 10000000, samples = 4, calls_per_step = 4;
  std::atomic<std::int64_t> calls{0};
  const CompiledScene scene = pushed_particle([&calls](double, const BodyKinematics&, int, Eigen::Vector3d& f_W,
                                                       Eigen::Vector3d&) {
    if (++calls == 1000) throw Boom();
    f_W = Eigen::Vector3d(0.0, 0.0, 1.0);
  });
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = 1e-6;
  o.steps = steps;
  o.record_every = steps;
  const std::vector<std::vector<BodyState>> initial(samples, std::vector<BodyState>{ParticleState{}});
  try {
    simulate_batch({scene}, initial, o, {}, 2);
    FAIL() << "no exception";
  } catch (const SampleFailure& failure) {
    EXPECT_LT(failure.sample(), static_cast<std::size_t>(samples));
    EXPECT_EQ(std::string(failure.what()), "sample " + std::to_string(failure.sample()) + ": boom");
    EXPECT_THROW(std::rethrow_exception(failure.cause()), Boom);
  }
  // every sample run to its end would make samples * steps * 4 = 1.6e8 calls; stopped, the other thread's sample
  // makes at most the calls of its steps in a pace interval (about 0.01 s: ~1e5 steps at ~0.1 us each): a tenth
  // of the whole leaves room for a thread slowed 20-fold
  EXPECT_LT(calls.load(), samples * steps * calls_per_step / 10);
}

TEST(BatchFailure, ASamplesOwnErrorStillLetsTheOthersRunAndNamesTheLowest) {
  // std::runtime_error itself: the sample's own error; every sample runs, the lowest failing one is named
  const CompiledScene scene = pushed_particle([](double t, const BodyKinematics& body, int, Eigen::Vector3d&,
                                                 Eigen::Vector3d&) {
    if (body.p_W.x() >= 2.0 && t > 0.0) throw std::runtime_error("far");
  });
  SimulationOptions o;
  o.method = Method::rk4;
  o.dt = 1e-3;
  o.steps = 10;
  std::vector<std::vector<BodyState>> initial;
  for (int i = 0; i < 5; ++i) {
    ParticleState s;
    s.p_W = Eigen::Vector3d(i, 0.0, 0.0);
    initial.push_back({s});
  }
  for (int threads : {1, 2, 3}) {
    try {
      simulate_batch({scene}, initial, o, {}, threads);
      FAIL() << "no exception";
    } catch (const SampleFailure&) {
      FAIL() << "a sample's own error stopped the batch";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "sample 2: far");
    }
  }
}

}  // namespace
}  // namespace rigiddyn
