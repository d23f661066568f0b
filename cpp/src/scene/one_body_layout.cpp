// The one-body layout of a scene (scene/one_body_layouts.hpp).
#include "rigiddyn/scene/one_body_layouts.hpp"
#include "rigiddyn/scene/one_body_scene.hpp"

#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

namespace rigiddyn {

namespace {

// The layout of `elements` for the body's slot, of mass m [kg]
template <OneBodyElements elements, class Slot>
OneBodySceneModel<Slot, elements> layout(const Slot& slot, double m, const std::optional<UniformGravityTerm>& gravity,
                                         int gravity_element, const std::optional<ScheduledLoadsTerm>& loads,
                                         int loads_element) {
  return OneBodySceneModel<Slot, elements>(slot, m, gravity, gravity_element, loads, loads_element);
}

}  // namespace

OneBodyModel one_body_layout_of(const Scene& scene, const std::vector<SceneModel::Term>& terms) {
  if (scene.bodies.size() != 1 || scene.frame || has_mass_flow(scene, 0)) return std::monostate{};
  std::optional<UniformGravityTerm> gravity;
  std::optional<ScheduledLoadsTerm> loads;
  int g = -1, l = -1;
  for (std::size_t e = 0; e < terms.size(); ++e) {
    const auto* u = std::get_if<UniformGravityTerm>(&terms[e]);
    const auto* s = std::get_if<ScheduledLoadsTerm>(&terms[e]);
    if (u && !gravity) {
      gravity = *u, g = static_cast<int>(e);
    } else if (s && !loads) {
      loads = *s, l = static_cast<int>(e);
    } else {
      return std::monostate{};
    }
  }
  return one_body_layout_of(scene.bodies[0], std::move(gravity), g, std::move(loads), l);
}

OneBodyModel one_body_layout_of(const Body& body, std::optional<UniformGravityTerm> gravity, int g,
                                std::optional<ScheduledLoadsTerm> loads, int l) {
  const double m = mass_of(body);
  OneBodyModel out;
  std::visit(
      [&](const auto& kind) {
        using Kind = std::decay_t<decltype(kind)>;
        if constexpr (std::is_same_v<Kind, Particle> || std::is_same_v<Kind, PlanarBody> || std::is_same_v<Kind, RigidBody>) {
          detail::with_first_slot(kind, [&](const auto& slot) {
            if (!gravity && !loads) {
              out = detail::OneBodyLayoutsOf<OneBodyElements::none>(layout<OneBodyElements::none>(slot, m, gravity, g, loads, l));
            } else if (!loads) {
              out = detail::OneBodyLayoutsOf<OneBodyElements::gravity>(layout<OneBodyElements::gravity>(slot, m, gravity, g, loads, l));
            } else {
              out = detail::OneBodyLayoutsOf<OneBodyElements::gravity_and_loads>(
                  layout<OneBodyElements::gravity_and_loads>(slot, m, gravity, g, loads, l));
            }
          });
        } else if constexpr (std::is_same_v<Kind, PivotedPlanarBody>) {
          detail::with_first_slot(kind, [&](const auto& slot) {
            if (!gravity && !loads) {
              out = layout<OneBodyElements::none>(slot, m, gravity, g, loads, l);
            } else if (!loads) {
              out = layout<OneBodyElements::gravity>(slot, m, gravity, g, loads, l);
            } else {
              out = layout<OneBodyElements::gravity_and_loads>(slot, m, gravity, g, loads, l);
            }
          });
        }
      },
      body);
  return out;
}

}  // namespace rigiddyn
