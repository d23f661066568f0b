// The fast model of one particle in a frame turning at a constant rate (scene/fast/rotating_frame_particle_model.hpp):
// the free particle's run in F against the straight line of W seen from F for every method of order >= 2,
// the exact flow of its loads part against a fine integration of that part, Jacobi's integral and the work
// bookkeeping, the Coriolis power, its agreement with the generic SceneModel running the same terms, and its
// bad input.
#include "invalid_argument_message.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/integrators/method.hpp"
#include "rigiddyn/scene/elements/fictitious_forces.hpp"
#include "rigiddyn/scene/fast/rotating_frame_particle_model.hpp"
#include "rigiddyn/scene/scene_model.hpp"
#include "rigiddyn/scene/simulate_scene.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace rigiddyn;
using Model = RotatingFrameParticleModel;

using rigiddyn::test::kEps;

const Eigen::Vector3d axis(0.3, -0.2, 1.0);
constexpr double rate = 1.0;  // [rad/s]
constexpr double mass = 1.7;  // [kg]

// The free particle in F (no gravity; elements: 0 centrifugal, 1 Coriolis)
Model free_model(const SceneFrame& frame) { return Model(Particle(mass), frame, Eigen::Vector3d::Zero(), -1, 0, 1, 2); }

template <class Integrator>
Model::Coordinates run(const Model& model, Model::Coordinates y, double h, int steps) {
  auto work = workspace<Integrator>(model, y);
  for (int i = 0; i < steps; ++i) Integrator::step(model, y, h, work);
  return y;
}

// The straight line of W seen from F (F = W at t = 0, origins shared): p_W(t) = p0 + v0_W t with
// v0_W = v0 + Ω × p0; p_F = R_FW(t) p_W, v_F = R_FW v0_W − Ω × p_F (R_WF(t) from the frame's motion).
ParticleState line_in_F(const SceneFrame& frame, const ParticleState& s0, double t) {
  const FrameKinematics K = frame.motion.at(t);
  const Eigen::Vector3d w_F = K.R_PF.transpose() * K.w_PF_P;
  const Eigen::Vector3d v0_W = s0.v_W + w_F.cross(s0.p_W);  // R_WF(0) = 1
  const Eigen::Vector3d p_F = K.R_PF.transpose() * (s0.p_W + t * v0_W);
  return {p_F, K.R_PF.transpose() * v0_W - w_F.cross(p_F)};
}

// error of a run of Integrator over T = 0.5 s at step h against the line
template <class Integrator>
double line_error(double h) {
  const SceneFrame frame = SceneFrame::rotating(axis, rate);
  const Model model = free_model(frame);
  const ParticleState s0{Eigen::Vector3d(1.0, 0.5, -0.3), Eigen::Vector3d(-0.2, 0.7, 0.4)};
  const int steps = static_cast<int>(std::lround(0.5 / h));
  const Model::Coordinates y = run<Integrator>(model, Model::coordinates(s0, 0.0), h, steps);
  const ParticleState expected = line_in_F(frame, s0, 0.5), got = Model::state(y);
  return std::max((got.p_W - expected.p_W).norm(), (got.v_W - expected.v_W).norm());
}

// The run in F equals the run in W transformed, to 1e-10, for every method of order >= 2
// at a small step. The error of an order-p method is C h^p + round-off. Each case checks first that the
// error at 2h is 2^p times that at h within 30 % (the asymptotic regime, so that C h^p is the error at h and
// no term is missing: a wrong force would leave an O(1) error independent of h), then that it is <= 1e-10.
// Measured over T = 0.5 s with |Ω| = 1 rad/s, |p0|, |v0| ~ 1: C ≈ 0.28 (implicit midpoint), 0.08 (the
// order-2 splittings), 1e-2 (RK4, RKMK4), 1.5e-2 (Yoshida); h is chosen so that C h^p <= 1e-11 (a factor 10
// below the bound). The round-off of T/h <= 1e5 steps adds ~√(1e5) · 2 ε · 3 ≈ 1e-13 (a random walk; at
// most 1e5 · 2 ε · 3 ≈ 7e-11 if every rounding had the same sign).
struct LineCase {
  const char* name;
  int order;
  double h;
  double (*error)(double);
};
const LineCase line_cases[] = {
    {"rk4", 4, 2e-3, &line_error<Rk4>},
    {"rkmk4", 4, 2e-3, &line_error<Rkmk4>},
    {"implicit_midpoint", 2, 5e-6, &line_error<ImplicitMidpoint>},
    {"splitting_dlm", 2, 1e-5, &line_error<SplittingDlm>},
    {"splitting_dlm_yoshida4", 4, 2e-3, &line_error<Yoshida4>},
    {"exact_flow_kick", 2, 1e-5, &line_error<ExactFlowKick>},
};

