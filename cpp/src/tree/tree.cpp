#include "rigiddyn/tree/tree.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

#include "rigiddyn/check.hpp"
#include "rigiddyn/so3/quaternion.hpp"

namespace rigiddyn {

namespace {

// "link 3 ('forearm')": how messages name a link.
std::string link_label(int index, const std::string& name) {
  return "link " + std::to_string(index) + " ('" + name + "')";
}

}  // namespace

Tree::Tree(const Eigen::Vector3d& gravity) { set_gravity(gravity); }

void Tree::set_gravity(const Eigen::Vector3d& gravity) {
  require_finite(gravity.transpose(), "gravity");
  gravity_ = gravity;
}

int Tree::add_link(const std::string& name, int parent, const Joint& joint, const SpatialInertia& inertia,
                   const Transform& X_T) {
  const int n = num_links();
  const std::string label = link_label(n, name);
  if (name.empty()) throw std::invalid_argument(label + ": name: expected a non-empty string, got ''");
  for (const Link& other : links_)
    if (other.name == name) throw std::invalid_argument(label + ": name: expected a name not yet used, got '" + name + "'");
  if (parent < -1 || parent >= n) {
    throw std::invalid_argument(label + ": parent: expected an index in [-1, " + std::to_string(n - 1) +
                                "] (-1 for the world; parents are added first), got " + std::to_string(parent));
  }
  // a positive-definite spatial inertia <=> m > 0 and I_C positive definite (Schur complement of m 1)
  const Eigen::Vector3d moments = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(inertia.inertia_com()).eigenvalues();
  if (!(moments.minCoeff() > 0.0)) {
    throw std::invalid_argument(label + ": inertia: expected a positive-definite spatial inertia (every principal " +
                                "moment about the centre of mass > 0), got principal moments " +
                                format_value(moments.transpose().eval()));
  }
  Link link{name, parent, joint, X_T, inertia, inertia.matrix(), motion_subspace(joint), nq_, joint_nq(joint),
            nv_, joint_nv(joint)};
  nq_ += link.nq;
  nv_ += link.nv;
  links_.push_back(std::move(link));
  return n;
}

int Tree::link_index(const std::string& name) const {
  for (int i = 0; i < num_links(); ++i)
    if (links_[i].name == name) return i;
  throw std::invalid_argument("name: expected the name of a link, got '" + name + "'");
}

Eigen::VectorXd Tree::neutral_configuration() const {
  Eigen::VectorXd q(nq_);
  for (const Link& link : links_) joint_neutral(link.joint, q.segment(link.idx_q, link.nq));
  return q;
}

void Tree::integrate(const Eigen::Ref<const Eigen::VectorXd>& q, const Eigen::Ref<const Eigen::VectorXd>& v, double dt,
                     Eigen::Ref<Eigen::VectorXd> q_out) const {
  check_configuration(q);
  check_velocity(v, "v");
  require_finite(dt, "dt");
  if (q_out.size() != nq_) throw_invalid("q_out", "size nq = " + std::to_string(nq_), q_out.size());
  for (const Link& link : links_) {
    // a joint's update reads only its own segment of q, so q_out may alias q
    const Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 7, 1> q_i = q.segment(link.idx_q, link.nq);
    joint_integrate(link.joint, q_i, v.segment(link.idx_v, link.nv), dt, q_out.segment(link.idx_q, link.nq));
  }
}

void Tree::check_configuration(const Eigen::Ref<const Eigen::VectorXd>& q, const char* name) const {
  if (q.size() != nq_) throw_invalid(name, "shape (nq,) = (" + std::to_string(nq_) + ",)", "shape (" + std::to_string(q.size()) + ",)");
  require_finite(q.transpose(), name);
  for (int i = 0; i < num_links(); ++i) {
    const Link& link = links_[i];
    if (!joint_has_quaternion(link.joint)) continue;
    const double norm = q.segment(link.idx_q + link.nq - 4, 4).norm();
    if (!(std::abs(norm - 1.0) <= unit_quaternion_tolerance)) {
      const int k = link.idx_q + link.nq - 4;
      throw_invalid(std::string(name) + "[" + std::to_string(k) + ":" + std::to_string(k + 4) + "] (the quaternion of " +
                        link_label(i, link.name) + ")",
                    "a unit quaternion (x, y, z, w), |q| within 1e-6 of 1", q.segment(k, 4).transpose().eval());
    }
  }
}

void Tree::check_velocity(const Eigen::Ref<const Eigen::VectorXd>& v, const char* name) const {
  if (v.size() != nv_) throw_invalid(name, "shape (nv,) = (" + std::to_string(nv_) + ",)", "shape (" + std::to_string(v.size()) + ",)");
  require_finite(v.transpose(), name);
}

}  // namespace rigiddyn
