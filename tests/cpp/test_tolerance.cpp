// run_to_tolerance and its error model (simulate/tolerance.hpp): ε(t) ≈ C dt^p (t − t0) fitted, inverted and
// refined; measures by name; a free body run to a tolerance against the closed form (the method 'exact').
#include <gtest/gtest.h>

#include "rigiddyn/simulate/tolerance.hpp"
#include "rigiddyn/so3/angular_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rigiddyn {
namespace {

// The runs of a free body I = (1, 2, 3) kg m² from rest at W's origin turning at w_B, as run_to_tolerance asks for
// them: each by its candidate's method with the options given, told first to `log` (what a test keeps of each run).
struct FreeBodyRuns {
  RigidBody body{1.0, Eigen::Vector3d(1.0, 2.0, 3.0)};
  RigidBodyState initial;

  explicit FreeBodyRuns(const Eigen::Vector3d& w_B) { initial.w_B = w_B; }

  template <class Log>
  auto logged(Log log) const {
    return [this, log](const ToleranceCandidate& c, const SimulationOptions& o) {
      log(c, o);
      SimulationOptions x = o;
      x.method = c.method;
      return simulate(body, initial, x);
    };
  }
  auto plain() const {
    return logged([](const ToleranceCandidate&, const SimulationOptions&) {});
  }
};

TEST(ToleranceModel, StepForErrorInvertsPredictedError) {
  const double C = 3.7, T = 20.0, target = 1e-6;
  for (const int p : {1, 2, 4}) {
    const double dt = step_for_error(C, p, T, target);
    EXPECT_NEAR(predicted_error(C, p, dt, T), target, 1e-12 * target);  // a power and its root: round-off only
  }
  EXPECT_EQ(step_for_error(0.0, 4, T, target), std::numeric_limits<double>::infinity());  // no error: any step
}

TEST(ToleranceModel, StepsAreTheFewestMultipleWithinTheStep) {
  EXPECT_EQ(steps_for(10.0, 0.1, 4), 100);  // exactly 100 steps of 0.1 s (no extra block for the round-off of 10/0.1)
  EXPECT_EQ(steps_for(10.0, 0.099, 4), 104);
  EXPECT_EQ(steps_for(10.0, 0.099, 12), 108);
  EXPECT_EQ(steps_for(10.0, std::numeric_limits<double>::infinity(), 4), 4);  // at least one block
}

TEST(ToleranceModel, AGridMakesEveryStepADivisorOfItsBlock) {
  EXPECT_EQ(on_grid(4, 0), 4);  // no grid
  EXPECT_EQ(on_grid(4, 6), 12);
  EXPECT_EQ(on_grid(8, 40), 40);
  // 30 s in blocks of 0.25 s (120 of them): at most 0.1 s is 0.25 / 3; at most 0.3 s is the block itself
  EXPECT_DOUBLE_EQ(step_on_grid(0.1, 30.0, 120), 0.25 / 3.0);
  EXPECT_DOUBLE_EQ(step_on_grid(0.3, 30.0, 120), 0.25);
  EXPECT_DOUBLE_EQ(step_on_grid(0.125, 30.0, 120), 0.125);  // a divisor itself (no extra division for round-off)
  EXPECT_DOUBLE_EQ(step_on_grid(0.1, 30.0, 0), 0.1);
  EXPECT_EQ(steps_for(30.0, 0.1, on_grid(4, 120)), 360);  // the fewest multiple of 120 within 0.1 s: dt = 0.25 / 3
}

// A certificate 100x its prediction over 100 s at τ = 1e-3 (target 5e-4): scaled alike (C f = 1e-4), an order-2
// candidate needs dt = 0.05^(1/2) = 0.224 s, 448 steps at 2e-6 s a step (9.0e-4 s); an order-4 one dt = 0.05^(1/4) =
// 0.473 s (within its pilot's 0.5 s), 212 steps at 3e-6 s (6.4e-4 s): the cheapest, where the chosen one's own
// refinement would take 2 000 steps at 1e-6 s (2e-3 s). At most the step of the run refined, 0.2 s (500 steps): the
// order-2 one (500 steps at 2e-6 s, 1e-3 s) is then the cheapest.
TEST(ToleranceModel, AMispredictionScaledAlikeReplansOnTheCheapestCandidate) {
  const auto pilot = [](Method method, int order, double constant, double dt, double seconds) {
    PilotRun p;
    p.method = method, p.order = order, p.constant = constant, p.dt = dt, p.seconds_per_step = seconds;
    p.verdict = tolerance_detail::used;
    return p;
  };
  const std::vector<PilotRun> pilots = {pilot(Method::splitting_dlm, 1, 1e-6, 0.5, 1e-6),
                                        pilot(Method::exact_flow_kick, 2, 1e-6, 0.5, 2e-6),
                                        pilot(Method::rk4, 4, 1e-6, 0.5, 3e-6)};
  const ToleranceRequest request{1e-3, ErrorMeasure::attitude, 100.0, 10'000'000};
  using tolerance_detail::cheaper_with_growth;
  const tolerance_detail::Replan other = cheaper_with_growth(pilots, pilots[0], 2000, 100.0, 0.5, request, 4);
  ASSERT_NE(other.pilot, nullptr);
  EXPECT_EQ(other.pilot->method, Method::rk4);
  EXPECT_EQ(other.steps, 212);
  const tolerance_detail::Replan finer = cheaper_with_growth(pilots, pilots[0], 2000, 100.0, 0.2, request, 4);
  ASSERT_NE(finer.pilot, nullptr);
  EXPECT_EQ(finer.pilot->method, Method::exact_flow_kick);
  EXPECT_EQ(finer.steps, 500);
  // a refinement cheaper than any re-plan, or no misprediction (f <= 1): the chosen method stays
  EXPECT_EQ(cheaper_with_growth(pilots, pilots[0], 100, 100.0, 0.5, request, 4).pilot, nullptr);
  EXPECT_EQ(cheaper_with_growth(pilots, pilots[0], 2000, 0.5, 0.5, request, 4).pilot, nullptr);
  EXPECT_EQ(cheaper_with_growth(pilots, pilots[0], 2000, std::nan(""), 0.5, request, 4).pilot, nullptr);
}

TEST(ToleranceModel, AGridThroughSwitchTimesEndsABlockOfFourStepsAtEach) {
  // 10 s and 20 s of 30 s: 1/3 and 2/3, steps a multiple of 12 (4 dt = 10 s / k)
  EXPECT_EQ(grid_steps_through({10.0, 20.0}, 0.0, 30.0, 1'000'000), 12);
  EXPECT_EQ(grid_steps_through({2.5}, 0.0, 10.0, 1'000'000), 16);  // 1/4: 4 dt = 2.5 s / k
  EXPECT_EQ(grid_steps_through({5.0}, 0.0, 10.0, 1'000'000), 8);
  EXPECT_EQ(grid_steps_through({7.5}, 0.0, 10.0, 1'000'000), 16);  // 3/4: 16 steps of 0.625 s, 4 dt = 2.5 s
  EXPECT_EQ(grid_steps_through({3.1}, 1.0, 7.0, 1'000'000), 40);   // t − t0 = 2.1 s of 7 s: 3/10
  EXPECT_EQ(grid_steps_through({}, 0.0, 30.0, 1'000'000), 1);      // no switch: any steps
  EXPECT_EQ(grid_steps_through({3.14159265358979}, 0.0, 10.0, 1'000'000), 0);  // no fraction with b <= 1e4
  EXPECT_EQ(grid_steps_through({1234.5}, 0.0, 86400.0, 1'000'000), 0);  // 2469 / 172800: b > 1e4, no grid
  EXPECT_EQ(grid_steps_through({10.0, 20.0}, 0.0, 30.0, 8), 0);   // beyond the limit
}

TEST(ToleranceModel, ARefinementShrinksTheStepByTheMeasuredRatio) {
  // measured 16x the target at order 4: dt / 2
  EXPECT_DOUBLE_EQ(refined_step(0.1, 4, 16e-6, 1e-6), 0.05);
  // measured below the target (not reliable, or the safety margin): still at most dt / 2^(1/p)
  EXPECT_DOUBLE_EQ(refined_step(0.1, 2, 0.5e-6, 1e-6), 0.1 / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(refined_step(0.1, 2, std::nan(""), 1e-6), 0.05);
}

TEST(ToleranceModel, TheConstantOfAnExactlyLinearErrorIsRecovered) {
  const double C = 2.5, dt = 0.01, t0 = 1.0;
  GlobalErrorEstimate e;
  e.order = 2;
  std::vector<double> t;
  for (int i = 0; i < 5; ++i) {
    t.push_back(t0 + 0.04 * i);
    e.attitude.push_back(C * dt * dt * (t.back() - t0));
    e.verdict.push_back("reliable");
  }
  ErrorRecords r;
  r.n = t.size(), r.t = t.data();
  EXPECT_NEAR(error_constant(e, r, dt, ErrorMeasure::attitude), C, 1e-12 * C);  // round-off of the division
  e.attitude[2] *= 3.0;  // a record above the line: the largest ratio wins (conservative)
  EXPECT_NEAR(error_constant(e, r, dt, ErrorMeasure::attitude), 3.0 * C, 1e-12 * C);
}

// A fourth-order estimate of the attitude at four records: the first at round-off, the next two reliable (orders 4 and
// `third_order`), the last not asymptotic at the order `last_order` (a zero crossing's noise)
GlobalErrorEstimate attitude_with_a_noisy_last_record(std::vector<double> attitude, double third_order,
                                                      const std::string& last_order) {
  GlobalErrorEstimate e;
  e.order = 4;
  e.attitude = std::move(attitude);
  e.observed_order = {std::nan(""), 4.0, third_order, std::stod(last_order)};
  e.verdict = {"reliable", "reliable", "reliable",
               "not asymptotic: observed order " + last_order + " where 4 is expected (attitude)"};
  return e;
}

TEST(ToleranceModel, TheLargestErrorAndTheFirstUnreliableRecord) {
  GlobalErrorEstimate e;
  e.energy = {0.0, 2e-7, 1e-7};
  e.verdict = {"reliable", "reliable", "not asymptotic"};
  EXPECT_EQ(largest_error(e, ErrorMeasure::energy), 2e-7);
  EXPECT_EQ(first_unreliable(e, ErrorMeasure::energy, 1e-6), 2u);
  // an order above the window over-estimates (accepted), one below it is not asymptotic (refused)
  e.verdict.set(2, "not asymptotic: observed order 4.6 where 4 is expected (energy)");
  EXPECT_EQ(first_unreliable(e, ErrorMeasure::energy, 1e-6), 3u);
  e.verdict.set(2, "not asymptotic: observed order 3.2 where 4 is expected (energy)");
  EXPECT_EQ(first_unreliable(e, ErrorMeasure::energy, 1e-6), 2u);
  // ... unless its estimate is negligible: 1e-7 <= 1e-5 / 16
  EXPECT_EQ(first_unreliable(e, ErrorMeasure::energy, 1e-5), 3u);
  e.energy[2] = std::nan("");  // a record without an estimate: no largest error
  EXPECT_TRUE(std::isnan(largest_error(e, ErrorMeasure::energy)));
}

TEST(ToleranceModel, AnEstimateIsAtRoundOffWhereNoRecordMeasuredAnOrder) {
  GlobalErrorEstimate e;
  const double nan = std::nan("");
  e.observed_order = {nan, nan, nan};  // every difference at or below the round-off of the run at h
  EXPECT_TRUE(at_round_off(e));
  e.observed_order[1] = 4.0;  // one record measured its order: a truncation error
  EXPECT_FALSE(at_round_off(e));
}

TEST(ToleranceModel, AnErrorFallingFasterThanItsOrderIsExtrapolatedAtItsObservedOrderUpToOneMore) {
  GlobalErrorEstimate e;
  e.order = 4;
  e.attitude = {0.0, 1e-7};
  const auto at_order = [&](double q) {
    e.observed_order = {std::nan(""), q};  // the largest error's d2 / d1 = 2^q
    return extrapolation_order(e, ErrorMeasure::attitude);
  };
  EXPECT_NEAR(at_order(4.6), 4.6, 1e-12);  // between p and p + 1: q
  EXPECT_EQ(at_order(6.0), 5.0);           // above: p + 1
  EXPECT_EQ(at_order(3.5), 4.0);           // below p: p (no step is made smaller than the order asks)
  EXPECT_EQ(at_order(std::nan("")), 4.0);  // none measured (round-off): p
}

TEST(ToleranceModel, TheLargestErrorsOrderOverridesANoisyRecord) {
  // the last record at a zero crossing: its ratio is noise
  GlobalErrorEstimate e = attitude_with_a_noisy_last_record({0.0, 1e-7, 2e-7, 1e-9}, 4.1, "1");
  // max d2 / max d1 = 2^4.1 (record 2's): log2 = 4.1
  EXPECT_NEAR(observed_order_of_largest(e, ErrorMeasure::attitude), 4.1, 1e-12);
  // at a tolerance of 1e-8 the noisy record (1e-9 > 1e-8 / 16) is not negligible: the record is not accepted, the
  // run is (its largest error's order is 4.1)
  EXPECT_EQ(first_unreliable(e, ErrorMeasure::attitude, 1e-8), 3u);
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-8), 4u);
  // at 1e-6 it is (1e-9 <= 1e-6 / 16): an estimate 16x too small would still meet the tolerance
  EXPECT_EQ(first_unreliable(e, ErrorMeasure::attitude, 1e-6), 4u);
  e.observed_order[2] = 2.0;  // the largest error itself is not asymptotic (log2(max d2 / max d1) = 3): refused
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-8), 3u);
}

