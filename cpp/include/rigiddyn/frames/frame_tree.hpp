// A tree of reference frames rooted at the inertial world frame "world" (Craig: R ground,
// R1 shaft, R2 disk, ...). Each frame is placed relative to its parent by a FrameMotion; queries
// relate any frame to any other at a time t [s], with results expressed in a frame the caller
// names. Cycles are impossible: a frame's parent must already be in the tree, and set_parent
// refuses a new parent that is the frame itself or one of its descendants.
#pragma once
#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

#include "rigiddyn/frames/frame_kinematics.hpp"
#include "rigiddyn/frames/frame_motion.hpp"
#include "rigiddyn/frames/point_kinematics.hpp"

namespace rigiddyn {

class FrameTree {
 public:
  // The name of the root, the inertial world frame.
  static const std::string world;

  // A tree holding only "world".
  FrameTree();

  // Adds frame `name` as a child of `parent`, placed by `motion`. Throws std::invalid_argument on an
  // empty or duplicate name or an unknown parent.
  void add_frame(const std::string& name, const std::string& parent, FrameMotion motion);

  // Moves frame `name` (with its subtree) under `parent`, placed by `motion`. Throws
  // std::invalid_argument if `name` is "world" or unknown, `parent` is unknown, or `parent` is
  // `name` or one of its descendants (a cycle).
  void set_parent(const std::string& name, const std::string& parent, FrameMotion motion);

  // True if a frame named `name` exists (never throws).
  bool has_frame(const std::string& name) const { return frames_.count(name) != 0; }
  // The parent's name ("" for world). Throws on an unknown name.
  const std::string& parent(const std::string& name) const;
  // The motion placing `name` in its parent (world: fixed at the identity). Throws on an unknown name.
  const FrameMotion& motion(const std::string& name) const;
  // All names, world first, then in the order they were added.
  const std::vector<std::string>& frame_names() const { return names_; }

  // Every query evaluates the FrameMotion of each frame on the paths from world to the frames it
  // names, checks the value (finite, R_PF a rotation) and throws std::invalid_argument naming the
  // frame and t if it is bad or if the motion itself throws std::invalid_argument.

  // Frame `frame` (F) relative to `relative_to` (A) at time t, expressed in A (R_PF = R_AF, ...).
  FrameKinematics kinematics(const std::string& frame, const std::string& relative_to, double t) const;

  // R_AF: maps `frame` (F) coordinates to `relative_to` (A) coordinates at time t.
  Eigen::Matrix3d rotation(const std::string& frame, const std::string& relative_to, double t) const;

  // w_AF_E: angular velocity of `frame` F relative to `relative_to` A, expressed in `expressed_in`
  // E [rad/s] (addition theorem along the tree path, Craig).
  Eigen::Vector3d angular_velocity(const std::string& frame, const std::string& relative_to,
                                   const std::string& expressed_in, double t) const;

  // alpha_AF_E: angular acceleration of F relative to A (d/dt in A of w_AF), expressed in E
  // [rad/s^2]. Not the sum of the links' accelerations: includes the w x w terms (Craig).
  Eigen::Vector3d angular_acceleration(const std::string& frame, const std::string& relative_to,
                                       const std::string& expressed_in, double t) const;

  // Transport theorem (Craig): d^A u/dt = d^B u/dt + w_AB x u, with A = `to_frame`,
  // B = `from_frame`; u_E and du_B_E (the derivative of u seen from B) and the result are expressed
  // in `expressed_in` E.
  Eigen::Vector3d transport_derivative(const Eigen::Vector3d& u_E, const Eigen::Vector3d& du_B_E,
                                       const std::string& from_frame, const std::string& to_frame,
                                       const std::string& expressed_in, double t) const;

  // p_AQ_E: position of a point Q relative to the origin of `relative_to` A, expressed in E [m];
  // p_FQ_F: Q relative to the origin of `frame` F, expressed in F.
  Eigen::Vector3d point_position(const std::string& frame, const Eigen::Vector3d& p_FQ_F,
                                 const std::string& relative_to, const std::string& expressed_in,
                                 double t) const;

  // Velocity of Q seen from A, term by term (Rigid-body notes (4.38)), each term expressed in E [m/s].
  // Q is at p_FQ_F and moves with v_FQ_F as seen from F (both expressed in F); v = 0 for a point
  // fixed in F.
  PointVelocity point_velocity(const std::string& frame, const Eigen::Vector3d& p_FQ_F,
                               const Eigen::Vector3d& v_FQ_F, const std::string& relative_to,
                               const std::string& expressed_in, double t) const;

  // Acceleration of Q seen from A, term by term (origin, tangential, centripetal, relative,
  // Coriolis; Rigid-body notes (4.39), Craig), each term expressed in E [m/s^2]; a_FQ_F: Q's
  // acceleration seen from F, expressed in F.
  PointAcceleration point_acceleration(const std::string& frame, const Eigen::Vector3d& p_FQ_F,
                                       const Eigen::Vector3d& v_FQ_F, const Eigen::Vector3d& a_FQ_F,
                                       const std::string& relative_to, const std::string& expressed_in,
                                       double t) const;

 private:
  struct Node {
    std::string parent;
    FrameMotion motion;
  };
  // The node of a known frame; else std::invalid_argument naming `argument`.
  const Node& node(const std::string& name, const std::string& argument) const;
  // F relative to world at t, expressed in world (checking each link's FrameMotion value). Walks
  // the path iteratively, so a chain of any depth costs memory O(depth), never stack.
  FrameKinematics in_world(const std::string& name, double t) const;
  // The checked value of node n's motion at t (F = `name` relative to its parent); throws
  // std::invalid_argument naming the frame and t.
  static FrameKinematics link(const std::string& name, const Node& n, double t);
  // What every query needs: F relative to A (K_AF, expressed in A) and R_EA; checks all names and t.
  struct Query {
    FrameKinematics K_AF;
    Eigen::Matrix3d R_EA;
  };
  Query query(const std::string& frame, const std::string& relative_to, const std::string& expressed_in,
              double t) const;
  // The frame names as one string, for error messages ("world, A, ..."; the first 20 and the count).
  std::string known_names() const;

  std::map<std::string, Node> frames_;
  std::vector<std::string> names_;
};

}  // namespace rigiddyn
