// The sub-flows the structure-preserving rigid-body methods are built from (splitting_dlm.hpp,
// yoshida4.hpp, exact_flow_kick.hpp, implicit_midpoint.hpp). Each is the EXACT flow of one part
// of the split Newton–Euler equations (seed 001), so a composition of them keeps what each part keeps:
//
//   loads part   ṗ = 0, q̇ = 0, m v̇ = f_W(q), I ω̇ = n_B(q)      (loads_kick: v, ω move linearly)
//   free part    ṗ = v, v̇ = 0 (free_translation);  Euler–Poinsot ṁ = m × ω, Ṙ = R ω̂ (rotation)
//
// The free rotation is split once more, H = Σ m_i²/(2 I_i) over the principal axes
// (Dullweber, Leimkuhler & McLachlan 1997; McLachlan 1993; Reich 1994): the flow of one term
// H_i turns m about the principal axis e_i by −θ and the attitude about it by +θ, θ = h m_i/I_i,
// so |m|, the spatial L_W = R m and unit |q| are exact in every sub-flow (principal_axis_flow).
#pragma once
#include "rigiddyn/models/rigid_body.hpp"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <type_traits>

namespace rigiddyn {

// True for RigidBodyModel<Euler>: the methods below use the rigid body's structure there and fall
// back to velocity-Verlet-like forms for models without a gyroscopic term (particle, planar body).
template <class Model>
struct is_rigid_body_model : std::false_type {};
template <class Euler>
struct is_rigid_body_model<RigidBodyModel<Euler>> : std::true_type {};
template <class Model>
inline constexpr bool is_rigid_body_model_v = is_rigid_body_model<Model>::value;

// The rotational inertia about the centre of mass in B as a matrix [kg m²].
inline Eigen::Matrix3d inertia_matrix(const SphericalEuler& e) { return e.inertia * Eigen::Matrix3d::Identity(); }
inline Eigen::Matrix3d inertia_matrix(const PrincipalEuler& e) { return e.inertia.asDiagonal(); }
inline Eigen::Matrix3d inertia_matrix(const FullEuler& e) { return e.inertia; }

// Principal axes of an inertia: moments I_P (3,) [kg m²], the principal frame P in B (q_BP, det +1;
// identity for a diagonal inertia) and the axis indices sorted by increasing moment.
struct PrincipalSplit {
  Eigen::Vector3d moments;
  Eigen::Quaterniond q_BP;
  std::array<int, 3> ascending;
};

inline std::array<int, 3> ascending_axes(const Eigen::Vector3d& I) {
  std::array<int, 3> order{0, 1, 2};
  if (I(order[1]) < I(order[0])) std::swap(order[0], order[1]);
  if (I(order[2]) < I(order[1])) std::swap(order[1], order[2]);
  if (I(order[1]) < I(order[0])) std::swap(order[0], order[1]);
  return order;
}

inline PrincipalSplit principal_split(const PrincipalEuler& e) {
  return {e.inertia, Eigen::Quaterniond::Identity(), ascending_axes(e.inertia)};
}

// A full inertia is diagonalised at each call (Eigen's closed-form 3×3 solver, eigenvalues ascending).
inline PrincipalSplit principal_split(const FullEuler& e) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(e.inertia);
  Eigen::Matrix3d R_BP = solver.eigenvectors();
  if (R_BP.determinant() < 0.0) R_BP.col(2) = -R_BP.col(2);
  return {solver.eigenvalues(), Eigen::Quaterniond(R_BP).normalized(), {0, 1, 2}};
}

// The exact flow of the loads part over h [s] at the current attitude (no gyroscopic term):
// v += h f_W/m, ω += h I⁻¹ n_B, and the work += h (f_W·v̄ + n_B·ω̄) with v̄, ω̄ the mean velocities
// (exact: v and ω are linear in t in this flow). One derivative evaluation (ξ at ω = 0 is
// (v, 0, f_W/m, I⁻¹ n_B, ·)). Returns the angular velocity increment h I⁻¹ n_B [rad/s].
template <class Euler>
Eigen::Vector3d loads_kick(const RigidBodyModel<Euler>& model, RigidBodyCoordinates& y, double h) {
  RigidBodyCoordinates still = y;
  still.segment<3>(10).setZero();
  const RigidBodyTangent xi = model.velocity(still);
  const Eigen::Vector3d dv = h * xi.segment<3>(6), dw = h * xi.segment<3>(9);
  const Eigen::Vector3d v_mean = y.segment<3>(7) + 0.5 * dv, w_mean = y.segment<3>(10) + 0.5 * dw;
  y(13) += model.mass() * dv.dot(v_mean) + model.euler().momentum(dw).dot(w_mean);
  y.segment<3>(7) += dv;
  y.segment<3>(10) += dw;
  return dw;
}

// Velocity Verlet kick(h/2) · drift(h) · kick(h/2) with the model's own kick and drift: what the
// splitting methods reduce to for models without a gyroscopic term (particle, planar body).
template <class Model>
void velocity_verlet(const Model& model, typename Model::Coordinates& y, double h) {
  model.kick(y, 0.5 * h);
  model.drift(y, h);
  model.kick(y, 0.5 * h);
}

// The free translation over h [s]: p += h v (no work: no load acts in this part).
inline void free_translation(RigidBodyCoordinates& y, double h) { y.segment<3>(0) += h * y.segment<3>(7); }

// The exact flow of H_i = m_i²/(2 I_i) over h [s] (axis i of the principal frame P, moment I_i):
// m_P ← Rot(e_i, −θ) m_P, q_WP ← q_WP ⊗ Rot(e_i, θ), θ = h m_i/I_i (m_i is constant in this flow).
inline void principal_axis_flow(int i, double I_i, double h, Eigen::Vector3d& m_P, Eigen::Quaterniond& q_WP) {
  const double half = 0.5 * h * m_P(i) / I_i;
  const double s_half = std::sin(half), c_half = std::cos(half);
  const double c = c_half * c_half - s_half * s_half, s = 2.0 * s_half * c_half;  // cos θ, sin θ
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double m_j = m_P(j), m_k = m_P(k);
  m_P(j) = c * m_j + s * m_k;
  m_P(k) = -s * m_j + c * m_k;
  Eigen::Quaterniond turn(c_half, 0.0, 0.0, 0.0);
  turn.vec()(i) = s_half;
  q_WP = q_WP * turn;
}

}  // namespace rigiddyn