// The certified figure: the largest estimate, where the largest error's order is asymptotic; else a record accepted only
// as negligible (its order below the window) counts its difference d(y_h, y_2h) = (2^p − 1) ε, not Richardson's
// extrapolation of it
TEST(ToleranceModel, ARecordAcceptedAsNegligibleCertifiesItsDifferenceWhereTheLargestErrorIsNotAsymptotic) {
  GlobalErrorEstimate e = attitude_with_a_noisy_last_record({0.0, 1e-8, 2e-8, 2e-9}, 4.1, "1.2");
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-6), 4u);  // 2e-9 <= 1e-6 / 16: accepted as negligible
  // the largest error's order 4.1: record 3 is noise about it (a zero crossing), the largest estimate the figure
  EXPECT_TRUE(asymptotic_largest(e, ErrorMeasure::attitude));
  EXPECT_EQ(certified_error(e, ErrorMeasure::attitude), 2e-8);
  // record 2 at order 2: the largest error's log2(max d2 / max d1) = log2(2.4e-6 / 3e-7) = 3, below the window (3.42);
  // nothing vouches for an extrapolation, and record 3's d1 = 3e-8 is the figure
  e.observed_order[2] = 2.0;
  EXPECT_FALSE(asymptotic_largest(e, ErrorMeasure::attitude));
  EXPECT_EQ(certified_error(e, ErrorMeasure::attitude), 15.0 * 2e-9);
  // an order above the window over-estimates (accepted): its estimate is the figure
  e.verdict.set(3, "not asymptotic: observed order 4.9 where 4 is expected (attitude)");
  EXPECT_EQ(certified_error(e, ErrorMeasure::attitude), 2e-8);
  e.attitude[1] = std::nan("");  // a record without an estimate: no figure
  EXPECT_TRUE(std::isnan(certified_error(e, ErrorMeasure::attitude)));
}

