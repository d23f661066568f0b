// The force elements of scenes (scene/elements/*.hpp), each against what defines it:
// force = −∇_p V and torque = −∂V/∂δθ (a small body rotation) by central differences of the element's own
// potential; the returned power = Σ f_W·v_W + tau_B·w_B; Newton's third law for internal elements; closed
// forms at known geometry (Newton's law, the spring, drag, the gravity-gradient pitch torque, the compass
// needle's torque and the force between coaxial magnetic dipoles); the
// gravity gradient against the exact attraction of a cloud of point masses; every validation message.
#include <gtest/gtest.h>

#include "test_inputs.hpp"
#include "test_numbers.hpp"
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/elements/drag.hpp"
#include "rigiddyn/scene/elements/function_force.hpp"
#include "rigiddyn/scene/elements/gravity_gradient.hpp"
#include "rigiddyn/scene/elements/magnetic_dipole.hpp"
#include "rigiddyn/scene/elements/mutual_gravity.hpp"
#include "rigiddyn/scene/elements/point_mass_gravity.hpp"
#include "rigiddyn/scene/elements/reaction_wheel.hpp"
#include "rigiddyn/scene/elements/spring_damper.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace rigiddyn {
namespace {

using rigiddyn::test::kEps;
using rigiddyn::test::kInf;
using rigiddyn::test::kNaN;
const std::string kName = "elements[2]";

using Kinematics = std::vector<BodyKinematics>;
using Wrenches = std::vector<BodyWrench>;

// A realizable full inertia: principal moments (1.0, 1.4, 2.1) [kg m²] turned by a fixed rotation.
using test::full_inertia;

// One body of each kind and a second rigid body: 0 particle, 1 planar body, 2 rigid (full inertia),
// 3 rigid (principal axes).
std::vector<Body> mixed_bodies() {
  return {Particle(1.3), PlanarBody(0.9, 0.4), RigidBody(1.7, full_inertia()),
          RigidBody(0.6, Eigen::Vector3d(0.3, 0.5, 0.7))};
}

// A uniformly random rotation (Shoemake 1992: a normalised 4-D Gaussian).
using test::random_rotation;

using test::random_vector;

// Random kinematics of mixed_bodies(), each kind as elements see it (body_kinematics.hpp). The centres of
// mass lie within 0.3 (per axis) of (0,0,0), (2,0,0), (0,2,0), (0,0,2): any two are >= 2 − 2·0.3·√3 > 0.9
// apart, and >= 4 from the attractor at (−3, −3, −3) used below.
Kinematics random_kinematics(std::mt19937& rng) {
  const Eigen::Vector3d base[4] = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}};
  Kinematics k(4);
  for (int b = 0; b < 4; ++b) {
    k[b].p_W = base[b] + random_vector(rng, 0.3);
    k[b].v_W = random_vector(rng, 1.0);
    set_attitude(k[b], random_rotation(rng));
    k[b].w_B = random_vector(rng, 2.0);
  }
  set_attitude(k[0], Eigen::Quaterniond::Identity());  // particle
  k[0].w_B.setZero();
  k[1].p_W.z() = 0.0, k[1].v_W.z() = 0.0, k[1].w_B.head<2>().setZero();  // planar
  set_attitude(k[1], Eigen::Quaterniond(Eigen::AngleAxisd(std::uniform_real_distribution<double>(-3, 3)(rng), Eigen::Vector3d::UnitZ())));
  const std::vector<Body> bodies = mixed_bodies();
  for (int b = 0; b < 4; ++b) k[b].m = mass_of(bodies[b]);  // the mass now, as the model sets it
  return k;
}

const Eigen::Vector3d kAttractor(-3.0, -3.0, -3.0);

template <class Term>
Wrenches wrenches_of(const Term& term, const Kinematics& k, double* power = nullptr, double t = 0.0) {
  Wrenches w(k.size());
  const double p = term.add_wrenches(t, k, w);
  if (power) *power = p;
  return w;
}

// Central differences of the term's potential: f_W[i] ≈ −(V(p + h e_i) − V(p − h e_i))/(2h) and, for the
// body rotation q → q exp(h e_i / 2) (δθ = h e_i in B, the variation conjugate to w_B),
// tau_B[i] ≈ −(V(+) − V(−))/(2h), for every body, also particles (whose V ignores the attitude: 0).
// Error bound: truncation h²/6 max|∂³V| plus rounding 2·(16 eps max|V|)/(2h) (V to 16 ulps). In every state
// used here (separations >= 0.9, distance to the attractor >= 4, masses <= 1.7, GM, G, k <= 3, lever
// arms <= 1, |I| <= 2.1) |∂³V| <= 1e3 (e.g. GM m ∂³(1/r) <= 3·1.7·15/0.9⁴ < 120 per pair, 8 pairs at
// most) and |V| <= 1e2; with h = 1e-5: 1e3·1e-10/6 + 16·2.2e-16·1e2/1e-5 < 5e-8.
template <class Term>
void expect_wrench_is_minus_gradient(const Term& term, const Kinematics& k) {
  constexpr double h = 1e-5, tol = 5e-8;
  const Wrenches w = wrenches_of(term, k);
  for (std::size_t b = 0; b < k.size(); ++b) {
    for (int i = 0; i < 3; ++i) {
      Kinematics plus = k, minus = k;
      plus[b].p_W[i] += h, minus[b].p_W[i] -= h;
      EXPECT_NEAR(w[b].f_W[i], -(term.potential(plus) - term.potential(minus)) / (2 * h), tol) << "body " << b << " f_W[" << i << "]";
      const Eigen::Quaterniond turn(Eigen::AngleAxisd(h, Eigen::Vector3d::Unit(i)));
      plus = k, minus = k;
      set_attitude(plus[b], k[b].q_WB * turn), set_attitude(minus[b], k[b].q_WB * turn.conjugate());
      EXPECT_NEAR(w[b].tau_B[i], -(term.potential(plus) - term.potential(minus)) / (2 * h), tol) << "body " << b << " tau_B[" << i << "]";
    }
  }
}

// The returned power is Σ f_W·v_W + tau_B·w_B of the wrenches added. The two sides round differently (a
// term may compute it as f·ẋ of a rotated point): each of the <= 8 products to <= 16 ulps of
// |f||v| + |τ||ω| ⇒ tol = 128 eps Σ(|f||v| + |τ||ω|).
template <class Term>
void expect_power_matches(const Term& term, const Kinematics& k, double t = 0.0) {
  double power = 0.0;
  const Wrenches w = wrenches_of(term, k, &power, t);
  double sum = 0.0, scale = 0.0;
  for (std::size_t b = 0; b < k.size(); ++b) {
    sum += w[b].f_W.dot(k[b].v_W) + w[b].tau_B.dot(k[b].w_B);
    scale += w[b].f_W.norm() * k[b].v_W.norm() + w[b].tau_B.norm() * k[b].w_B.norm();
  }
  EXPECT_GT(scale, 0.0);  // the check is not vacuous
  EXPECT_NEAR(power, sum, 128 * kEps * scale);
}

