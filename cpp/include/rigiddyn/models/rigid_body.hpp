// The spatial rigid body (6 DOF): mass properties, state (docs/conventions.md "Body state") and the form of
// Euler's equations its inertia needs (euler_equations.hpp), so that a sphere pays nothing for the gyroscopic term.
//
// Equations of motion (Craig, "Rigid Body Dynamics" slides, Newton–Euler about the centre of mass G):
//   ṗ_W = v_W,  q̇_WB = ½ q_WB ⊗ (ω_B, 0),  m v̇_W = f_W + m g_W,  I ω̇_B + ω_B × I ω_B = tau_B.
#pragma once
#include "rigiddyn/inertia/spatial_inertia.hpp"
#include "rigiddyn/inertia/validity.hpp"  // InertiaCheck
#include "rigiddyn/models/euler_equations.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <stdexcept>
#include <string>

namespace rigiddyn {

// Which form of Euler's equations an inertia needs.
enum class EulerForm { spherical, principal, full };

// Mass [kg] and rotational inertia about the centre of mass [kg m²], expressed in the body frame B
// (origin at the centre of mass).
class RigidBody {
 public:
  // Throws std::invalid_argument (the inertia layer's checked_inertia, so the messages are those of
  // every other constructor of mass properties) for mass <= 0 or non-finite, for an inertia_com that is
  // not symmetric positive semi-definite or, under InertiaCheck::physical (the default), whose
  // principal moments violate I_a + I_b >= I_c (no real body has them; pass
  // InertiaCheck::allow_unrealizable to accept e.g. the Hairer–Lubich–Wanner test body
  // I = (2, 1, 2/3) on purpose); and for a singular inertia (Euler's equations need I⁻¹).
  RigidBody(double mass, const Eigen::Matrix3d& inertia_com, InertiaCheck check = InertiaCheck::physical);
  // The same from any Eigen expression: a 3×3 one is inertia_com; a 3-vector holds the principal
  // moments (I1, I2, I3) [kg m²] about the centre of mass, B's axes principal: inertia_com =
  // diag(I1, I2, I3). (One template for both, so that `RigidBody(m, Eigen::Matrix3d::Identity())` and
  // `RigidBody(m, Eigen::Vector3d(1, 2, 2.5))` are never ambiguous.)
  template <class Derived>
  RigidBody(double mass, const Eigen::MatrixBase<Derived>& inertia, InertiaCheck check = InertiaCheck::physical)
      : RigidBody(mass, as_inertia_com(inertia), check) {}
  // From mass properties: uses mass() and inertia_com() (B's axes, origin moved to the centre of mass).
  explicit RigidBody(const SpatialInertia& inertia, InertiaCheck check = InertiaCheck::physical);

  double mass() const { return mass_; }
  const Eigen::Matrix3d& inertia_com() const { return inertia_com_; }
  // spherical if I = s 1, principal if I is diagonal, full otherwise (relative tolerance 1e-12,
  // so dropping the terms changes the motion far below any integrator's error).
  EulerForm euler_form() const { return form_; }

 private:
  template <class Derived>
  static Eigen::Matrix3d as_inertia_com(const Eigen::MatrixBase<Derived>& inertia) {
    if constexpr (Derived::ColsAtCompileTime == 1) {
      static_assert(Derived::RowsAtCompileTime == 3, "RigidBody: principal moments are a 3-vector");
      return Eigen::Vector3d(inertia).asDiagonal();
    } else {
      static_assert(Derived::RowsAtCompileTime == 3 && Derived::ColsAtCompileTime == 3, "RigidBody: inertia_com is 3x3");
      return inertia;
    }
  }

  double mass_;
  Eigen::Matrix3d inertia_com_;
  EulerForm form_;
};

// Calls f(euler) with the Euler-equation form the body needs: SphericalEuler, PrincipalEuler or
// FullEuler. The single runtime switch; everything below it is compiled per form.
template <class F>
decltype(auto) with_euler_form(const RigidBody& body, F&& f) {
  const Eigen::Matrix3d& I = body.inertia_com();
  switch (body.euler_form()) {
    case EulerForm::spherical: return f(SphericalEuler(I.trace() / 3.0));
    case EulerForm::principal: return f(PrincipalEuler(I.diagonal()));
    case EulerForm::full: return f(FullEuler(I));
  }
  throw std::logic_error("with_euler_form: unknown EulerForm");
}

// State (docs/conventions.md): p_W of the centre of mass [m], unit q_WB, v_W of the centre of mass
// [m/s] in W, angular velocity w_B [rad/s] in B.
struct RigidBodyState {
  Eigen::Vector3d p_W = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_WB = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_B = Eigen::Vector3d::Zero();
};

// The state with its quaternion normalised; throws std::invalid_argument naming `name`.p_W etc.
// for a non-finite entry or a quaternion farther than 1e-6 from unit norm.
RigidBodyState checked_state(const RigidBodyState& state, const std::string& name = "state");

// Coordinates layout (rot/lin as MuJoCo): y = (p_W:3, q_WB xyzw:4, v_W:3, w_B:3, work:1) (14,), as the SIMD batch
// path holds a sample (batch/simd_rigid_body.hpp).
using RigidBodyCoordinates = Eigen::Matrix<double, 14, 1>;
RigidBodyCoordinates to_coordinates(const RigidBodyState& state, double work = 0.0);

}  // namespace rigiddyn
