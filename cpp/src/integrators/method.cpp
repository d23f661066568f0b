#include "rigiddyn/integrators/method.hpp"

#include "rigiddyn/check.hpp"
#include "rigiddyn/closest_name.hpp"

#include <cmath>
#include <limits>

namespace rigiddyn {

namespace {
constexpr double unconditional = std::numeric_limits<double>::infinity();
}  // namespace

// stability_limit: the largest dt·|ω| (|ω| the largest body rate on the torque-free orbit) at which
// each method is documented stable on a free spin; measured values are in docs/extremes.md.
const std::vector<MethodInfo>& method_table() {
  static const std::vector<MethodInfo> table = {
      {Method::explicit_euler, "explicit_euler", 1, 1, "unit |q| (by renormalisation) only",
       "energy and |L| grow every step on a free body: blows up; reference only",
       0.0, false},
      {Method::semi_implicit_euler, "semi_implicit_euler", 1, 1,
       "unit |q| (exact exponential update); symplectic for particle and planar body",
       "explicit gyroscopic term (as MuJoCo's and Pinocchio's Euler): gains energy and blows up on a "
       "fast spin of a non-symmetric body",
       0.0, false},
      {Method::semi_implicit_euler_implicit_gyroscopic, "semi_implicit_euler_implicit_gyroscopic", 1, 1,
       "unit |q| (exact exponential update); symplectic for particle and planar body",
       "one Newton step on I(w' - w) + h w' x I w' = h n: stable; dissipative for h|w| < ~1 (energy may grow transiently beyond)",
       unconditional, false},
      {Method::rk4, "rk4", 4, 4, "unit |q| (by renormalisation) only",
       "energy and |L| drift O(h^4) per unit time; unstable beyond dt*rho = 2*sqrt(2) (rho: fastest linear mode, <= |w|)",
       2.0 * std::sqrt(2.0), false},
      {Method::rkmk4, "rkmk4", 4, 4, "SO(3): unit |q| without projection",
       "Lie-group RK4 (Munthe-Kaas, dexp^-1 correction): 4th order in attitude; energy and |L| drift O(h^4); "
       "unstable beyond dt*rho = 2*sqrt(2) like rk4",
       2.0 * std::sqrt(2.0), false},
      {Method::implicit_midpoint, "implicit_midpoint", 2, 4,
       "energy and |L| up to the Newton tolerance (1e-14, at most 20 iterations); unit |q| (Cayley update)",
       "symmetric; evaluations = typical Newton iterations (one evaluation + one 3x3 solve each); the spatial L "
       "direction drifts O(h^2); A-stable, but beyond dt|w| ~ 3 the Newton iteration may stop unconverged "
       "(measured: converged up to dt|w| = 3 on six bodies, failed from 3.5 near the separatrix) and energy "
       "and |L| are then lost; on a kinematic tree it is the variational midpoint method (the midpoint discrete "
       "Lagrangian on the curve of constant joint velocity): symplectic, a symmetry's momentum kept to round-off, "
       "no energy drift",
       3.0, false},
      {Method::splitting_dlm, "splitting_dlm", 2, 2,
       "|L|, spatial L and unit |q| (SO(3)) to round-off (an unbiased walk: <= 10 eps sqrt(N) after N steps); "
       "energy bounded (symplectic, no drift)",
       "Dullweber-Leimkuhler-McLachlan splitting, exact rotations about the principal axes a(h/2) b(h/2) c(h) "
       "b(h/2) a(h/2) (I_a <= I_b <= I_c) inside Strang kicks of the loads; exact translation under constant "
       "force; energy error bounded and small up to dt|w| ~ 1 (measured max |dE|/E <= 8e-3 over 4000 steps on six "
       "bodies), O(1) from dt|w| ~ 2 (|L| still exact); elongated nearly symmetric bodies have a lower linear "
       "limit (0.035 at I = (1, 100, 100.01) spinning about the largest axis)",
       1.0, false},
      {Method::splitting_dlm_yoshida4, "splitting_dlm_yoshida4", 4, 4,
       "as splitting_dlm: |L|, spatial L, unit |q| to round-off; energy bounded",
       "Yoshida triple jump of splitting_dlm (3 DLM free rotations, 4 merged kicks); error constant larger than "
       "RK4's; its substeps reach 1.70 dt, so the energy error stays small only up to dt|w| ~ 0.7 (measured "
       "max |dE|/E <= 2.7e-3 over 4000 steps on six bodies), O(1) from dt|w| ~ 1.5",
       0.7, false},
      {Method::exact_flow_kick, "exact_flow_kick", 2, 2,
       "free body: energy, |L|, spatial L, unit |q| to round-off (exact flow)",
       "Strang kick(h/2) exact-torque-free-flow(h) kick(h/2) (Celledoni et al. 2008); the closed form over "
       "one step (principal frame cached per inertia; ~0.5 us/step, ~6 RK4 steps); exact without couples (then the error is round-off at any dt: no observed order)",
       unconditional, true},
      {Method::exact, "exact", 0, 0, "everything (closed-form Euler-Poinsot solution)",
       "torque-free bodies only (a couple throws); simulate evaluates the closed form at each record time "
       "(forces: world-frame, constant, exact ballistic); step() applies the exact flow over dt; order 0: no truncation error, no observed order",
       unconditional, true},
  };
  return table;
}

const MethodInfo& method_info(Method method) {
  for (const MethodInfo& info : method_table()) {
    if (info.method == method) return info;
  }
  throw std::invalid_argument("method: expected a rigiddyn::Method, got " + std::to_string(static_cast<int>(method)));
}

Method method_from_name(const std::string& name, const std::string& argument) {
  for (const MethodInfo& info : method_table()) {
    if (info.name == name) return info.method;
  }
  std::vector<std::string> names;  // no such method: the message lists them (built here only)
  std::string listed;
  for (const MethodInfo& info : method_table()) {
    names.push_back(info.name);
    listed += (listed.empty() ? "" : ", ") + info.name;
  }
  throw_invalid(argument, "one of " + listed + did_you_mean(name, names), "'" + name + "'");
}

}  // namespace rigiddyn