// A load that switches inside a step of the coarsest run: the runs at h, 2h and 4h split their steps at different
// places, and the largest error's order no longer vouches for the records that fail
TEST(ToleranceModel, ASwitchInsideACoarseStepLeavesNoFailingRecordCertified) {
  const GlobalErrorEstimate e = attitude_with_a_noisy_last_record({0.0, 1e-7, 2e-7, 1e-9}, 4.1, "1");
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-8, false), 4u);
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-8, true), 3u);
  // every record accepted on its own: certified either way
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-6, true), 4u);
}

// above the window: q > p + log2 1.5 (p = 4: 4.585), read from the verdict's text as global_error.cpp writes it
TEST(ToleranceModel, AnOrderAboveTheWindowIsReadFromItsVerdict) {
  EXPECT_TRUE(above_the_window("not asymptotic: observed order 4.7 where 4 is expected (attitude)"));
  EXPECT_TRUE(above_the_window("not asymptotic: observed order 1e+02 where 4 is expected (energy)"));
  EXPECT_TRUE(above_the_window("not asymptotic: observed order inf where 2 is expected (energy)"));
  EXPECT_FALSE(above_the_window("not asymptotic: observed order 4.5 where 4 is expected (attitude)"));
  EXPECT_FALSE(above_the_window("not asymptotic: observed order 1 where 4 is expected (attitude)"));
  EXPECT_FALSE(above_the_window("not asymptotic: observed order nan where 4 is expected (attitude)"));
  EXPECT_FALSE(above_the_window("not asymptotic: observed order 9 where 4 was expected"));
  EXPECT_FALSE(above_the_window("past the Lyapunov time of this scene: the differences grow as e^(3 t) from t = 1 s "
                                "(nearby trajectories diverge exponentially); not asymptotic: observed order 9 where "
                                "4 is expected (position)"));
  EXPECT_FALSE(above_the_window("reliable"));
  EXPECT_FALSE(above_the_window("not asymptotic: observed order "));
}