TEST(RotatingFrameParticleModel, FreeParticleRunEqualsTheLineOfWSeenFromF) {
  for (const LineCase& c : line_cases) {
    const double fine = c.error(c.h), coarse = c.error(2.0 * c.h);
    const double ratio = coarse / fine, expected = std::pow(2.0, c.order);
    EXPECT_GT(ratio, 0.7 * expected) << c.name << ": error " << fine << " at h, " << coarse << " at 2h";
    EXPECT_LT(ratio, 1.3 * expected) << c.name << ": error " << fine << " at h, " << coarse << " at 2h";
    EXPECT_LE(fine, 1e-10) << c.name;
  }
}

// The exact flow of the loads part (p frozen): v̇ = c − 2 Ω × v, works ẇ_g = m g·v, ẇ_cf = m a_cf·v, against
// RK4 with n sub-steps of that ODE, n such that each turns v by 2ωh/n <= 1e-3 rad (truncation (1e-3)⁵/120
// per sub-step, ~1e-17 relative: negligible); the reference's round-off, <= 8 ε per sub-step of the largest
// |v| (and of the largest integrand for the works), bounds the difference (the closed form's own rounding
// is a few ε).
TEST(RotatingFrameParticleModel, LoadsKickIsTheExactFlowOfTheLoadsPart) {
  const Eigen::Vector3d g(0.3, -1.0, -9.81);
  for (const double w : {0.0, earth_rotation_rate, 0.05, 1.0, 30.0}) {
    for (const double h : {1e-3, 0.1}) {
      const SceneFrame frame = SceneFrame::rotating(axis, w);
      const Model model(Particle(mass), frame, g, 0, 1, 2, 3);
      Model::Coordinates y = Model::Coordinates::Zero();
      y << 1.0, -2.0, 0.5, 0.3, 0.8, -1.1, 0.25, 0.1, 0.2, 0.3;
      const Eigen::Vector3d W = model.w_F(), p = y.segment<3>(0), a_cf = -W.cross(W.cross(p)), c = g + a_cf;
      // the loads part as an ODE in (v, work_g, work_cf)
      Eigen::Matrix<double, 5, 1> z;
      z << y.segment<3>(3), y[7], y[8];
      const auto f = [&](const Eigen::Matrix<double, 5, 1>& s) {
        const Eigen::Vector3d v = s.head<3>();
        Eigen::Matrix<double, 5, 1> d;
        d << c - 2.0 * W.cross(v), mass * g.dot(v), mass * a_cf.dot(v);
        return d;
      };
      const int n = std::max(200, static_cast<int>(std::ceil(2.0 * W.norm() * h / 1e-3)));
      const double k = h / n;
      double v_max = z.head<3>().norm();
      for (int i = 0; i < n; ++i) {
        const auto k1 = f(z), k2 = f(z + 0.5 * k * k1), k3 = f(z + 0.5 * k * k2), k4 = f(z + k * k3);
        z += (k / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        v_max = std::max(v_max, z.head<3>().norm());
      }
      const double roundoff = 8.0 * n * kEps;
      Model::Coordinates kicked = y;
      EXPECT_EQ(model.loads_kick(kicked, h), 0.0);
      EXPECT_LT((kicked.segment<3>(3) - z.head<3>()).norm(), roundoff * v_max) << "w = " << w << ", h = " << h;
      // the works: their start values (0.1, 0.2) plus integrals of size <= m |force/m| v_max h
      EXPECT_NEAR(kicked[7], z[3], roundoff * (0.1 + mass * g.norm() * v_max * h)) << "w = " << w << ", h = " << h;
      EXPECT_NEAR(kicked[8], z[4], roundoff * (0.2 + mass * a_cf.norm() * v_max * h)) << "w = " << w << ", h = " << h;
      // positions, t and the Coriolis work are frozen in this flow
      EXPECT_EQ(kicked.segment<3>(0), y.segment<3>(0));
      EXPECT_EQ(kicked[6], y[6]);
      EXPECT_EQ(kicked[9], y[9]);
    }
  }
}

// Jacobi's integral (T + V_g + V_cf relative to F, the recorded total_energy) and the work-energy balance
// ΔT = W_g + W_cf + W_co under gravity, RK4: both change only by RK4's truncation error, order 4 (checked
// by halving h: a wrong or missing term would give an O(1) change independent of h).
TEST(RotatingFrameParticleModel, JacobiIntegralAndWorkBalance) {
  const SceneFrame frame = SceneFrame::rotating(axis, 2.0);
  const Model model(Particle(mass), frame, Eigen::Vector3d(0.0, 0.0, -9.81), 0, 1, 2, 3);
  const ParticleState s0{Eigen::Vector3d(1.0, 0.5, -0.3), Eigen::Vector3d(-0.2, 0.7, 4.0)};
  struct Drift {
    double jacobi, balance, gravity, centrifugal;
  };
  const auto drift = [&](double h) {
    SceneSimulation r;
    Model::Coordinates y = Model::coordinates(s0, 0.0);
    model.record(y, 0.0, r);
    y = run<Rk4>(model, y, h, static_cast<int>(std::lround(1.0 / h)));
    model.record(y, 1.0, r);
    const double dT = r.kinetic_energy[1] - r.kinetic_energy[0];
    const double V_g = -mass * Eigen::Vector3d(0, 0, -9.81).dot(Model::state(y).p_W - s0.p_W);
    const double dV = r.potential_energy[1] - r.potential_energy[0];
    return Drift{std::abs(r.total_energy[1] - r.total_energy[0]), std::abs(dT - (r.work[3] + r.work[4] + r.work[5])),
                 std::abs(r.work[3] + V_g), std::abs(r.work[4] - (-(dV - V_g)))};
  };
  const Drift coarse = drift(0.02), fine = drift(0.01);
  for (const auto& [name, c, f] : {std::tuple{"jacobi", coarse.jacobi, fine.jacobi}, std::tuple{"balance", coarse.balance, fine.balance},
                                   std::tuple{"centrifugal work", coarse.centrifugal, fine.centrifugal}}) {
    EXPECT_LT(f, 1e-6) << name;  // |T| ~ 20 J; (|Ω| h)⁴ ~ 2e-7 relative at h = 0.01
    EXPECT_GT(c / f, 10.0) << name << ": " << c << " at 2h, " << f << " at h";
  }
  // gravity's work m g·∫v and the displacement ∫v take the same RK4 weights of the same stage velocities:
  // W_g = −ΔV_g to round-off (100 steps, each a few ε of m |g| |Δp| ~ 100 J)
  EXPECT_LT(fine.gravity, 100 * 8.0 * kEps * 100.0);
}

TEST(RotatingFrameParticleModel, CoriolisPowerAndWorkAreZero) {
  const SceneFrame frame = SceneFrame::rotating(axis, 3.0);
  const Model model(Particle(mass), frame, Eigen::Vector3d(0.0, 0.0, -9.81), 0, 1, 2, 3);
  Model::Coordinates y = Model::coordinates(ParticleState{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, -5, 6)}, 0.0);
  SceneSimulation r;
  auto work = workspace<Rk4>(model, y);
  for (int i = 0; i < 100; ++i) {
    model.record(y, y[6], r);
    Rk4::step(model, y, 0.01, work);
  }
  for (std::size_t i = 0; i < r.size(); ++i) {
    const Eigen::Vector3d v(&r.v_W[3 * i]);
    // m (−2 Ω × v)·v: three products of size m |Ω| |v|², each rounded: a few ε of it
    EXPECT_LE(std::abs(r.power[3 * i + 2]), 8.0 * kEps * mass * 2.0 * model.w_F().norm() * v.squaredNorm());
    // its work: the sum of RK4's weighted powers, each round-off: N steps of the same size
    EXPECT_LE(std::abs(r.work[3 * i + 2]), 8.0 * kEps * mass * 2.0 * model.w_F().norm() * 1e3 * 0.01 * static_cast<double>(i + 1));
  }
  // the splitting methods do no Coriolis work at all
  Model::Coordinates z = Model::coordinates(ParticleState{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, -5, 6)}, 0.0);
  z = run<SplittingDlm>(model, z, 0.01, 100);
  EXPECT_EQ(z[9], 0.0);
}

