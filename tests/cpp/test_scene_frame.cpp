// The scene's moving frame (scene/scene_frame.hpp) and its fictitious terms (scene/elements/fictitious_forces.hpp):
// each force and torque against a sum over the point masses of a rigid cloud (an independent derivation: the
// "Rigid body kinematics and dynamics" notes' eq. (4.39) for each point, Σ m_i ρ_i × a_fict,i for the moment),
// the Coriolis power, Jacobi's integral of a turning frame, runs in F against runs in W transformed, and the
// frame's bad values.
#include "invalid_argument_message.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/integrators/rk4.hpp"
#include "rigiddyn/scene/elements/fictitious_forces.hpp"
#include "rigiddyn/scene/scene_frame.hpp"
#include "rigiddyn/scene/scene_model.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace rigiddyn;

using rigiddyn::test::kEps;

// The scene model runs the frame terms (alternatives of its Term variant).
using FrameModel = SceneModel;

// A general frame motion relative to W (every term non-zero): R_WF(t) = Rz(φ(t)) Rx(ψ(t)), φ = 0.3 t + 0.1 t²,
// ψ = 0.5 sin t (a product of two rotations about fixed axes, so ω and α follow in closed form), origin
// p_WO = (sin t, 0.2 t², cos 2t) [m].
FrameKinematics general_motion(double t) {
  const double phi = 0.3 * t + 0.1 * t * t, dphi = 0.3 + 0.2 * t, ddphi = 0.2;
  const double psi = 0.5 * std::sin(t), dpsi = 0.5 * std::cos(t), ddpsi = -0.5 * std::sin(t);
  const Eigen::Matrix3d Rz = Eigen::AngleAxisd(phi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3d Rx = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  FrameKinematics K;
  K.R_PF = Rz * Rx;
  // ω = φ̇ z + ψ̇ Rz x (addition theorem, Craig); α = φ̈ z + ψ̈ Rz x + φ̇ z × ψ̇ Rz x
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ(), x_rot = Rz * Eigen::Vector3d::UnitX();
  K.w_PF_P = dphi * z + dpsi * x_rot;
  K.alpha_PF_P = ddphi * z + ddpsi * x_rot + (dphi * z).cross(dpsi * x_rot);
  K.p_PF_P = Eigen::Vector3d(std::sin(t), 0.2 * t * t, std::cos(2.0 * t));
  K.v_PF_P = Eigen::Vector3d(std::cos(t), 0.4 * t, -2.0 * std::sin(2.0 * t));
  K.a_PF_P = Eigen::Vector3d(-std::sin(t), 0.4, -4.0 * std::cos(2.0 * t));
  return K;
}

// A rigid cloud of point masses about its centre of mass: masses m_i, offsets ρ_i in B (Σ m_i ρ_i = 0).
struct Cloud {
  std::vector<double> m;
  std::vector<Eigen::Vector3d> rho_B;
  double mass() const {
    double M = 0.0;
    for (const double mi : m) M += mi;
    return M;
  }
  Eigen::Matrix3d inertia_com() const {  // Σ m (|ρ|² 1 − ρ ρᵀ)
    Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < m.size(); ++i) I += m[i] * (rho_B[i].squaredNorm() * Eigen::Matrix3d::Identity() - rho_B[i] * rho_B[i].transpose());
    return I;
  }
};

Cloud random_cloud(std::mt19937& rng) {
  std::uniform_real_distribution<double> mass(0.5, 2.0), coordinate(-1.0, 1.0);
  Cloud c;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (int i = 0; i < 7; ++i) {
    c.m.push_back(mass(rng));
    c.rho_B.emplace_back(coordinate(rng), 0.6 * coordinate(rng), 0.3 * coordinate(rng));
    moment += c.m.back() * c.rho_B.back();
  }
  const Eigen::Vector3d centre = moment / c.mass();
  for (auto& r : c.rho_B) r -= centre;
  return c;
}