TEST(ToleranceModel, ASwitchIsInsideACoarseStepWhereNoMultipleOf4dtReachesIt) {
  SimulationOptions o;
  o.t0 = 0.0, o.dt = 1.875, o.steps = 16;  // 4 dt = 7.5 s over 30 s
  EXPECT_TRUE(switch_inside_coarse_step({10.0}, o));
  EXPECT_FALSE(switch_inside_coarse_step({7.5, 15.0, 22.5}, o));
  EXPECT_FALSE(switch_inside_coarse_step({0.0, 30.0, 31.0, -1.0}, o));  // at or outside the run's ends: no step
  EXPECT_TRUE(switch_inside_coarse_step({7.5, 20.0}, o));
  o.dt = 2.5, o.steps = 12;  // 4 dt = 10 s
  EXPECT_FALSE(switch_inside_coarse_step({10.0, 20.0}, o));
  o.t0 = 0.1, o.dt = 0.1, o.steps = 300;  // grid times t0 + k 0.4 s, rounded: on the grid within a few ulps
  EXPECT_FALSE(switch_inside_coarse_step({0.1 + 0.4 * 7, 12.1}, o));
  EXPECT_TRUE(switch_inside_coarse_step({12.1 + 1e-9}, o));
  EXPECT_FALSE(switch_inside_coarse_step({}, o));
}

TEST(ToleranceModel, ACoarseRunBeyondTheStabilityLimitIsNeverCertified) {
  GlobalErrorEstimate e;
  e.order = 4;
  e.attitude = {0.0, 1e-7, 2e-7, 3e-7};
  e.observed_order = {std::nan(""), 4.0, 4.1, 4.0};  // the largest error's order looks right ...
  e.verdict = {"reliable", "reliable", "reliable", "reliable"};
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-8), 4u);
  // ... but the run at 4h gained energy beyond |T| + |V| at record 3: its error is no power of h (the Foucault
  // pendulum at 1420 rk4 steps over an hour: estimate 1.8e-6 rad where the error is 0.02 rad)
  e.verdict.set(3, "step beyond the stability limit: the energy of the run at 4h departs from the run at 2h's by "
                   "more than |T| + |V|");
  EXPECT_EQ(first_uncertified(e, ErrorMeasure::attitude, 1e-8), 3u);
}

// The measure's own estimate (zeros for the other quantities) cannot see a coarse run's runaway energy: the full
// estimate's instability verdicts are copied onto it, record by record, and its other verdicts kept
TEST(ToleranceModel, TheMeasuresEstimateKeepsTheRunsInstabilityVerdicts) {
  GlobalErrorEstimate all, measure;
  all.verdict = {"reliable", "step beyond the stability limit: the run at 4h diverged",
                 "not asymptotic: observed order 2 where 4 is expected (energy)", "reliable"};
  measure.verdict = {"reliable", "reliable", "reliable",
                     "not asymptotic: observed order 3 where 4 is expected (attitude)"};
  keep_stability_verdicts(all, measure);
  EXPECT_EQ(measure.verdict[0], "reliable");
  EXPECT_EQ(measure.verdict[1], all.verdict[1]);
  EXPECT_EQ(measure.verdict[2], "reliable");  // another quantity's order: not the measure's
  EXPECT_EQ(measure.verdict[3], "not asymptotic: observed order 3 where 4 is expected (attitude)");
  EXPECT_TRUE(says_runs_unstable("step beyond the stability limit: the energy of the run at 4h departs ..."));
  EXPECT_FALSE(says_runs_unstable("interpolated between the reliable records before and after it"));
}

