// Python bindings of the dynamics layer.
#include "bindings.hpp"
#include "numpy_io.hpp"

namespace rigiddyn::bindings {

void bind_dynamics(pybind11::module_& m) { (void)m; }

}  // namespace rigiddyn::bindings