// Newton's third law of an internal element: Σ f_W = 0 and Σ (p_W × f_W + R_WB tau_B) = 0 (moment about
// W's origin). Rounding: each force/moment entry to a few ulps of its size, summed over the bodies:
// tol = 64 eps Σ (|f| (1 + |p|) + |τ|).
void expect_internal(const Wrenches& w, const Kinematics& k) {
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  double scale = 0.0;
  for (std::size_t b = 0; b < k.size(); ++b) {
    force += w[b].f_W;
    moment += k[b].p_W.cross(w[b].f_W) + k[b].q_WB * w[b].tau_B;
    scale += w[b].f_W.norm() * (1.0 + k[b].p_W.norm()) + w[b].tau_B.norm();
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(force.norm(), 64 * kEps * scale);
  EXPECT_LT(moment.norm(), 64 * kEps * scale);
}

// Runs make() and expects std::invalid_argument with exactly `message`.
void expect_error(const std::function<void()>& make, const std::string& message) {
  try {
    make();
    ADD_FAILURE() << "no exception, expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

// ---------------------------------------------------------------------------------------------------
// body.hpp helpers

TEST(SceneBody, MassAndInertiaOfEachKind) {
  const std::vector<Body> bodies = mixed_bodies();
  EXPECT_EQ(mass_of(bodies[0]), 1.3);
  EXPECT_EQ(mass_of(bodies[1]), 0.9);
  EXPECT_EQ(mass_of(bodies[2]), 1.7);
  EXPECT_TRUE(inertia_com_of(bodies[0]).isZero(0.0));
  EXPECT_EQ(inertia_com_of(bodies[1]), Eigen::Matrix3d(Eigen::Vector3d(0, 0, 0.4).asDiagonal()));
  EXPECT_EQ(inertia_com_of(bodies[2]), std::get<RigidBody>(bodies[2]).inertia_com());
  EXPECT_FALSE(has_attitude(bodies[0]));
  EXPECT_TRUE(has_attitude(bodies[1]) && has_attitude(bodies[2]));
}

TEST(SceneBody, KinematicsOfEachKind) {
  PlanarBodyState planar;
  planar.p_W = {1.0, 2.0}, planar.theta = 0.5, planar.v_W = {-1.0, 3.0}, planar.omega = 0.25;
  const BodyKinematics k = kinematics_of(planar);
  EXPECT_EQ(k.p_W, Eigen::Vector3d(1, 2, 0));
  EXPECT_EQ(k.v_W, Eigen::Vector3d(-1, 3, 0));
  EXPECT_EQ(k.w_B, Eigen::Vector3d(0, 0, 0.25));
  // Rz(θ) to one rounding of the angle-axis conversion
  EXPECT_LT((k.q_WB.toRotationMatrix() - Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix()).norm(), 4 * kEps);
  ParticleState particle;
  particle.p_W = {1, 2, 3}, particle.v_W = {4, 5, 6};
  const BodyKinematics kp = kinematics_of(particle);
  EXPECT_EQ(kp.p_W, particle.p_W);
  EXPECT_EQ(kp.v_W, particle.v_W);
  EXPECT_EQ(kp.q_WB.coeffs(), Eigen::Quaterniond::Identity().coeffs());
  EXPECT_TRUE(kp.w_B.isZero(0.0));
}

// A body's point in the spatial layer (body_kinematics.hpp): pose().act_point(r_B) moves at point_velocity_W(r_B) (the
// central difference of the point along the body's motion p + v t, R exp(t [w_B]×)), which is the velocity at r_W of
// the body's twist about its centre of mass in W's axes (R ω_B, v_W); a force f at the point, added as
// Force::at_point(r_W, f), gives the body the moment r_B × Rᵀ f in B and the power f·ẋ.
TEST(SceneBody, PointKinematicsAndWrenchInTheSpatialLayer) {
  std::mt19937 rng(40);
  for (int sample = 0; sample < 50; ++sample) {
    BodyKinematics k;
    k.p_W = random_vector(rng, 2.0), k.v_W = random_vector(rng, 1.0), k.w_B = random_vector(rng, 2.0);
    set_attitude(k, random_rotation(rng));
    const Eigen::Vector3d r_B = random_vector(rng, 1.0), f_W = random_vector(rng, 1.0);
    const auto point_at = [&](double t) {
      BodyKinematics moved = k;
      moved.p_W = k.p_W + t * k.v_W;
      set_attitude(moved, k.q_WB * Eigen::Quaterniond(Eigen::AngleAxisd(t * k.w_B.norm(), k.w_B.normalized())));
      return moved.pose().act_point(r_B);
    };
    const Motion twist_W(k.R_WB * k.w_B, k.v_W);
    const Eigen::Vector3d r_W = k.R_WB * r_B, xdot = k.point_velocity_W(r_B);
    // the two forms of the point's velocity differ by the roundings of R (ω × r) and (R ω) × (R r) (a few eps of |ω| |r|
    // <= 6.3 each) and R's departure from orthogonality: <= 16 eps (1 + |ω| |r|)
    EXPECT_LT((twist_W.velocity_at(r_W) - xdot).norm(), 16 * kEps * (1.0 + k.w_B.norm() * r_B.norm()));
    EXPECT_LT((point_at(0.0) - (k.p_W + r_W)).norm(), 8 * kEps * (k.p_W.norm() + r_B.norm()));
    // truncation h²/6 |x⃛| <= h²/6 |ω|³ |r| <= 1e-10/6 · 3.5³ · 1.8 < 1.3e-9 (|ω| <= 2√3, |r| <= √3); rounding
    // 2 · 16 eps |x| / (2h) with |x| <= 3√3 + √3 < 7: < 2.5e-9
    constexpr double h = 1e-5;
    EXPECT_LT((point_at(h) - point_at(-h) - 2.0 * h * xdot).norm() / (2.0 * h), 7e-9);
    BodyWrench wrench;
    wrench.add(k.R_WB, Force::at_point(r_W, f_W));
    EXPECT_EQ(wrench.f_W, f_W);
    const Eigen::Vector3d tau_B = r_B.cross(k.R_WB.transpose() * f_W);
    // the two forms differ by the roundings of R r, the cross product and Rᵀ n (each a row sum of three products: <= 3
    // eps of |r| |f|) and by R's departure from orthogonality (<= 4 eps): <= 16 eps |r| |f|
    EXPECT_LT((wrench.tau_B - tau_B).norm(), 16 * kEps * r_B.norm() * f_W.norm());
    // the power three ways: the pairing of the twist with the wrench, f·ẋ, f·v + τ·ω; each a sum of products of
    // |f| |v| and |f| |r| |ω| (|ω| <= 4) rounded a few times each: <= 32 eps of their scale
    const double power = f_W.dot(k.v_W) + wrench.tau_B.dot(k.w_B);
    const double scale = 1.0 + f_W.norm() * (k.v_W.norm() + 4.0 * r_B.norm());
    EXPECT_NEAR(twist_W.dot(Force::at_point(r_W, f_W)), power, 32 * kEps * scale);
    EXPECT_NEAR(f_W.dot(xdot), power, 32 * kEps * scale);
  }
}

TEST(SceneBody, CheckBodyIndex) {
  EXPECT_NO_THROW(check_body_index(3, 4, "x"));
  expect_error([] { check_body_index(4, 4, "elements[0].body_a"); }, "elements[0].body_a: expected a body index in [0, 4), got 4");
  expect_error([] { check_body_index(-1, 4, "b"); }, "b: expected a body index in [0, 4), got -1");
}

// ---------------------------------------------------------------------------------------------------
// PointMassGravity

TEST(PointMassGravity, NewtonsLawAtKnownGeometry) {
  const std::vector<Body> bodies = {Particle(2.0)};
  Kinematics k(1);
  k[0].p_W = Eigen::Vector3d(1.0, 1.0, 1.0) + Eigen::Vector3d(3.0, 4.0, 0.0);  // r = (3, 4, 0), |r| = 5
  k[0].m = 2.0;
  const PointMassGravityTerm term(PointMassGravity{5.0, Eigen::Vector3d(1, 1, 1), 0.0, {}}, bodies, kName);
  // f = −GM m r/|r|³ = −10 (3, 4, 0)/125, V = −GM m/|r| = −2; to a few ulps of the operands
  const Wrenches w = wrenches_of(term, k);
  EXPECT_LT((w[0].f_W - Eigen::Vector3d(-0.24, -0.32, 0.0)).norm(), 8 * kEps);
  EXPECT_NEAR(term.potential(k), -2.0, 8 * kEps);
  // softening ε = 12: |r|² + ε² = 13²
  const PointMassGravityTerm soft(PointMassGravity{5.0, Eigen::Vector3d(1, 1, 1), 12.0, {}}, bodies, kName);
  EXPECT_LT((wrenches_of(soft, k)[0].f_W - Eigen::Vector3d(-30.0, -40.0, 0.0) / 2197.0).norm(), 8 * kEps);
  EXPECT_NEAR(soft.potential(k), -10.0 / 13.0, 8 * kEps);
}

TEST(PointMassGravity, ConservativeWithCorrectPower) {
  std::mt19937 rng(11);
  const std::vector<Body> bodies = mixed_bodies();
  for (const double softening : {0.0, 0.7}) {
    const PointMassGravityTerm term(PointMassGravity{2.5, kAttractor, softening, {}}, bodies, kName);
    for (int trial = 0; trial < 5; ++trial) {
      const Kinematics k = random_kinematics(rng);
      expect_wrench_is_minus_gradient(term, k);
      expect_power_matches(term, k);
    }
  }
  const auto traits = PointMassGravityTerm::traits();
  EXPECT_TRUE(traits.has_potential);
  EXPECT_FALSE(traits.reads_attitude || traits.velocity_dependent || traits.time_dependent || traits.has_torque);
}

TEST(PointMassGravity, ActsOnlyOnListedBodies) {
  std::mt19937 rng(12);
  const std::vector<Body> bodies = mixed_bodies();
  const PointMassGravityTerm term(PointMassGravity{2.5, kAttractor, 0.0, {3, 1}}, bodies, kName);
  const Wrenches w = wrenches_of(term, random_kinematics(rng));
  EXPECT_TRUE(w[0].f_W.isZero(0.0) && w[2].f_W.isZero(0.0));
  EXPECT_FALSE(w[1].f_W.isZero(0.0) || w[3].f_W.isZero(0.0));
}

// ---------------------------------------------------------------------------------------------------
// MutualGravity

TEST(MutualGravity, TwoBodiesAtKnownGeometry) {
  const std::vector<Body> bodies = {Particle(2.0), Particle(3.0)};
  Kinematics k(2);
  k[1].p_W = Eigen::Vector3d(0.0, 0.0, 2.0);
  k[0].m = 2.0, k[1].m = 3.0;
  const MutualGravityTerm term(MutualGravity{0.5, 0.0, {}}, bodies, kName);
  // |f| = G m1 m2/r² = 0.5·6/4 = 0.75, body 0 pulled towards +z; V = −G m1 m2/r = −1.5 (few ulps)
  const Wrenches w = wrenches_of(term, k);
  EXPECT_LT((w[0].f_W - Eigen::Vector3d(0, 0, 0.75)).norm(), 4 * kEps);
  EXPECT_EQ(w[1].f_W, -w[0].f_W);  // the same computed f, negated
  EXPECT_NEAR(term.potential(k), -1.5, 4 * kEps);
}

TEST(MutualGravity, ConservativeInternalWithCorrectPower) {
  std::mt19937 rng(21);
  const std::vector<Body> bodies = mixed_bodies();
  for (const double softening : {0.0, 0.4}) {
    const MutualGravityTerm term(MutualGravity{2.0, softening, {}}, bodies, kName);
    EXPECT_TRUE(term.traits().zero_net_wrench);  // as expect_internal below finds
    for (int trial = 0; trial < 5; ++trial) {
      const Kinematics k = random_kinematics(rng);
      expect_wrench_is_minus_gradient(term, k);
      expect_power_matches(term, k);
      expect_internal(wrenches_of(term, k), k);
      // V against the pair sum written out here (rounding: 6 pairs, each to a few ulps)
      double V = 0.0, scale = 0.0;
      for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
          const double pair = 2.0 * mass_of(bodies[i]) * mass_of(bodies[j]) /
                              std::sqrt((k[i].p_W - k[j].p_W).squaredNorm() + softening * softening);
          V -= pair, scale += pair;
        }
      }
      EXPECT_NEAR(term.potential(k), V, 32 * kEps * scale);
    }
  }
}

TEST(MutualGravity, SubsetOfBodies) {
  std::mt19937 rng(22);
  const std::vector<Body> bodies = mixed_bodies();
  const Kinematics k = random_kinematics(rng);
  const MutualGravityTerm term(MutualGravity{1.0, 0.0, {3, 0}}, bodies, kName);
  const Wrenches w = wrenches_of(term, k);
  EXPECT_TRUE(w[1].f_W.isZero(0.0) && w[2].f_W.isZero(0.0));
  EXPECT_EQ(w[0].f_W, -w[3].f_W);
  const Eigen::Vector3d d = k[3].p_W - k[0].p_W;  // Newton's law for the one pair, to a few ulps
  EXPECT_LT((w[0].f_W - 1.3 * 0.6 * d / std::pow(d.norm(), 3)).norm(), 16 * kEps * w[0].f_W.norm());
  // one body or none: no pair, no force
  const MutualGravityTerm lonely(MutualGravity{1.0, 0.0, {2}}, bodies, kName);
  for (const BodyWrench& wb : wrenches_of(lonely, k)) EXPECT_TRUE(wb.f_W.isZero(0.0));
  EXPECT_EQ(lonely.potential(k), 0.0);
}

// Many bodies (odd count, so the vectorised inner loop meets every remainder length): each body's force
// against the sum over all j ≠ i written out here, total force ≈ 0, power = Σ f·v.
TEST(MutualGravity, ManyBodiesAgainstDirectSum) {
  std::mt19937 rng(23);
  const int n = 37;
  std::vector<Body> bodies;
  Kinematics k(n);
  for (int i = 0; i < n; ++i) {
    bodies.emplace_back(Particle(0.5 + std::uniform_real_distribution<double>(0, 1)(rng)));
    k[i].p_W = random_vector(rng, 3.0), k[i].v_W = random_vector(rng, 1.0);
    k[i].m = mass_of(bodies[i]);
  }
  const double G = 1.5, softening = 0.05;
  const MutualGravityTerm term(MutualGravity{G, softening, {}}, bodies, kName);
  double power = 0.0;
  const Wrenches w = wrenches_of(term, k, &power);
  const double sum_tol = 2 * (n + 4) * kEps;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  double total_scale = 0.0, expected_power = 0.0, V = 0.0, V_scale = 0.0;
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    double scale = 0.0;  // Σ_j |f_ij|
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const Eigen::Vector3d d = k[j].p_W - k[i].p_W;
      const double V_ij = G * mass_of(bodies[i]) * mass_of(bodies[j]) / std::sqrt(d.squaredNorm() + softening * softening);
      V -= 0.5 * V_ij, V_scale += 0.5 * V_ij;  // each pair met twice
      const Eigen::Vector3d f_ij = G * mass_of(bodies[i]) * mass_of(bodies[j]) * d / std::pow(d.squaredNorm() + softening * softening, 1.5);
      f += f_ij, scale += f_ij.norm();
    }
    // each pair force to a few ulps, summed in another order; a recursive sum of <= n terms errs by
    // <= (n − 1) eps Σ|terms| (Higham, the standard bound), on each side: tol = 2 (n + 4) eps Σ_j |f_ij|
    EXPECT_LT((w[i].f_W - f).norm(), sum_tol * scale) << "body " << i;
    total += w[i].f_W, total_scale += scale;
    expected_power += w[i].f_W.dot(k[i].v_W);
  }
  // Newton's third law pair by pair: the total is the rounding of the per-body sums (same bound)
  EXPECT_LT(total.norm(), sum_tol * total_scale);
  EXPECT_NEAR(power, expected_power, sum_tol * total_scale * 2.0);  // |v| <= √3 < 2
  EXPECT_NEAR(term.potential(k), V, 2 * sum_tol * V_scale);  // sums of sums (over j, then i): twice the bound
}

