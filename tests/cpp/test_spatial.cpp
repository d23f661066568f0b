// Spatial algebra: every structured operation against its dense 6x6 form (Featherstone), the
// physical meaning of the transforms (velocity of a body-fixed point), invariants (power, Jacobi,
// X* = X^-T) and the screw axis of a twist.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "rigiddyn/so3/elementary.hpp"
#include "rigiddyn/so3/matrix.hpp"
#include "rigiddyn/so3/skew.hpp"
#include "rigiddyn/spatial/cross.hpp"
#include "rigiddyn/spatial/force.hpp"
#include "rigiddyn/spatial/motion.hpp"
#include "rigiddyn/spatial/screw.hpp"
#include "rigiddyn/spatial/transform.hpp"

namespace rigiddyn {
namespace {

constexpr int kSamples = 200;
// One operation on samples with entries <= 1 and |p| <= 5.2: <= ~30 roundings of numbers <= 10
// (products with hat(p) R): <= 30 x 10 eps = 7e-14, relative to max(1, |value|) in Near().
constexpr double kTol = 1e-12;

// Random samples from a fixed seed: vectors with entries in [-scale, scale], uniform rotations.
class Sampler {
 public:
  Eigen::Vector3d vector3(double scale = 1.0) {
    return Eigen::Vector3d(uniform_(gen_), uniform_(gen_), uniform_(gen_)) * scale;
  }
  Eigen::Matrix3d rotation() {
    Eigen::Quaterniond q(normal_(gen_), normal_(gen_), normal_(gen_), normal_(gen_));
    return q.normalized().toRotationMatrix();
  }
  Motion motion() { return Motion(vector3(), vector3()); }
  Force force() { return Force(vector3(), vector3()); }
  Transform transform() { return Transform(rotation(), vector3(3.0)); }

 private:
  std::mt19937_64 gen_{20240601};
  std::uniform_real_distribution<double> uniform_{-1.0, 1.0};
  std::normal_distribution<double> normal_{0.0, 1.0};
};

// Relative-or-absolute closeness of two 6-vectors (or matrices).
template <typename A, typename B>
::testing::AssertionResult Near(const A& a, const B& b, double tol = kTol) {
  const double err = (a - b).cwiseAbs().maxCoeff();
  const double scale = std::max(1.0, std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff()));
  if (err <= tol * scale) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "max |a - b| = " << err << "\na =\n" << a << "\nb =\n" << b;
}

// Expects std::invalid_argument whose message starts with "<name>:".
template <typename F>
void ExpectInvalid(F&& f, const std::string& name) {
  try {
    f();
    ADD_FAILURE() << "expected std::invalid_argument naming " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(name + ":", 0), 0u) << e.what();
  }
}

// --- Motion and Force containers ---------------------------------------------------------------

TEST(Motion, VectorLayoutIsAngularFirst) {
  const Motion m(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(m.to_vector(), (Vector6d() << 1, 2, 3, 4, 5, 6).finished());
  const Motion back = Motion::from_vector(m.to_vector());
  EXPECT_EQ(back.angular, m.angular);
  EXPECT_EQ(back.linear, m.linear);
  const Force f = Force::from_vector((Vector6d() << 1, 2, 3, 4, 5, 6).finished());
  EXPECT_EQ(f.angular, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(f.linear, Eigen::Vector3d(4, 5, 6));
}

TEST(Motion, ArithmeticMatchesVectorArithmetic) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Motion a = s.motion(), b = s.motion();
    const Force f = s.force(), g = s.force();
    EXPECT_TRUE(Near((a + b).to_vector(), a.to_vector() + b.to_vector()));
    EXPECT_TRUE(Near((a - b).to_vector(), a.to_vector() - b.to_vector()));
    EXPECT_TRUE(Near((-a).to_vector(), -a.to_vector()));
    EXPECT_TRUE(Near((2.5 * a).to_vector(), 2.5 * a.to_vector()));
    EXPECT_TRUE(Near((f + g).to_vector(), f.to_vector() + g.to_vector()));
    EXPECT_TRUE(Near((f - g).to_vector(), f.to_vector() - g.to_vector()));
    EXPECT_TRUE(Near((f * -3.0).to_vector(), -3.0 * f.to_vector()));
    Motion c = a;
    c += b;
    c -= b;
    EXPECT_TRUE(c.is_approx(a));
    EXPECT_NEAR(a.dot(f), a.to_vector().dot(f.to_vector()), kTol);
    EXPECT_DOUBLE_EQ(f.dot(a), a.dot(f));
  }
}

