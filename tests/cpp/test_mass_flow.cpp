// Mass flows and the Thrust element (scene/mass_flow.hpp, scene/elements/thrust.hpp): every
// check names its field; the inertia rules; the torque scale against Euler's equations of I(m); the
// out-of-mass error and the up-front check of a constant rate at the exact grid step; the thrust's force,
// torque and power against the notes' eq. (4.36) written out by hand at random states.
#include <gtest/gtest.h>

#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "invalid_argument_message.hpp"
#include "rigiddyn/models/euler_equations.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/elements/thrust.hpp"
#include "rigiddyn/scene/mass_flow.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;
using rigiddyn::test::kInf;
using rigiddyn::test::kNaN;

using test::message_of;

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// A realizable full inertia [kg m²]: principal moments (1.0, 1.4, 2.1) turned by a fixed rotation.
using test::full_inertia;

using test::random_vector;

using test::random_rotation;

// ---- MassFlow checks -------------------------------------------------------------------------------

TEST(MassFlow, NonFiniteRateNamesTheField) {
  for (const double bad : {kInf, -kInf, kNaN}) {
    MassFlow flow;
    flow.rate = bad;
    EXPECT_TRUE(starts_with(message_of([&] { check_mass_flow(flow, "mass_flows[2]"); }), "mass_flows[2].rate: expected a finite"));
    EXPECT_TRUE(starts_with(message_of([&] { mass_rate(flow, 0.0, "mass_flows[2]"); }), "mass_flows[2].rate: expected a finite mass rate"));
  }
}

TEST(MassFlow, RateOfTimeReturningNonFiniteNamesTheFieldAndTheTime) {
  MassFlow flow;
  flow.rate_of_t = [](double t) { return t < 1.0 ? -0.5 : std::log(1.0 - t); };  // -inf at 1, NaN after
  EXPECT_NO_THROW(check_mass_flow(flow, "mass_flows[0]"));
  EXPECT_EQ(mass_rate(flow, 0.5, "mass_flows[0]"), -0.5);
  EXPECT_EQ(message_of([&] { mass_rate(flow, 1.0, "mass_flows[0]"); }),
            "mass_flows[0].rate: expected a finite mass rate [kg/s] at t = 1 s, got -inf");
  EXPECT_TRUE(starts_with(message_of([&] { mass_rate(flow, 2.0, "mass_flows[0]"); }), "mass_flows[0].rate: expected a finite"));
}

TEST(MassFlow, NegativeAndPositiveRatesAreAllowed) {
  for (const double rate : {-3.0, 0.0, 2.5}) {
    MassFlow flow;
    flow.rate = rate;
    EXPECT_NO_THROW(check_mass_flow(flow, "mass_flows[0]"));
    EXPECT_EQ(mass_rate(flow, 7.0), rate);
    EXPECT_TRUE(has_constant_rate(flow));
  }
}

TEST(MassFlow, TwoRatesAreRefused) {
  MassFlow flow;
  flow.rate = -1.0;
  flow.rate_of_t = [](double) { return -1.0; };
  EXPECT_TRUE(starts_with(message_of([&] { check_mass_flow(flow, "mass_flows[1]"); }), "mass_flows[1].rate: expected 0 when rate_of_t is given"));
}

TEST(MassFlow, InertiaRuleAndItsFunctionMustAgree) {
  MassFlow function_without;
  function_without.inertia_rule = InertiaRule::function;
  EXPECT_EQ(message_of([&] { check_mass_flow(function_without, "mass_flows[0]"); }),
            "mass_flows[0].inertia_of_mass: expected a function of the mass for InertiaRule::function, got none");
  MassFlow scaled_with;
  scaled_with.inertia_of_mass = [](double m) -> Eigen::Matrix3d { return m * Eigen::Matrix3d::Identity(); };
  EXPECT_TRUE(starts_with(message_of([&] { check_mass_flow(scaled_with, "mass_flows[0]"); }),
                          "mass_flows[0].inertia_of_mass: expected none for InertiaRule::scaled"));
  MassFlow bad_rule;
  bad_rule.inertia_rule = static_cast<InertiaRule>(7);
  EXPECT_EQ(message_of([&] { check_mass_flow(bad_rule, "mass_flows[0]"); }),
            "mass_flows[0].inertia_rule: expected InertiaRule::scaled or InertiaRule::function, got 7");
}