// ---------------------------------------------------------------------------------------------------
// GravityGradient

TEST(GravityGradient, ConservativeWithCorrectPower) {
  std::mt19937 rng(31);
  std::vector<Body> bodies = mixed_bodies();
  bodies[1] = Particle(0.9);  // planar bodies are refused (below)
  const GravityGradientTerm term(GravityGradient{3.0, kAttractor, {}}, bodies, kName);
  EXPECT_EQ(term.bodies(), (std::vector<int>{2, 3}));  // particles skipped
  for (int trial = 0; trial < 5; ++trial) {
    Kinematics k = random_kinematics(rng);
    set_attitude(k[1], Eigen::Quaterniond::Identity());  // body 1 is a particle here
    k[1].w_B.setZero();
    expect_wrench_is_minus_gradient(term, k);
    expect_power_matches(term, k);
    const Wrenches w = wrenches_of(term, k);
    EXPECT_TRUE(w[0].f_W.isZero(0.0) && w[1].f_W.isZero(0.0));
    EXPECT_GT(w[2].tau_B.norm(), 1e-3);  // the derivative check above is not vacuous
  }
  const auto traits = GravityGradientTerm::traits();
  EXPECT_TRUE(traits.has_potential && traits.reads_attitude && traits.has_torque);
  EXPECT_FALSE(traits.velocity_dependent || traits.time_dependent);
}

