// One body's records (rigiddyn.BodyRecords, bind_body_records.cpp) of a run's result (SceneResult.body) or of a
// batch's (BatchSceneResult.body): the result's arrays that carry a bodies axis, read at one body.
#pragma once
#include <pybind11/pybind11.h>

#include <string>

namespace rigiddyn::bindings {

// What BodyRecords reads of a result: its arrays of shape (n, nb, ...), or (N, n, nb, ...) for a batch (t (n,) or
// (N, n)), its wheels' columns (n, nw) or (N, n, nw) with the body index of each wheel, and its body names.
struct BodyColumnsSource {
  pybind11::tuple body_names, wheel_bodies;
  pybind11::object t, p_W, q_WB, v_W, w_B, mass, pivot_reaction_W, angular_momentum_O_W, mass_flow_energy, wheel_speed,
      motor_work;
  bool scalar_first = false;
};

// The BodyRecords of body `key` (an index in [-nb, nb) or a name of body_names: TypeError or ValueError naming key
// otherwise): views of the source's arrays at that body, (n, ...) or (N, n, ...).
pybind11::object body_records(const BodyColumnsSource& source, pybind11::handle key);

// The docstring of a result's body(key): `summary`, the key parameter, `returns` (what its BodyRecords hold), the
// errors, then `examples` (doctest lines).
std::string body_method_doc(const std::string& summary, const std::string& returns, const std::string& examples);

}  // namespace rigiddyn::bindings