Eigen::Vector3d random_vector(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return scale * Eigen::Vector3d(u(rng), u(rng), u(rng));
}

Eigen::Quaterniond random_attitude(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
}

// The four fictitious point accelerations of eq. (4.39) at the point r with velocity v relative to F.
struct PointAccelerations {
  Eigen::Vector3d origin, euler, centrifugal, coriolis;
};
PointAccelerations point_accelerations(const FrameTerms& f, const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
  return {-f.a_O_F, -f.alpha_F.cross(r), -f.w_F.cross(f.w_F.cross(r)), -2.0 * f.w_F.cross(v)};
}

// The wrench (at C, torque in B) and power of one term on one body with kinematics k.
template <class Term>
BodyWrench term_wrench(const Term& term, double t, const BodyKinematics& k, double& power) {
  std::vector<BodyWrench> w(1);
  power = term.add_wrenches(t, {k}, w);
  return w[0];
}

TEST(SceneFrame, FictitiousWrenchesEqualSumsOverPointMasses) {
  std::mt19937 rng(12);
  const SceneFrame frame = SceneFrame::moving(FrameMotion(general_motion));
  ASSERT_FALSE(frame.constant_rotation);
  for (int trial = 0; trial < 20; ++trial) {
    const Cloud cloud = random_cloud(rng);
    const std::vector<Body> bodies{RigidBody(cloud.mass(), cloud.inertia_com())};
    const double t = 0.37 * trial;
    BodyKinematics k;
    k.p_W = random_vector(rng, 2.0), k.v_W = random_vector(rng), k.w_B = random_vector(rng, 3.0);
    set_attitude(k, random_attitude(rng));
    k.m = cloud.mass();
    const FrameTerms f = frame_terms(frame, t);
    // the point sums: force Σ m_i a_i, moment about C Σ R ρ_i × m_i a_i (to B), power Σ m_i a_i·v_i
    PointAccelerations sum_f{}, sum_tau{};
    for (auto* v : {&sum_f.origin, &sum_f.euler, &sum_f.centrifugal, &sum_f.coriolis, &sum_tau.origin, &sum_tau.euler,
                    &sum_tau.centrifugal, &sum_tau.coriolis}) {
      v->setZero();
    }
    double power[4] = {0.0, 0.0, 0.0, 0.0};
    for (std::size_t i = 0; i < cloud.m.size(); ++i) {
      const Eigen::Vector3d rho_F = k.q_WB * cloud.rho_B[i];
      const Eigen::Vector3d r = k.p_W + rho_F, v = k.v_W + k.q_WB * k.w_B.cross(cloud.rho_B[i]);
      const PointAccelerations a = point_accelerations(f, r, v);
      const Eigen::Vector3d* parts[4] = {&a.origin, &a.euler, &a.centrifugal, &a.coriolis};
      Eigen::Vector3d* forces[4] = {&sum_f.origin, &sum_f.euler, &sum_f.centrifugal, &sum_f.coriolis};
      Eigen::Vector3d* moments[4] = {&sum_tau.origin, &sum_tau.euler, &sum_tau.centrifugal, &sum_tau.coriolis};
      for (int j = 0; j < 4; ++j) {
        *forces[j] += cloud.m[i] * *parts[j];
        *moments[j] += k.q_WB.conjugate() * rho_F.cross(cloud.m[i] * *parts[j]);
        power[j] += cloud.m[i] * parts[j]->dot(v);
      }
    }
    double p[4];
    const BodyWrench w[4] = {term_wrench(FrameOriginTerm(frame, bodies, "o"), t, k, p[0]),
                             term_wrench(EulerForceTerm(frame, bodies, "e"), t, k, p[1]),
                             term_wrench(CentrifugalTerm(frame, bodies, "c"), t, k, p[2]),
                             term_wrench(CoriolisTerm(frame, bodies, "k"), t, k, p[3])};
    const Eigen::Vector3d* forces[4] = {&sum_f.origin, &sum_f.euler, &sum_f.centrifugal, &sum_f.coriolis};
    const Eigen::Vector3d* moments[4] = {&sum_tau.origin, &sum_tau.euler, &sum_tau.centrifugal, &sum_tau.coriolis};
    // Both sides are sums of a few dozen products (|r| ≤ 4.5, |ρ| ≤ 2, |v| ≤ 12, |Ω|, |α| ≤ 2.6, m ≤ 14): the
    // largest partial products are ≤ 14·2·(2.6·2.6·4.5 + 2·2.6·12 + 4.5) ≈ 2.8e3; each side rounds to a few
    // dozen ε of that (the point sums also cancel Σ m ρ = 0, itself true only to round-off): 64 ε × 2.8e3.
    const double tolerance = 64.0 * kEps * 2.8e3;
    for (int j = 0; j < 4; ++j) {
      EXPECT_LT((w[j].f_W - *forces[j]).norm(), tolerance) << "term " << j << " trial " << trial;
      EXPECT_LT((w[j].tau_B - *moments[j]).norm(), tolerance) << "term " << j << " trial " << trial;
      // Σ m_i a_i·v_i = f·v_C + τ·ω for a rigid body: the term's power
      EXPECT_NEAR(p[j], power[j], tolerance) << "term " << j << " trial " << trial;
    }
    EXPECT_GT(sum_tau.coriolis.norm(), 0.1);  // the test sees a real torque
  }
}