// --- cross products ------------------------------------------------------------------------------

TEST(Cross, StructuredMatchesDenseCrmAndCrf) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Motion m = s.motion(), m2 = s.motion();
    const Force f = s.force();
    EXPECT_TRUE(Near(m.cross(m2).to_vector(), motion_cross_matrix(m) * m2.to_vector()));
    EXPECT_TRUE(Near(m.cross(f).to_vector(), force_cross_matrix(m) * f.to_vector()));
    // crf = -crm^T (Featherstone 2.9)
    EXPECT_TRUE(Near(force_cross_matrix(m), Matrix6d(-motion_cross_matrix(m).transpose())));
  }
}

TEST(Cross, DenseCrmIsBuiltFromSkewBlocks) {
  const Motion m(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(-4, 5, -6));
  const Matrix6d crm = motion_cross_matrix(m);
  EXPECT_EQ(Eigen::Matrix3d(crm.topLeftCorner<3, 3>()), hat(m.angular));
  EXPECT_EQ(Eigen::Matrix3d(crm.topRightCorner<3, 3>()), Eigen::Matrix3d::Zero());
  EXPECT_EQ(Eigen::Matrix3d(crm.bottomLeftCorner<3, 3>()), hat(m.linear));
  EXPECT_EQ(Eigen::Matrix3d(crm.bottomRightCorner<3, 3>()), hat(m.angular));
}

TEST(Cross, JacobiIdentityAntisymmetryAndDuality) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Motion a = s.motion(), b = s.motion(), c = s.motion();
    const Force f = s.force();
    const Motion jacobi = a.cross(b.cross(c)) + b.cross(c.cross(a)) + c.cross(a.cross(b));
    EXPECT_TRUE(Near(jacobi.to_vector(), Vector6d::Zero()));
    EXPECT_TRUE(Near(a.cross(b).to_vector(), (-b.cross(a)).to_vector()));
    EXPECT_TRUE(Near(a.cross(a).to_vector(), Vector6d::Zero()));
    // duality: (a x b) . f = -b . (a x* f)
    EXPECT_NEAR(a.cross(b).dot(f), -b.dot(a.cross(f)), kTol);
  }
}

// --- transforms ----------------------------------------------------------------------------------

