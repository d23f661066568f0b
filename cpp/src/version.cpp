#include "rigiddyn/version.hpp"

namespace rigiddyn {

std::string version() { return "0.1.0"; }

}  // namespace rigiddyn
