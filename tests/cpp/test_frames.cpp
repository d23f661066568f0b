// Frames and moving-frame kinematics: Craig's worked example (Craig, shaft and disk), the
// addition theorem, angular accelerations, the transport theorem and the five acceleration terms
// against finite differences of positions and rotation matrices, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "test_numbers.hpp"
#include "rigiddyn/frames/frame_tree.hpp"
#include "rigiddyn/so3/exp_log.hpp"
#include "rigiddyn/so3/skew.hpp"

namespace rigiddyn {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

using rigiddyn::test::kPi;

void expect_near(const Vector3d& got, const Vector3d& want, double tol, const std::string& what) {
  EXPECT_LE((got - want).norm(), tol) << what << "\n got  " << got.transpose() << "\n want " << want.transpose();
}

// ---------------------------------------------------------------------------------------------
// Craig worked example: ground R, shaft R1 turning at 5 rad/s about i, disk R2 turning at
// 4 rad/s about k1 relative to the shaft; P fixed in the disk on its x2 axis at r = 0.06 m, at the
// instant the disk angle is theta = 30 deg, so r_OP = r cos(theta) i1 + r sin(theta) j1.
// Answer: a_P = (-16 r cos(theta), -41 r sin(theta), 40 r cos(theta)) in R1 components.
constexpr double r = 0.06;
constexpr double theta = kPi / 6;
constexpr double t_example = theta / 4;  // the disk turns from angle 0 at t = 0

FrameTree shaft_and_disk(double shaft_length) {
  FrameTree tree;
  tree.add_frame("shaft", "world", FrameMotion::constant_rotation(Vector3d::UnitX(), 5.0));
  // O, the end of the shaft, on the shaft's axis (fixed in R); the disk turns about k1 through O
  tree.add_frame("disk", "shaft",
                 FrameMotion::constant_rotation(Vector3d::UnitZ(), 4.0, Matrix3d::Identity(),
                                                Vector3d(shaft_length, 0, 0)));
  return tree;
}

const Vector3d p_R2P_R2(r, 0, 0);
const Vector3d c_s_0(std::cos(theta), std::sin(theta), 0);
const Vector3d textbook_answer_R1(-16 * r * std::cos(theta), -41 * r * std::sin(theta), 40 * r * std::cos(theta));

TEST(CraigWorkedExample, DiskAnglesAndAngularVelocityAndAcceleration) {
  for (double L : {0.0, 0.25}) {
    const FrameTree tree = shaft_and_disk(L);
    const Vector3d r_OP_R1 = tree.point_position("disk", p_R2P_R2, "shaft", "shaft", t_example) - Vector3d(L, 0, 0);
    // the worked example: a few roundings of numbers of the size of each value (0.06 m, 5 rad/s,
    // 20 rad/s^2, 2.5 m/s^2): <= 8 eps of it; 0 where the term is structurally zero
    expect_near(r_OP_R1, r * c_s_0, 1e-15, "r_OP = r cos(theta) i1 + r sin(theta) j1");
    // addition theorem: w_R_R2 = 5 i + 4 k1
    expect_near(tree.angular_velocity("disk", "world", "shaft", t_example), Vector3d(5, 0, 4), 1e-14, "w_R_R2 in R1");
    // alpha_R_R2 = 4 (d^R k1/dt) = 4 (5 i1 x k1) = -20 j1, though both links turn at constant rates
    expect_near(tree.angular_acceleration("disk", "world", "shaft", t_example), Vector3d(0, -20, 0), 1e-13,
                "alpha_R_R2 in R1");
    expect_near(tree.angular_acceleration("shaft", "world", "shaft", t_example), Vector3d::Zero(), 0, "alpha_R_R1");
    expect_near(tree.angular_acceleration("disk", "shaft", "shaft", t_example), Vector3d::Zero(), 0, "alpha_R1_R2");
  }
}

TEST(CraigWorkedExample, FirstSolutionPointFixedInDisk) {
  for (double L : {0.0, 0.25}) {
    const PointAcceleration a =
        shaft_and_disk(L).point_acceleration("disk", p_R2P_R2, Vector3d::Zero(), Vector3d::Zero(), "world", "shaft", t_example);
    const double c = std::cos(theta), s = std::sin(theta);
    expect_near(a.origin, Vector3d::Zero(), 1e-15, "a_O = 0 (O fixed in R)");
    expect_near(a.tangential, Vector3d(0, 0, 20 * r * c), 1e-14, "alpha x r = -20 j1 x r");
    expect_near(a.centripetal, Vector3d(-16 * r * c, -41 * r * s, 20 * r * c), 1e-14, "w x (w x r)");
    expect_near(a.relative, Vector3d::Zero(), 0, "P fixed in R2");
    expect_near(a.coriolis, Vector3d::Zero(), 0, "P fixed in R2");
    expect_near(a.total(), textbook_answer_R1, 1e-14, "textbook answer");
  }
}

TEST(CraigWorkedExample, AlternateSolutionPointMovingInShaft) {
  const FrameTree tree = shaft_and_disk(0.0);
  // P seen from R1: it circles O at 4 rad/s; its velocity and acceleration in R1 from the library
  const Vector3d r_OP_R1 = tree.point_position("disk", p_R2P_R2, "shaft", "shaft", t_example);
  const Vector3d v_rel = tree.point_velocity("disk", p_R2P_R2, Vector3d::Zero(), "shaft", "shaft", t_example).total();
  const Vector3d a_rel =
      tree.point_acceleration("disk", p_R2P_R2, Vector3d::Zero(), Vector3d::Zero(), "shaft", "shaft", t_example).total();
  const double c = std::cos(theta), s = std::sin(theta);
  expect_near(v_rel, Vector3d(-4 * r * s, 4 * r * c, 0), 1e-15, "R1 v_P = 4 k1 x r_OP");
  expect_near(a_rel, -16 * r * c_s_0, 1e-15, "R1 a_P = 4 k1 x (4 k1 x r_OP)");
  const PointAcceleration a = tree.point_acceleration("shaft", r_OP_R1, v_rel, a_rel, "world", "shaft", t_example);
  expect_near(a.origin, Vector3d::Zero(), 0, "a_O");
  expect_near(a.tangential, Vector3d::Zero(), 0, "alpha_R_R1 = 0");
  expect_near(a.centripetal, Vector3d(0, -25 * r * s, 0), 1e-14, "5 i1 x (5 i1 x r_OP)");
  expect_near(a.relative, -16 * r * c_s_0, 1e-15, "R1 a_P");
  expect_near(a.coriolis, Vector3d(0, 0, 40 * r * c), 1e-14, "2 (5 i1) x R1 v_P");
  expect_near(a.total(), textbook_answer_R1, 1e-14, "same result");
}

// ---------------------------------------------------------------------------------------------
// A 3-level chain of non-uniform motions: each link turns about a fixed axis n (in its parent) by
// theta(t) = c0 t + c1 sin(c2 t) and its origin moves along p(t) = p0 + d sin(e t) (per component).
FrameMotion wobble(const Vector3d& axis, double c0, double c1, double c2, const Vector3d& p0,
                   const Vector3d& d, double e) {
  const Vector3d n = axis.normalized();
  return FrameMotion([=](double t) {
    FrameKinematics K;
    const double th = c0 * t + c1 * std::sin(c2 * t);
    K.R_PF = rotvec_to_matrix(th * n);
    K.w_PF_P = (c0 + c1 * c2 * std::cos(c2 * t)) * n;
    K.alpha_PF_P = (-c1 * c2 * c2 * std::sin(c2 * t)) * n;
    K.p_PF_P = p0 + d * std::sin(e * t);
    K.v_PF_P = d * (e * std::cos(e * t));
    K.a_PF_P = d * (-e * e * std::sin(e * t));
    return K;
  });
}

FrameTree chain() {
  FrameTree tree;
  tree.add_frame("a", "world", wobble(Vector3d(1, 2, 3), 0.7, 0.4, 1.3, Vector3d(1, -2, 0.5), Vector3d(0.3, 0.1, -0.2), 0.9));
  tree.add_frame("b", "a", wobble(Vector3d(-2, 1, 0.5), -1.1, 0.8, 2.1, Vector3d(0.4, 0.2, -0.3), Vector3d(-0.1, 0.2, 0.3), 1.7));
  tree.add_frame("c", "b", wobble(Vector3d(0.3, -1, 2), 2.3, -0.5, 0.6, Vector3d(-0.2, 0.5, 0.1), Vector3d(0.2, -0.3, 0.1), 2.5));
  tree.add_frame("side", "a", wobble(Vector3d(0, 1, 1), 0.5, 0.3, 3.0, Vector3d(0, 0, 1), Vector3d(0.1, 0.1, 0.1), 0.4));
  return tree;
}

// Fourth-order central differences of f at t: first and second derivative.
template <typename F>
auto d1(const F& f, double t, double h) -> decltype(f(t)) {
  return ((f(t - 2 * h) - f(t + 2 * h)) + 8 * (f(t + h) - f(t - h))) / (12 * h);
}
template <typename F>
auto d2(const F& f, double t, double h) -> decltype(f(t)) {
  return (-(f(t + 2 * h) + f(t - 2 * h)) + 16 * (f(t + h) + f(t - h)) - 30 * f(t)) / (12 * h * h);
}

constexpr double h = 1e-3;
// The finite differences are checked against their own error estimate: a fourth-order difference
// d(h) errs by ~ (d(2h) - d(h))/15 (Richardson), so |exact - d(h)| <= |d(2h) - d(h)| plus
// round-off, which divides each value's few-eps error by h (d1: 1.5/h, d2: 5.3/h^2 times 16 eps |f|).
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
const std::vector<std::pair<std::string, std::string>> pairs = {
    {"c", "world"}, {"c", "a"}, {"c", "b"}, {"world", "c"}, {"side", "c"}, {"b", "side"}};

TEST(Chain, AngularVelocityMatchesDerivativeOfRotation) {
  const FrameTree tree = chain();
  for (const auto& [F, A] : pairs) {
    for (double t : {0.0, 0.37, 2.9}) {
      const auto R_AF = [&](double s) { return tree.rotation(F, A, s); };
      // w_AF expressed in A: hat(w) = dR_AF/dt R_AF^T
      const Vector3d w_fd = vee(d1(R_AF, t, h) * R_AF(t).transpose());
      // Richardson estimate plus round-off (1.5/h x 16 eps |R| = 1, for d(h) and d(2h))
      const double tol = (w_fd - vee(d1(R_AF, t, 2 * h) * R_AF(t).transpose())).norm() + 48 * kEpsilon / h;
      expect_near(tree.angular_velocity(F, A, A, t), w_fd, tol, F + " in " + A);
      // expressed in F: hat(w_F) = R_AF^T dR_AF/dt
      expect_near(tree.angular_velocity(F, A, F, t), vee(R_AF(t).transpose() * d1(R_AF, t, h)), tol,
                  F + " in " + A + " expressed in " + F);
    }
  }
}

TEST(Chain, AngularAccelerationMatchesDerivativeOfAngularVelocity) {
  const FrameTree tree = chain();
  for (const auto& [F, A] : pairs) {
    for (double t : {0.0, 0.37, 2.9}) {
      // the derivative seen from A has as components (in A) the time derivatives of w_AF_A;
      // w_AF_A itself from finite differences of R_AF, so this checks alpha against rotations only
      const auto w_AF_A = [&](double s) {
        const auto R_AF = [&](double u) { return tree.rotation(F, A, u); };
        return Vector3d(vee(d1(R_AF, s, h) * R_AF(s).transpose()));
      };
      // Richardson estimate plus the inner difference's round-off (48 eps/h) divided by h again (1.5/h)
      const double tol = (d1(w_AF_A, t, h) - d1(w_AF_A, t, 2 * h)).norm() + 3 * 48 * kEpsilon / (h * h);
      expect_near(tree.angular_acceleration(F, A, A, t), d1(w_AF_A, t, h), tol, F + " in " + A);
    }
  }
  // no addition theorem: alpha_Wc differs from the sum of the links' accelerations by w x w terms
  const double t = 0.37;
  const Vector3d sum = tree.angular_acceleration("a", "world", "world", t) +
                       tree.angular_acceleration("b", "a", "world", t) + tree.angular_acceleration("c", "b", "world", t);
  EXPECT_GT((tree.angular_acceleration("c", "world", "world", t) - sum).norm(), 0.1);
}

TEST(Chain, TransportTheoremMatchesFiniteDifferences) {
  const FrameTree tree = chain();
  // u has components u_B(t) in B; its derivative seen from B has components du_B(t)
  const auto u_B = [](double t) { return Vector3d(std::sin(t), t * t, std::cos(2 * t)); };
  const auto du_B = [](double t) { return Vector3d(std::cos(t), 2 * t, -2 * std::sin(2 * t)); };
  for (const auto& [B, A] : pairs) {
    for (const std::string& E : {A, B, std::string("side")}) {
      const double t = 0.81;
      const auto u_A = [&](double s) { return Vector3d(tree.rotation(B, A, s) * u_B(s)); };
      const Matrix3d R_EA = tree.rotation(A, E, t), R_EB = tree.rotation(B, E, t);
      const Vector3d got = tree.transport_derivative(R_EB * u_B(t), R_EB * du_B(t), B, A, E, t);
      // Richardson estimate plus round-off (1.5/h x 16 eps |u| (<= 1.2), twice)
      const double tol = (d1(u_A, t, h) - d1(u_A, t, 2 * h)).norm() + 64 * kEpsilon / h;
      expect_near(got, R_EA * d1(u_A, t, h), tol, "d^" + A + " u from d^" + B + " u, in " + E);
    }
  }
}

TEST(Chain, PointMotionTermsMatchFiniteDifferencesOfPosition) {
  const FrameTree tree = chain();
  // Q moves in F along p_FQ_F(t)
  const auto p = [](double t) { return Vector3d(0.3 + 0.2 * std::sin(3 * t), -0.1 * t * t, 0.5 * std::cos(t)); };
  const auto v = [](double t) { return Vector3d(0.6 * std::cos(3 * t), -0.2 * t, -0.5 * std::sin(t)); };
  const auto a = [](double t) { return Vector3d(-1.8 * std::sin(3 * t), -0.2, -0.5 * std::cos(t)); };
  for (const auto& [F, A] : pairs) {
    for (const std::string& E : {A, F, std::string("b")}) {
      const double t = 1.3;
      const auto p_AQ_A = [&](double s) { return tree.point_position(F, p(s), A, A, s); };
      const Matrix3d R_EA = tree.rotation(A, E, t);
      const PointVelocity vel = tree.point_velocity(F, p(t), v(t), A, E, t);
      const PointAcceleration acc = tree.point_acceleration(F, p(t), v(t), a(t), A, E, t);
      const std::string what = "Q in " + F + " seen from " + A + " expressed in " + E;
      // Richardson estimates plus round-off (|p_AQ| <= 4: 16 eps 4 per value; d1 1.5/h, d2 5.3/h^2, twice)
      const double size = p_AQ_A(t).cwiseAbs().maxCoeff();
      const double tol_v = (d1(p_AQ_A, t, h) - d1(p_AQ_A, t, 2 * h)).norm() + 2 * 1.5 * 16 * kEpsilon * size / h;
      const double tol_a = (d2(p_AQ_A, t, h) - d2(p_AQ_A, t, 2 * h)).norm() + 2 * 5.3 * 16 * kEpsilon * size / (h * h);
      expect_near(vel.total(), R_EA * d1(p_AQ_A, t, h), tol_v, what);
      expect_near(acc.total(), R_EA * d2(p_AQ_A, t, h), tol_a, what);
      // the terms are the ones named
      const FrameKinematics K_AF = tree.kinematics(F, A, t);
      const Vector3d r_A = K_AF.R_PF * p(t), v_rel_A = K_AF.R_PF * v(t);
      // one evaluation per term on each side: a few roundings of numbers <= 50: <= 16 eps 50 = 2e-13
      expect_near(acc.coriolis, R_EA * (2 * K_AF.w_PF_P.cross(v_rel_A)), 1e-12, "Coriolis " + what);
      expect_near(acc.centripetal, R_EA * K_AF.w_PF_P.cross(K_AF.w_PF_P.cross(r_A)), 1e-12, "centripetal " + what);
      expect_near(acc.relative, R_EA * K_AF.R_PF * a(t), 1e-12, "relative " + what);
      expect_near(vel.rotational, R_EA * K_AF.w_PF_P.cross(r_A), 1e-12, "w x r " + what);
    }
  }
}

TEST(Chain, ComposeAndRelativeAreInverse) {
  const FrameTree tree = chain();
  const double t = 0.6;
  const FrameKinematics K_ab = tree.kinematics("b", "a", t), K_bc = tree.kinematics("c", "b", t);
  const FrameKinematics K_ac = tree.kinematics("c", "a", t), K_ca = tree.kinematics("a", "c", t);
  const FrameKinematics composed = compose_kinematics(K_ab, K_bc), back = relative_kinematics(K_ab, K_ac);
  const FrameKinematics round = compose_kinematics(K_ac, K_ca);  // a relative to a: identity, at rest
  // compose and undo: a few dozen roundings of terms no larger than |w|^2 |p| (rates <= 3.3 rad/s,
  // |p| <= 2.5: <= 30), each tolerance ~16 eps of its quantity's largest term
  EXPECT_LE((composed.R_PF - K_ac.R_PF).norm(), 1e-14);
  for (const auto& [x, y] : {std::pair{composed, K_ac}, std::pair{back, K_bc}}) {
    EXPECT_LE((x.R_PF - y.R_PF).norm(), 1e-14);
    expect_near(x.w_PF_P, y.w_PF_P, 1e-13, "w");
    expect_near(x.alpha_PF_P, y.alpha_PF_P, 1e-12, "alpha");
    expect_near(x.p_PF_P, y.p_PF_P, 1e-14, "p");
    expect_near(x.v_PF_P, y.v_PF_P, 1e-13, "v");
    expect_near(x.a_PF_P, y.a_PF_P, 1e-12, "a");
  }
  EXPECT_LE((round.R_PF - Matrix3d::Identity()).norm(), 1e-14);
  for (const Vector3d& x : {round.w_PF_P, round.alpha_PF_P, round.p_PF_P, round.v_PF_P, round.a_PF_P})
    expect_near(x, Vector3d::Zero(), 1e-12, "a relative to itself");
}

TEST(ConstantRotation, MatchesItsDefinition) {
  const Vector3d axis(1, -1, 2);
  const Matrix3d R0 = rotvec_to_matrix(Vector3d(0.2, 0.1, -0.4));
  FrameTree tree;
  tree.add_frame("f", "world", FrameMotion::constant_rotation(axis, -3.0, R0, Vector3d(1, 2, 3)));
  const double t = 0.4;
  // the same formula on the same numbers, at most a product reordered: a few eps of unit entries
  EXPECT_LE((tree.rotation("f", "world", t) - rotvec_to_matrix(-3.0 * t * axis.normalized()) * R0).norm(), 1e-15);
  expect_near(tree.angular_velocity("f", "world", "world", t), -3.0 * axis.normalized(), 1e-15, "w");
  // the axis is fixed in F too, and F's origin stays put
  expect_near(tree.angular_velocity("f", "world", "f", t), -3.0 * R0.transpose() * axis.normalized(), 1e-14, "w in F");
  expect_near(tree.point_position("f", Vector3d::Zero(), "world", "world", t), Vector3d(1, 2, 3), 0, "origin");
}

// A motion keeps how it was built: FrameTree::motion(name).function().target<...>() gives the
// parameters back (what the Python bindings save), and nothing for a general function.
TEST(FrameMotion, KeepsItsParameters) {
  const Vector3d axis(1, -1, 2), p(1, 2, 3);
  const Matrix3d R0 = rotvec_to_matrix(Vector3d(0.2, 0.1, -0.4));
  FrameTree tree;
  tree.add_frame("spin", "world", FrameMotion::constant_rotation(axis, -3.0, R0, p));
  tree.add_frame("fixed", "spin", FrameMotion::fixed(R0, p));
  tree.add_frame("user", "fixed", FrameMotion([](double) { return FrameKinematics(); }));
  const auto* spin = tree.motion("spin").function().target<ConstantRotation>();
  ASSERT_NE(spin, nullptr);
  EXPECT_EQ(spin->axis_P, axis);  // as given (not normalised), so that rebuilding gives the same motion
  EXPECT_EQ(spin->rate, -3.0);
  EXPECT_EQ(spin->R_PF0, R0);
  EXPECT_EQ(spin->p_PF_P, p);
  const auto* fixed = tree.motion("fixed").function().target<FixedPlacement>();
  ASSERT_NE(fixed, nullptr);
  EXPECT_EQ(fixed->R_PF, R0);
  EXPECT_EQ(fixed->p_PF_P, p);
  EXPECT_NE(tree.motion("world").function().target<FixedPlacement>(), nullptr);
  EXPECT_EQ(tree.motion("user").function().target<FixedPlacement>(), nullptr);
  // rebuilt from its parameters, the motion is bitwise the same at any time
  const FrameMotion again = FrameMotion::constant_rotation(spin->axis_P, spin->rate, spin->R_PF0, spin->p_PF_P);
  for (double t : {0.0, 0.4, -7.0}) EXPECT_EQ(again.at(t).R_PF, tree.motion("spin").at(t).R_PF);
  EXPECT_THROW(tree.motion("nowhere"), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Bad input: std::invalid_argument whose message names the argument (and the frame).
void expect_invalid_mentioning(const std::function<void()>& f, const std::string& part1, const std::string& part2 = "") {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one mentioning " << part1;
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(part1), std::string::npos) << msg;
    EXPECT_NE(msg.find(part2), std::string::npos) << msg;
  }
}

TEST(ConstantRotation, AnyFiniteAngleGivesARotation) {
  // |rate t| = 1e300: a rotation vector of that norm overflows when squared (NaN R before); the
  // angle is a double, so R is exactly the rotation by that double (its sine and cosine, few eps)
  for (const auto& [rate, t] : {std::pair{1e300, 1.0}, std::pair{-1e300, 1.5}, std::pair{1.0, 1e300}}) {
    const Matrix3d R = FrameMotion::constant_rotation(Vector3d(0, 0, 2), rate).at(t).R_PF;
    const double c = std::cos(rate * t), s = std::sin(rate * t);
    Matrix3d expected;
    expected << c, -s, 0, s, c, 0, 0, 0, 1;
    EXPECT_LE((R - expected).cwiseAbs().maxCoeff(), 4 * kEpsilon) << "rate " << rate << ", t " << t;
  }
  // rate t beyond double: refused, naming t
  expect_invalid_mentioning([] { FrameMotion::constant_rotation(Vector3d::UnitZ(), 1e300).at(1e300); }, "t: expected a time",
                 "rate * t finite");
}

TEST(DeepChain, EveryWalkIsIterative) {
  // a chain of 12 000 frames overflowed the stack of a recursive walk; 100 000 here
  constexpr int depth = 100000;
  constexpr double rate = 1e-4, t = 1.0;
  FrameTree tree;
  std::string parent = "world";
  for (int i = 0; i < depth; ++i) {
    const std::string name = "f" + std::to_string(i);
    tree.add_frame(name, parent, FrameMotion::constant_rotation(Vector3d::UnitZ(), rate));
    parent = name;
  }
  // about z by depth rate t = 10 rad; each composition rounds a product of rotations by <= 3 eps
  // per entry, so the chain errs by <= 3 eps depth
  const double angle = depth * rate * t;
  Matrix3d expected;
  expected << std::cos(angle), -std::sin(angle), 0, std::sin(angle), std::cos(angle), 0, 0, 0, 1;
  EXPECT_LE((tree.rotation(parent, "world", t) - expected).cwiseAbs().maxCoeff(), 3 * kEpsilon * depth);
  // the sum of depth rates of 1e-4: each addition rounds by <= eps of the total
  EXPECT_NEAR(tree.angular_velocity(parent, "f0", "world", t).z(), (depth - 1) * rate, kEpsilon * angle * depth);
  // the cycle check walks from the new parent up to world
  expect_invalid_mentioning([&] { tree.set_parent("f0", parent, FrameMotion::fixed()); }, "parent:", "cycle");
}

TEST(BadInput, UnknownAndDuplicateNames) {
  FrameTree tree = shaft_and_disk(0.0);
  expect_invalid_mentioning([&] { tree.add_frame("x", "nowhere", FrameMotion::fixed()); }, "parent:", "'nowhere'");
  expect_invalid_mentioning([&] { tree.add_frame("disk", "world", FrameMotion::fixed()); }, "name:", "'disk'");
  expect_invalid_mentioning([&] { tree.add_frame("world", "world", FrameMotion::fixed()); }, "name:", "'world'");
  expect_invalid_mentioning([&] { tree.add_frame("", "world", FrameMotion::fixed()); }, "name:", "non-empty");
  expect_invalid_mentioning([&] { tree.rotation("nope", "world", 0); }, "frame:", "'nope'");
  expect_invalid_mentioning([&] { tree.angular_velocity("disk", "nope", "world", 0); }, "relative_to:", "'nope'");
  expect_invalid_mentioning([&] { tree.angular_acceleration("disk", "world", "nope", 0); }, "expressed_in:", "'nope'");
  expect_invalid_mentioning([&] { tree.parent("nope"); }, "name:", "world, shaft, disk");
  EXPECT_EQ(tree.parent("disk"), "shaft");
  EXPECT_EQ(tree.frame_names(), (std::vector<std::string>{"world", "shaft", "disk"}));
}

TEST(BadInput, CyclesAreRefused) {
  FrameTree tree = shaft_and_disk(0.0);
  tree.add_frame("pin", "disk", FrameMotion::fixed());
  // a frame cannot be its own parent, nor move under its descendants, nor can world get a parent
  expect_invalid_mentioning([&] { tree.add_frame("loop", "loop", FrameMotion::fixed()); }, "parent:", "'loop'");
  expect_invalid_mentioning([&] { tree.set_parent("shaft", "shaft", FrameMotion::fixed()); }, "parent:", "cycle");
  expect_invalid_mentioning([&] { tree.set_parent("shaft", "pin", FrameMotion::fixed()); }, "parent:", "cycle");
  expect_invalid_mentioning([&] { tree.set_parent("world", "disk", FrameMotion::fixed()); }, "name:", "'world'");
  EXPECT_EQ(tree.parent("shaft"), "world");  // unchanged after the refused attempts
  // a legal move: the pin now hangs from the shaft
  tree.set_parent("pin", "shaft", FrameMotion::fixed(Matrix3d::Identity(), Vector3d(0, 1, 0)));
  EXPECT_EQ(tree.parent("pin"), "shaft");
  expect_near(tree.point_position("pin", Vector3d::Zero(), "shaft", "shaft", 1.0), Vector3d(0, 1, 0), 0, "pin");
}

TEST(BadInput, NonFiniteAndNonRotationValues) {
  const double nan = std::nan("");
  Matrix3d skewed = Matrix3d::Identity();
  skewed(0, 1) = 0.1;
  expect_invalid_mentioning([&] { FrameMotion::fixed(skewed); }, "R_PF");
  expect_invalid_mentioning([&] { FrameMotion::fixed(-Matrix3d::Identity()); }, "R_PF");  // reflection
  expect_invalid_mentioning([&] { FrameMotion::fixed(Matrix3d::Identity(), Vector3d(0, nan, 0)); }, "p_PF_P");
  expect_invalid_mentioning([&] { FrameMotion::constant_rotation(Vector3d::Zero(), 1.0); }, "axis_P", "non-zero");
  expect_invalid_mentioning([&] { FrameMotion::constant_rotation(Vector3d::UnitX(), INFINITY); }, "rate");
  expect_invalid_mentioning([&] { FrameMotion::constant_rotation(Vector3d::UnitX(), 1.0, skewed); }, "R_PF0");
  expect_invalid_mentioning([] { FrameMotion(FrameMotion::Function()); }, "kinematics_at");

  FrameTree tree = shaft_and_disk(0.0);
  expect_invalid_mentioning([&] { tree.rotation("disk", "world", nan); }, "t:");
  expect_invalid_mentioning([&] { tree.point_velocity("disk", Vector3d(nan, 0, 0), Vector3d::Zero(), "world", "world", 0); }, "p_FQ_F");
  expect_invalid_mentioning([&] { tree.point_acceleration("disk", Vector3d::Zero(), Vector3d::Zero(), Vector3d(0, 0, INFINITY), "world", "world", 0); },
                 "a_FQ_F");
  expect_invalid_mentioning([&] { tree.transport_derivative(Vector3d(nan, 0, 0), Vector3d::Zero(), "disk", "world", "world", 0); }, "u_E");
  // a general motion whose value turns bad at some t: named by frame and field when queried
  tree.add_frame("bad", "disk", FrameMotion([skewed](double t) {
                   FrameKinematics K;
                   if (t > 1) K.R_PF = skewed;
                   if (t > 2) K.R_PF = Matrix3d::Identity(), K.v_PF_P.x() = std::nan("");
                   return K;
                 }));
  tree.add_frame("throws", "world", FrameMotion([](double) -> FrameKinematics {
                   throw std::invalid_argument("speed: expected a number, got a fish");
                 }));
  expect_invalid_mentioning([&] { tree.rotation("throws", "world", 0.0); }, "motion of frame 'throws' at t=0: speed");
  tree.rotation("bad", "world", 0.5);
  expect_invalid_mentioning([&] { tree.rotation("bad", "world", 1.5); }, "frame 'bad'", "R_PF");
  expect_invalid_mentioning([&] { tree.point_position("pin", Vector3d::Zero(), "bad", "world", 1.5); }, "frame:", "'pin'");
  expect_invalid_mentioning([&] { tree.angular_velocity("shaft", "bad", "world", 2.5); }, "frame 'bad'", "v_PF_P");
}

}  // namespace
}  // namespace rigiddyn
