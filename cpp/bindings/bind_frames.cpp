// Python bindings of the frames layer.
#include "bindings.hpp"
#include "numpy_io.hpp"

namespace rigiddyn::bindings {

void bind_frames(pybind11::module_& m) { (void)m; }

}  // namespace rigiddyn::bindings
