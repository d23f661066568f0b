#include "rigiddyn/scene/elements/pair_forces.hpp"

#include "rigiddyn/vector_instructions.hpp"

#include <cmath>
#include <stdexcept>

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define RIGIDDYN_HAS_AVX2_FMA_KERNELS 1
#include <immintrin.h>
#endif

namespace rigiddyn::detail {

void add_pair_forces(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  if (vector_instructions() == VectorInstructions::avx2_fma) {
    add_pair_forces_avx2_fma(columns, n, G, softening2);
  } else {
    add_pair_forces_portable(columns, n, G, softening2);
  }
}

// The pairs (i, j > i) of each i as column segments, which Eigen evaluates two doubles per SSE2 instruction
// (square root and division included).
void add_pair_forces_portable(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  auto x = columns.col(0), y = columns.col(1), z = columns.col(2);
  auto f_x = columns.col(3), f_y = columns.col(4), f_z = columns.col(5), g = columns.col(6), mass = columns.col(7);
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const Eigen::Index j = i + 1, count = n - j;
    const auto dx = x.segment(j, count) - x(i);
    const auto dy = y.segment(j, count) - y(i);
    const auto dz = z.segment(j, count) - z(i);
    auto g_j = g.segment(j, count);
    g_j = dx.square() + dy.square() + dz.square() + softening2;  // |d|² + ε²
    g_j = (G * mass(i)) * mass.segment(j, count) / (g_j * g_j.sqrt());
    f_x(i) += (g_j * dx).sum(), f_x.segment(j, count) -= g_j * dx;
    f_y(i) += (g_j * dy).sum(), f_y.segment(j, count) -= g_j * dy;
    f_z(i) += (g_j * dz).sum(), f_z.segment(j, count) -= g_j * dz;
  }
}

#ifdef RIGIDDYN_HAS_AVX2_FMA_KERNELS

namespace {

__attribute__((target("avx2,fma"))) inline double lane_sum(__m256d v) {
  const __m128d two = _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_add_sd(two, _mm_unpackhi_pd(two, two)));
}

}  // namespace

// The pairs (i, j > i) of each i four j at a time; the last n − i − 1 mod 4 pairs one at a time with the same
// operations (std::fma: one rounding, as the vector lanes).
__attribute__((target("avx2,fma"))) void add_pair_forces_avx2_fma(Eigen::ArrayXXd& columns, Eigen::Index n, double G,
                                                                  double softening2) {
  const double* x = columns.col(0).data();
  const double* y = columns.col(1).data();
  const double* z = columns.col(2).data();
  double* f_x = columns.col(3).data();
  double* f_y = columns.col(4).data();
  double* f_z = columns.col(5).data();
  const double* mass = columns.col(7).data();
  const __m256d eps2 = _mm256_set1_pd(softening2);
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const __m256d x_i = _mm256_set1_pd(x[i]), y_i = _mm256_set1_pd(y[i]), z_i = _mm256_set1_pd(z[i]);
    const double Gm_i = G * mass[i];
    const __m256d Gm = _mm256_set1_pd(Gm_i);
    __m256d s_x = _mm256_setzero_pd(), s_y = _mm256_setzero_pd(), s_z = _mm256_setzero_pd();
    Eigen::Index j = i + 1;
    for (; j + 4 <= n; j += 4) {
      const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(x + j), x_i);
      const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(y + j), y_i);
      const __m256d dz = _mm256_sub_pd(_mm256_loadu_pd(z + j), z_i);
      const __m256d r2 = _mm256_fmadd_pd(dz, dz, _mm256_fmadd_pd(dy, dy, _mm256_fmadd_pd(dx, dx, eps2)));  // |d|² + ε²
      const __m256d g = _mm256_div_pd(_mm256_mul_pd(Gm, _mm256_loadu_pd(mass + j)), _mm256_mul_pd(r2, _mm256_sqrt_pd(r2)));
      s_x = _mm256_fmadd_pd(g, dx, s_x), s_y = _mm256_fmadd_pd(g, dy, s_y), s_z = _mm256_fmadd_pd(g, dz, s_z);
      _mm256_storeu_pd(f_x + j, _mm256_fnmadd_pd(g, dx, _mm256_loadu_pd(f_x + j)));
      _mm256_storeu_pd(f_y + j, _mm256_fnmadd_pd(g, dy, _mm256_loadu_pd(f_y + j)));
      _mm256_storeu_pd(f_z + j, _mm256_fnmadd_pd(g, dz, _mm256_loadu_pd(f_z + j)));
    }
    double t_x = lane_sum(s_x), t_y = lane_sum(s_y), t_z = lane_sum(s_z);
    for (; j < n; ++j) {
      const double dx = x[j] - x[i], dy = y[j] - y[i], dz = z[j] - z[i];
      const double r2 = std::fma(dz, dz, std::fma(dy, dy, std::fma(dx, dx, softening2)));
      const double g = Gm_i * mass[j] / (r2 * std::sqrt(r2));
      t_x = std::fma(g, dx, t_x), t_y = std::fma(g, dy, t_y), t_z = std::fma(g, dz, t_z);
      f_x[j] = std::fma(-g, dx, f_x[j]), f_y[j] = std::fma(-g, dy, f_y[j]), f_z[j] = std::fma(-g, dz, f_z[j]);
    }
    f_x[i] += t_x, f_y[i] += t_y, f_z[i] += t_z;
  }
}

#else

void add_pair_forces_avx2_fma(Eigen::ArrayXXd&, Eigen::Index, double, double) {
  throw std::logic_error("add_pair_forces_avx2_fma: this build has no AVX2 kernels (cpu_has_avx2_fma() is false)");
}

#endif

}  // namespace rigiddyn::detail
