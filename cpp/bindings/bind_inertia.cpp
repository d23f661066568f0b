// Python bindings of the inertia layer.
#include "bindings.hpp"
#include "numpy_io.hpp"

namespace rigiddyn::bindings {

void bind_inertia(pybind11::module_& m) { (void)m; }

}  // namespace rigiddyn::bindings
