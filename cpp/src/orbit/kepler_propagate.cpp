#include "rigiddyn/orbit/kepler_propagate.hpp"

#include <cmath>

#include "rigiddyn/check.hpp"
#include "rigiddyn/orbit/anomaly.hpp"

namespace rigiddyn {

double mean_motion(double p, double e, double mu) {
  const double n_p = std::sqrt(mu / p) / p;  // √(μ/p³), without overflowing p³
  if (e == 1.0) return n_p;
  const double q = std::abs((1.0 - e) * (1.0 + e));
  return n_p * q * std::sqrt(q);
}

OrbitState kepler_propagate(const Eigen::Vector3d& r_W, const Eigen::Vector3d& v_W, double mu, double t) {
  require_finite(t, "t");
  ClassicalElements el = elements_from_state(r_W, v_W, mu);
  // ν in (−π, π]: M₀ then carries no revolution, whose 2π would swamp a small M₀ + n t (near-parabolic orbits)
  const double M = true_to_mean_anomaly(std::remainder(el.nu, 2.0 * 3.141592653589793), el.e) + mean_motion(el.p, el.e, mu) * t;
  el.nu = mean_to_true_anomaly(M, el.e);
  return state_from_elements(el, mu);
}

}  // namespace rigiddyn
