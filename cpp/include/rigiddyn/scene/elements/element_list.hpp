// Every force element a scene can declare: each is one file under scene/elements/ (its spec with its
// field table, its compiled term) and one row here. The Python classes, the scene file's [[force]] types and
// describe() follow from this list; a scene model's terms are the specs' terms (`Spec::Term`).
#pragma once
#include "rigiddyn/scene/elements/atmospheric_drag.hpp"
#include "rigiddyn/scene/elements/drag.hpp"
#include "rigiddyn/scene/elements/function_force.hpp"
#include "rigiddyn/scene/elements/gravity_gradient.hpp"
#include "rigiddyn/scene/elements/magnetic_dipole.hpp"
#include "rigiddyn/scene/elements/mutual_gravity.hpp"
#include "rigiddyn/scene/elements/point_mass_gravity.hpp"
#include "rigiddyn/scene/elements/prismatic_motor.hpp"
#include "rigiddyn/scene/elements/prismatic_spring_damper.hpp"
#include "rigiddyn/scene/elements/reaction_wheel.hpp"
#include "rigiddyn/scene/elements/revolute_motor.hpp"
#include "rigiddyn/scene/elements/revolute_spring_damper.hpp"
#include "rigiddyn/scene/elements/scheduled_loads.hpp"
#include "rigiddyn/scene/elements/solar_radiation_pressure.hpp"
#include "rigiddyn/scene/elements/spherical_spring_damper.hpp"
#include "rigiddyn/scene/elements/spring_damper.hpp"
#include "rigiddyn/scene/elements/thrust.hpp"
#include "rigiddyn/scene/elements/uniform_gravity.hpp"
#include "rigiddyn/scene/elements/zonal_gravity.hpp"

#include <variant>

namespace rigiddyn {

using Element = std::variant<UniformGravity,    //
                             PointMassGravity,  //
                             MutualGravity,     //
                             GravityGradient,   //
                             SpringDamper,      //
                             Drag,              //
                             ScheduledLoads,    //
                             FunctionForce,     //
                             Thrust,            //
                             MagneticDipole,    //
                             ReactionWheel,     //
                             ZonalGravity,      //
                             AtmosphericDrag,   //
                             SolarRadiationPressure,  //
                             RevoluteSpringDamper,    //
                             PrismaticSpringDamper,   //
                             RevoluteMotor,           //
                             PrismaticMotor,          //
                             SphericalSpringDamper>;

// The variant of the elements' compiled terms followed by More...: TermsOf<Element, X>::type =
// std::variant<UniformGravityTerm, …, ThrustTerm, X>.
template <class Elements, class... More>
struct TermsOf;
template <class... Spec, class... More>
struct TermsOf<std::variant<Spec...>, More...> {
  using type = std::variant<typename Spec::Term..., More...>;
};

}  // namespace rigiddyn