// Pitch of a satellite on a circular orbit: r along W's z, pitch θ about the body (and orbit-normal) y
// axis: r_B = |r| (−sin θ, 0, cos θ), so tau_B = 3GM/|r|⁵ r_B × I r_B = −(3/2) n² (I_x − I_z) sin 2θ ŷ with
// n² = GM/|r|³, hence −3 n² (I_x − I_z) θ for small θ (the pitch-libration restoring torque).
TEST(GravityGradient, PitchRestoringTorque) {
  const double gm = 3.986004418e14, radius = 7.0e6, Ix = 120.0, Iy = 100.0, Iz = 80.0;
  const double n2 = gm / std::pow(radius, 3);
  const std::vector<Body> bodies = {RigidBody(500.0, Eigen::Vector3d(Ix, Iy, Iz))};
  const GravityGradientTerm term(GravityGradient{gm, Eigen::Vector3d::Zero(), {}}, bodies, kName);
  for (const double theta : {1e-3, 0.3, -1.1}) {
    Kinematics k(1);
    k[0].p_W = Eigen::Vector3d(0, 0, radius);
    set_attitude(k[0], Eigen::Quaterniond(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY())));
    const Eigen::Vector3d tau = wrenches_of(term, k)[0].tau_B;
    const double expected = -1.5 * n2 * (Ix - Iz) * std::sin(2 * theta);
    // rounding: r_B to a few ulps of |r|, the products and r⁵ to ~16 ulps relative to 3 n² I_max
    const double tol = 64 * kEps * 3 * n2 * Ix;
    EXPECT_NEAR(tau.y(), expected, tol);
    EXPECT_NEAR(tau.x(), 0.0, tol);
    EXPECT_NEAR(tau.z(), 0.0, tol);
    if (theta == 1e-3) {
      // small angle: sin 2θ/2 = θ (1 − (2θ)²/6 + ...): relative difference 4θ²/6 < 1e-6
      EXPECT_NEAR(tau.y(), -3 * n2 * (Ix - Iz) * theta, 1e-6 * std::abs(expected));
    }
  }
}

TEST(GravityGradient, SphereFeelsNothing) {
  std::mt19937 rng(32);
  const std::vector<Body> bodies = {RigidBody(2.0, Eigen::Matrix3d(0.8 * Eigen::Matrix3d::Identity()))};
  const GravityGradientTerm term(GravityGradient{3.0, kAttractor, {}}, bodies, kName);
  Kinematics k(1);
  k[0].p_W = random_vector(rng, 1.0);
  set_attitude(k[0], random_rotation(rng));
  const Wrenches w = wrenches_of(term, k);
  // tr I − 5 s/|r|² = −2i cancels 2 I_W r = 2i r: zero to rounding of terms of size 3GM·0.8·3/|r|⁴
  const double scale = 3.0 * 3.0 * 0.8 * 3.0 / std::pow((k[0].p_W - kAttractor).norm(), 4);
  EXPECT_LT(w[0].f_W.norm(), 32 * kEps * scale);
  EXPECT_LT(w[0].tau_B.norm(), 32 * kEps * scale * (k[0].p_W - kAttractor).norm());
}

// Independent reference: a body made of 6 point masses, ± pairs on its axes, attracted point by point.
// The multipole expansion of Σ −GM m_k/|r + R ρ_k| has no odd terms (the pairs are symmetric), so
// exact − point-mass term = gravity gradient + O(V₄), V₄ = −GM Σ m_k ρ_k⁴ P₄(cos γ_k)/|r|⁵. With
// |P₄| <= 1, |P₄'| <= 10: |∇V₄| <= (5 + 10) GM Σ m ρ⁴/|r|⁶ and |∂V₄/∂δθ| <= 10 GM Σ m ρ⁴/|r|⁵; the
// tolerance is twice these (covering V₆, smaller by ρ²/|r|² = 1/400, and rounding).
TEST(GravityGradient, MatchesExactAttractionOfPointMassCloud) {
  std::mt19937 rng(33);
  const double gm = 2.0, m[3] = {0.5, 0.8, 1.1}, a[3] = {1.0, 0.6, 0.8}, distance = 60.0;
  double mass = 0.0, sum_m_rho4 = 0.0;
  Eigen::Vector3d moments = Eigen::Vector3d::Zero();
  std::vector<std::pair<double, Eigen::Vector3d>> points;  // (m_k, ρ_k in B)
  for (int axis = 0; axis < 3; ++axis) {
    for (const double sign : {1.0, -1.0}) points.emplace_back(m[axis], sign * a[axis] * Eigen::Vector3d::Unit(axis));
    mass += 2 * m[axis], sum_m_rho4 += 2 * m[axis] * std::pow(a[axis], 4);
    // I about the centre of mass: the pair on `axis` adds 2 m a² to the two other moments
    moments += 2 * m[axis] * a[axis] * a[axis] * (Eigen::Vector3d::Ones() - Eigen::Vector3d::Unit(axis));
  }
  const std::vector<Body> bodies = {RigidBody(mass, moments)};
  const GravityGradientTerm gradient(GravityGradient{gm, Eigen::Vector3d::Zero(), {}}, bodies, kName);
  const PointMassGravityTerm monopole(PointMassGravity{gm, Eigen::Vector3d::Zero(), 0.0, {}}, bodies, kName);
  for (int trial = 0; trial < 5; ++trial) {
    Kinematics k(1);
    k[0].p_W = distance * random_vector(rng, 1.0).normalized();
    set_attitude(k[0], random_rotation(rng));
    k[0].m = mass;
    Eigen::Vector3d f_exact = Eigen::Vector3d::Zero(), tau_exact = Eigen::Vector3d::Zero();
    for (const auto& [m_k, rho_B] : points) {
      const Eigen::Vector3d x = k[0].p_W + k[0].q_WB * rho_B;
      const Eigen::Vector3d f = -gm * m_k * x / std::pow(x.norm(), 3);
      f_exact += f;
      tau_exact += rho_B.cross(k[0].q_WB.conjugate() * f);
    }
    const BodyWrench w = wrenches_of(gradient, k)[0];
    const Eigen::Vector3d f_second_order = f_exact - wrenches_of(monopole, k)[0].f_W;
    const double force_tol = 2 * 15 * gm * sum_m_rho4 / std::pow(distance, 6);
    const double torque_tol = 2 * 10 * gm * sum_m_rho4 / std::pow(distance, 5);
    EXPECT_LT((w.f_W - f_second_order).norm(), force_tol);
    EXPECT_LT((w.tau_B - tau_exact).norm(), torque_tol);
    EXPECT_GT(w.f_W.norm(), 10 * force_tol);  // the comparison resolves the term
    EXPECT_GT(w.tau_B.norm(), 10 * torque_tol);
  }
}

