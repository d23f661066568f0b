// The message of the std::invalid_argument a call throws, for the tests that check that bad input is refused
// naming its argument.
#pragma once
#include <stdexcept>
#include <string>
#include <utility>

namespace rigiddyn::test {

// e.what() of the std::invalid_argument that f() throws, "" when it throws none (any other exception propagates)
template <class F>
std::string message_of(F&& f) {
  try {
    std::forward<F>(f)();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace rigiddyn::test