// The generic SceneModel with the same terms (UniformGravityTerm, CentrifugalTerm, CoriolisTerm) integrates
// the same equations: a RK4 run agrees to round-off (different orders of the same operations: a few ε per
// step, growing at most linearly over 500 steps with the flow's Jacobian ~ e^{|Ω| T}).
TEST(RotatingFrameParticleModel, AgreesWithTheSceneModel) {
  const SceneFrame frame = SceneFrame::rotating(axis, 1.5);
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  const std::vector<Body> bodies{Particle(mass)};
  std::vector<SceneModel::Term> terms;
  terms.emplace_back(UniformGravityTerm(UniformGravity{g, {}}, bodies, "elements[0]"));
  terms.emplace_back(CentrifugalTerm(frame, bodies, "frame.centrifugal"));
  terms.emplace_back(CoriolisTerm(frame, bodies, "frame.coriolis"));
  const SceneModel generic(bodies, terms);
  const Model fast(Particle(mass), frame, g, 0, 1, 2, 3);
  const std::vector<BodyState> s0{ParticleState{Eigen::Vector3d(1.0, 0.5, -0.3), Eigen::Vector3d(-0.2, 0.7, 4.0)}};
  Eigen::VectorXd y_generic = generic.coordinates(s0, 0.1);
  Model::Coordinates y_fast = fast.coordinates(s0, 0.1);
  SceneSimulation r_generic, r_fast;
  auto work_generic = workspace<Rk4>(generic, y_generic);
  auto work_fast = workspace<Rk4>(fast, y_fast);
  for (int i = 0; i < 500; ++i) Rk4::step(generic, y_generic, 0.002, work_generic), Rk4::step(fast, y_fast, 0.002, work_fast);
  generic.record(y_generic, 1.1, r_generic);
  fast.record(y_fast, 1.1, r_fast);
  const double tolerance = 500 * 16.0 * kEps * 20.0;  // 500 steps × 16 ε × the state's size (~20) × e^{1.5}/e
  const auto near = [&](const std::vector<double>& a, const std::vector<double>& b, const char* field) {
    ASSERT_EQ(a.size(), b.size()) << field;
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], tolerance * (1.0 + std::abs(b[i]))) << field << "[" << i << "]";
  };
  near(r_fast.t, r_generic.t, "t");
  near(r_fast.p_W, r_generic.p_W, "p_W");
  near(r_fast.q_WB, r_generic.q_WB, "q_WB");
  near(r_fast.v_W, r_generic.v_W, "v_W");
  near(r_fast.w_B, r_generic.w_B, "w_B");
  near(r_fast.kinetic_energy, r_generic.kinetic_energy, "kinetic_energy");
  near(r_fast.potential_energy, r_generic.potential_energy, "potential_energy");
  near(r_fast.total_energy, r_generic.total_energy, "total_energy");
  near(r_fast.linear_momentum_W, r_generic.linear_momentum_W, "linear_momentum_W");
  near(r_fast.angular_momentum_W, r_generic.angular_momentum_W, "angular_momentum_W");
  near(r_fast.pivot_reaction_W, r_generic.pivot_reaction_W, "pivot_reaction_W");
  near(r_fast.angular_momentum_O_W, r_generic.angular_momentum_O_W, "angular_momentum_O_W");
  near(r_fast.mass, r_generic.mass, "mass");
  near(r_fast.work, r_generic.work, "work");
  near(r_fast.power, r_generic.power, "power");
  EXPECT_EQ(fast.time_index(), 6);
  EXPECT_NEAR(y_fast[fast.time_index()], 1.1, 1e-14);
  EXPECT_EQ(fast.states(y_fast).size(), 1u);
  EXPECT_EQ(Model::state(y_fast).p_W, y_fast.segment<3>(0));
}