TEST(Transform, HandComputedMotionAndForce) {
  // B turned 90 deg about z, origin at (1, 0, 0) in A.
  const Transform X_AB(rot_z(M_PI / 2), Eigen::Vector3d(1, 0, 0));
  // spin 1 rad/s about B's z axis through B's origin: A's origin moves with w x (0 - p) = (0, -1, 0)
  const Motion m_A = X_AB.act(Motion(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::Zero()));
  EXPECT_TRUE(Near(m_A.angular, Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(Near(m_A.linear, Eigen::Vector3d(0, -1, 0)));
  // a force of 1 N along B's x (= A's y) at B's origin: moment about A's origin p x f = (0, 0, 1)
  const Force f_A = X_AB.act(Force(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0)));
  EXPECT_TRUE(Near(f_A.linear, Eigen::Vector3d(0, 1, 0)));
  EXPECT_TRUE(Near(f_A.angular, Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(Near(X_AB.act_point(Eigen::Vector3d(1, 0, 0)), Eigen::Vector3d(1, 1, 0)));
}

TEST(Transform, MotionActIsVelocityOfTheBodyPointAtTheNewOrigin) {
  // independent of Featherstone's formula: v at A's origin = v_Bo + w x (r_AoBo), computed in B
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X_AB = s.transform();
    const Motion m_B = s.motion();
    const Eigen::Vector3d Ao_in_B = X_AB.act_inv_point(Eigen::Vector3d::Zero());
    const Eigen::Vector3d v_Ao_B = m_B.linear + m_B.angular.cross(Ao_in_B);
    const Motion m_A = X_AB.act(m_B);
    EXPECT_TRUE(Near(m_A.angular, Eigen::Vector3d(X_AB.rotation() * m_B.angular)));
    EXPECT_TRUE(Near(m_A.linear, Eigen::Vector3d(X_AB.rotation() * v_Ao_B)));
  }
}

TEST(Motion, VelocityAtIsTheMotionAboutTheShiftedPoint) {
  // v + w × r is the linear part of the same motion expressed at the point r (a frame of the same axes, origin at r):
  // X_OP = (1, r), m_P = X_OP⁻¹ m_O, by the dense matrix
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Motion m = s.motion();
    const Eigen::Vector3d r = s.vector3(3.0);
    const Transform X_OP(Eigen::Matrix3d::Identity(), r);
    const Vector6d m_P = X_OP.motion_matrix().inverse() * m.to_vector();
    EXPECT_TRUE(Near(m.velocity_at(r), Eigen::Vector3d(m_P.tail<3>())));
  }
  // hand-computed: 1 rad/s about z, the point 2 m along x moves at 2 m/s along y
  EXPECT_TRUE(Near(Motion(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::Zero()).velocity_at(Eigen::Vector3d(2, 0, 0)),
                   Eigen::Vector3d(0, 2, 0)));
}

TEST(Force, AtPointIsTheForceMovedFromItsPoint) {
  // (r × f, f) is the pure force f at the point r, expressed at the reference point: X_OP* (0, f), X_OP = (1, r)
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Eigen::Vector3d r = s.vector3(3.0), f = s.vector3();
    const Transform X_OP(Eigen::Matrix3d::Identity(), r);
    EXPECT_TRUE(Near(Force::at_point(r, f).to_vector(), X_OP.force_matrix() * Force(Eigen::Vector3d::Zero(), f).to_vector()));
    // its power on a motion is that of f on the velocity of its point (terms <= 16 (|w| |r| |f| <= √3 · 3√3 · √3):
    // ~20 roundings of them, <= 7e-14 < kTol)
    const Motion m = s.motion();
    EXPECT_NEAR(m.dot(Force::at_point(r, f)), f.dot(m.velocity_at(r)), kTol);
  }
}

TEST(Transform, StructuredActMatchesDenseMatrices) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Motion m = s.motion();
    const Force f = s.force();
    const Matrix6d M = X.motion_matrix(), F = X.force_matrix();
    EXPECT_TRUE(Near(X.act(m).to_vector(), M * m.to_vector()));
    EXPECT_TRUE(Near(X.act(f).to_vector(), F * f.to_vector()));
    EXPECT_TRUE(Near(X.act_inv(m).to_vector(), M.inverse() * m.to_vector(), 1e-11));
    EXPECT_TRUE(Near(X.act_inv(f).to_vector(), F.inverse() * f.to_vector(), 1e-11));
    // X* = X^-T (Featherstone 2.24)
    EXPECT_TRUE(Near(F, Matrix6d(M.inverse().transpose()), 1e-11));
    // dense blocks as documented: [[R, 0], [p^ R, R]]
    EXPECT_TRUE(Near(Eigen::Matrix3d(M.bottomLeftCorner<3, 3>()), Eigen::Matrix3d(hat(X.translation()) * X.rotation())));
    EXPECT_EQ(Eigen::Matrix3d(M.topRightCorner<3, 3>()), Eigen::Matrix3d::Zero());
    EXPECT_EQ(Eigen::Matrix3d(F.bottomLeftCorner<3, 3>()), Eigen::Matrix3d::Zero());
  }
}