TEST(SceneFrame, CoriolisPowerIsZeroToRoundOff) {
  std::mt19937 rng(7);
  const SceneFrame frame = SceneFrame::moving(FrameMotion(general_motion));
  const Cloud cloud = random_cloud(rng);
  const std::vector<Body> bodies{Particle(1.3), PlanarBody(2.0, 0.4), RigidBody(cloud.mass(), cloud.inertia_com())};
  const CoriolisTerm coriolis(frame, bodies, "frame.coriolis");
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<BodyKinematics> k(3);
    for (std::size_t b = 0; b < 3; ++b) {
      k[b].p_W = random_vector(rng, 3.0), k[b].v_W = random_vector(rng, 2.0), k[b].m = mass_of(bodies[b]);
    }
    k[1].p_W.z() = 0.0, k[1].v_W.z() = 0.0, k[1].w_B = Eigen::Vector3d(0.0, 0.0, 1.7);
    set_attitude(k[1], Eigen::Quaterniond(Eigen::AngleAxisd(0.4 * trial, Eigen::Vector3d::UnitZ())));
    set_attitude(k[2], random_attitude(rng));
    k[2].w_B = random_vector(rng, 5.0);
    std::vector<BodyWrench> w(3);
    const double t = 0.1 * trial, power = coriolis.add_wrenches(t, k, w);
    // each product f·v, τ·ω is zero in exact arithmetic; its rounding is a few ε of Σ |f||v| + |τ||ω|
    double scale = 0.0;
    for (std::size_t b = 0; b < 3; ++b) scale += w[b].f_W.norm() * k[b].v_W.norm() + w[b].tau_B.norm() * k[b].w_B.norm();
    ASSERT_GT(scale, 1.0);
    EXPECT_LE(std::abs(power), 16.0 * kEps * scale) << "trial " << trial;
  }
}

