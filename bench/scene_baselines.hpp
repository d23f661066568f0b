// Hand-written baseline loops for the scene benchmarks (bench_scene.cpp): plain arrays of doubles (and
// plain Eigen arrays over them), no rigiddyn code, the same method and the same arithmetic as the library's scene path, so that
// "<case>:rigiddyn" / "<case>:baseline" measures only what the scene machinery adds.
#pragma once
#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace rigiddyn::bench {

// N particles [kg] and initial positions [m] / velocities [m/s] in W: a cluster in a unit cube, fixed
// seed, so that every benchmark (and every N) starts from the same kind of state. The cost of a
// direct-sum step does not depend on the positions (no branch on them), only on N.
struct ParticleCluster {
  std::vector<double> mass;   // (N,) [kg]
  std::vector<double> p_W;    // (N, 3) row-major [m]
  std::vector<double> v_W;    // (N, 3) row-major [m/s]
};

inline ParticleCluster particle_cluster(std::size_t n) {
  std::mt19937_64 rng(20261124);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), mass(0.5, 1.5);
  ParticleCluster c;
  c.mass.resize(n);
  c.p_W.resize(3 * n);
  c.v_W.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    c.mass[i] = mass(rng);
    for (int k = 0; k < 3; ++k) c.p_W[3 * i + k] = unit(rng), c.v_W[3 * i + k] = 0.1 * unit(rng);
  }
  return c;
}

// Classic RK4 on N gravitating particles, Newton's law of gravitation summed directly over the pairs
// i < j with the third law (each pair evaluated once, its force added to i and subtracted from j):
//   f_ij = −G m_i m_j r_ij / (|r_ij|² + ε²)^{3/2},  r_ij = p_i − p_j,  a_i = Σ_j f_ij / m_i.
// y = (per body p_W 3, v_W 3) then t [s] then the work of gravity [J] (its rate Σ f_i·v_i): the layout
// and the diagnostics the scene model carries, so both integrate the same 6N + 2 numbers.
// Two ways to write the sum by hand:
//   scalar  one pair at a time on the positions where they are in y (what a first hand loop does);
//   packed  the positions copied into columns x, y, z first, then for each i the pairs j > i as whole
//           column segments (Eigen arrays over the plain columns: 2 or more pairs per instruction,
//           divide and square root included), the fastest plain loop on this machine.
enum class PairSum { scalar, packed };

class NBodyRk4Baseline {
 public:
  NBodyRk4Baseline(std::vector<double> mass, double G, double softening, PairSum sum = PairSum::packed)
      : mass_(std::move(mass)), inverse_mass_(mass_.size()), n_(mass_.size()), G_(G), eps2_(softening * softening),
        sum_(sum), force_(3 * n_), columns_(7 * n_), k1_(size()), k2_(size()), k3_(size()), k4_(size()), stage_(size()) {
    for (std::size_t i = 0; i < n_; ++i) inverse_mass_[i] = 1.0 / mass_[i];
  }

  std::size_t size() const { return 6 * n_ + 2; }

  std::vector<double> initial(const ParticleCluster& c) const {
    std::vector<double> y(size(), 0.0);
    for (std::size_t i = 0; i < n_; ++i)
      for (int k = 0; k < 3; ++k) y[6 * i + k] = c.p_W[3 * i + k], y[6 * i + 3 + k] = c.v_W[3 * i + k];
    return y;
  }

  // one RK4 step of size h [s] (tableau c = (0, ½, ½, 1), b = (1/6, 1/3, 1/3, 1/6))
  void step(std::vector<double>& y, double h) {
    const std::size_t m = size();
    rate(y.data(), k1_.data());
    for (std::size_t i = 0; i < m; ++i) stage_[i] = y[i] + 0.5 * h * k1_[i];
    rate(stage_.data(), k2_.data());
    for (std::size_t i = 0; i < m; ++i) stage_[i] = y[i] + 0.5 * h * k2_[i];
    rate(stage_.data(), k3_.data());
    for (std::size_t i = 0; i < m; ++i) stage_[i] = y[i] + h * k3_[i];
    rate(stage_.data(), k4_.data());
    for (std::size_t i = 0; i < m; ++i)
      y[i] += h * (k1_[i] / 6.0 + k2_[i] / 3.0 + k3_[i] / 3.0 + k4_[i] / 6.0);
  }