// ---------------------------------------------------------------------------------------------------
// SpringDamper

// Body a rigid at the origin, turned 90° about z, point_a_B = (1, 0, 0) ⇒ x_a = (0, 1, 0); anchor (0, 1, 2):
// d = (0, 0, −2), ℓ = 2, u = −ẑ. v_a = (0, 0, 1), w_B = (0, 0, 2) ⇒ ẋ_a = v_a + R (w_B × point_a_B) =
// (0, 0, 1) + Rz(90°)(0, 2, 0) = (−2, 0, 1), ℓ̇ = u·ẋ_a = −1.
// A dipole in a uniform field plus a source dipole at the attractor's place (>= 4 from every body): with
// μ₀/(4π)|M| = 2 [T m³] and |m_B| < 1.2, |V| <= |m|(|B_W| + 2·2/4³) < 2 and |∂³V| <= |m|·2·60/4⁶ + |m||B_W|
// < 2 (the rotation derivatives of −(R m)·B are bounded by |m||B|): within expect_wrench_is_minus_gradient's
// stated bound.
MagneticDipole dipole_in_fields() {
  MagneticDipole spec;
  spec.m_B = Eigen::Vector3d(0.7, -0.4, 0.8);
  spec.B_W = Eigen::Vector3d(0.3, 0.1, -0.5);
  spec.source_moment_W = Eigen::Vector3d(1.0, -0.5, 1.5).normalized() * (2.0 / MagneticDipoleTerm::mu0_over_4pi);
  spec.source_p_W = kAttractor;
  return spec;
}

TEST(MagneticDipole, ConservativeWithCorrectPower) {
  std::mt19937 rng(37);
  const std::vector<Body> bodies = mixed_bodies();
  const MagneticDipoleTerm term(dipole_in_fields(), bodies, kName);
  EXPECT_EQ(term.bodies(), (std::vector<int>{1, 2, 3}));  // the particle skipped
  for (int trial = 0; trial < 5; ++trial) {
    const Kinematics k = random_kinematics(rng);
    expect_wrench_is_minus_gradient(term, k);
    expect_power_matches(term, k);
    const Wrenches w = wrenches_of(term, k);
    EXPECT_TRUE(w[0].f_W.isZero(0.0) && w[0].tau_B.isZero(0.0));
    EXPECT_GT(w[2].f_W.norm(), 1e-3);  // the source's gradient is felt: the check above is not vacuous
    EXPECT_GT(w[2].tau_B.norm(), 1e-3);
  }
  const auto traits = term.traits();
  EXPECT_TRUE(traits.has_potential && traits.reads_attitude && traits.has_torque);
  EXPECT_FALSE(traits.velocity_dependent || traits.time_dependent);
}

// A compass needle m_B = μ x̂ turned by θ about z in B_W = B x̂: tau_B = m_B × Rᵀ B_W = −μ B sin θ ẑ (it turns
// back towards the field), no force, V = −μ B cos θ. Each entry to a few ulps of μ B.
TEST(MagneticDipole, CompassNeedleInAUniformField) {
  const double mu = 0.3, B = 5e-5;
  MagneticDipole spec;
  spec.m_B = Eigen::Vector3d(mu, 0.0, 0.0), spec.B_W = Eigen::Vector3d(B, 0.0, 0.0);
  const MagneticDipoleTerm term(spec, {RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 1.0))}, kName);
  for (const double theta : {0.0, 0.3, -1.2, 2.9}) {
    Kinematics k(1);
    set_attitude(k[0], Eigen::Quaterniond(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ())));
    const Wrenches w = wrenches_of(term, k);
    EXPECT_TRUE(w[0].f_W.isZero(0.0));
    EXPECT_NEAR(w[0].tau_B.z(), -mu * B * std::sin(theta), 8 * kEps * mu * B);
    EXPECT_NEAR(w[0].tau_B.head<2>().norm(), 0.0, 8 * kEps * mu * B);
    EXPECT_NEAR(term.potential(k), -mu * B * std::cos(theta), 8 * kEps * mu * B);
  }
}

// Two coaxial dipoles m ẑ and M ẑ a distance d apart along z attract: f = −3 μ₀ m M/(2π d⁴) ẑ on the upper
// one (from ∇(m·B) of the on-axis field 2kM/d³); to a few ulps.
TEST(MagneticDipole, CoaxialDipolesAttract) {
  const double m = 2.0, M = 3e3, d = 0.25;
  MagneticDipole spec;
  spec.m_B = Eigen::Vector3d(0.0, 0.0, m), spec.source_moment_W = Eigen::Vector3d(0.0, 0.0, M);
  spec.source_p_W = Eigen::Vector3d(1.0, -2.0, 0.5);
  const MagneticDipoleTerm term(spec, {RigidBody(1.0, Eigen::Vector3d(1.0, 1.0, 1.0))}, kName);
  Kinematics k(1);
  k[0].p_W = spec.source_p_W + Eigen::Vector3d(0.0, 0.0, d);
  const Wrenches w = wrenches_of(term, k);
  const double expected = -3.0 * 1.25663706212e-6 * m * M / (2.0 * M_PI * std::pow(d, 4));
  EXPECT_NEAR(w[0].f_W.z(), expected, 16 * kEps * std::abs(expected));
  EXPECT_NEAR(w[0].f_W.head<2>().norm(), 0.0, 16 * kEps * std::abs(expected));
  EXPECT_TRUE(w[0].tau_B.isZero(0.0));  // m parallel to the on-axis field
}

// The gyrostat's couple tau_B = −ω × J Ω a − J Ω̇ a, with Ω̇ held over the piece set_time chose and Ω(t)
// clamped to the ramp; its power tau_B·ω = −J Ω̇ a·ω. Each entry to a few ulps of J |Ω| |ω| + J |Ω̇|.
TEST(ReactionWheel, GyrostatCoupleAndPower) {
  ReactionWheel spec;
  spec.body = 2, spec.axis_B = Eigen::Vector3d(0.0, 3.0, 4.0), spec.inertia = 0.05;
  spec.speed = 10.0, spec.acceleration = -4.0, spec.t_start = 1.0, spec.t_end = 2.0;
  ReactionWheelTerm term(spec, mixed_bodies(), kName);
  const Eigen::Vector3d a(0.0, 0.6, 0.8);
  Kinematics k(4);
  k[2].w_B = Eigen::Vector3d(0.3, -1.1, 0.7);
  for (const double t : {0.5, 1.0, 1.5, 2.0, 3.0}) {
    term.set_time(t);
    const double Omega = 10.0 - 4.0 * (std::clamp(t, 1.0, 2.0) - 1.0);
    const double Omega_dot = t >= 1.0 && t < 2.0 ? -4.0 : 0.0;
    double power = 0.0;
    const Wrenches w = wrenches_of(term, k, &power, t);
    const Eigen::Vector3d expected = -0.05 * Omega * k[2].w_B.cross(a) - 0.05 * Omega_dot * a;
    const double scale = 0.05 * (std::abs(Omega) * k[2].w_B.norm() + std::abs(Omega_dot));
    EXPECT_LT((w[2].tau_B - expected).norm(), 16 * kEps * scale) << "t = " << t;
    EXPECT_NEAR(power, -0.05 * Omega_dot * a.dot(k[2].w_B), 16 * kEps * scale * k[2].w_B.norm());
    EXPECT_TRUE(w[2].f_W.isZero(0.0) && w[0].tau_B.isZero(0.0) && w[3].tau_B.isZero(0.0));
  }
  EXPECT_TRUE(term.traits().velocity_dependent && term.traits().time_dependent && term.traits().has_torque);
  EXPECT_FALSE(term.traits().has_potential);
  spec.acceleration = 0.0;
  EXPECT_FALSE(ReactionWheelTerm(spec, mixed_bodies(), kName).traits().time_dependent);  // a constant speed
}

