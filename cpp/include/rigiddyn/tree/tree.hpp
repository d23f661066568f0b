// A kinematic tree (Featherstone §4.1-4.2): links numbered 0..n-1 in the order added, each with its
// parent λ(i) < i (-1 for the world W, the fixed root), the joint that connects it to its parent, the
// placement X_T = X_λJ of the joint frame J in the parent's frame, and its spatial inertia I_i in its
// own frame L_i. The pose of link i in its parent is X_λi = X_T X_J(q_i), and in the world
// X_Wi = X_Wλ X_λi. The configuration q stacks the joints' q_i in link order (nq entries), the
// velocity v their qd_i (nv entries); Link::idx_q / idx_v locate each segment.
// Uniform gravity g [m/s^2] in W (zero unless asked, docs/conventions.md).
#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

#include "rigiddyn/inertia/spatial_inertia.hpp"
#include "rigiddyn/spatial/transform.hpp"
#include "rigiddyn/tree/joint.hpp"

namespace rigiddyn {

struct Link {
  std::string name;
  int parent;              // λ(i): the parent's index, -1 for the world
  Joint joint;             // connects the parent (predecessor) to this link (successor)
  Transform X_T;           // X_λJ: the joint frame J in the parent's frame (W for a root link)
  SpatialInertia inertia;  // I_i: mass, centre of mass and I_C, expressed in this link's frame L_i
  Matrix6d I;              // I_i as the 6x6 spatial inertia about L_i's origin (angular first)
  MotionSubspace S;        // (6, nv) in L_i
  int idx_q, nq;           // this joint's segment of q
  int idx_v, nv;           // this joint's segment of v
};

class Tree {
 public:
  // gravity: g [m/s^2] in W, finite; throws std::invalid_argument naming "gravity".
  explicit Tree(const Eigen::Vector3d& gravity = Eigen::Vector3d::Zero());

  // Appends link n = num_links(), placed at X_T = X_λJ in its parent, and returns n. Throws std::invalid_argument, naming the link, for a
  // name that is empty or already used, a parent outside [-1, n-1] (links are added parents first) or
  // an inertia that is not positive definite (a principal moment of I_C <= 0, e.g. a point mass).
  int add_link(const std::string& name, int parent, const Joint& joint, const SpatialInertia& inertia,
               const Transform& X_T = Transform());

  int num_links() const { return static_cast<int>(links_.size()); }
  int nq() const { return nq_; }
  int nv() const { return nv_; }
  const Link& link(int i) const { return links_[i]; }
  const std::vector<Link>& links() const { return links_; }
  // The index of the link called `name`; throws std::invalid_argument naming "name" if none is.
  int link_index(const std::string& name) const;

  const Eigen::Vector3d& gravity() const { return gravity_; }
  void set_gravity(const Eigen::Vector3d& gravity);

  // The neutral configuration (every angle and offset 0, every quaternion the identity), (nq,).
  Eigen::VectorXd neutral_configuration() const;
  // q_out = q ⊕ v dt joint by joint (joints/*.hpp); q_out may alias q. Checks q and v as below.
  void integrate(const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Ref<const Eigen::VectorXd>& v, double dt,
                 Eigen::Ref<Eigen::VectorXd> q_out) const;

  // Argument checks of the algorithms (std::invalid_argument naming the argument): q of size nq,
  // finite, each joint quaternion within unit_quaternion_tolerance of unit norm (naming the link);
  // a vector of size nv (velocity, acceleration, torque), finite.
  void check_configuration(const Eigen::Ref<const Eigen::VectorXd>& q, const char* name = "q") const;
  void check_velocity(const Eigen::Ref<const Eigen::VectorXd>& v, const char* name) const;

 private:
  std::vector<Link> links_;
  int nq_ = 0, nv_ = 0;
  Eigen::Vector3d gravity_;
};

}  // namespace rigiddyn