TEST(SceneFrame, ConstantRotationHasOnlyCentrifugalAndCoriolisTerms) {
  const SceneFrame frame = SceneFrame::rotating(Eigen::Vector3d(0.0, 0.0, 2.0), 0.5);
  EXPECT_TRUE(frame.constant_rotation);
  for (const double t : {0.0, 1.0, 1e3}) {
    const FrameTerms f = frame_terms(frame, t);
    EXPECT_EQ(f.w_F, Eigen::Vector3d(0.0, 0.0, 0.5));  // the axis is fixed in F and in W: exact
    EXPECT_EQ(f.alpha_F, Eigen::Vector3d::Zero());
    EXPECT_EQ(f.a_O_F, Eigen::Vector3d::Zero());
  }
  const std::vector<Body> bodies{Particle(1.0)};
  EXPECT_TRUE(CentrifugalTerm(frame, bodies, "c").traits().has_potential);
  EXPECT_FALSE(CentrifugalTerm(frame, bodies, "c").traits().time_dependent);
  EXPECT_FALSE(CentrifugalTerm(SceneFrame::moving(FrameMotion(general_motion)), bodies, "c").traits().has_potential);
  EXPECT_TRUE(CoriolisTerm(frame, bodies, "k").traits().velocity_dependent);
  // a motion built by FrameMotion::constant_rotation is recognised as one
  EXPECT_TRUE(SceneFrame::moving(FrameMotion::constant_rotation(Eigen::Vector3d::UnitX(), 1.0)).constant_rotation);
}

TEST(SceneFrame, EarthFrameTurnsAboutTheLocalNorthAxis) {
  const double latitude = 0.8526;  // ≈ 48.85°
  const FrameTerms f = frame_terms(SceneFrame::earth(latitude), 3600.0);
  // cos, sin and one product each: 2 ulps of Ω
  EXPECT_NEAR(f.w_F.x(), 0.0, 0.0);
  EXPECT_NEAR(f.w_F.y(), 7.2921159e-5 * std::cos(latitude), 2.0 * kEps * 7.3e-5);
  EXPECT_NEAR(f.w_F.z(), 7.2921159e-5 * std::sin(latitude), 2.0 * kEps * 7.3e-5);
}

using rigiddyn::test::message_of;

TEST(SceneFrame, BadFrameValuesRaiseNamingTheirArgument) {
  const SceneFrame nan_after_1s = SceneFrame::moving(FrameMotion([](double t) {
    FrameKinematics K = general_motion(t);
    if (t > 1.0) K.alpha_PF_P.x() = std::numeric_limits<double>::quiet_NaN();
    return K;
  }));
  EXPECT_NO_THROW(frame_terms(nan_after_1s, 0.5));
  const std::string message = message_of([&] { frame_terms(nan_after_1s, 2.0); });
  EXPECT_EQ(message.rfind("frame: expected finite values from the motion function at t = 2 s, got ", 0), 0u) << message;
  // through a term, as a run meets it
  const std::vector<Body> bodies{Particle(1.0)};
  std::vector<BodyKinematics> k(1);
  k[0].m = 1.0;
  std::vector<BodyWrench> w(1);
  EXPECT_EQ(message_of([&] { EulerForceTerm(nan_after_1s, bodies, "e").add_wrenches(2.0, k, w); }).rfind("frame: ", 0), 0u);
  const SceneFrame infinite_origin = SceneFrame::moving(FrameMotion([](double t) {
    FrameKinematics K = general_motion(t);
    K.a_PF_P.z() = std::numeric_limits<double>::infinity();
    return K;
  }));
  EXPECT_EQ(message_of([&] { FrameOriginTerm(infinite_origin, bodies, "o").add_wrenches(0.0, k, w); }).rfind("frame: ", 0), 0u);
  const SceneFrame not_a_rotation = SceneFrame::moving(FrameMotion([](double) {
    FrameKinematics K;
    K.R_PF(0, 0) = 2.0;
    return K;
  }));
  EXPECT_EQ(message_of([&] { frame_terms(not_a_rotation, 0.0); }).rfind("frame: expected a rotation matrix", 0), 0u);
  EXPECT_EQ(message_of([] { SceneFrame::rotating(Eigen::Vector3d::Zero(), 1.0); }).rfind("axis_F: ", 0), 0u);
  EXPECT_EQ(message_of([] { SceneFrame::rotating(Eigen::Vector3d(0, 0, std::nan("")), 1.0); }).rfind("axis_F: ", 0), 0u);
  EXPECT_EQ(message_of([] { SceneFrame::rotating(Eigen::Vector3d::UnitZ(), INFINITY); }).rfind("rate: ", 0), 0u);
  EXPECT_EQ(message_of([] { SceneFrame::earth(2.0); }).rfind("latitude: ", 0), 0u);
  EXPECT_EQ(message_of([] { SceneFrame::earth(std::nan("")); }).rfind("latitude: ", 0), 0u);
}

