// Mass properties of a set of point masses (Rigid-body notes eqs. (4.53)-(4.54)):
//   m = sum m_i,  c = (1/m) sum m_i r_i,  I_C = sum m_i (|r_i - c|^2 1 - (r_i - c)(r_i - c)^T).
#pragma once
#include <Eigen/Core>

#include "rigiddyn/inertia/spatial_inertia.hpp"

namespace rigiddyn {

// masses: (n,) [kg], each finite and >= 0 with a positive sum; positions: (n, 3) [m], row i the
// position of mass i in the frame of expression. Throws std::invalid_argument naming the argument
// (and the offending index) otherwise.
SpatialInertia from_point_masses(const Eigen::Ref<const Eigen::VectorXd>& masses,
                                 const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>& positions);

}  // namespace rigiddyn
