// Python bindings of the so3 layer.
#include "bindings.hpp"
#include "numpy_io.hpp"

namespace rigiddyn::bindings {

void bind_so3(pybind11::module_& m) { (void)m; }

}  // namespace rigiddyn::bindings