TEST(Transform, PointsMatchHomogeneousMatrix) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Eigen::Vector3d p = s.vector3(5.0);
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    T.topLeftCorner<3, 3>() = X.rotation();
    T.topRightCorner<3, 1>() = X.translation();
    EXPECT_TRUE(Near(X.act_point(p), Eigen::Vector3d((T * p.homogeneous()).head<3>())));
    EXPECT_TRUE(Near(X.act_inv_point(p), Eigen::Vector3d((T.inverse() * p.homogeneous()).head<3>()), 1e-11));
    EXPECT_TRUE(Near(X.act_inv_point(X.act_point(p)), p));
  }
}

TEST(Transform, PowerIsInvariant) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Motion m = s.motion();
    const Force f = s.force();
    // power is frame invariant: the transformed vectors have entries <= |p| |w| + |v| ~ 10 and carry
    // ~kTol of them; a 6-term dot product of such vectors: 6 x 10 x 10 x eps-level, <= 1e-11
    EXPECT_NEAR(X.act(m).dot(X.act(f)), m.dot(f), 1e-11);
    EXPECT_NEAR(X.act_inv(m).dot(X.act_inv(f)), m.dot(f), 1e-11);
  }
}

TEST(Transform, ActInvUndoesAct) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Motion m = s.motion();
    const Force f = s.force();
    EXPECT_TRUE(Near(X.act_inv(X.act(m)).to_vector(), m.to_vector()));
    EXPECT_TRUE(Near(X.act(X.act_inv(m)).to_vector(), m.to_vector()));
    EXPECT_TRUE(Near(X.act_inv(X.act(f)).to_vector(), f.to_vector()));
    EXPECT_TRUE(Near(X.act(X.act_inv(f)).to_vector(), f.to_vector()));
    EXPECT_TRUE(Near(X.inverse().act(m).to_vector(), X.act_inv(m).to_vector()));
    EXPECT_TRUE(Near(X.inverse().act(f).to_vector(), X.act_inv(f).to_vector()));
  }
}

TEST(Transform, CompositionMatchesMatrixProductAndIsAssociative) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X_AB = s.transform(), X_BC = s.transform(), X_CD = s.transform();
    const Transform X_AC = X_AB * X_BC;
    EXPECT_TRUE(Near(X_AC.motion_matrix(), Matrix6d(X_AB.motion_matrix() * X_BC.motion_matrix())));
    EXPECT_TRUE(Near(X_AC.force_matrix(), Matrix6d(X_AB.force_matrix() * X_BC.force_matrix())));
    const Transform left = (X_AB * X_BC) * X_CD, right = X_AB * (X_BC * X_CD);
    EXPECT_TRUE(Near(left.rotation(), right.rotation()));
    EXPECT_TRUE(Near(left.translation(), right.translation()));
    const Eigen::Vector3d p_C = s.vector3();
    EXPECT_TRUE(Near(X_AC.act_point(p_C), X_AB.act_point(X_BC.act_point(p_C))));
  }
}

TEST(Transform, InverseComposesToIdentity) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Transform I1 = X * X.inverse(), I2 = X.inverse() * X;
    EXPECT_TRUE(Near(I1.motion_matrix(), Matrix6d::Identity()));
    EXPECT_TRUE(Near(I2.motion_matrix(), Matrix6d::Identity()));
    EXPECT_TRUE(Near(X.inverse().motion_matrix(), Matrix6d(X.motion_matrix().inverse()), 1e-11));
  }
}

TEST(Transform, CrossProductsAreEquivariant) {
  // X (m1 x m2) = (X m1) x (X m2) and X* (m x* f) = (X m) x* (X* f) (Featherstone 2.30)
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Motion a = s.motion(), b = s.motion();
    const Force f = s.force();
    EXPECT_TRUE(Near(X.act(a.cross(b)).to_vector(), X.act(a).cross(X.act(b)).to_vector(), 1e-11));
    EXPECT_TRUE(Near(X.act(a.cross(f)).to_vector(), X.act(a).cross(X.act(f)).to_vector(), 1e-11));
  }
}

