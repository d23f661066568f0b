#include "rigiddyn/frames/frame_tree.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rigiddyn/check.hpp"

namespace rigiddyn {

const std::string FrameTree::world = "world";

namespace {
std::string quoted(const std::string& name) { return "'" + name + "'"; }
}  // namespace

FrameTree::FrameTree() {
  frames_.emplace(world, Node{"", FrameMotion::fixed()});
  names_.push_back(world);
}

std::string FrameTree::known_names() const {
  constexpr size_t listed = 20;  // a message stays readable for a tree of any size
  std::ostringstream out;
  for (size_t i = 0; i < std::min(names_.size(), listed); ++i) out << (i ? ", " : "") << names_[i];
  if (names_.size() > listed) out << ", ... (" << names_.size() << " frames)";
  return out.str();
}

const FrameTree::Node& FrameTree::node(const std::string& name, const std::string& argument) const {
  const auto it = frames_.find(name);
  if (it == frames_.end()) throw_invalid(argument, "the name of a frame in the tree (" + known_names() + ")", quoted(name));
  return it->second;
}

const std::string& FrameTree::parent(const std::string& name) const { return node(name, "name").parent; }

const FrameMotion& FrameTree::motion(const std::string& name) const { return node(name, "name").motion; }

void FrameTree::add_frame(const std::string& name, const std::string& parent, FrameMotion motion) {
  if (name.empty()) throw_invalid("name", "a non-empty frame name", quoted(name));
  if (has_frame(name)) throw_invalid("name", "a name not already in the tree (" + known_names() + ")", quoted(name));
  node(parent, "parent");
  frames_.emplace(name, Node{parent, std::move(motion)});
  names_.push_back(name);
}

void FrameTree::set_parent(const std::string& name, const std::string& parent, FrameMotion motion) {
  if (name == world) throw_invalid("name", "a frame other than the root " + quoted(world), quoted(name));
  node(name, "name");
  node(parent, "parent");
  // walking up from the new parent must not reach `name`, else the tree would get a cycle
  for (std::string a = parent; !a.empty(); a = frames_.at(a).parent) {
    if (a == name) {
      throw_invalid("parent", "a frame that is neither " + quoted(name) +
                                  " nor one of its descendants (that would make a cycle)",
                    quoted(parent));
    }
  }
  Node& n = frames_.at(name);
  n.parent = parent;
  n.motion = std::move(motion);
}

FrameKinematics FrameTree::link(const std::string& name, const Node& n, double t) {
  try {
    FrameKinematics K_PF = n.motion.at(t);
    check_frame_kinematics(K_PF);
    return K_PF;
  } catch (const std::invalid_argument& e) {  // name the frame whose motion failed
    std::ostringstream where;
    where.precision(17);
    where << "motion of frame " << quoted(name) << " at t=" << t << ": " << e.what();
    throw std::invalid_argument(where.str());
  }
}

FrameKinematics FrameTree::in_world(const std::string& name, double t) const {
  // the path from `name` up to world (iterative: a chain of any depth, no recursion)
  std::vector<std::pair<const std::string*, const Node*>> path;
  for (const std::string* a = &name;;) {
    const Node& n = frames_.at(*a);
    if (n.parent.empty()) break;  // reached world
    path.emplace_back(a, &n);
    a = &n.parent;
  }
  // K_WF = K_WP1 (+) K_P1P2 (+) ... (+) K_PnF, composed from world down
  FrameKinematics K_WF;
  for (auto it = path.rbegin(); it != path.rend(); ++it) K_WF = compose_kinematics(K_WF, link(*it->first, *it->second, t));
  return K_WF;
}

FrameTree::Query FrameTree::query(const std::string& frame, const std::string& relative_to,
                                  const std::string& expressed_in, double t) const {
  node(frame, "frame");
  node(relative_to, "relative_to");
  node(expressed_in, "expressed_in");
  require_finite(t, "t");
  const FrameKinematics K_WA = in_world(relative_to, t);
  const FrameKinematics K_WE = expressed_in == relative_to ? K_WA : in_world(expressed_in, t);
  return {relative_kinematics(K_WA, in_world(frame, t)), K_WE.R_PF.transpose() * K_WA.R_PF};  // R_EA = R_WE^T R_WA
}

FrameKinematics FrameTree::kinematics(const std::string& frame, const std::string& relative_to, double t) const {
  return query(frame, relative_to, relative_to, t).K_AF;
}

Eigen::Matrix3d FrameTree::rotation(const std::string& frame, const std::string& relative_to, double t) const {
  return kinematics(frame, relative_to, t).R_PF;
}

Eigen::Vector3d FrameTree::angular_velocity(const std::string& frame, const std::string& relative_to,
                                            const std::string& expressed_in, double t) const {
  const Query q = query(frame, relative_to, expressed_in, t);
  return q.R_EA * q.K_AF.w_PF_P;
}

Eigen::Vector3d FrameTree::angular_acceleration(const std::string& frame, const std::string& relative_to,
                                                const std::string& expressed_in, double t) const {
  const Query q = query(frame, relative_to, expressed_in, t);
  return q.R_EA * q.K_AF.alpha_PF_P;
}

Eigen::Vector3d FrameTree::transport_derivative(const Eigen::Vector3d& u_E, const Eigen::Vector3d& du_B_E,
                                                const std::string& from_frame, const std::string& to_frame,
                                                const std::string& expressed_in, double t) const {
  require_finite(u_E, "u_E");
  require_finite(du_B_E, "du_B_E");
  node(from_frame, "from_frame");  // named as this function's arguments, not as the query's
  node(to_frame, "to_frame");
  const Eigen::Vector3d w_AB_E = angular_velocity(from_frame, to_frame, expressed_in, t);
  return rigiddyn::transport_derivative(w_AB_E, u_E, du_B_E);
}

Eigen::Vector3d FrameTree::point_position(const std::string& frame, const Eigen::Vector3d& p_FQ_F,
                                          const std::string& relative_to, const std::string& expressed_in,
                                          double t) const {
  require_finite(p_FQ_F, "p_FQ_F");
  const Query q = query(frame, relative_to, expressed_in, t);
  return q.R_EA * (q.K_AF.p_PF_P + q.K_AF.R_PF * p_FQ_F);  // p_AQ = p_AF + R_AF p_FQ
}

PointVelocity FrameTree::point_velocity(const std::string& frame, const Eigen::Vector3d& p_FQ_F,
                                        const Eigen::Vector3d& v_FQ_F, const std::string& relative_to,
                                        const std::string& expressed_in, double t) const {
  require_finite(p_FQ_F, "p_FQ_F");
  require_finite(v_FQ_F, "v_FQ_F");
  const Query q = query(frame, relative_to, expressed_in, t);
  return rigiddyn::point_velocity(q.K_AF, p_FQ_F, v_FQ_F).rotated(q.R_EA);
}

PointAcceleration FrameTree::point_acceleration(const std::string& frame, const Eigen::Vector3d& p_FQ_F,
                                                const Eigen::Vector3d& v_FQ_F, const Eigen::Vector3d& a_FQ_F,
                                                const std::string& relative_to,
                                                const std::string& expressed_in, double t) const {
  require_finite(p_FQ_F, "p_FQ_F");
  require_finite(v_FQ_F, "v_FQ_F");
  require_finite(a_FQ_F, "a_FQ_F");
  const Query q = query(frame, relative_to, expressed_in, t);
  return rigiddyn::point_acceleration(q.K_AF, p_FQ_F, v_FQ_F, a_FQ_F).rotated(q.R_EA);
}

}  // namespace rigiddyn
