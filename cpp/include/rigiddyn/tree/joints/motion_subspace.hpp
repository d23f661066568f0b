// The motion subspace S of a joint (Featherstone §4.4): the 6 x nv matrix, angular rows first, whose
// columns span the joint's relative motions, expressed in the successor link's frame, so that the
// joint velocity is v_J = S qd. Every joint here has S constant in that frame (so c_J = S' qd = 0).
// At most 6 columns, stored in place (no heap).
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

using MotionSubspace = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::ColMajor, 6, 6>;

// A configuration or velocity segment of one joint (a view into the tree's q or v).
using JointVector = Eigen::Ref<const Eigen::VectorXd>;
using JointVectorOut = Eigen::Ref<Eigen::VectorXd>;

}  // namespace rigiddyn
