// Private helper of the element terms (scene/elements/*.hpp): the bodies an element acts on.
#pragma once
#include "rigiddyn/check.hpp"
#include "rigiddyn/scene/body.hpp"

#include <string>
#include <vector>

namespace rigiddyn::detail {

// The indices of the bodies an element acts on: `list` itself when it is valid (each index in
// [0, body_count), no index twice), every body 0 … body_count − 1 when it is empty. Throws
// std::invalid_argument "<name>.bodies: expected ..., got ..." otherwise.
inline std::vector<int> resolve_bodies(const BodyList& list, std::size_t body_count, const std::string& name) {
  std::vector<int> out;
  if (list.empty()) {
    for (std::size_t b = 0; b < body_count; ++b) out.push_back(static_cast<int>(b));
    return out;
  }
  std::vector<bool> seen(body_count, false);
  for (std::size_t k = 0; k < list.size(); ++k) {
    const int b = list[k];
    const std::string where = name + ".bodies[" + std::to_string(k) + "]";
    if (b < 0 || static_cast<std::size_t>(b) >= body_count) {
      throw_invalid(where, "a body index in [0, " + std::to_string(body_count) + ")", b);
    }
    if (seen[b]) throw_invalid(where, "each body once", b);
    seen[b] = true;
    out.push_back(b);
  }
  return out;
}

}  // namespace rigiddyn::detail