// ---- runs ------------------------------------------------------------------------------------------------

// The terms of `frame` for compile's rule: a constant rotation adds centrifugal + Coriolis, else all four.
std::vector<FrameModel::Term> frame_terms_of(const SceneFrame& frame, const std::vector<Body>& bodies) {
  std::vector<FrameModel::Term> terms;
  if (!frame.constant_rotation) {
    terms.emplace_back(FrameOriginTerm(frame, bodies, "frame.origin"));
    terms.emplace_back(EulerForceTerm(frame, bodies, "frame.euler"));
  }
  terms.emplace_back(CentrifugalTerm(frame, bodies, "frame.centrifugal"));
  terms.emplace_back(CoriolisTerm(frame, bodies, "frame.coriolis"));
  return terms;
}

template <class Model>
typename Model::Coordinates run_rk4(const Model& model, typename Model::Coordinates y, double h, int steps) {
  auto work = workspace<Rk4>(model, y);
  for (int i = 0; i < steps; ++i) Rk4::step(model, y, h, work);
  return y;
}

// A torque-free asymmetric rigid body and a free particle, run in W, and run in F from the same initial
// state seen from F: at t the F-run equals the W-run transformed (p_F = R_FW (p_W − p_WO), v_F = R_FW (v_W −
// v_WO) − Ω × p_F, q_FB = q_FW q_WB, ω_rel = ω_abs − Ω_B). Both runs are RK4 at h = 1e-3 over 2 s.
TEST(SceneFrame, RunInGeneralMovingFrameEqualsInertialRunTransformed) {
  const SceneFrame frame = SceneFrame::moving(FrameMotion(general_motion));
  Eigen::Matrix3d I;
  I << 2.0, 0.1, -0.05, 0.1, 2.5, 0.2, -0.05, 0.2, 3.0;
  const std::vector<Body> bodies{RigidBody(1.5, I), Particle(0.7)};
  RigidBodyState body_W;
  body_W.p_W = Eigen::Vector3d(0.3, -0.2, 0.5), body_W.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  body_W.v_W = Eigen::Vector3d(0.5, 0.1, -0.3), body_W.w_B = Eigen::Vector3d(0.4, 1.5, -0.6);
  const ParticleState particle_W{Eigen::Vector3d(1.0, 0.5, -0.4), Eigen::Vector3d(-0.3, 0.8, 0.2)};
  // one frame's view of a state in W at t
  const auto to_F = [&](double t, const RigidBodyState& s, RigidBodyState& out) {
    const FrameKinematics K = general_motion(t);
    const Eigen::Matrix3d R_FW = K.R_PF.transpose();
    const Eigen::Vector3d w_F = R_FW * K.w_PF_P;
    out.p_W = R_FW * (s.p_W - K.p_PF_P);
    out.v_W = R_FW * (s.v_W - K.v_PF_P) - w_F.cross(out.p_W);
    out.q_WB = Eigen::Quaterniond(R_FW) * s.q_WB;
    out.w_B = s.w_B - out.q_WB.conjugate() * w_F;
  };
  const SceneModel inertial(bodies, {});
  const FrameModel moving(bodies, frame_terms_of(frame, bodies));
  const double t0 = 0.2, h = 1e-3;
  const int steps = 2000;
  RigidBodyState body_F;
  to_F(t0, body_W, body_F);
  RigidBodyState particle_as_body{particle_W.p_W, Eigen::Quaterniond::Identity(), particle_W.v_W, Eigen::Vector3d::Zero()}, particle_F;
  to_F(t0, particle_as_body, particle_F);
  const auto yW = run_rk4(inertial, inertial.coordinates({body_W, particle_W}, t0), h, steps);
  const auto yF = run_rk4(moving, moving.coordinates({body_F, ParticleState{particle_F.p_W, particle_F.v_W}}, t0), h, steps);
  const double t1 = t0 + steps * h;
  EXPECT_NEAR(yF[moving.time_index()], t1, 1e-12);
  const auto sW = inertial.states(yW), sF = moving.states(yF);
  RigidBodyState expected, expected_particle;
  to_F(t1, std::get<RigidBodyState>(sW[0]), expected);
  const ParticleState& pW = std::get<ParticleState>(sW[1]);
  to_F(t1, RigidBodyState{pW.p_W, Eigen::Quaterniond::Identity(), pW.v_W, Eigen::Vector3d::Zero()}, expected_particle);
  const auto& got = std::get<RigidBodyState>(sF[0]);
  const auto& got_particle = std::get<ParticleState>(sF[1]);
  // RK4's global error in each run ≲ T h⁴ max|y⁽⁵⁾|/120 with |y⁽⁵⁾| ≲ (|ω| + |Ω| + |α|)⁵ |y| ≈ 4⁵·3 ≈ 3e3:
  // 2·1e-12·3e3/120 ≈ 5e-11 per run; 1e-9 leaves a factor 10 for the constants of the bound.
  const double bound = 1e-9;
  EXPECT_LT((got.p_W - expected.p_W).norm(), bound);
  EXPECT_LT((got.v_W - expected.v_W).norm(), bound);
  EXPECT_LT(got.q_WB.angularDistance(expected.q_WB), bound);
  EXPECT_LT((got.w_B - expected.w_B).norm(), bound);
  EXPECT_LT((got_particle.p_W - expected_particle.p_W).norm(), bound);
  EXPECT_LT((got_particle.v_W - expected_particle.v_W).norm(), bound);
  // the frame moved the run: the F-state is far from the W-state
  EXPECT_GT((got.p_W - std::get<RigidBodyState>(sW[0]).p_W).norm(), 0.1);
}