TEST(Transform, QuaternionRoundTrip) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Transform X = s.transform();
    const Eigen::Quaterniond q = X.quat();
    EXPECT_GE(q.w(), 0.0);
    const Transform Y = Transform::from_quat(q, X.translation());
    EXPECT_TRUE(Near(Y.rotation(), X.rotation()));
    EXPECT_EQ(Y.translation(), X.translation());
  }
  EXPECT_TRUE(Transform().is_approx(Transform::Identity()));
  EXPECT_EQ(Transform().rotation(), Eigen::Matrix3d::Identity());
}

TEST(Transform, RejectsBadInput) {
  const Eigen::Vector3d p(1, 2, 3);
  ExpectInvalid([&] { Transform(2.0 * Eigen::Matrix3d::Identity(), p); }, "rotation");
  ExpectInvalid([&] { Transform(Eigen::Vector3d(1, 1, -1).asDiagonal().toDenseMatrix(), p); }, "rotation");
  Eigen::Matrix3d nan_R = Eigen::Matrix3d::Identity();
  nan_R(1, 2) = std::numeric_limits<double>::quiet_NaN();
  ExpectInvalid([&] { Transform(nan_R, p); }, "rotation");
  ExpectInvalid([&] { Transform(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, std::nan(""), 0)); }, "translation");
  ExpectInvalid([&] { Transform::from_quat(Eigen::Quaterniond(2, 0, 0, 0), p); }, "q_AB");
  ExpectInvalid([&] { Transform::from_quat(Eigen::Quaterniond(1, 0, 0, 0), Eigen::Vector3d::Constant(INFINITY)); },
                "translation");
}

// --- screw axis ----------------------------------------------------------------------------------

TEST(Screw, HandComputedRotationAboutAnOffsetAxis) {
  // 2 rad/s about z through c = (1, 2, 0), advancing 0.5 m/rad: v_O = w x (O - c) + h w
  const Eigen::Vector3d w(0, 0, 2), c(1, 2, 0);
  const Motion twist(w, w.cross(-c) + 0.5 * w);
  EXPECT_TRUE(Near(twist.linear, Eigen::Vector3d(4, -2, 1)));
  const Screw screw = twist_to_screw(twist);
  EXPECT_TRUE(Near(screw.direction, Eigen::Vector3d(0, 0, 1)));
  EXPECT_TRUE(Near(screw.point, c));
  EXPECT_NEAR(screw.pitch, 0.5, kTol);
  EXPECT_NEAR(screw.magnitude, 2.0, kTol);
}

TEST(Screw, ReconstructsTheTwistAndIsCovariant) {
  Sampler s;
  for (int i = 0; i < kSamples; ++i) {
    const Motion twist = s.motion();
    const Screw screw = twist_to_screw(twist);
    EXPECT_NEAR(screw.direction.norm(), 1.0, kTol);
    // point = w x v/|w|^2 and pitch = w.v/|w|^2 carry a few eps of |v|/|w| (<= ~100 for these
    // samples): absolute checks of products with w or direction stay within 1e-11 (1e-10 after a
    // transform, |p| <= 5.2 moving the axis)
    EXPECT_NEAR(screw.point.dot(screw.direction), 0.0, 1e-11);  // closest point to the origin
    // the velocity of the body point on the axis is along the axis: v + w x c = pitch w
    const Eigen::Vector3d v_on_axis = twist.linear + twist.angular.cross(screw.point);
    EXPECT_TRUE(Near(v_on_axis, Eigen::Vector3d(screw.pitch * twist.angular), 1e-11));
    EXPECT_TRUE(Near(screw_to_twist(screw).to_vector(), twist.to_vector(), 1e-11));
    // the same screw seen from another frame: direction rotates, axis moves rigidly, pitch and
    // magnitude are invariants
    const Transform X = s.transform();
    const Screw moved = twist_to_screw(X.act(twist));
    EXPECT_TRUE(Near(moved.direction, Eigen::Vector3d(X.rotation() * screw.direction)));
    const Eigen::Vector3d offset = X.act_point(screw.point) - moved.point;
    EXPECT_TRUE(Near(offset.cross(moved.direction), Eigen::Vector3d::Zero(), 1e-10));
    EXPECT_NEAR(moved.pitch, screw.pitch, 1e-10);
    EXPECT_NEAR(moved.magnitude, screw.magnitude, 1e-12);
  }
}