// Three runs at h, 2h and 4h of two bodies, recorded every 4 steps of h (every record common): each quantity its
// exact value plus an error C (f h)^q g(t) of its own order q (f = 1, 2, 4), so that the quantities' verdicts differ
// (the angular velocity's order 2 where the method's is 4), and its energy balance T − W off by a 4th-order error
class SyntheticRuns {
 public:
  static constexpr std::size_t n = 33;
  static constexpr std::int64_t bodies = 2;
  static constexpr double h = 0.05;

  explicit SyntheticRuns(int factor) {
    const double dt = factor * h;
    const auto error = [dt](int q, double c, double t) { return c * std::pow(dt, q) * t * (1.0 + 0.3 * std::sin(t)); };
    for (std::size_t i = 0; i < n; ++i) {
      const double t = 4.0 * h * static_cast<double>(i);
      t_.push_back(t);
      for (std::int64_t b = 0; b < bodies; ++b) {
        const double angle = (1.0 + b) * t + error(4, 0.7 + b, t);
        for (const double x : {0.0, 0.0, std::sin(0.5 * angle), std::cos(0.5 * angle)}) q_.push_back(x);
        for (int a = 0; a < 3; ++a) {
          w_.push_back(std::cos(t + a) + error(2, 0.4, t));
          p_.push_back(std::sin(t + a + b) + error(4, 1.1, t));
          v_.push_back(std::cos(t + a + b) + error(4, 0.9 + a, t));
        }
      }
      energy_.push_back(3.0 + error(5, 2.0, t)), kinetic_.push_back(1.0 + 0.5 * std::sin(t));
      records_.momentum.push_back(2.0 + error(4, 0.6, t));
      records_.balance.push_back(1.0 + error(4, 0.2, t));
    }
    records_.n = n, records_.bodies = bodies, records_.t = t_.data(), records_.q_WB = q_.data();
    records_.w_B = w_.data(), records_.p_W = p_.data(), records_.v_W = v_.data();
    records_.energy = energy_.data(), records_.energy_scale = kinetic_.data();
  }
  const ErrorRecords& records() const { return records_; }

  // these records with every quantity but `measure` the same in any run (zero; the identity attitude), the balance
  // kept: an estimate of all of them then checks `measure` alone
  ErrorRecords with_only(ErrorMeasure measure) {
    zeros_.assign(n * bodies * 4, 0.0), identity_ = zeros_;
    for (std::size_t k = 3; k < identity_.size(); k += 4) identity_[k] = 1.0;
    ErrorRecords r = records_;
    const auto keep = [measure](ErrorMeasure m, const double* own, const double* same) {
      return m == measure ? own : same;
    };
    r.q_WB = keep(ErrorMeasure::attitude, r.q_WB, identity_.data());
    r.w_B = keep(ErrorMeasure::angular_velocity, r.w_B, zeros_.data());
    r.p_W = keep(ErrorMeasure::position, r.p_W, zeros_.data());
    r.v_W = keep(ErrorMeasure::velocity, r.v_W, zeros_.data());
    r.energy = keep(ErrorMeasure::energy, r.energy, zeros_.data());
    r.energy_scale = keep(ErrorMeasure::energy, r.energy_scale, zeros_.data());
    if (measure != ErrorMeasure::angular_momentum) r.momentum.assign(n, 0.0);
    return r;
  }

 private:
  std::vector<double> t_, q_, w_, p_, v_, energy_, kinetic_, zeros_, identity_;
  ErrorRecords records_;
};

// The measure's estimate checks the measure alone: the same bits as the full estimate of runs that agree on every
// other quantity, which it no longer computes (NaN)
TEST(ToleranceModel, TheMeasuresEstimateIsTheEstimateOfRunsAgreeingOnTheOtherQuantities) {
  SyntheticRuns h(1), h2(2), h4(4);
  SimulationOptions o;
  o.dt = SyntheticRuns::h, o.record_every = 4, o.steps = 4 * static_cast<std::int64_t>(SyntheticRuns::n - 1);
  const GlobalErrorEstimate all = estimate_global_error(h.records(), h2.records(), h4.records(), o, 4);
  EXPECT_EQ(all.verdict[5], "not asymptotic: observed order 2 where 4 is expected (angular velocity)");
  for (const ErrorMeasure measure : {ErrorMeasure::attitude, ErrorMeasure::angular_velocity, ErrorMeasure::position,
                                     ErrorMeasure::velocity, ErrorMeasure::energy, ErrorMeasure::angular_momentum}) {
    const GlobalErrorEstimate alone =
        estimate_global_error_and_alone(h.records(), h2.records(), h4.records(), o, 4, measure).second;
    const GlobalErrorEstimate agreeing =
        estimate_global_error(h.with_only(measure), h2.with_only(measure), h4.with_only(measure), o, 4);
    const std::string name = error_measure_name(measure);
    ASSERT_EQ(alone.verdict.size(), SyntheticRuns::n) << name;
    for (std::size_t i = 0; i < SyntheticRuns::n; ++i) {
      EXPECT_EQ(alone.verdict[i], agreeing.verdict[i]) << name << ", record " << i;
      EXPECT_EQ(std::isnan(alone.observed_order[i]), std::isnan(agreeing.observed_order[i]))
          << name << ", record " << i;
      if (!std::isnan(alone.observed_order[i])) {
        EXPECT_EQ(alone.observed_order[i], agreeing.observed_order[i]) << name;
      }
    }
    EXPECT_EQ(values_of(alone, measure), values_of(agreeing, measure)) << name;
    const ErrorMeasure other = measure == ErrorMeasure::energy ? ErrorMeasure::position : ErrorMeasure::energy;
    EXPECT_TRUE(std::isnan(values_of(alone, other)[5])) << name << ": another quantity is not estimated";
    if (measure != ErrorMeasure::angular_velocity) {
      EXPECT_EQ(alone.verdict[5], "reliable") << name;
    }
  }
}