TEST(SceneElementErrors, ReactionWheel) {
  const std::vector<Body> bodies = mixed_bodies();
  ReactionWheel spec;
  spec.body = 2, spec.inertia = 0.1;
  auto make = [&] { ReactionWheelTerm(spec, bodies, kName); };
  spec.body = 0;
  expect_error(make, "elements[2].body: expected a rigid body, free or pinned (a wheel needs the body's full inertia), got particle 0");
  spec.body = 1;
  expect_error(make, "elements[2].body: expected a rigid body, free or pinned (a wheel needs the body's full inertia), got planar body 1");
  spec.body = 4;
  expect_error(make, "elements[2].body: expected a body index in [0, 4), got 4");
  spec.body = 2, spec.inertia = 0.0;
  expect_error(make, "elements[2].inertia: expected a finite number > 0, got 0");
  spec.inertia = 0.1, spec.axis_B.setZero();
  expect_error(make, "elements[2].axis_B: expected a finite non-zero vector, got [0; 0; 0]");
  spec.axis_B = Eigen::Vector3d::UnitX(), spec.t_end = 0.0;
  expect_error(make, "elements[2].t_end: expected a time after t_start = 0, got 0");
  spec.t_end = 1.0, spec.speed = kNaN;
  expect_error(make, "elements[2].speed: expected a finite number, got nan");
}

TEST(SpringDamper, ClosedFormWithWorldAnchor) {
  const std::vector<Body> bodies = {RigidBody(1.0, Eigen::Vector3d(1, 1, 1))};
  Kinematics k(1);
  set_attitude(k[0], Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())));
  k[0].v_W = Eigen::Vector3d(0, 0, 1), k[0].w_B = Eigen::Vector3d(0, 0, 2);
  SpringDamper spec{0, Eigen::Vector3d(1, 0, 0), -1, Eigen::Vector3d(0, 1, 2), 3.0, 0.5, 0.7};
  // ℓ0 = 0.5: f = −(k (ℓ − ℓ0) + c ℓ̇) u = −(4.5 − 0.7) (0, 0, −1) = (0, 0, 3.8); τ_B = (1,0,0) × Rᵀ f =
  // (1, 0, 0) × (0, 0, 3.8) = (0, −3.8, 0); power f·ẋ_a = 3.8; V = ½ 3 1.5² = 3.375. Tolerances: the
  // quaternion of a 90° turn rounds to ~1 ulp, products of numbers <= 5: 16 eps·5.
  const double tol = 16 * kEps * 5;
  double power = 0.0;
  Wrenches w = wrenches_of(SpringDamperTerm(spec, bodies, kName), k, &power);
  EXPECT_LT((w[0].f_W - Eigen::Vector3d(0, 0, 3.8)).norm(), tol);
  EXPECT_LT((w[0].tau_B - Eigen::Vector3d(0, -3.8, 0)).norm(), tol);
  EXPECT_NEAR(power, 3.8, tol);
  EXPECT_NEAR(SpringDamperTerm(spec, bodies, kName).potential(k), 3.375, tol);
  // ℓ0 = 0: d = (0, 0, −2), ℓ̇ = u·ẋ_a = −1, f = −(k ℓ + c ℓ̇) u = −(6 − 0.7) (0, 0, −1) = (0, 0, 5.3) (along
  // the line, = −k d − c ℓ̇ u); τ_B = (1, 0, 0) × (0, 0, 5.3) = (0, −5.3, 0); power f·ẋ_a = 5.3; V = ½ 3 4 = 6.
  spec.rest_length = 0.0;
  w = wrenches_of(SpringDamperTerm(spec, bodies, kName), k, &power);
  EXPECT_LT((w[0].f_W - Eigen::Vector3d(0, 0, 5.3)).norm(), tol);
  EXPECT_LT((w[0].tau_B - Eigen::Vector3d(0, -5.3, 0)).norm(), tol);
  EXPECT_NEAR(power, 5.3, tol);
  EXPECT_NEAR(SpringDamperTerm(spec, bodies, kName).potential(k), 6.0, tol);
}

// Springs without damping between every pair of kinds and to anchors: conservative, correct power, and
// (between two bodies) internal.
TEST(SpringDamper, ConservativeInternalWithCorrectPower) {
  std::mt19937 rng(41);
  const std::vector<Body> bodies = mixed_bodies();
  const Eigen::Vector3d planar_point(0.4, -0.3, 0.0), rigid_point(0.2, 0.5, -0.6);
  auto point = [&](int b) { return b == 0 ? Eigen::Vector3d::Zero() : b == 1 ? planar_point : rigid_point; };
  for (const double rest_length : {0.0, 0.8}) {
    for (int a = 0; a < 4; ++a) {
      for (int b = -1; b < 4; ++b) {
        if (b == a) continue;
        const SpringDamper spec{a, point(a), b, b < 0 ? Eigen::Vector3d(0.5, 1.0, -0.5) : point(b), 2.5, rest_length, 0.0};
        const SpringDamperTerm term(spec, bodies, kName);
        const Kinematics k = random_kinematics(rng);
        expect_wrench_is_minus_gradient(term, k);
        expect_power_matches(term, k);
        EXPECT_EQ(term.traits().zero_net_wrench, b >= 0);  // a world anchor takes the reaction
        if (b >= 0) expect_internal(wrenches_of(term, k), k);
      }
    }
  }
}

TEST(SpringDamper, DampingDissipatesAndKeepsMomenta) {
  std::mt19937 rng(42);
  const std::vector<Body> bodies = mixed_bodies();
  const Eigen::Vector3d point_a(0.2, 0.5, -0.6), point_b(-0.3, 0.1, 0.4);
  for (int trial = 0; trial < 5; ++trial) {
    const Kinematics k = random_kinematics(rng);
    // a pure damper along the line (ℓ0 > 0, k = 0): power −c ℓ̇² <= 0, internal (force along d)
    const SpringDamperTerm damper(SpringDamper{2, point_a, 3, point_b, 0.0, 1.0, 0.9}, bodies, kName);
    double power = 0.0;
    const Wrenches w = wrenches_of(damper, k, &power);
    EXPECT_LT(power, 0.0);
    expect_power_matches(damper, k);
    expect_internal(w, k);
    // ℓ0 = 0 with damping: spring −k d and damper −c ℓ̇ u both along d, so internal (no net moment) too
    const SpringDamperTerm zero_rest(SpringDamper{2, point_a, 3, point_b, 1.5, 0.0, 0.9}, bodies, kName);
    expect_internal(wrenches_of(zero_rest, k), k);
    expect_power_matches(zero_rest, k);
    const SpringDamperTerm pure(SpringDamper{2, point_a, 3, point_b, 0.0, 0.0, 0.9}, bodies, kName);
    wrenches_of(pure, k, &power);
    EXPECT_LT(power, 0.0);
  }
}

