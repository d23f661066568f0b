// Python bindings of the exact layer.
#include "bindings.hpp"
#include "numpy_io.hpp"

namespace rigiddyn::bindings {

void bind_exact(pybind11::module_& m) { (void)m; }

}  // namespace rigiddyn::bindings
