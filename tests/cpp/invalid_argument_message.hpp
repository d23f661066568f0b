// The message of the std::invalid_argument a call throws, and the check that it names the argument, for the tests
// that check that bad input is refused naming its argument.
#pragma once
#include <gtest/gtest.h>

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

// Expects f() to throw a std::invalid_argument whose message starts with "<name>: expected".
template <class F>
void expect_invalid(F&& f, const std::string& name) {
  try {
    std::forward<F>(f)();
    ADD_FAILURE() << "no exception for " << name;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(name + ": expected", 0), 0u) << e.what();
  }
}

}  // namespace rigiddyn::test
