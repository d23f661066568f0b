#include "rigiddyn/scene/scene_order.hpp"

#include <variant>

namespace rigiddyn {

bool kick_freezes_velocities(Method method, const ElementTraits& traits) {
  const bool kicks = method == Method::splitting_dlm || method == Method::splitting_dlm_yoshida4 ||
                     method == Method::exact_flow_kick;
  return kicks && traits.velocity_dependent;
}

int scene_order(const CompiledScene& compiled) { return scene_order(compiled, compiled.method()); }

int scene_order(const CompiledScene& compiled, Method method) {
  const auto& traits = compiled.element_traits();
  for (std::size_t i = 0; i < traits.size(); ++i) {
    if (compiled.element_types()[i] == "CoriolisForce") continue;  // its kick is exact
    if (kick_freezes_velocities(method, traits[i])) return 1;
  }
  return method_info(method).order;
}

std::string opaque_force(const CompiledScene& compiled) {
  const auto& elements = compiled.scene().elements;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (const auto* f = std::get_if<FunctionForce>(&elements[i])) {
      return "elements[" + std::to_string(i) + "] (" + f->type_name + ")";
    }
  }
  return {};
}

}  // namespace rigiddyn