// ---- inertia at a mass, torque scale ---------------------------------------------------------------

TEST(MassFlow, ScaledInertiaIsProportionalToTheMass) {
  const MassFlow flow;  // scaled by default
  const Eigen::Matrix3d I0 = full_inertia();
  // one rounding of m/m0 and one per entry: 2 eps relative
  EXPECT_LE((inertia_at_mass(flow, I0, 4.0, 3.0) - 0.75 * I0).cwiseAbs().maxCoeff(), 2.0 * kEps * I0.cwiseAbs().maxCoeff());
}

TEST(MassFlow, FunctionInertiaIsCheckedSymmetricPositiveDefinite) {
  MassFlow flow;
  flow.inertia_rule = InertiaRule::function;
  flow.inertia_of_mass = [](double m) -> Eigen::Matrix3d { return m * full_inertia(); };
  EXPECT_LE((inertia_at_mass(flow, Eigen::Matrix3d::Zero(), 1.0, 2.0, "mass_flows[3]") - 2.0 * full_inertia()).cwiseAbs().maxCoeff(),
            4.0 * kEps);  // the symmetric part of a matrix symmetric to a few ulps
  const auto refused = [&](std::function<Eigen::Matrix3d(double)> f) {
    flow.inertia_of_mass = std::move(f);
    return starts_with(message_of([&] { inertia_at_mass(flow, Eigen::Matrix3d::Zero(), 1.0, 2.0, "mass_flows[3]"); }),
                       "mass_flows[3].inertia_of_mass: expected a finite symmetric positive definite inertia [kg m²] at m = 2 kg, got");
  };
  EXPECT_TRUE(refused([](double) -> Eigen::Matrix3d { return Eigen::Matrix3d::Constant(kNaN); }));
  EXPECT_TRUE(refused([](double) -> Eigen::Matrix3d {
    Eigen::Matrix3d I = full_inertia();
    I(0, 1) += 0.1;  // not symmetric
    return I;
  }));
  EXPECT_TRUE(refused([](double) -> Eigen::Matrix3d { return Eigen::Vector3d(1.0, 1.0, -0.5).asDiagonal(); }));  // indefinite
  EXPECT_TRUE(refused([](double) -> Eigen::Matrix3d { return Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal(); }));   // singular
}

// α = I_C0⁻¹((m0/m) τ − ω × I_C0 ω) (the scaled rule in the Euler form of I_C0) equals Euler's equations of
// I(m) = I_C0 m/m0 solved directly, α = I(m)⁻¹(τ − ω × I(m) ω), at random ω, τ, m.
TEST(MassFlow, TorqueScaleGivesEulersEquationsOfTheInertiaNow) {
  std::mt19937 rng(12);
  const Eigen::Matrix3d I0 = full_inertia();
  const FullEuler euler0(I0);
  const double m0 = 5.0;
  std::uniform_real_distribution<double> mass(0.1, 10.0);
  for (int trial = 0; trial < 100; ++trial) {
    const double m = mass(rng);
    const Eigen::Vector3d w = random_vector(rng, 3.0), tau = random_vector(rng, 2.0);
    const Eigen::Vector3d alpha = euler0.angular_acceleration(w, torque_scale(m0, m) * tau);
    const Eigen::Matrix3d I = inertia_at_mass(MassFlow{}, I0, m0, m);
    const Eigen::Vector3d direct = I.ldlt().solve(tau - w.cross(I * w));
    // both solve with I (κ = 2.1) terms of size ≤ |τ| m0/m + |ω|²|I| ≤ 100 + 40: a few dozen roundings of
    // 140/λ_min(I) = 140 · m0/(m · 1.0): 64 eps · 140 · m0/m
    EXPECT_LE((alpha - direct).norm(), 64.0 * kEps * 140.0 * m0 / m) << m;
  }
}

// ---- running out of mass ---------------------------------------------------------------------------