TEST(SpringDamper, ZeroLengthWithRestLength) {
  const std::vector<Body> bodies = {Particle(1.0)};
  Kinematics k(1);
  k[0].p_W = Eigen::Vector3d(1, 2, 3), k[0].v_W = Eigen::Vector3d(1, 0, 0);
  const SpringDamperTerm term(SpringDamper{0, Eigen::Vector3d::Zero(), -1, Eigen::Vector3d(1, 2, 3), 4.0, 0.5, 1.0}, bodies, kName);
  double power = 1.0;
  const Wrenches w = wrenches_of(term, k, &power);
  EXPECT_TRUE(w[0].f_W.isZero(0.0));  // u undefined: no force (documented), finite state
  EXPECT_EQ(power, 0.0);
  EXPECT_EQ(term.potential(k), 0.5 * 4.0 * 0.25);
  // ℓ0 = 0 at ℓ = 0: the spring's −k d is zero and the damper's direction undefined: no force
  const SpringDamperTerm linear(SpringDamper{0, Eigen::Vector3d::Zero(), -1, Eigen::Vector3d(1, 2, 3), 4.0, 0.0, 1.0}, bodies, kName);
  EXPECT_TRUE(wrenches_of(linear, k)[0].f_W.isZero(0.0));
}

TEST(SpringDamper, Traits) {
  const std::vector<Body> bodies = mixed_bodies();
  auto traits = SpringDamperTerm(SpringDamper{0, Eigen::Vector3d::Zero(), 3, Eigen::Vector3d::Zero(), 1.0, 0.0, 0.0}, bodies, kName).traits();
  EXPECT_TRUE(traits.has_potential);
  EXPECT_FALSE(traits.reads_attitude || traits.has_torque || traits.velocity_dependent || traits.time_dependent);
  traits = SpringDamperTerm(SpringDamper{2, Eigen::Vector3d(0, 0, 1), -1, Eigen::Vector3d(5, 0, 0), 1.0, 0.0, 0.3}, bodies, kName).traits();
  EXPECT_TRUE(traits.reads_attitude && traits.has_torque && traits.velocity_dependent);
  // an anchor away from the origin is not an offset on a body
  traits = SpringDamperTerm(SpringDamper{0, Eigen::Vector3d::Zero(), -1, Eigen::Vector3d(5, 0, 0), 1.0, 0.0, 0.0}, bodies, kName).traits();
  EXPECT_FALSE(traits.reads_attitude || traits.has_torque);
}

// ---------------------------------------------------------------------------------------------------
// Drag

TEST(Drag, OpposesVelocityWithClosedForm) {
  std::mt19937 rng(51);
  const std::vector<Body> bodies = mixed_bodies();
  const DragTerm term(Drag{0.3, 0.2, 0.05, 0.1, {}}, bodies, kName);
  for (int trial = 0; trial < 5; ++trial) {
    const Kinematics k = random_kinematics(rng);
    double power = 0.0;
    const Wrenches w = wrenches_of(term, k, &power);
    for (int b = 0; b < 4; ++b) {
      const Eigen::Vector3d f = -(0.3 + 0.2 * k[b].v_W.norm()) * k[b].v_W;
      const Eigen::Vector3d tau = -(0.05 + 0.1 * k[b].w_B.norm()) * k[b].w_B;
      // the same products in another order: a few ulps of |f| and |τ|
      EXPECT_LE((w[b].f_W - f).norm(), 8 * kEps * f.norm());
      EXPECT_LE((w[b].tau_B - tau).norm(), 8 * kEps * tau.norm());
      EXPECT_LT(w[b].f_W.dot(k[b].v_W), 0.0);
    }
    EXPECT_TRUE(w[0].tau_B.isZero(0.0));  // a particle does not turn
    EXPECT_LT(power, 0.0);
    expect_power_matches(term, k);
  }
  auto traits = term.traits();
  EXPECT_TRUE(traits.velocity_dependent && traits.has_torque);
  EXPECT_FALSE(traits.has_potential || traits.reads_attitude || traits.time_dependent);
  EXPECT_FALSE(DragTerm(Drag{1.0, 0.0, 0.0, 0.0, {}}, bodies, kName).traits().has_torque);
  EXPECT_EQ(term.potential(random_kinematics(rng)), 0.0);
}

// ---------------------------------------------------------------------------------------------------
// FunctionForce

TEST(FunctionForce, CallsTheFunctionPerListedBody) {
  std::mt19937 rng(61);
  const std::vector<Body> bodies = mixed_bodies();
  std::vector<int> called;
  FunctionForce spec;
  spec.bodies = {3, 1};
  spec.f = [&called](double t, const BodyKinematics& body, int index, Eigen::Vector3d& f_W, Eigen::Vector3d& tau_B) {
    EXPECT_TRUE(f_W.isZero(0.0) && tau_B.isZero(0.0));  // outputs arrive zeroed
    called.push_back(index);
    f_W = t * body.p_W;
    tau_B = Eigen::Vector3d(index, 0, 1);
  };
  const FunctionForceTerm term(spec, bodies, kName);
  const Kinematics k = random_kinematics(rng);
  Wrenches w(4);
  w[3].f_W = Eigen::Vector3d(1, 1, 1);  // it adds to what is there
  const double power = term.add_wrenches(2.0, k, w);
  EXPECT_EQ(called, (std::vector<int>{3, 1}));
  EXPECT_EQ(w[3].f_W, Eigen::Vector3d(1, 1, 1) + 2.0 * k[3].p_W);
  EXPECT_EQ(w[1].tau_B, Eigen::Vector3d(1, 0, 1));
  EXPECT_TRUE(w[0].f_W.isZero(0.0) && w[2].f_W.isZero(0.0));
  const double expected = 2.0 * k[3].p_W.dot(k[3].v_W) + Eigen::Vector3d(3, 0, 1).dot(k[3].w_B) +
                          2.0 * k[1].p_W.dot(k[1].v_W) + Eigen::Vector3d(1, 0, 1).dot(k[1].w_B);
  EXPECT_NEAR(power, expected, 32 * kEps * (1 + std::abs(expected)));  // same products, any order
  const auto traits = FunctionForceTerm::traits();
  EXPECT_TRUE(traits.reads_attitude && traits.velocity_dependent && traits.time_dependent && traits.has_torque);
  EXPECT_FALSE(traits.has_potential);
}

// ---------------------------------------------------------------------------------------------------
// Validation: every message

TEST(SceneElementErrors, BodyLists) {
  const std::vector<Body> bodies = mixed_bodies();
  expect_error([&] { PointMassGravityTerm(PointMassGravity{1.0, Eigen::Vector3d::Zero(), 0.0, {0, 4}}, bodies, kName); },
               "elements[2].bodies[1]: expected a body index in [0, 4), got 4");
  expect_error([&] { MutualGravityTerm(MutualGravity{1.0, 0.0, {-1}}, bodies, kName); },
               "elements[2].bodies[0]: expected a body index in [0, 4), got -1");
  expect_error([&] { DragTerm(Drag{1.0, 0.0, 0.0, 0.0, {2, 3, 2}}, bodies, kName); },
               "elements[2].bodies[2]: expected each body once, got 2");
  expect_error([&] { GravityGradientTerm(GravityGradient{1.0, Eigen::Vector3d::Zero(), {3, 3}}, bodies, kName); },
               "elements[2].bodies[1]: expected each body once, got 3");
  expect_error([&] { FunctionForceTerm(FunctionForce{{9}, [](double, const BodyKinematics&, int, Eigen::Vector3d&, Eigen::Vector3d&) {}}, bodies, kName); },
               "elements[2].bodies[0]: expected a body index in [0, 4), got 9");
}

