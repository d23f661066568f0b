// The bodies of a scene (docs/scenes.md §1, docs/fixed_point_frames_mass.md §1): one body kind each, with the
// helpers that force elements need to read their mass properties and to check the body indices they are given.
// "W" is the scene frame: W itself when the scene declares no moving frame, else F (states are relative to it).
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/overloaded.hpp"
#include "rigiddyn/models/gyrostat.hpp"
#include "rigiddyn/models/particle.hpp"
#include "rigiddyn/models/pivoted_body.hpp"
#include "rigiddyn/models/pivoted_planar_body.hpp"
#include "rigiddyn/models/planar_body.hpp"
#include "rigiddyn/models/rigid_body.hpp"
#include "rigiddyn/scene/body_kinematics.hpp"
#include "rigiddyn/tree/tree_link.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

namespace rigiddyn {

// A body of a scene: a particle (3 DOF, no attitude), a planar body (x, y, θ in W's xy plane), a
// spatial rigid body (6 DOF), a rigid body pinned at a point O fixed in W (3 rotational DOF), a planar
// body pinned at O (the compound pendulum, θ about z), a gyrostat (a rigid body carrying motor-driven wheels,
// 6 DOF and one per wheel) or a link of a kinematic tree (its joint's DOF; the tree's links are consecutive bodies,
// tree/tree_link.hpp).
using Body = std::variant<Particle, PlanarBody, RigidBody, PivotedBody, PivotedPlanarBody, Gyrostat, TreeLink>;
// The state of a body of the matching kind (same alternative index as its Body).
using BodyState = std::variant<ParticleState, PlanarBodyState, RigidBodyState, PivotedBodyState, PivotedPlanarBodyState,
                               GyrostatState, JointState>;
// Indices into a scene's bodies that an element acts on; empty means every body.
using BodyList = std::vector<int>;

// The mass [kg] of a body of any kind.
inline double mass_of(const Body& body) {
  return std::visit([](const auto& b) { return b.mass(); }, body);
}

// The rotational inertia about the centre of mass, expressed in B [kg m²]:
//   particle                    zero (a point mass has none);
//   planar body (also pinned)   diag(0, 0, I_zz): the only moment a planar body carries; its in-plane
//                               moments are unknown and taken as zero (an element that needs them must
//                               refuse planar bodies);
//   rigid body (also pinned)    inertia_com(), about the centre of mass (not the pivot's I_O);
//   gyrostat                    inertia_com(), the whole body's with its wheels locked;
//   tree link                   inertia_com(), the link's, in axes parallel to its link frame.
inline Eigen::Matrix3d inertia_com_of(const Body& body) {
  return std::visit(
      [](const auto& b) -> Eigen::Matrix3d {
        using T = std::decay_t<decltype(b)>;
        if constexpr (std::is_same_v<T, RigidBody> || std::is_same_v<T, PivotedBody> || std::is_same_v<T, Gyrostat> ||
                      std::is_same_v<T, TreeLink>) {
          return b.inertia_com();
        } else if constexpr (std::is_same_v<T, PlanarBody> || std::is_same_v<T, PivotedPlanarBody>) {
          return Eigen::Vector3d(0.0, 0.0, b.inertia_zz()).asDiagonal();
        } else {
          return Eigen::Matrix3d::Zero();
        }
      },
      body);
}

// What elements and checks ask of a body kind (never its type): one entry per kind, so that a kind added to
// Body and not described here does not compile.
struct BodyTraits {
  bool has_attitude;         // forces can turn it (every kind but the particle)
  bool is_planar;            // it moves in W's xy plane: forces keep their x, y parts and torques their z part
  bool is_pivoted;           // it is pinned at a point O fixed in W
  bool has_spatial_inertia;  // it carries a full 3×3 inertia about its centre of mass (inertia_com_of)
  bool has_rotors;           // it carries wheels spinning relative to it (a gyrostat): coordinates beyond its motion
  bool is_linked;            // it is a link of a tree: its joint and the other links' motion hold it
};

inline BodyTraits body_traits(const Body& body) {
  return std::visit(overloaded{[](const Particle&) { return BodyTraits{false, false, false, false, false, false}; },
                               [](const PlanarBody&) { return BodyTraits{true, true, false, false, false, false}; },
                               [](const RigidBody&) { return BodyTraits{true, false, false, true, false, false}; },
                               [](const PivotedBody&) { return BodyTraits{true, false, true, true, false, false}; },
                               [](const PivotedPlanarBody&) { return BodyTraits{true, true, true, false, false, false}; },
                               [](const Gyrostat&) { return BodyTraits{true, false, false, true, true, false}; },
                               [](const TreeLink&) { return BodyTraits{true, false, false, true, false, true}; }},
                    body);
}

inline bool has_attitude(const Body& body) { return body_traits(body).has_attitude; }

// The wheels a body carries (a gyrostat's; 0 for the other kinds), and those of a scene's bodies: the columns of
// SceneSimulation::wheel_speed.
inline std::size_t wheel_count(const Body& body) {
  const auto* gyrostat = std::get_if<Gyrostat>(&body);
  return gyrostat ? gyrostat->wheels().size() : 0;
}
inline std::size_t wheel_count(const std::vector<Body>& bodies) {
  std::size_t n = 0;
  for (const Body& body : bodies) n += wheel_count(body);
  return n;
}
// The trees' coordinates and velocities among a scene's bodies (their nq and nv summed, each tree counted at its
// link 0): the columns of SceneSimulation::joint_q and joint_v.
struct JointCounts {
  std::size_t q = 0, v = 0;
};
inline JointCounts joint_counts(const std::vector<Body>& bodies) {
  JointCounts n;
  for (const Body& body : bodies) {
    const auto* link = std::get_if<TreeLink>(&body);
    if (link && link->link == 0) n.q += static_cast<std::size_t>(link->tree->nq()), n.v += static_cast<std::size_t>(link->tree->nv());
  }
  return n;
}
inline bool is_planar(const Body& body) { return body_traits(body).is_planar; }
inline bool is_pivoted(const Body& body) { return body_traits(body).is_pivoted; }

// A short name of the body's kind for messages: "particle", "planar body", "rigid body", "pivoted body",
// "pivoted planar body", "gyrostat" or "tree link".
inline const char* kind_name(const Body& body) {
  static constexpr const char* names[] = {"particle",     "planar body",         "rigid body",
                                          "pivoted body", "pivoted planar body", "gyrostat", "tree link"};
  static_assert(std::variant_size_v<Body> == sizeof names / sizeof names[0], "a name per body kind");
  return names[body.index()];
}

// The name of the state type of each body kind for messages ("ParticleState", ...).
inline const char* state_type_name(std::size_t kind) {
  static constexpr const char* names[] = {"ParticleState", "PlanarBodyState", "RigidBodyState", "PivotedBodyState",
                                          "PivotedPlanarBodyState", "GyrostatState", "JointState"};
  static_assert(std::variant_size_v<BodyState> == sizeof names / sizeof names[0], "a name per state type");
  return names[kind];
}

// Throws std::invalid_argument "<name>: expected a body index in [0, n_bodies), got i" unless
// 0 <= i < n_bodies.
inline void check_body_index(int i, int n_bodies, const std::string& name) {
  if (i < 0 || i >= n_bodies) throw_invalid(name, "a body index in [0, " + std::to_string(n_bodies) + ")", i);
}

// The kinematics an element sees of a free body in `state` (body_kinematics.hpp), without its mass
// (k.m = 0; kinematics_of(body, state) sets it): a particle has q_WB = identity and w_B = 0; a planar body
// p_W = (x, y, 0), q_WB = Rz(θ), v_W = (v_x, v_y, 0), w_B = (0, 0, ω). A pinned body's kinematics need the
// body (its pivot): std::invalid_argument "state: ..." for a pivoted state; a tree link's need its whole tree's
// state (the scene model's): std::invalid_argument for a JointState.
inline BodyKinematics kinematics_of(const BodyState& state) {
  // one lambda per state kind: a kind added to BodyState and not handled here does not compile
  const auto pinned = [](const auto& /*pivoted_state*/) -> BodyKinematics {
    throw std::invalid_argument("state: expected the state of a free body (a pinned body's kinematics "
                                "need its pivot: use kinematics_of(body, state)), got a pivoted state");
  };
  return std::visit(overloaded{[](const ParticleState& s) {
                                 BodyKinematics k;
                                 k.p_W = s.p_W, k.v_W = s.v_W;
                                 return k;
                               },
                               [](const PlanarBodyState& s) {
                                 BodyKinematics k;
                                 k.p_W << s.p_W, 0.0;
                                 set_attitude(k, Eigen::Quaterniond(Eigen::AngleAxisd(s.theta, Eigen::Vector3d::UnitZ())));
                                 k.v_W << s.v_W, 0.0;
                                 k.w_B << 0.0, 0.0, s.omega;
                                 return k;
                               },
                               [](const RigidBodyState& s) {
                                 BodyKinematics k;
                                 k.p_W = s.p_W, k.v_W = s.v_W, k.w_B = s.w_B;
                                 set_attitude(k, s.q_WB);
                                 return k;
                               },
                               [&](const PivotedBodyState& s) { return pinned(s); },
                               [&](const PivotedPlanarBodyState& s) { return pinned(s); },
                               [](const GyrostatState& s) {
                                 BodyKinematics k;
                                 k.p_W = s.p_W, k.v_W = s.v_W, k.w_B = s.w_B;
                                 set_attitude(k, s.q_WB);
                                 return k;
                               },
                               [](const JointState&) -> BodyKinematics {
                                 throw std::invalid_argument("state: expected the state of a free body (a tree link's "
                                                             "kinematics need its whole tree's state), got a JointState");
                               }},
                    state);
}

// The kinematics an element sees of `body` in `state` (of its kind), with its (initial) mass k.m [kg];
// a pinned body at its centre of mass (models/pivoted_body.hpp, pivoted_planar_body.hpp).
inline BodyKinematics kinematics_of(const Body& body, const BodyState& state) {
  if (const auto* b = std::get_if<PivotedBody>(&body)) return kinematics_of(*b, std::get<PivotedBodyState>(state));
  if (const auto* b = std::get_if<PivotedPlanarBody>(&body)) return kinematics_of(*b, std::get<PivotedPlanarBodyState>(state));
  BodyKinematics k = kinematics_of(state);
  k.m = mass_of(body);
  return k;
}

}  // namespace rigiddyn