// Every method of the registry runs on the fast model through the scene run loop (detail::run_scene), each
// record filled for every field. The methods that evaluate the whole derivative (explicit Euler, RK4,
// RKMK4, implicit midpoint) give the generic SceneModel's records to round-off (500 steps of a few ε of
// states of size ~10: 1e-11 relative); the kick–drift methods differ from the generic model's
// (whose kicks take the Coriolis force explicitly; here the exact loads flow) by their own O(h) or O(h²)
// error, 1e-3 at h = 2e-3 over 1 s (the first-order semi-implicit Euler: ~|a| h ~ 0.02, bounded by 0.1).
TEST(RotatingFrameParticleModel, EveryMethodRunsThroughTheSceneRunLoop) {
  const SceneFrame frame = SceneFrame::rotating(axis, 1.5);
  const Eigen::Vector3d g(0.0, 0.0, -9.81);
  const std::vector<Body> bodies{Particle(mass)};
  std::vector<SceneModel::Term> terms;
  terms.emplace_back(UniformGravityTerm(UniformGravity{g, {}}, bodies, "elements[0]"));
  terms.emplace_back(CentrifugalTerm(frame, bodies, "frame.centrifugal"));
  terms.emplace_back(CoriolisTerm(frame, bodies, "frame.coriolis"));
  const SceneModel generic(bodies, terms);
  const Model fast(Particle(mass), frame, g, 0, 1, 2, 3);
  const std::vector<BodyState> s0{ParticleState{Eigen::Vector3d(1.0, 0.5, -0.3), Eigen::Vector3d(-0.2, 0.7, 4.0)}};
  for (const MethodInfo& info : method_table()) {
    if (info.method == Method::exact) continue;  // compile refuses 'exact' with a frame
    SimulationOptions o;
    o.method = info.method, o.dt = 2e-3, o.steps = 500, o.record_every = 100;
    const SceneSimulation a = detail::run_scene(fast, fast.coordinates(s0, 0.0), o, {});
    const SceneSimulation b = detail::run_scene(generic, generic.coordinates(s0, 0.0), o, {});
    ASSERT_EQ(a.size(), 6u) << info.name;
    for (const auto* v : {&a.p_W, &a.v_W, &a.w_B, &a.pivot_reaction_W, &a.angular_momentum_O_W, &a.linear_momentum_W, &a.angular_momentum_W, &a.work,
                          &a.power}) {
      EXPECT_EQ(v->size(), 18u) << info.name;
    }
    EXPECT_EQ(a.q_WB.size(), 24u) << info.name;
    for (const auto* v : {&a.mass, &a.kinetic_energy, &a.potential_energy, &a.total_energy}) EXPECT_EQ(v->size(), 6u) << info.name;
    const bool whole_derivative = info.method == Method::explicit_euler || info.method == Method::rk4 || info.method == Method::rkmk4 ||
                                  info.method == Method::implicit_midpoint;
    const double tolerance = whole_derivative ? 1e-11 : 0.1;
    for (std::size_t i = 0; i < a.p_W.size(); ++i) {
      EXPECT_NEAR(a.p_W[i], b.p_W[i], tolerance * (1.0 + std::abs(b.p_W[i]))) << info.name;
      EXPECT_NEAR(a.v_W[i], b.v_W[i], tolerance * (1.0 + std::abs(b.v_W[i]))) << info.name;
    }
    EXPECT_FALSE(a.diverged) << info.name;
  }
}