TEST(ToleranceModel, OrderPruningFigure) {
  // at 1e-8 relative: order 4 needs 100 steps x 4 evaluations, order 2 10^4 x 2
  EXPECT_NEAR(order_cost_figure(4, 4, 1e-8), 400.0, 1e-9);
  EXPECT_NEAR(order_cost_figure(2, 2, 1e-8), 2e4, 1e-7);
}

// A plan as its pilot gives it: `method` at `steps` over the horizon, in `seconds` (`verdict` "used" unless given).
PilotRun plan(Method method, std::int64_t steps, double seconds, const std::string& verdict = "used") {
  PilotRun p;
  p.method = method, p.order = 4, p.planned_steps = steps, p.planned_seconds = seconds, p.verdict = verdict;
  return p;
}

TEST(ToleranceModel, PlansWithinTheTimingsNoiseAreTakenByTheirEvaluations) {
  using tolerance_detail::cheapest_plan;
  using tolerance_detail::plan_tie;
  // rk4 and rkmk4 (4 evaluations a step each) at the same steps, rkmk4 timed 5 % faster: a tie, taken in the
  // candidates' order (rk4 first), whichever was timed faster
  std::vector<PilotRun> pilots = {plan(Method::rk4, 100, 1.0e-3), plan(Method::rkmk4, 100, 0.95e-3)};
  EXPECT_EQ(cheapest_plan(pilots, 1000)->method, Method::rk4);
  std::swap(pilots[0].planned_seconds, pilots[1].planned_seconds);
  EXPECT_EQ(cheapest_plan(pilots, 1000)->method, Method::rk4);
  // fewer steps within the tie win; beyond it the faster plan does
  pilots[0].planned_seconds = 1.0e-3;
  pilots[1] = plan(Method::rkmk4, 70, 1.0e-3 * (plan_tie - 0.01));
  EXPECT_EQ(cheapest_plan(pilots, 1000)->method, Method::rkmk4);
  pilots[1].planned_seconds = 1.0e-3 * (plan_tie + 0.01);
  EXPECT_EQ(cheapest_plan(pilots, 1000)->method, Method::rk4);
  // a plan above max_steps, or without a usable pilot, is none
  pilots[1] = plan(Method::rkmk4, 70, 0.5e-3, "not asymptotic at dt = 0.1 s: ...");
  EXPECT_EQ(cheapest_plan(pilots, 1000)->method, Method::rk4);
  EXPECT_EQ(cheapest_plan(pilots, 99), nullptr);
}

TEST(ToleranceMeasure, NamesRoundTripAndAMistypeIsNamed) {
  for (const std::string& name : error_measure_names()) {
    EXPECT_EQ(error_measure_name(error_measure_from_name(name)), name);
  }
  try {
    error_measure_from_name("attitud");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("did you mean 'attitude'"), std::string::npos) << e.what();
  }
}

// A free body I = (1, 2, 3) tumbling near its middle axis for 20 s: the run to 1e-6 rad must be within 1e-6 rad
// of the closed form ('exact', round-off ~1e-13 rad) at every record.
TEST(RunToTolerance, AFreeBodyMeetsItsToleranceAgainstTheClosedForm) {
  const FreeBodyRuns free(Eigen::Vector3d(0.1, 1.0, 0.1));
  SimulationOptions base;
  base.record_every = 4;
  const double tolerance = 1e-6;
  const auto run = free.plain();
  const auto out = run_to_tolerance<Trajectory>({{Method::rk4, 4}, {Method::splitting_dlm, 2}}, base,
                                                {tolerance, ErrorMeasure::attitude, 20.0, 10'000'000}, run);
  ASSERT_TRUE(out.ran);
  EXPECT_TRUE(out.choice.met) << out.choice.reason;
  EXPECT_LE(out.choice.certified_error, tolerance);
  EXPECT_EQ(out.choice.steps % 4, 0);
  EXPECT_NEAR(out.choice.dt * static_cast<double>(out.choice.steps), 20.0, 1e-12);
  SimulationOptions exact = base;
  exact.method = Method::exact, exact.dt = out.choice.dt, exact.steps = out.choice.steps;
  const Trajectory reference = simulate(free.body, free.initial, exact);
  ASSERT_EQ(reference.size(), out.records.size());
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const auto q = [](const Trajectory& r, std::size_t k) {
      return Eigen::Quaterniond(r.q_WB[4 * k + 3], r.q_WB[4 * k], r.q_WB[4 * k + 1], r.q_WB[4 * k + 2]);
    };
    EXPECT_LE(angular_distance(q(reference, i), q(out.records, i)), tolerance) << "record " << i;
  }
}