// A free planar body (in W's xy plane) seen from a frame turning about z: its run in F equals the W-run
// turned by −Ω t (θ_F = θ_W − Ω t, ω_F = ω_W − Ω, p_F = R_FW p_W, v_F = R_FW v_W − Ω × p_F); with Ω along z its
// fictitious torques vanish and its in-plane forces carry the motion. RK4, h = 1e-3 over 2 s: RK4's error
// ≲ T h⁴ |y⁽⁵⁾|/120 with |y⁽⁵⁾| ≲ (2|Ω| + |ω|)⁵ |y| ≈ 3.4⁵ · 3 ≈ 1.4e3, ~3e-11; 1e-9 leaves a factor 30.
TEST(SceneFrame, PlanarBodyRunInRotatingFrameEqualsInertialRunTransformed) {
  const double rate = 0.7;
  const SceneFrame frame = SceneFrame::rotating(Eigen::Vector3d::UnitZ(), rate);
  const std::vector<Body> bodies{PlanarBody(1.2, 0.3)};
  const SceneModel inertial(bodies, {});
  const SceneModel moving(bodies, frame_terms_of(frame, bodies));
  const PlanarBodyState s_W{Eigen::Vector2d(0.5, 0.2), 0.3, Eigen::Vector2d(0.4, 1.0), 2.0};
  const auto to_F = [&](double t, const PlanarBodyState& s) {
    const Eigen::Matrix2d R_FW = Eigen::Rotation2Dd(-rate * t).toRotationMatrix();
    const Eigen::Vector2d p = R_FW * s.p_W;
    const Eigen::Vector2d w_x_p(-rate * p.y(), rate * p.x());  // Ω × p in the plane
    return PlanarBodyState{p, s.theta - rate * t, R_FW * s.v_W - w_x_p, s.omega - rate};
  };
  const auto yW = run_rk4(inertial, inertial.coordinates({s_W}, 0.0), 1e-3, 2000);
  const auto yF = run_rk4(moving, moving.coordinates({to_F(0.0, s_W)}, 0.0), 1e-3, 2000);
  const PlanarBodyState expected = to_F(2.0, std::get<PlanarBodyState>(inertial.states(yW)[0]));
  const PlanarBodyState got = std::get<PlanarBodyState>(moving.states(yF)[0]);
  EXPECT_LT((got.p_W - expected.p_W).norm(), 1e-9);
  EXPECT_LT((got.v_W - expected.v_W).norm(), 1e-9);
  EXPECT_NEAR(got.theta, expected.theta, 1e-9);
  EXPECT_NEAR(got.omega, expected.omega, 1e-9);
  EXPECT_GT((got.p_W - std::get<PlanarBodyState>(inertial.states(yW)[0]).p_W).norm(), 0.1);  // F moved the run
}