using rigiddyn::test::message_of;

TEST(RotatingFrameParticleModel, BadInputRaisesNamingTheArgument) {
  const SceneFrame frame = SceneFrame::rotating(axis, rate);
  const Particle p(1.0);
  const Eigen::Vector3d g(0, 0, -9.81), none = Eigen::Vector3d::Zero();
  const SceneFrame general = SceneFrame::moving(FrameMotion([](double t) {
    FrameKinematics K;
    K.w_PF_P = Eigen::Vector3d(0.0, 0.0, t);
    return K;
  }));
  const auto starts = [](const std::string& message, const char* prefix) { return message.rfind(prefix, 0) == 0; };
  EXPECT_TRUE(starts(message_of([&] { Model(p, general, none, -1, 0, 1, 2); }), "frame: "));
  EXPECT_TRUE(starts(message_of([&] { Model(p, frame, Eigen::Vector3d(0, 0, NAN), 0, 1, 2, 3); }), "g_F: "));
  EXPECT_TRUE(starts(message_of([&] { Model(p, frame, g, -1, 0, 1, 2); }), "g_F: "));
  EXPECT_TRUE(starts(message_of([&] { Model(p, frame, g, 3, 1, 2, 3); }), "gravity_element: "));
  EXPECT_TRUE(starts(message_of([&] { Model(p, frame, g, 0, 0, 2, 3); }), "centrifugal_element: "));
  EXPECT_TRUE(starts(message_of([&] { Model(p, frame, g, 0, 1, -2, 3); }), "coriolis_element: "));
  EXPECT_TRUE(starts(message_of([&] { Model(p, frame, none, -1, -1, 0, 1); }), "centrifugal_element: "));
  // a frame at rest needs no frame terms
  EXPECT_EQ(message_of([&] { Model(p, SceneFrame::rotating(axis, 0.0), none, -1, -1, -1, 0); }), "");
}

}  // namespace