TEST(Screw, PureTranslationHasInfinitePitch) {
  const Motion twist(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 3, 4));
  const Screw screw = twist_to_screw(twist);
  EXPECT_TRUE(std::isinf(screw.pitch) && screw.pitch > 0);
  EXPECT_TRUE(Near(screw.direction, Eigen::Vector3d(0, 0.6, 0.8)));
  EXPECT_EQ(screw.point, Eigen::Vector3d::Zero());
  EXPECT_DOUBLE_EQ(screw.magnitude, 5.0);
  EXPECT_TRUE(Near(screw_to_twist(screw).to_vector(), twist.to_vector()));
}

TEST(Screw, PureRotationHasZeroPitch) {
  const Motion twist(Eigen::Vector3d(0, -3, 0), Eigen::Vector3d::Zero());
  const Screw screw = twist_to_screw(twist);
  EXPECT_EQ(screw.pitch, 0.0);
  EXPECT_EQ(screw.point, Eigen::Vector3d::Zero());
  EXPECT_TRUE(Near(screw.direction, Eigen::Vector3d(0, -1, 0)));
  EXPECT_DOUBLE_EQ(screw.magnitude, 3.0);
}

TEST(Screw, SubnormalPartsKeepAUnitAxis) {
  // |(1, 1, 1) 5e-324| rounds to 1e-323, so w / |w| would be 0.5 each; the axis is scaled first
  const Eigen::Vector3d tiny = Eigen::Vector3d::Constant(5e-324);
  const Screw rotating = twist_to_screw(Motion(tiny, Eigen::Vector3d::Zero()));
  EXPECT_TRUE(Near(rotating.direction, Eigen::Vector3d::Constant(1.0 / std::sqrt(3.0))));
  EXPECT_GT(rotating.magnitude, 0.0);
  EXPECT_NO_THROW(screw_to_twist(rotating));  // which asks for a unit direction
  const Screw moving = twist_to_screw(Motion(Eigen::Vector3d::Zero(), tiny));
  EXPECT_TRUE(Near(moving.direction, Eigen::Vector3d::Constant(1.0 / std::sqrt(3.0))));
  EXPECT_TRUE(std::isinf(moving.pitch));
}

TEST(Screw, RejectsBadInput) {
  ExpectInvalid([] { twist_to_screw(Motion::Zero()); }, "twist");
  ExpectInvalid([] { twist_to_screw(Motion(Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::Zero())); }, "twist");
  // an angular part so small that the axis is out of range of double
  ExpectInvalid([] { twist_to_screw(Motion(Eigen::Vector3d(1e-300, 0, 0), Eigen::Vector3d(0, 1e10, 0))); }, "twist");
  ExpectInvalid([] { screw_to_twist(Screw{Eigen::Vector3d(1, 1, 0), Eigen::Vector3d::Zero(), 0.0, 1.0}); },
                "direction");
  ExpectInvalid([] { screw_to_twist(Screw{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::Zero(), NAN, 1.0}); }, "pitch");
  ExpectInvalid([] { screw_to_twist(Screw{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::Zero(), -INFINITY, 1.0}); },
                "pitch");
}

}  // namespace
}  // namespace rigiddyn