TEST(MassFlow, BurnOutTime) {
  EXPECT_EQ(burn_out_time(10.0, -2.0, 1.0), 6.0);
  EXPECT_EQ(burn_out_time(10.0, 0.0, 1.0), kInf);
  EXPECT_EQ(burn_out_time(10.0, 3.0, 1.0), kInf);
}

TEST(MassFlow, OutOfMassErrorText) {
  EXPECT_EQ(std::string(out_of_mass_error("mass_flows[1]", "rocket", -0.25, 5.25, 4.75).what()),
            "mass_flows[1]: expected a positive mass, got m = -0.25 kg at t = 5.25 s (the body 'rocket' runs out of "
            "mass in the step from t = 4.75 s)");
}

// m0 = 10 kg, ṁ = −2 kg/s from t0 = 1 s: the mass runs out at t = 6 s. With dt = 0.25 s (exact in
// binary, so the grid and the masses are exact) the 20th step ends there with m = 0: 19 steps run,
// 20 are refused, naming that step.
TEST(MassFlow, UpFrontCheckRefusesTheRunAtTheStepWhereTheMassRunsOut) {
  MassFlow flow;
  flow.rate = -2.0;
  EXPECT_NO_THROW(check_mass_over_run(flow, 10.0, 1.0, 0.25, 19, "mass_flows[0]", "rocket"));
  EXPECT_EQ(message_of([&] { check_mass_over_run(flow, 10.0, 1.0, 0.25, 20, "mass_flows[0]", "rocket"); }),
            "mass_flows[0]: expected a positive mass, got m = 0 kg at t = 6 s (the body 'rocket' runs out of mass in "
            "the step from t = 5.75 s); steps, dt: expected a run that ends before the mass runs out at t = 6 s (at "
            "most 19 steps of dt = 0.25 s), got 20 steps");
  // dt = 0.3 s: the mass runs out inside the step from t = 5.8 s (the 17th: 16 steps end at 5.8 s, m = 0.4 kg)
  EXPECT_NO_THROW(check_mass_over_run(flow, 10.0, 1.0, 0.3, 16, "mass_flows[0]", "rocket"));
  const std::string text = message_of([&] { check_mass_over_run(flow, 10.0, 1.0, 0.3, 1000, "mass_flows[0]", "rocket"); });
  EXPECT_NE(text.find("runs out of mass in the step from t = " + format_value(1.0 + 16 * 0.3) + " s)"), std::string::npos) << text;
  EXPECT_NE(text.find("(at most 16 steps of dt = " + format_value(0.3) + " s), got 1000 steps"), std::string::npos) << text;
  // a gaining or constant mass, and a rate of t, are never refused up front
  for (const double rate : {0.0, 1.0}) {
    flow.rate = rate;
    EXPECT_NO_THROW(check_mass_over_run(flow, 10.0, 1.0, 0.3, 1000000, "mass_flows[0]", "rocket"));
  }
  MassFlow of_t;
  of_t.rate_of_t = [](double) { return -100.0; };
  EXPECT_NO_THROW(check_mass_over_run(of_t, 10.0, 1.0, 0.3, 1000000, "mass_flows[0]", "rocket"));
}

// ---- the Thrust element ----------------------------------------------------------------------------

std::vector<std::optional<MassFlow>> flows_on(std::size_t n, int body, const MassFlow& flow) {
  std::vector<std::optional<MassFlow>> out(n);
  out[body] = flow;
  return out;
}

MassFlow constant(double rate) {
  MassFlow flow;
  flow.rate = rate;
  return flow;
}

