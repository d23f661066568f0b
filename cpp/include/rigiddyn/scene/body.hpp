// The bodies of a scene (scene_api.md §2): one of today's body kinds each, with the helpers that force
// elements need to read their mass properties and to check the body indices they are given.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/models/particle.hpp"
#include "rigiddyn/models/planar_body.hpp"
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace rigiddyn {

// A body of a scene: a particle (3 DOF, no attitude), a planar body (x, y, θ in W's xy plane) or a
// spatial rigid body (6 DOF).
using Body = std::variant<Particle, PlanarBody, RigidBody>;
// The state of a body of the matching kind (same alternative index as its Body).
using BodyState = std::variant<ParticleState, PlanarBodyState, RigidBodyState>;
// Indices into a scene's bodies that an element acts on; empty means every body.
using BodyList = std::vector<int>;

// The mass [kg] of a body of any kind.
inline double mass_of(const Body& body) {
  return std::visit([](const auto& b) { return b.mass(); }, body);
}

// The rotational inertia about the centre of mass, expressed in B [kg m²]:
//   particle      zero (a point mass has none);
//   planar body   diag(0, 0, I_zz): the only moment a planar body carries; its in-plane moments are
//                 unknown and taken as zero (an element that needs them must refuse planar bodies);
//   rigid body    inertia_com().
inline Eigen::Matrix3d inertia_com_of(const Body& body) {
  return std::visit(
      [](const auto& b) -> Eigen::Matrix3d {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, RigidBody>) {
          return b.inertia_com();
        } else if constexpr (std::is_same_v<T, PlanarBody>) {
          return Eigen::Vector3d(0.0, 0.0, b.inertia_zz()).asDiagonal();
        } else {
          return Eigen::Matrix3d::Zero();
        }
      },
      body);
}

// True for a body with an attitude that forces can turn (planar and rigid bodies), false for a particle.
inline bool has_attitude(const Body& body) { return !std::holds_alternative<Particle>(body); }

// A short name of the body's kind for messages: "particle", "planar body" or "rigid body".
inline const char* kind_name(const Body& body) {
  static constexpr const char* names[] = {"particle", "planar body", "rigid body"};
  return names[body.index()];
}

// Throws std::invalid_argument "<name>: expected a body index in [0, n_bodies), got i" unless
// 0 <= i < n_bodies.
inline void check_body_index(int i, int n_bodies, const std::string& name) {
  if (i < 0 || i >= n_bodies) throw_invalid(name, "a body index in [0, " + std::to_string(n_bodies) + ")", i);
}

// The kinematics an element sees of a body in `state` (body_kinematics.hpp): a particle has q_WB =
// identity and w_B = 0; a planar body p_W = (x, y, 0), q_WB = Rz(θ), v_W = (v_x, v_y, 0), w_B = (0, 0, ω).
inline BodyKinematics kinematics_of(const BodyState& state) {
  return std::visit(
      [](const auto& s) {
        using T = std::decay_t<decltype(s)>;
        BodyKinematics k;
        if constexpr (std::is_same_v<T, RigidBodyState>) {
          k.p_W = s.p_W, k.q_WB = s.q_WB, k.v_W = s.v_W, k.w_B = s.w_B;
        } else if constexpr (std::is_same_v<T, PlanarBodyState>) {
          k.p_W << s.p_W, 0.0;
          k.q_WB = Eigen::Quaterniond(Eigen::AngleAxisd(s.theta, Eigen::Vector3d::UnitZ()));
          k.v_W << s.v_W, 0.0;
          k.w_B << 0.0, 0.0, s.omega;
        } else {
          k.p_W = s.p_W, k.v_W = s.v_W;
        }
        return k;
      },
      state);
}

}  // namespace rigiddyn
