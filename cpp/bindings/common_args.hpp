// Arguments that several layers' bindings take in the same form: the frame a vector is expressed
// in, and gravity. Converted here once so that every binding names and checks them alike.
#pragma once
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include "numpy_io.hpp"
#include "rigiddyn/simulate/simulate.hpp"  // standard_gravity
#include "rigiddyn/so3/integrate.hpp"      // Frame

namespace rigiddyn::bindings {

// 'world' or 'body' (the frame a vector is expressed in), else TypeError / ValueError naming `name`.
inline Frame as_frame(pybind11::handle frame, const std::string& name = "frame") {
  return py_io::as_choice<Frame>(frame, name, {{"world", Frame::world}, {"body", Frame::body}});
}

// None or False: no gravity; True: standard gravity (0, 0, -9.81) [m/s²]; else a 3-vector [m/s²] in W.
inline Eigen::Vector3d as_gravity(pybind11::handle obj) {
  if (obj.is_none()) return Eigen::Vector3d::Zero();
  if (pybind11::isinstance<pybind11::bool_>(obj))
    return obj.cast<bool>() ? standard_gravity() : Eigen::Vector3d::Zero();
  return py_io::as_vector3(py_io::in_si(obj, "m/s^2", "gravity"), "gravity");  // a float array [m/s²] or a pint quantity
}

}  // namespace rigiddyn::bindings