TEST(Thrust, RefusesABodyWithoutMassFlow) {
  const std::vector<Body> bodies{Particle(1.0), RigidBody(2.0, full_inertia())};
  Thrust spec;
  spec.body = 1;
  spec.frame = Frame::world;
  const std::string expected = "elements[4].body: expected a body with a mass flow (mass_flows[1]: a thrust is the force of "
                               "the mass it exchanges), got body 1 of constant mass";
  EXPECT_EQ(message_of([&] { ThrustTerm(spec, bodies, {}, "elements[4]"); }), expected);                          // no flows
  EXPECT_EQ(message_of([&] { ThrustTerm(spec, bodies, flows_on(2, 0, constant(-1.0)), "elements[4]"); }), expected);  // not this body
  EXPECT_NO_THROW(ThrustTerm(spec, bodies, flows_on(2, 1, constant(-1.0)), "elements[4]"));
  spec.body = 2;
  EXPECT_TRUE(starts_with(message_of([&] { ThrustTerm(spec, bodies, flows_on(2, 1, constant(-1.0)), "elements[4]"); }),
                          "elements[4].body: expected a body index in [0, 2), got 2"));
}

TEST(Thrust, FieldChecksNameTheirField) {
  const std::vector<Body> bodies{Particle(1.0), PlanarBody(1.0, 0.5), RigidBody(2.0, full_inertia())};
  std::vector<std::optional<MassFlow>> flows(3, constant(-1.0));
  const auto message = [&](const Thrust& spec) { return message_of([&] { ThrustTerm(spec, bodies, flows, "elements[0]"); }); };
  Thrust particle_body_frame;  // Frame::body by default
  EXPECT_EQ(message(particle_body_frame),
            "elements[0].frame: expected Frame::world on a particle (a point has no axes to turn u_rel with), got Frame::body");
  Thrust particle_point;
  particle_point.frame = Frame::world, particle_point.r_B = Eigen::Vector3d(0.0, 0.0, 1.0);
  EXPECT_TRUE(starts_with(message(particle_point), "elements[0].r_B: expected zero (a particle is a point)"));
  Thrust not_finite;
  not_finite.body = 2, not_finite.u_rel = Eigen::Vector3d(0.0, kNaN, 0.0);
  EXPECT_TRUE(starts_with(message(not_finite), "elements[0].u_rel: expected finite values"));
  Thrust out_of_plane;
  out_of_plane.body = 1, out_of_plane.u_rel = Eigen::Vector3d(1.0, 0.0, 0.5);
  EXPECT_TRUE(starts_with(message(out_of_plane), "elements[0].u_rel: expected a velocity in the plane of the planar body (z = 0)"));
  Thrust planar_point;
  planar_point.body = 1, planar_point.r_B = Eigen::Vector3d(0.0, 0.1, 0.2);
  EXPECT_TRUE(starts_with(message(planar_point), "elements[0].r_B: expected a point in the body's xy plane (z = 0)"));
  Thrust bad_frame;
  bad_frame.body = 2, bad_frame.frame = static_cast<Frame>(5);
  EXPECT_EQ(message(bad_frame), "elements[0].frame: expected Frame::body or Frame::world, got 5");
}

// f = ṁ u_rel (u_rel turned to W when given in B) at C + r_B: tau_B = r_B × f_B; power f·v + τ·ω;
// written out at random states of a rigid body, for both frames, with a rate of t.
TEST(Thrust, ForceTorqueAndPowerOfTheExchangedMass) {
  std::mt19937 rng(4);
  const std::vector<Body> bodies{Particle(1.0), RigidBody(2.0, full_inertia())};
  MassFlow flow;
  flow.rate_of_t = [](double t) { return -0.5 - 0.1 * t; };
  for (const Frame frame : {Frame::body, Frame::world}) {
    for (int trial = 0; trial < 20; ++trial) {
      Thrust spec;
      spec.body = 1, spec.frame = frame, spec.u_rel = random_vector(rng, 300.0), spec.r_B = random_vector(rng, 0.5);
      const ThrustTerm term(spec, bodies, flows_on(2, 1, flow), "elements[0]");
      std::vector<BodyKinematics> k(2);
      set_attitude(k[1], random_rotation(rng));
      k[1].v_W = random_vector(rng, 10.0), k[1].w_B = random_vector(rng, 2.0), k[1].m = 1.5;
      std::vector<BodyWrench> w(2);
      w[1].f_W = Eigen::Vector3d(1.0, 2.0, 3.0);  // adds to what is there
      const double t = 3.0 * trial / 20.0, rate = -0.5 - 0.1 * t;
      const double power = term.add_wrenches(t, k, w);
      const Eigen::Matrix3d R = k[1].q_WB.toRotationMatrix();
      const Eigen::Vector3d f_W = frame == Frame::body ? Eigen::Vector3d(R * (rate * spec.u_rel)) : Eigen::Vector3d(rate * spec.u_rel);
      const Eigen::Vector3d tau_B = spec.r_B.cross(R.transpose() * f_W);
      // |f| ≤ 1 · 520 N, one rotation of a few roundings: 8 eps |f|; τ: |r| |f| ≤ 0.9 · 520
      const double f_scale = 8.0 * kEps * 520.0;
      EXPECT_LE((w[1].f_W - Eigen::Vector3d(1.0, 2.0, 3.0) - f_W).norm(), f_scale);
      EXPECT_LE((w[1].tau_B - tau_B).norm(), f_scale);
      EXPECT_TRUE(w[0].f_W.isZero(0.0) && w[0].tau_B.isZero(0.0));  // the other body untouched
      EXPECT_LE(std::abs(power - (f_W.dot(k[1].v_W) + tau_B.dot(k[1].w_B))), f_scale * 20.0);  // × (|v| + |ω|) ≤ 20
    }
  }
}

