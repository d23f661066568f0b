// Python bindings of the spatial layer.
#include "bindings.hpp"
#include "numpy_io.hpp"

namespace rigiddyn::bindings {

void bind_spatial(pybind11::module_& m) { (void)m; }

}  // namespace rigiddyn::bindings