// Jacobi's integral: kinetic energy relative to F plus the potentials of gravity and of the centrifugal
// force, for an asymmetric rigid body and a particle in a frame turning at a constant rate (the recorded
// total_energy). Its change over a RK4 run is RK4's truncation error: order 4 in h, which the test checks
// by halving h (a wrong or missing term would change the integral at O(1), independent of h).
TEST(SceneFrame, JacobiIntegralIsConservedInAConstantRotation) {
  const SceneFrame frame = SceneFrame::rotating(Eigen::Vector3d(0.2, -0.3, 1.0), 0.8);
  const std::vector<Body> bodies{RigidBody(2.0, Eigen::Vector3d(1.0, 2.0, 2.5)), Particle(0.5)};
  std::vector<FrameModel::Term> terms = frame_terms_of(frame, bodies);
  terms.insert(terms.begin(), UniformGravityTerm(UniformGravity{Eigen::Vector3d(0.0, 0.0, -9.81), {}}, bodies, "elements[0]"));
  const FrameModel model(bodies, terms);
  RigidBodyState body;
  body.p_W = Eigen::Vector3d(1.0, 0.5, 0.0), body.v_W = Eigen::Vector3d(0.0, 0.3, 1.0);
  body.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY())), body.w_B = Eigen::Vector3d(0.5, 1.2, -0.3);
  const ParticleState particle{Eigen::Vector3d(-0.5, 1.0, 0.2), Eigen::Vector3d(0.4, 0.0, 2.0)};
  const auto jacobi_change = [&](double h) {
    const int steps = static_cast<int>(std::lround(2.0 / h));
    SceneSimulation records;
    auto y = model.coordinates({body, particle}, 0.0);
    model.record(y, 0.0, records);
    y = run_rk4(model, y, h, steps);
    model.record(y, 2.0, records);
    return std::abs(records.total_energy[1] - records.total_energy[0]);
  };
  const double coarse = jacobi_change(0.02), fine = jacobi_change(0.01);
  // the integral is ~30 J; RK4 at h = 0.01: ~1e-7 relative; the ratio of an order-4 error: 16 (≥ 10 with the
  // next term of the expansion)
  EXPECT_LT(fine, 1e-6);
  EXPECT_GT(coarse / fine, 10.0) << coarse << " " << fine;
  // the potential includes the centrifugal part: the terms' own potential at the start is not zero
  std::vector<BodyKinematics> k{kinematics_of(bodies[0], body), kinematics_of(bodies[1], particle)};
  EXPECT_LT(CentrifugalTerm(frame, bodies, "c").potential(k), -0.1);
}

}  // namespace