TEST(Thrust, ParticleTakesTheWorldForceOnly) {
  const std::vector<Body> bodies{Particle(3.0)};
  Thrust spec;
  spec.frame = Frame::world, spec.u_rel = Eigen::Vector3d(0.0, -20.0, -250.0);
  const ThrustTerm term(spec, bodies, flows_on(1, 0, constant(-2.0)), "elements[1]");
  std::vector<BodyKinematics> k(1);
  k[0].v_W = Eigen::Vector3d(1.0, 2.0, 30.0), k[0].m = 3.0;
  std::vector<BodyWrench> w(1);
  const double power = term.add_wrenches(0.0, k, w);
  EXPECT_EQ(w[0].f_W, Eigen::Vector3d(0.0, 40.0, 500.0));  // exact: products of small integers
  EXPECT_TRUE(w[0].tau_B.isZero(0.0));
  EXPECT_EQ(power, 80.0 + 15000.0);
  const ElementTraits traits = term.traits();
  EXPECT_FALSE(traits.reads_attitude || traits.velocity_dependent || traits.time_dependent || traits.has_potential ||
               traits.has_torque);
  EXPECT_EQ(term.potential(k), 0.0);
}

TEST(Thrust, TraitsFollowTheSpec) {
  const std::vector<Body> bodies{RigidBody(2.0, full_inertia())};
  MassFlow of_t;
  of_t.rate_of_t = [](double) { return -1.0; };
  Thrust spec;  // Frame::body through C
  ElementTraits t = ThrustTerm(spec, bodies, flows_on(1, 0, of_t), "e").traits();
  EXPECT_TRUE(t.reads_attitude && t.time_dependent && !t.has_torque && !t.has_potential && !t.velocity_dependent);
  spec.frame = Frame::world, spec.r_B = Eigen::Vector3d(0.0, 0.0, -1.0);
  t = ThrustTerm(spec, bodies, flows_on(1, 0, constant(-1.0)), "e").traits();
  EXPECT_TRUE(t.reads_attitude && !t.time_dependent && t.has_torque);
}

TEST(Thrust, NonFiniteRateOfTimeNamesTheFlowsField) {
  const std::vector<Body> bodies{Particle(1.0), Particle(1.0)};
  MassFlow flow;
  flow.rate_of_t = [](double) { return kNaN; };
  Thrust spec;
  spec.body = 1, spec.frame = Frame::world, spec.u_rel = Eigen::Vector3d::UnitX();
  const ThrustTerm term(spec, bodies, flows_on(2, 1, flow), "elements[0]");
  std::vector<BodyKinematics> k(2);
  std::vector<BodyWrench> w(2);
  EXPECT_EQ(message_of([&] { term.add_wrenches(0.5, k, w); }), "mass_flows[1].rate: expected a finite mass rate [kg/s] at t = 0.5 s, got nan");
}

}  // namespace
}  // namespace rigiddyn