TEST(SceneElementErrors, Gravity) {
  const std::vector<Body> bodies = mixed_bodies();
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  expect_error([&] { PointMassGravityTerm(PointMassGravity{0.0, o, 0.0, {}}, bodies, kName); },
               "elements[2].gm: expected a finite number > 0, got 0");
  expect_error([&] { PointMassGravityTerm(PointMassGravity{-2.0, o, 0.0, {}}, bodies, kName); },
               "elements[2].gm: expected a finite number > 0, got -2");
  expect_error([&] { PointMassGravityTerm(PointMassGravity{kNaN, o, 0.0, {}}, bodies, kName); },
               "elements[2].gm: expected a finite number > 0, got nan");
  expect_error([&] { PointMassGravityTerm(PointMassGravity{1.0, Eigen::Vector3d(kInf, 0, 0), 0.0, {}}, bodies, kName); },
               "elements[2].p_W: expected finite values, got [inf; 0; 0]");
  expect_error([&] { PointMassGravityTerm(PointMassGravity{1.0, o, -0.5, {}}, bodies, kName); },
               "elements[2].softening: expected a finite number >= 0, got -0.5");
  expect_error([&] { MutualGravityTerm(MutualGravity{0.0, 0.0, {}}, bodies, kName); },
               "elements[2].G: expected a finite number > 0, got 0");
  expect_error([&] { MutualGravityTerm(MutualGravity{1.0, kInf, {}}, bodies, kName); },
               "elements[2].softening: expected a finite number >= 0, got inf");
  expect_error([&] { GravityGradientTerm(GravityGradient{-1.0, o, {}}, bodies, kName); },
               "elements[2].gm: expected a finite number > 0, got -1");
  expect_error([&] { GravityGradientTerm(GravityGradient{1.0, Eigen::Vector3d(0, kNaN, 0), {}}, bodies, kName); },
               "elements[2].p_W: expected finite values, got [0; nan; 0]");
  // a planar body, listed or among every body
  const std::string planar =
      "elements[2].bodies: expected particles or rigid bodies (a planar body has no in-plane moments I_xx, I_yy, which "
      "the gravity-gradient torque needs), got planar body 1";
  expect_error([&] { GravityGradientTerm(GravityGradient{1.0, o, {}}, bodies, kName); }, planar);
  expect_error([&] { GravityGradientTerm(GravityGradient{1.0, o, {2, 1}}, bodies, kName); }, planar);
  EXPECT_NO_THROW(GravityGradientTerm(GravityGradient{1.0, o, {2, 0}}, bodies, kName));
}

TEST(SceneElementErrors, MagneticDipole) {
  const std::vector<Body> bodies = mixed_bodies();
  MagneticDipole spec;
  spec.m_B = Eigen::Vector3d(kNaN, 0, 0);
  expect_error([&] { MagneticDipoleTerm(spec, bodies, kName); }, "elements[2].m_B: expected finite values, got [nan; 0; 0]");
  spec.m_B = Eigen::Vector3d::UnitX(), spec.B_W = Eigen::Vector3d(0, kInf, 0);
  expect_error([&] { MagneticDipoleTerm(spec, bodies, kName); }, "elements[2].B_W: expected finite values, got [0; inf; 0]");
  spec.B_W.setZero(), spec.source_moment_W = Eigen::Vector3d(0, 0, kNaN);
  expect_error([&] { MagneticDipoleTerm(spec, bodies, kName); },
               "elements[2].source_moment_W: expected finite values, got [0; 0; nan]");
  spec.source_moment_W.setZero(), spec.source_p_W = Eigen::Vector3d(-kInf, 0, 0);
  expect_error([&] { MagneticDipoleTerm(spec, bodies, kName); },
               "elements[2].source_p_W: expected finite values, got [-inf; 0; 0]");
  spec.source_p_W.setZero(), spec.bodies = {4};
  expect_error([&] { MagneticDipoleTerm(spec, bodies, kName); },
               "elements[2].bodies[0]: expected a body index in [0, 4), got 4");
}

TEST(SceneElementErrors, SpringDamper) {
  const std::vector<Body> bodies = mixed_bodies();
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  auto make = [&](SpringDamper spec) { return [spec, &bodies] { SpringDamperTerm(spec, bodies, kName); }; };
  expect_error(make({4, o, -1, o, 1.0, 0.0, 0.0}), "elements[2].body_a: expected a body index in [0, 4), got 4");
  expect_error(make({-1, o, 2, o, 1.0, 0.0, 0.0}), "elements[2].body_a: expected a body index in [0, 4), got -1");
  expect_error(make({0, o, -2, o, 1.0, 0.0, 0.0}),
               "elements[2].body_b: expected -1 (a world anchor) or a body index in [0, 4), got -2");
  expect_error(make({0, o, 4, o, 1.0, 0.0, 0.0}),
               "elements[2].body_b: expected -1 (a world anchor) or a body index in [0, 4), got 4");
  expect_error(make({2, o, 2, o, 1.0, 0.0, 0.0}), "elements[2].body_b: expected a body other than body_a, got 2");
  expect_error(make({0, Eigen::Vector3d(0.1, 0, 0), -1, o, 1.0, 0.0, 0.0}),
               "elements[2].point_a_B: expected zero (a particle is a point), got [0.1; 0; 0]");
  expect_error(make({2, o, 0, Eigen::Vector3d(0, 0, 1), 1.0, 0.0, 0.0}),
               "elements[2].point_b: expected zero (a particle is a point), got [0; 0; 1]");
  expect_error(make({1, Eigen::Vector3d(1, 0, 0.5), -1, o, 1.0, 0.0, 0.0}),
               "elements[2].point_a_B: expected a point in the body's xy plane (z = 0), got [1; 0; 0.5]");
  expect_error(make({2, Eigen::Vector3d(kNaN, 0, 0), -1, o, 1.0, 0.0, 0.0}),
               "elements[2].point_a_B: expected finite values, got [nan; 0; 0]");
  expect_error(make({2, o, -1, Eigen::Vector3d(0, 0, -kInf), 1.0, 0.0, 0.0}),
               "elements[2].point_b: expected finite values, got [0; 0; -inf]");
  expect_error(make({2, o, -1, o, -1.0, 0.0, 0.0}), "elements[2].stiffness: expected a finite number >= 0, got -1");
  expect_error(make({2, o, -1, o, 1.0, kNaN, 0.0}), "elements[2].rest_length: expected a finite number >= 0, got nan");
  expect_error(make({2, o, -1, o, 1.0, 0.0, kInf}), "elements[2].damping: expected a finite number >= 0, got inf");
  // a world anchor may lie anywhere, also off a planar body's plane (the plane takes the z part)
  EXPECT_NO_THROW(make({1, Eigen::Vector3d(1, 0, 0), -1, Eigen::Vector3d(0, 0, 3), 1.0, 0.0, 0.0})());
}

TEST(SceneElementErrors, DragAndFunction) {
  const std::vector<Body> bodies = mixed_bodies();
  expect_error([&] { DragTerm(Drag{-0.1, 0.0, 0.0, 0.0, {}}, bodies, kName); },
               "elements[2].linear: expected a finite number >= 0, got -0.10000000000000001");
  expect_error([&] { DragTerm(Drag{0.0, kNaN, 0.0, 0.0, {}}, bodies, kName); },
               "elements[2].quadratic: expected a finite number >= 0, got nan");
  expect_error([&] { DragTerm(Drag{0.0, 0.0, -1.0, 0.0, {}}, bodies, kName); },
               "elements[2].angular_linear: expected a finite number >= 0, got -1");
  expect_error([&] { DragTerm(Drag{0.0, 0.0, 0.0, kInf, {}}, bodies, kName); },
               "elements[2].angular_quadratic: expected a finite number >= 0, got inf");
  expect_error([&] { FunctionForceTerm(FunctionForce{}, bodies, kName); },
               "elements[2].f: expected a callable, got an empty function");
}

}  // namespace
}  // namespace rigiddyn