// On a grid of 0.3 s blocks (a controller sampled every 1.2 s), every run the planner makes, the pilots', the run's and
// their estimates' runs at 2 dt and 4 dt, steps on a divisor of 1.2 s, and the tolerance is met all the same.
TEST(RunToTolerance, EveryRunOnAGridStepsOnADivisorOfItsPeriod) {
  const FreeBodyRuns free(Eigen::Vector3d(0.1, 1.0, 0.1));
  const double period = 1.2, horizon = 24.0;
  std::vector<double> steps_taken;
  const auto run =
      free.logged([&](const ToleranceCandidate&, const SimulationOptions& o) { steps_taken.push_back(o.dt); });
  ToleranceRequest request{1e-6, ErrorMeasure::attitude, horizon, 10'000'000};
  request.grid_steps = static_cast<std::int64_t>(std::lround(4.0 * horizon / period));
  SimulationOptions base;
  base.record_every = 4;
  const auto out = run_to_tolerance<Trajectory>({{Method::rk4, 4}, {Method::splitting_dlm, 2}}, base, request, run);
  ASSERT_TRUE(out.ran);
  EXPECT_TRUE(out.choice.met) << out.choice.reason;
  EXPECT_EQ(out.choice.steps % request.grid_steps, 0);
  ASSERT_FALSE(steps_taken.empty());
  for (const double dt : steps_taken) {
    const double per_period = period / dt;  // a whole number, to the round-off of the divisions that made dt
    EXPECT_NEAR(per_period, std::round(per_period), 1e-9 * per_period) << "dt = " << dt;
  }
}

TEST(ToleranceModel, APilotsAttemptsHalveItsStep) {
  for (int attempt = 0; attempt < pilot_attempts; ++attempt) {
    const PilotSpan at = pilot_span(64.0, attempt);
    EXPECT_EQ(at.span / static_cast<double>(at.steps), std::ldexp(1.0, -attempt)) << attempt;  // T / 64 / 2^attempt
    EXPECT_GE(at.span, 64.0 / 32.0);
  }
  EXPECT_EQ(pilot_span(64.0, 0).span, 16.0);
  EXPECT_EQ(pilot_span(64.0, pilot_attempts - 1).steps, 512);
}

// A later candidate's pilot starts one attempt before the coarsest an earlier pilot was used at: at twice its step
// (a free body spinning at 10 rad/s, whose rk4 pilot is not asymptotic at 16 steps over T/4 or T/8)
TEST(RunToTolerance, ALaterPilotStartsAtTwiceTheStepAnEarlierOneWasUsedAt) {
  const FreeBodyRuns free(Eigen::Vector3d(1.0, 10.0, 1.0));
  std::vector<std::pair<Method, double>> runs;  // each run's method and step, in order
  const auto run = free.logged([&](const ToleranceCandidate& c, const SimulationOptions& o) {
    runs.emplace_back(c.method, o.dt);
  });
  SimulationOptions base;
  base.record_every = 4;
  const double horizon = 20.0;
  const auto out = run_to_tolerance<Trajectory>({{Method::rk4, 4}, {Method::splitting_dlm, 2}}, base,
                                                {1e-3, ErrorMeasure::attitude, horizon, 10'000'000}, run);
  ASSERT_TRUE(out.ran);
  ASSERT_EQ(out.choice.pilots[0].method, Method::rk4);
  ASSERT_EQ(out.choice.pilots[0].verdict, "used");
  const double used = out.choice.pilots[0].dt;
  EXPECT_LT(used, horizon / 64.0);  // rk4's first attempts were not used (else this checks nothing)
  const auto first_splitting = std::find_if(runs.begin(), runs.end(), [](const auto& r) {
    return r.first == Method::splitting_dlm;
  });
  ASSERT_NE(first_splitting, runs.end());
  EXPECT_EQ(first_splitting->second, 2.0 * used);
}

// A free body turning slowly (|ω| 0.1 rad/s over 2 s): rk4 at 16 steps is certified far below 1e-3 rad, so the call
// is that run with its estimate (three runs: h, 2h, 4h), no other candidate piloted and, with a lazy admit, no other
// candidate's method asked for.
TEST(RunToTolerance, AProblemMetAtTheFewestStepsIsThatRunAlone) {
  const FreeBodyRuns free(Eigen::Vector3d(0.01, 0.1, 0.01));
  std::vector<Method> runs, admitted;
  const auto run =
      free.logged([&](const ToleranceCandidate& c, const SimulationOptions&) { runs.push_back(c.method); });
  const auto admit = [&](const ToleranceCandidate& c) {
    admitted.push_back(c.method);
    return true;
  };
  const auto out = run_to_tolerance<Trajectory>({{Method::splitting_dlm, 2}, {Method::rk4, 4}}, SimulationOptions{},
                                                {1e-3, ErrorMeasure::attitude, 2.0, 10'000'000}, run, admit);
  ASSERT_TRUE(out.ran);
  EXPECT_TRUE(out.choice.met) << out.choice.reason;
  EXPECT_EQ(out.choice.method, Method::rk4);  // the highest order first
  EXPECT_EQ(out.choice.steps, fewest_run_steps);
  EXPECT_LE(out.choice.certified_error, 0.5 * 1e-3);  // within s τ
  EXPECT_EQ(runs, std::vector<Method>(3, Method::rk4));
  EXPECT_EQ(admitted, std::vector<Method>{Method::rk4});
  ASSERT_EQ(out.choice.pilots.size(), 2u);
  EXPECT_EQ(out.choice.pilots[0].verdict, "used");
  EXPECT_EQ(out.choice.pilots[0].horizon, 2.0);
  EXPECT_EQ(out.choice.pilots[1].verdict, "not piloted: rk4 met the tolerance at the fewest steps");
  EXPECT_EQ(out.records.size(), static_cast<std::size_t>(fewest_run_steps) + 1);  // every step recorded
}

