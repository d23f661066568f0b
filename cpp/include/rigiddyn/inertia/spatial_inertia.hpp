// The mass properties of one rigid body (CONVENTIONS.md "Inertia"): mass m, centre of mass c and
// rotational inertia about the centre of mass, all expressed in one frame (the body frame B unless
// a name says otherwise).
//
// This header is the shared interface of the inertia layer; the inertia issue extends it.
#pragma once
#include <Eigen/Core>

namespace rigiddyn {

class SpatialInertia {
 public:
  // mass [kg] > 0; com: centre of mass [m] in the frame of expression;
  // inertia_com: rotational inertia about the centre of mass [kg m^2], symmetric, in that frame.
  // Throws std::invalid_argument on non-finite input, mass <= 0 or an asymmetric inertia.
  SpatialInertia(double mass, const Eigen::Vector3d& com, const Eigen::Matrix3d& inertia_com);

  double mass() const { return mass_; }
  const Eigen::Vector3d& com() const { return com_; }
  const Eigen::Matrix3d& inertia_com() const { return inertia_com_; }

 private:
  double mass_;
  Eigen::Vector3d com_;
  Eigen::Matrix3d inertia_com_;
};

}  // namespace rigiddyn
