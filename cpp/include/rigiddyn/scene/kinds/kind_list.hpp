// The body kinds of the scene model, one file each (body_slot.hpp says what a kind's slot has): the one list
// the scene model folds over. A kind is added here and in the Body variant (scene/body.hpp); a Body alternative
// without its add_slot does not compile.
#pragma once
#include "rigiddyn/scene/body.hpp"
#include "rigiddyn/scene/kinds/gyrostat_slot.hpp"
#include "rigiddyn/scene/kinds/mass_particle_slot.hpp"
#include "rigiddyn/scene/kinds/mass_rigid_slot.hpp"
#include "rigiddyn/scene/kinds/particle_slot.hpp"
#include "rigiddyn/scene/kinds/pivoted_planar_slot.hpp"
#include "rigiddyn/scene/kinds/pivoted_slot.hpp"
#include "rigiddyn/scene/kinds/planar_slot.hpp"
#include "rigiddyn/scene/kinds/rigid_slot.hpp"
#include "rigiddyn/scene/kinds/tree_slot.hpp"

#include <stdexcept>
#include <tuple>
#include <variant>
#include <vector>

namespace rigiddyn::detail {

// The slots of a scene's bodies, grouped by slot type (the rigid kinds by Euler form: a sphere pays nothing for
// the gyroscopic term); the model visits only the groups that hold a body.
using SlotGroups =
    std::tuple<std::vector<ParticleSlot<>>, std::vector<PlanarSlot<>>, std::vector<RigidSlot<SphericalEuler>>,
               std::vector<RigidSlot<PrincipalEuler>>, std::vector<RigidSlot<FullEuler>>,
               std::vector<PivotedSlot<SphericalEuler>>, std::vector<PivotedSlot<PrincipalEuler>>,
               std::vector<PivotedSlot<FullEuler>>, std::vector<PivotedPlanarSlot<>>, std::vector<MassParticleSlot>,
               std::vector<MassRigidSlot<SphericalEuler>>, std::vector<MassRigidSlot<PrincipalEuler>>,
               std::vector<MassRigidSlot<FullEuler>>, std::vector<FunctionRigidSlot>, std::vector<GyrostatSlot>,
               std::vector<TreeSlot>>;

// The slot of body b (its kind's add_slot) at the offsets y, ξ, which it advances past its blocks
inline void add_body_slot(SlotGroups& groups, int b, const Body& body, Eigen::Index& y, Eigen::Index& xi) {
  std::visit([&](const auto& kind) { add_slot(groups, b, kind, y, xi); }, body);
}

// A kind without a mass coordinate (compile refuses a MassFlow on it before a model is built)
template <class Groups, class Kind>
void add_mass_slot(Groups&, int b, const Kind&, const MassCoordinate&, Eigen::Index&, Eigen::Index&) {
  throw std::logic_error("a MassFlow on body " + std::to_string(b) + ", of a kind without a mass coordinate");
}

// The slot of body b with a MassFlow (its kind's add_mass_slot), mass its flow and names
inline void add_body_mass_slot(SlotGroups& groups, int b, const Body& body, const MassCoordinate& mass, Eigen::Index& y,
                               Eigen::Index& xi) {
  std::visit([&](const auto& kind) { add_mass_slot(groups, b, kind, mass, y, xi); }, body);
}

}  // namespace rigiddyn::detail