 private:
  void rate(const double* y, double* dy) {
    if (sum_ == PairSum::packed) {
      packed_forces(y);
    } else {
      scalar_forces(y);
    }
    double power = 0.0;
    for (std::size_t i = 0; i < n_; ++i) {
      const double* v = y + 6 * i + 3;
      const double* f = force_.data() + 3 * i;
      for (int k = 0; k < 3; ++k) dy[6 * i + k] = v[k], dy[6 * i + 3 + k] = inverse_mass_[i] * f[k];
      power += f[0] * v[0] + f[1] * v[1] + f[2] * v[2];
    }
    dy[6 * n_] = 1.0;  // dt/dt
    dy[6 * n_ + 1] = power;
  }

  void scalar_forces(const double* y) {
    for (double& f : force_) f = 0.0;
    for (std::size_t i = 0; i < n_; ++i) {
      const double* p_i = y + 6 * i;
      const double Gm_i = G_ * mass_[i];
      double fx = 0.0, fy = 0.0, fz = 0.0;  // force on i from the j > i, kept in registers
      for (std::size_t j = i + 1; j < n_; ++j) {
        const double* p_j = y + 6 * j;
        const double rx = p_i[0] - p_j[0], ry = p_i[1] - p_j[1], rz = p_i[2] - p_j[2];
        const double r2 = rx * rx + ry * ry + rz * rz + eps2_;
        const double s = Gm_i * mass_[j] / (r2 * std::sqrt(r2));
        fx -= s * rx, fy -= s * ry, fz -= s * rz;
        force_[3 * j] += s * rx, force_[3 * j + 1] += s * ry, force_[3 * j + 2] += s * rz;
      }
      force_[3 * i] += fx, force_[3 * i + 1] += fy, force_[3 * i + 2] += fz;
    }
  }

  // columns_ = (x, y, z, f_x, f_y, f_z, s), N each; for pair (i, j): r = p_i − p_j, s = G m_i m_j/(|r|²+ε²)^{3/2}
  void packed_forces(const double* y) {
    using Column = Eigen::Map<Eigen::ArrayXd>;
    const Eigen::Index n = static_cast<Eigen::Index>(n_);
    Column x(columns_.data(), n), yy(columns_.data() + n, n), z(columns_.data() + 2 * n, n);
    Column fx(columns_.data() + 3 * n, n), fy(columns_.data() + 4 * n, n), fz(columns_.data() + 5 * n, n);
    Column s(columns_.data() + 6 * n, n);
    const Eigen::Map<const Eigen::ArrayXd> m(mass_.data(), n);
    for (Eigen::Index i = 0; i < n; ++i) x[i] = y[6 * i], yy[i] = y[6 * i + 1], z[i] = y[6 * i + 2];
    fx.setZero(), fy.setZero(), fz.setZero();
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
      const Eigen::Index j = i + 1, count = n - j;
      const auto rx = x[i] - x.segment(j, count), ry = yy[i] - yy.segment(j, count), rz = z[i] - z.segment(j, count);
      auto s_j = s.segment(j, count);
      s_j = rx.square() + ry.square() + rz.square() + eps2_;
      s_j = (G_ * m[i]) * m.segment(j, count) / (s_j * s_j.sqrt());
      fx[i] -= (s_j * rx).sum(), fx.segment(j, count) += s_j * rx;
      fy[i] -= (s_j * ry).sum(), fy.segment(j, count) += s_j * ry;
      fz[i] -= (s_j * rz).sum(), fz.segment(j, count) += s_j * rz;
    }
    for (Eigen::Index i = 0; i < n; ++i) force_[3 * i] = fx[i], force_[3 * i + 1] = fy[i], force_[3 * i + 2] = fz[i];
  }

  std::vector<double> mass_, inverse_mass_;
  std::size_t n_;
  double G_, eps2_;
  PairSum sum_;
  std::vector<double> force_;    // (N, 3) per evaluation
  std::vector<double> columns_;  // (7, N) for the packed sum
  std::vector<double> k1_, k2_, k3_, k4_, stage_;
};

}  // namespace rigiddyn::bench
