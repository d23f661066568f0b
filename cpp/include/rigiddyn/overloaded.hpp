// overloaded{f, g, ...}: one callable from several lambdas, for std::visit with one lambda per alternative
// (a visit whose lambdas take each alternative by its exact type fails to compile when an alternative is
// added and not handled, where an if/else chain on std::get_if would take it silently).
#pragma once

namespace rigiddyn {

template <class... F>
struct overloaded : F... {
  using F::operator()...;
};
template <class... F>
overloaded(F...) -> overloaded<F...>;

}  // namespace rigiddyn
