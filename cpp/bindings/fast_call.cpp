#include "fast_call.hpp"

#include <cstdlib>
#include <string>
#include <vector>

namespace rigiddyn::bindings {
namespace {

// The installers FastCall::add registered, in order.
std::vector<void (*)(pybind11::module_&)>& installers() {
  static std::vector<void (*)(pybind11::module_&)> all;
  return all;
}

}  // namespace

void register_fast_call(void (*install)(pybind11::module_&)) { installers().push_back(install); }

void install_fast_calls(pybind11::module_& m) {
  if (const char* stubgen = std::getenv("RIGIDDYN_STUBGEN"); stubgen && std::string(stubgen) == "1") return;
  for (auto* install : installers()) install(m);
}

}  // namespace rigiddyn::bindings