// A free body at s τ 8x below what 16 steps certify: that error, scaled by dt^q (q in [4, 5]), asks for 16 8^(1/q)
// steps, 24.3 to 26.9, so 28 (a multiple of 4), fewer than direct_plan_steps: the final run takes them without a pilot
// (its three runs after the first three, where the certificate holds at once).
TEST(RunToTolerance, AShortProblemIsPlannedFromItsRunAtTheFewestStepsWithoutAPilot) {
  const FreeBodyRuns free(Eigen::Vector3d(0.1, 1.0, 0.1));
  std::vector<std::int64_t> steps_run;
  const auto run =
      free.logged([&](const ToleranceCandidate&, const SimulationOptions& o) { steps_run.push_back(o.steps); });
  const std::vector<ToleranceCandidate> candidates = {{Method::rk4, 4}, {Method::splitting_dlm, 2}};
  const ToleranceRequest loose{1.0, ErrorMeasure::attitude, 2.0, 10'000'000};
  const auto first = run_to_tolerance<Trajectory>(candidates, SimulationOptions{}, loose, run);
  ASSERT_TRUE(first.choice.met && first.choice.steps == fewest_run_steps) << first.choice.reason;
  const double sixteen = first.choice.certified_error;
  ASSERT_GT(sixteen, 0.0);
  steps_run.clear();
  const double tolerance = sixteen / 4.0;  // s τ = sixteen / 8
  const auto out = run_to_tolerance<Trajectory>(candidates, SimulationOptions{},
                                                {tolerance, ErrorMeasure::attitude, 2.0, 10'000'000}, run);
  ASSERT_TRUE(out.ran);
  EXPECT_TRUE(out.choice.met) << out.choice.reason;
  EXPECT_EQ(out.choice.refinements, 0) << out.choice.reason;
  EXPECT_EQ(out.choice.steps, 28);
  const std::vector<std::int64_t> expected = {16, 8, 4, out.choice.steps, out.choice.steps / 2, out.choice.steps / 4};
  EXPECT_EQ(steps_run, expected);
  ASSERT_EQ(out.choice.pilots.size(), 2u);
  EXPECT_EQ(out.choice.pilots[0].steps, fewest_run_steps);
  EXPECT_EQ(out.choice.pilots[0].planned_steps, out.choice.steps);
  EXPECT_EQ(out.choice.pilots[1].verdict.rfind("not piloted: rk4 over the whole horizon at the fewest steps sets", 0),
            0u)
      << out.choice.pilots[1].verdict;
}

// A candidate the model refuses (admit false) is never run: the fewest steps are tried with the next one.
TEST(RunToTolerance, ACandidateTheModelRefusesIsNeverRun) {
  const FreeBodyRuns free(Eigen::Vector3d(0.01, 0.1, 0.01));
  std::vector<Method> runs;
  const auto run =
      free.logged([&](const ToleranceCandidate& c, const SimulationOptions&) { runs.push_back(c.method); });
  const ToleranceRequest request{1e-3, ErrorMeasure::attitude, 2.0, 10'000'000};
  const auto out = run_to_tolerance<Trajectory>({{Method::rk4, 4}, {Method::splitting_dlm, 2}}, SimulationOptions{},
                                                request, run,
                                                [](const ToleranceCandidate& c) { return c.method != Method::rk4; });
  ASSERT_TRUE(out.ran);
  EXPECT_TRUE(out.choice.met) << out.choice.reason;
  EXPECT_EQ(out.choice.method, Method::splitting_dlm);
  EXPECT_TRUE(std::find(runs.begin(), runs.end(), Method::rk4) == runs.end());
}

TEST(RunToTolerance, TheCostCapIsReportedWithoutARun) {
  const FreeBodyRuns free(Eigen::Vector3d(0.1, 1.0, 0.1));
  const auto run = free.plain();
  // 1e-12 rad over 20 s needs thousands of rk4 steps: a cap of 8 cannot hold them
  const auto out = run_to_tolerance<Trajectory>({{Method::rk4, 4}}, SimulationOptions{},
                                                {1e-12, ErrorMeasure::attitude, 20.0, 8}, run);
  EXPECT_FALSE(out.ran);
  EXPECT_FALSE(out.choice.met);
  EXPECT_NE(out.choice.reason.find("max_steps = 8"), std::string::npos) << out.choice.reason;
}

}  // namespace
}  // namespace rigiddyn
