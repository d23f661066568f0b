// Library version.
#pragma once
#include <string>

namespace rigiddyn {

// The version of the rigiddyn library, "major.minor.patch".
std::string version();

}  // namespace rigiddyn
