// A downstream program linking the installed rigiddyn.
#include <rigiddyn/version.hpp>

#include <iostream>

int main() {
  std::cout << "rigiddyn " << rigiddyn::version() << "\n";
  return rigiddyn::version().empty() ? 1 : 0;
}
