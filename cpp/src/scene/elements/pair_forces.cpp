#include "rigiddyn/scene/elements/pair_forces.hpp"

#include "rigiddyn/vector_instructions.hpp"

#include <cmath>
#include <stdexcept>

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define RIGIDDYN_HAS_AVX2_FMA_KERNELS 1
#include <immintrin.h>
#endif

namespace rigiddyn::detail {

// The fewest bodies for which a wider path pays (pair_forces.hpp): below them a body's pairs fill few blocks of lanes,
// and the wider path's set-up per body (its sums zeroed and folded) costs more than its lanes save. Measured on a Xeon
// with AVX-512, one core (ns per sum): the forces by AVX2 and AVX-512 24 and 42 at n = 4, 318 and 321 at 20, 441 and
// 431 at 24; the potential by the portable path, AVX2 and AVX-512 83, 106 and 95 at 10, 126, 145 and 104 at 12, 208,
// 220 and 173 at 16, 313, 305 and 196 at 20.
constexpr Eigen::Index avx512_forces_from = 24, avx512_potential_from = 12, avx2_potential_from = 20;

bool avx2_divides_every_pair() {
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
  static const bool amd = __builtin_cpu_is("amd");  // once per process, as vector_instructions()
  return amd;
#else
  return false;
#endif
}

void add_pair_forces(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  switch (vector_instructions()) {
    case VectorInstructions::avx512:
      if (n >= avx512_forces_from) return add_pair_forces_avx512(columns, n, G, softening2);
      return add_pair_forces_avx2_fma(columns, n, G, softening2);
    case VectorInstructions::avx2_fma: return add_pair_forces_avx2_fma(columns, n, G, softening2);
    case VectorInstructions::portable: return add_pair_forces_portable(columns, n, G, softening2);
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

double pair_potential(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  switch (vector_instructions()) {
    case VectorInstructions::avx512:
      if (n >= avx512_potential_from) return pair_potential_avx512(columns, n, G, softening2);
      break;
    case VectorInstructions::avx2_fma:
      if (n >= avx2_potential_from) return pair_potential_avx2_fma(columns, n, G, softening2);
      break;
    case VectorInstructions::portable: break;
  }
  return pair_potential_portable(columns, n, G, softening2);
}

// The pairs (i, j > i) of each i as column segments (their distances in the scratch column), as the forces'
double pair_potential_portable(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  auto x = columns.col(0), y = columns.col(1), z = columns.col(2), r = columns.col(6), mass = columns.col(7);
  double V = 0.0;
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const Eigen::Index j = i + 1, count = n - j;
    auto r_j = r.segment(j, count);
    r_j = ((x.segment(j, count) - x(i)).square() + (y.segment(j, count) - y(i)).square() +
           (z.segment(j, count) - z(i)).square() + softening2).sqrt();  // √(|d|² + ε²)
    V -= G * mass(i) * (mass.segment(j, count) / r_j).sum();
  }
  return V;
}

#ifdef RIGIDDYN_HAS_AVX2_FMA_KERNELS

namespace {

// The columns of the sum (pair_forces.hpp) as pointers.
struct PairColumns {
  const double *x, *y, *z, *mass;
  double *f_x, *f_y, *f_z;
  explicit PairColumns(Eigen::ArrayXXd& c)
      : x(c.col(0).data()), y(c.col(1).data()), z(c.col(2).data()), mass(c.col(7).data()), f_x(c.col(3).data()),
        f_y(c.col(4).data()), f_z(c.col(5).data()) {}
};

// Body i's sums over its pairs, lane by lane, in registers of four and of eight doubles
struct Sums4 {
  __m256d x, y, z;
};
struct Sums8 {
  __m512d x, y, z;
};

// d = p_j − p_i of the pairs (i, j … j + 3) and r² = |d|² + ε², by fused multiply–adds (the AVX2 potential's terms)
struct Separation4 {
  __m256d dx, dy, dz, r2;
};

__attribute__((target("avx2,fma"))) inline Separation4 separation(const PairColumns& c, Eigen::Index i, Eigen::Index j,
                                                                  __m256d eps2) {
  const __m256d dx = _mm256_sub_pd(_mm256_loadu_pd(c.x + j), _mm256_set1_pd(c.x[i]));
  const __m256d dy = _mm256_sub_pd(_mm256_loadu_pd(c.y + j), _mm256_set1_pd(c.y[i]));
  const __m256d dz = _mm256_sub_pd(_mm256_loadu_pd(c.z + j), _mm256_set1_pd(c.z[i]));
  return {dx, dy, dz, _mm256_fmadd_pd(dz, dz, _mm256_fmadd_pd(dy, dy, _mm256_fmadd_pd(dx, dx, eps2)))};
}

__attribute__((target("avx2,fma"))) inline double lane_sum(__m256d v) {
  const __m128d two = _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_add_sd(two, _mm_unpackhi_pd(two, two)));
}

// g = G m_i m_j / (r² √r²) of four pairs by the divider's square root and division (Gm_im_j = G m_i m_j).
__attribute__((target("avx2,fma"))) inline __m256d strength_by_division(__m256d Gm_im_j, __m256d r2) {
  return _mm256_div_pd(Gm_im_j, _mm256_mul_pd(r2, _mm256_sqrt_pd(r2)));
}

// Whether the four r² lie in [2⁻¹²⁰, 2¹²⁰], where a float's reciprocal square root holds them (reciprocal_root)
__attribute__((target("avx2,fma"))) inline bool in_float_range(__m256d r2) {
  const __m256d in_range = _mm256_and_pd(_mm256_cmp_pd(r2, _mm256_set1_pd(0x1p-120), _CMP_GE_OQ),
                                         _mm256_cmp_pd(r2, _mm256_set1_pd(0x1p120), _CMP_LE_OQ));
  return _mm256_movemask_pd(in_range) == 0xF;
}

// y = 1/√r² of four pairs (their r² in_float_range) by the reciprocal square root of r² as a float (relative error at
// most 1.5 · 2⁻¹² by the instruction's specification, 2⁻¹¹ with the conversion) refined by three Newton steps
// y ← y (3/2 − (r²/2) y²), each of which squares the error (e ← −e² (3 + e) / 2: 2⁻¹¹, 2⁻²¹, 2⁻⁴¹, 2⁻⁸¹), so that y is
// within the last step's own rounding, 3 u, of 1/√r².
__attribute__((target("avx2,fma"))) inline __m256d reciprocal_root(__m256d r2) {
  const __m256d half_r2 = _mm256_mul_pd(_mm256_set1_pd(0.5), r2), three_halves = _mm256_set1_pd(1.5);
  __m256d y = _mm256_cvtps_pd(_mm_rsqrt_ps(_mm256_cvtpd_ps(r2)));
  for (int step = 0; step < 3; ++step) {
    y = _mm256_mul_pd(y, _mm256_fnmadd_pd(half_r2, _mm256_mul_pd(y, y), three_halves));
  }
  return y;
}

// The same g as G m_i m_j y³, y = reciprocal_root(r²); four pairs with an r² outside the floats' range take the
// division. Multiplications and additions run beside the divider, which the division's pairs keep busy: four pairs of
// each kind per block of eight run in the time of the division's four alone.
__attribute__((target("avx2,fma"))) inline __m256d strength_by_reciprocal_root(__m256d Gm_im_j, __m256d r2) {
  if (!in_float_range(r2)) return strength_by_division(Gm_im_j, r2);
  const __m256d y = reciprocal_root(r2);
  return _mm256_mul_pd(Gm_im_j, _mm256_mul_pd(y, _mm256_mul_pd(y, y)));
}

// The bodies j … j + 3 of a block of four pairs (their positions and masses), and a body i's position and G m_i in
// every lane
struct Block4 {
  __m256d x, y, z, mass;
};
__attribute__((target("avx2,fma"))) inline Block4 block4(const PairColumns& c, Eigen::Index j) {
  return {_mm256_loadu_pd(c.x + j), _mm256_loadu_pd(c.y + j), _mm256_loadu_pd(c.z + j), _mm256_loadu_pd(c.mass + j)};
}
struct Body4 {
  __m256d x, y, z, Gm;
};
__attribute__((target("avx2,fma"))) inline Body4 body4(const PairColumns& c, Eigen::Index i, double G) {
  return {_mm256_set1_pd(c.x[i]), _mm256_set1_pd(c.y[i]), _mm256_set1_pd(c.z[i]), _mm256_set1_pd(G * c.mass[i])};
}

// The four pairs (i, j … j + 3): d = p_j − p_i, r² = |d|² + ε² by fused multiply–adds, g = G m_i m_j / (r² √r²) by
// `strength` (one of the two above), and g d added to body i's sums
struct Pairs4 {
  __m256d dx, dy, dz, g;
};
template <__m256d (*strength)(__m256d, __m256d)>
__attribute__((target("avx2,fma"))) inline Pairs4 four_pairs(const Block4& b, const Body4& i, __m256d eps2, Sums4& s) {
  const __m256d dx = _mm256_sub_pd(b.x, i.x), dy = _mm256_sub_pd(b.y, i.y), dz = _mm256_sub_pd(b.z, i.z);
  const __m256d r2 = _mm256_fmadd_pd(dz, dz, _mm256_fmadd_pd(dy, dy, _mm256_fmadd_pd(dx, dx, eps2)));
  const __m256d g = strength(_mm256_mul_pd(i.Gm, b.mass), r2);
  s.x = _mm256_fmadd_pd(g, dx, s.x), s.y = _mm256_fmadd_pd(g, dy, s.y), s.z = _mm256_fmadd_pd(g, dz, s.z);
  return {dx, dy, dz, g};
}

// f_j −= g d of the block's pairs with body i
__attribute__((target("avx2,fma"))) inline void subtract(const PairColumns& c, Eigen::Index j, const Pairs4& p) {
  _mm256_storeu_pd(c.f_x + j, _mm256_fnmadd_pd(p.g, p.dx, _mm256_loadu_pd(c.f_x + j)));
  _mm256_storeu_pd(c.f_y + j, _mm256_fnmadd_pd(p.g, p.dy, _mm256_loadu_pd(c.f_y + j)));
  _mm256_storeu_pd(c.f_z + j, _mm256_fnmadd_pd(p.g, p.dz, _mm256_loadu_pd(c.f_z + j)));
}

// The pair (i, j) with the same operations as the lanes, one at a time (std::fma: one rounding each): g d added to
// body i's sums t and subtracted from f_j.
__attribute__((target("avx2,fma"))) inline void one_pair(const PairColumns& c, Eigen::Index i, Eigen::Index j,
                                                           double Gm_i, double softening2, double& t_x, double& t_y,
                                                           double& t_z) {
  const double dx = c.x[j] - c.x[i], dy = c.y[j] - c.y[i], dz = c.z[j] - c.z[i];
  const double r2 = std::fma(dz, dz, std::fma(dy, dy, std::fma(dx, dx, softening2)));
  const double g = Gm_i * c.mass[j] / (r2 * std::sqrt(r2));
  t_x = std::fma(g, dx, t_x), t_y = std::fma(g, dy, t_y), t_z = std::fma(g, dz, t_z);
  c.f_x[j] = std::fma(-g, dx, c.f_x[j]), c.f_y[j] = std::fma(-g, dy, c.f_y[j]), c.f_z[j] = std::fma(-g, dz, c.f_z[j]);
}

// The lanes of a last block of count < 4 bodies j … j + count − 1: those from count on are off (their positions,
// masses and forces neither read nor written, their g zero)
__attribute__((target("avx2,fma"))) inline __m256i lanes4(Eigen::Index count) {
  return _mm256_cmpgt_epi64(_mm256_set1_epi64x(count), _mm256_setr_epi64x(0, 1, 2, 3));
}
__attribute__((target("avx2,fma"))) inline Block4 block4(const PairColumns& c, Eigen::Index j, __m256i lanes) {
  return {_mm256_maskload_pd(c.x + j, lanes), _mm256_maskload_pd(c.y + j, lanes), _mm256_maskload_pd(c.z + j, lanes),
          _mm256_maskload_pd(c.mass + j, lanes)};
}

// The pairs of a last block by the division, as four_pairs with g zero in the lanes that are off (an off lane's
// r² may be zero, and its quotient NaN)
__attribute__((target("avx2,fma"))) inline Pairs4 last_four_pairs(const Block4& b, const Body4& i, __m256d eps2,
                                                                    __m256i lanes, Sums4& s) {
  const __m256d dx = _mm256_sub_pd(b.x, i.x), dy = _mm256_sub_pd(b.y, i.y), dz = _mm256_sub_pd(b.z, i.z);
  const __m256d r2 = _mm256_fmadd_pd(dz, dz, _mm256_fmadd_pd(dy, dy, _mm256_fmadd_pd(dx, dx, eps2)));
  const __m256d g = _mm256_and_pd(strength_by_division(_mm256_mul_pd(i.Gm, b.mass), r2), _mm256_castsi256_pd(lanes));
  s.x = _mm256_fmadd_pd(g, dx, s.x), s.y = _mm256_fmadd_pd(g, dy, s.y), s.z = _mm256_fmadd_pd(g, dz, s.z);
  return {dx, dy, dz, g};
}
__attribute__((target("avx2,fma"))) inline void subtract(const PairColumns& c, Eigen::Index j, const Pairs4& p,
                                                           __m256i lanes) {
  _mm256_maskstore_pd(c.f_x + j, lanes, _mm256_fnmadd_pd(p.g, p.dx, _mm256_maskload_pd(c.f_x + j, lanes)));
  _mm256_maskstore_pd(c.f_y + j, lanes, _mm256_fnmadd_pd(p.g, p.dy, _mm256_maskload_pd(c.f_y + j, lanes)));
  _mm256_maskstore_pd(c.f_z + j, lanes, _mm256_fnmadd_pd(p.g, p.dz, _mm256_maskload_pd(c.f_z + j, lanes)));
}

// Body i's pairs from j on after its blocks of eight, by the division: four (where four are left), then the last
// 1-3 as a block of four with its lanes beyond n off (faster than one at a time: docs/perf/scenes.md); its lane sums
// s added to f_i.
__attribute__((target("avx2,fma"))) inline void finish_body(const PairColumns& c, Eigen::Index i, Eigen::Index j,
                                                              Eigen::Index n, double G, double softening2, Sums4 s) {
  const Body4 a = body4(c, i, G);
  const __m256d eps2 = _mm256_set1_pd(softening2);
  if (j + 4 <= n) subtract(c, j, four_pairs<strength_by_division>(block4(c, j), a, eps2, s)), j += 4;
  if (j < n) {
    const __m256i lanes = lanes4(n - j);
    subtract(c, j, last_four_pairs(block4(c, j, lanes), a, eps2, lanes, s), lanes);
  }
  c.f_x[i] += lane_sum(s.x), c.f_y[i] += lane_sum(s.y), c.f_z[i] += lane_sum(s.z);
}

// y = 1/√r² of eight pairs: the reciprocal square root in double (relative error below 2⁻¹⁴ over the whole range of
// doubles) refined by two Newton steps (the error 1.5 · 2⁻²⁸, then 3.4 · 2⁻⁵⁶ < u: y within the last step's rounding,
// 3 u, of 1/√r²). The masked form with every lane set: GCC 12's unmasked form reads an undefined register, which its
// -Wmaybe-uninitialized reports.
__attribute__((target("avx512f,avx2,fma"))) inline __m512d reciprocal_root(__m512d r2) {
  const __mmask8 all = 0xFF;
  const __m512d half_r2 = _mm512_mul_pd(_mm512_set1_pd(0.5), r2), three_halves = _mm512_set1_pd(1.5);
  __m512d y = _mm512_maskz_rsqrt14_pd(all, r2);
  for (int step = 0; step < 2; ++step) {
    y = _mm512_mul_pd(y, _mm512_fnmadd_pd(half_r2, _mm512_mul_pd(y, y), three_halves));
  }
  return y;
}

// The bodies j … j + 7 of a block of eight pairs: their positions and masses, loaded once for the one or two bodies i
// whose pairs with them the block holds
struct Block8 {
  __m512d x, y, z, mass;
};
__attribute__((target("avx512f,avx2,fma"))) inline Block8 block(const PairColumns& c, Eigen::Index j) {
  return {_mm512_loadu_pd(c.x + j), _mm512_loadu_pd(c.y + j), _mm512_loadu_pd(c.z + j), _mm512_loadu_pd(c.mass + j)};
}

// Body i's position and G m_i in every lane
struct Body8 {
  __m512d x, y, z, Gm;
};
__attribute__((target("avx512f,avx2,fma"))) inline Body8 body(const PairColumns& c, Eigen::Index i, double G) {
  return {_mm512_set1_pd(c.x[i]), _mm512_set1_pd(c.y[i]), _mm512_set1_pd(c.z[i]), _mm512_set1_pd(G * c.mass[i])};
}

// The eight pairs (i, j … j + 7): d = p_j − p_i, r² = |d|² + ε² by fused multiply–adds, g = G m_i m_j y³ with
// y = reciprocal_root(r²) (within 3 u of 1/√r², as on the AVX2 path), and g d added to body i's sums. Twice as fast as
// the division at N = 1000 (docs/perf/scenes.md): the divider takes as long for eight lanes as for four. An r² of zero
// or infinity (coincident bodies without softening, a position at infinity) gives a NaN force, as the division's g d
// does (∞ · 0, 0 · ∞). Lanes off (a last block's beyond n, a first block's pairs of a body with itself or counted
// already: two_bodies) have a g of zero (their r² may be zero: y NaN there).
struct Pairs8 {
  __m512d dx, dy, dz, g;
};
__attribute__((target("avx512f,avx2,fma"))) inline Pairs8 eight_pairs(const Block8& b, const Body8& i, __m512d eps2,
                                                                        Sums8& s, __mmask8 lanes = 0xFF) {
  const __m512d dx = _mm512_sub_pd(b.x, i.x), dy = _mm512_sub_pd(b.y, i.y), dz = _mm512_sub_pd(b.z, i.z);
  const __m512d r2 = _mm512_fmadd_pd(dz, dz, _mm512_fmadd_pd(dy, dy, _mm512_fmadd_pd(dx, dx, eps2)));
  const __m512d y = reciprocal_root(r2);
  const __m512d g = _mm512_maskz_mul_pd(lanes, _mm512_mul_pd(i.Gm, b.mass), _mm512_mul_pd(y, _mm512_mul_pd(y, y)));
  s.x = _mm512_fmadd_pd(g, dx, s.x), s.y = _mm512_fmadd_pd(g, dy, s.y), s.z = _mm512_fmadd_pd(g, dz, s.z);
  return {dx, dy, dz, g};
}

// f_j −= g d of the block's pairs with one body i (p), or with two (p, then q: the order of the one-body sums)
__attribute__((target("avx512f,avx2,fma"))) inline void subtract(const PairColumns& c, Eigen::Index j,
                                                                   const Pairs8& p) {
  _mm512_storeu_pd(c.f_x + j, _mm512_fnmadd_pd(p.g, p.dx, _mm512_loadu_pd(c.f_x + j)));
  _mm512_storeu_pd(c.f_y + j, _mm512_fnmadd_pd(p.g, p.dy, _mm512_loadu_pd(c.f_y + j)));
  _mm512_storeu_pd(c.f_z + j, _mm512_fnmadd_pd(p.g, p.dz, _mm512_loadu_pd(c.f_z + j)));
}
__attribute__((target("avx512f,avx2,fma"))) inline void subtract(const PairColumns& c, Eigen::Index j, const Pairs8& p,
                                                                   const Pairs8& q) {
  _mm512_storeu_pd(c.f_x + j, _mm512_fnmadd_pd(q.g, q.dx, _mm512_fnmadd_pd(p.g, p.dx, _mm512_loadu_pd(c.f_x + j))));
  _mm512_storeu_pd(c.f_y + j, _mm512_fnmadd_pd(q.g, q.dy, _mm512_fnmadd_pd(p.g, p.dy, _mm512_loadu_pd(c.f_y + j))));
  _mm512_storeu_pd(c.f_z + j, _mm512_fnmadd_pd(q.g, q.dz, _mm512_fnmadd_pd(p.g, p.dz, _mm512_loadu_pd(c.f_z + j))));
}

// The lanes of a last block of count < 8 bodies j … j + count − 1 (those from count on off: their positions, masses
// and forces neither read nor written), its load and its subtract
__attribute__((target("avx512f,avx2,fma"))) inline __mmask8 lanes8(Eigen::Index count) {
  return static_cast<__mmask8>((1u << count) - 1u);
}
__attribute__((target("avx512f,avx2,fma"))) inline Block8 block(const PairColumns& c, Eigen::Index j, __mmask8 lanes) {
  return {_mm512_maskz_loadu_pd(lanes, c.x + j), _mm512_maskz_loadu_pd(lanes, c.y + j),
          _mm512_maskz_loadu_pd(lanes, c.z + j), _mm512_maskz_loadu_pd(lanes, c.mass + j)};
}
__attribute__((target("avx512f,avx2,fma"))) inline void subtract(const PairColumns& c, Eigen::Index j, const Pairs8& p,
                                                                   const Pairs8& q, __mmask8 lanes) {
  const __m512d f_x = _mm512_maskz_loadu_pd(lanes, c.f_x + j);
  _mm512_mask_storeu_pd(c.f_x + j, lanes, _mm512_fnmadd_pd(q.g, q.dx, _mm512_fnmadd_pd(p.g, p.dx, f_x)));
  const __m512d f_y = _mm512_maskz_loadu_pd(lanes, c.f_y + j);
  _mm512_mask_storeu_pd(c.f_y + j, lanes, _mm512_fnmadd_pd(q.g, q.dy, _mm512_fnmadd_pd(p.g, p.dy, f_y)));
  const __m512d f_z = _mm512_maskz_loadu_pd(lanes, c.f_z + j);
  _mm512_mask_storeu_pd(c.f_z + j, lanes, _mm512_fnmadd_pd(q.g, q.dz, _mm512_fnmadd_pd(p.g, p.dz, f_z)));
}

// the upper four lanes added to the lower four (masked extracts, as in reciprocal_root)
__attribute__((target("avx512f,avx2,fma"))) inline __m256d halves_sum(__m512d v) {
  return _mm256_add_pd(_mm512_maskz_extractf64x4_pd(0xF, v, 0), _mm512_maskz_extractf64x4_pd(0xF, v, 1));
}

// m_j / √r² of four pairs by the divider's square root and division
__attribute__((target("avx2,fma"))) inline __m256d mass_over_distance_by_division(__m256d m_j, __m256d r2) {
  return _mm256_div_pd(m_j, _mm256_sqrt_pd(r2));
}

// the same as m_j y, y = reciprocal_root(r²), beside the divider (four pairs outside the floats' range by the division)
__attribute__((target("avx2,fma"))) inline __m256d mass_over_distance_by_reciprocal_root(__m256d m_j, __m256d r2) {
  if (!in_float_range(r2)) return mass_over_distance_by_division(m_j, r2);
  return _mm256_mul_pd(m_j, reciprocal_root(r2));
}

// the potential's terms m_j / r of the pairs (i, j … j + 3), by `mass_over_distance` (one of the two above), added
// to the lanes of `sum`
template <__m256d (*mass_over_distance)(__m256d, __m256d)>
__attribute__((target("avx2,fma"))) inline void four_terms(const PairColumns& c, Eigen::Index i, Eigen::Index j,
                                                             __m256d eps2, __m256d& sum) {
  sum = _mm256_add_pd(sum, mass_over_distance(_mm256_loadu_pd(c.mass + j), separation(c, i, j, eps2).r2));
}

// the same terms of the pairs (i, j) for j from `first` to n − 1 one at a time (r² by std::fma, as the lanes), added to
// the lanes' sum t
__attribute__((target("avx2,fma"))) inline double last_terms(const PairColumns& c, Eigen::Index i, Eigen::Index first,
                                                             Eigen::Index n, double softening2, double t) {
  for (Eigen::Index j = first; j < n; ++j) {
    const double dx = c.x[j] - c.x[i], dy = c.y[j] - c.y[i], dz = c.z[j] - c.z[i];
    t += c.mass[j] / std::sqrt(std::fma(dz, dz, std::fma(dy, dy, std::fma(dx, dx, softening2))));
  }
  return t;
}

// the terms of body i's pairs with a block of eight bodies j (their lanes on where `lanes` says; an off lane's term
// not added) as m_j y, y = reciprocal_root(r²), added to the lanes of `sum` by a fused multiply–add; a block with an r²
// outside [2⁻¹⁰⁰⁰, 2¹⁰⁰⁰] by the division (r² = 0 or ∞ make the Newton steps' 0 · ∞ a NaN, where the division gives
// the portable path's ∞ or 0)
__attribute__((target("avx512f,avx2,fma"))) inline void eight_terms(const Block8& b, const Body8& i, __m512d eps2,
                                                                      __mmask8 lanes, __m512d& sum) {
  const __m512d dx = _mm512_sub_pd(b.x, i.x), dy = _mm512_sub_pd(b.y, i.y), dz = _mm512_sub_pd(b.z, i.z);
  const __m512d r2 = _mm512_fmadd_pd(dz, dz, _mm512_fmadd_pd(dy, dy, _mm512_fmadd_pd(dx, dx, eps2)));
  const __mmask8 in_range = _mm512_mask_cmp_pd_mask(lanes, r2, _mm512_set1_pd(0x1p-1000), _CMP_GE_OQ) &
                            _mm512_mask_cmp_pd_mask(lanes, r2, _mm512_set1_pd(0x1p1000), _CMP_LE_OQ);
  if (in_range != lanes) {
    sum = _mm512_mask_add_pd(sum, lanes, sum, _mm512_div_pd(b.mass, _mm512_maskz_sqrt_pd(0xFF, r2)));
  } else {
    sum = _mm512_mask3_fmadd_pd(b.mass, reciprocal_root(r2), sum, lanes);
  }
}

// Body i's pairs with each block of eight j > i, four by the division and four by `second` (the division, or the
// reciprocal square root, which keeps the multiply–add units busy beside the divider), then its last pairs
// (finish_body)
template <__m256d (*second)(__m256d, __m256d)>
__attribute__((target("avx2,fma"))) inline void avx2_one_body(const PairColumns& c, Eigen::Index i, Eigen::Index n,
                                                                double G, double softening2) {
  const __m256d eps2 = _mm256_set1_pd(softening2);
  const Body4 a = body4(c, i, G);
  Sums4 s{_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd()};
  Eigen::Index j = i + 1;
  for (; j + 8 <= n; j += 8) {
    subtract(c, j, four_pairs<strength_by_division>(block4(c, j), a, eps2, s));
    subtract(c, j + 4, four_pairs<second>(block4(c, j + 4), a, eps2, s));
  }
  finish_body(c, i, j, n, G, softening2, s);
}

// The bodies one at a time (avx2_one_body). (Two at a time, as the AVX-512 path, measured at most 5 % faster here:
// docs/perf/scenes.md.)
template <__m256d (*second)(__m256d, __m256d)>
__attribute__((target("avx2,fma"))) void avx2_pair_forces(Eigen::ArrayXXd& columns, Eigen::Index n, double G,
                                                          double softening2) {
  const PairColumns c(columns);
  for (Eigen::Index i = 0; i + 1 < n; ++i) avx2_one_body<second>(c, i, n, G, softening2);
}

}  // namespace

void add_pair_forces_avx2_fma(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  if (avx2_divides_every_pair()) return add_pair_forces_avx2_fma_division(columns, n, G, softening2);
  add_pair_forces_avx2_fma_mixed(columns, n, G, softening2);
}

void add_pair_forces_avx2_fma_mixed(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  avx2_pair_forces<strength_by_reciprocal_root>(columns, n, G, softening2);
}

void add_pair_forces_avx2_fma_division(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  avx2_pair_forces<strength_by_division>(columns, n, G, softening2);
}

// f_i += its lane sums s
__attribute__((target("avx512f,avx2,fma"))) inline void add_sums(const PairColumns& c, Eigen::Index i, const Sums8& s) {
  c.f_x[i] += lane_sum(halves_sum(s.x));
  c.f_y[i] += lane_sum(halves_sum(s.y));
  c.f_z[i] += lane_sum(halves_sum(s.z));
}

// The bodies i and k = i + 1 together: their pairs with each block of eight bodies from i on (eight_pairs) and with a
// last block of fewer (its lanes beyond n off), each block loaded and f_j stored once for both. The first block starts
// at i itself: its lane 0 (i, i) is off for i, and its lanes 0 and 1 for k ((k, i) is i's lane 1, (k, k) nothing).
// Measured on a Xeon with AVX-512 (Ice Lake), one core, both versions built side by side in one process
// (bench/python/pair_sum_side_by_side.py, which so compares any two revisions): against a body at a time (its last
// pairs four by the division and one at a time), 1.00-1.12x the time at n = 24, 0.99-1.01 at 50, 0.85-0.90 at 100,
// 0.69-0.70 at 1000; the pair (i, k) in the first block, against it alone in scalar operations (one_pair) before the
// blocks from k + 1, 0.82-0.86x at n = 24, 0.92 at 50, 0.95 at 100, 0.98 at 300, 0.99 at 1000 (docs/perf/scenes.md;
// the same sums, bit for bit, as blocks from k, which measured 1.10-1.11x this time at n = 300).
__attribute__((target("avx512f,avx2,fma"))) inline void two_bodies(const PairColumns& c, Eigen::Index i, Eigen::Index n,
                                                                     double G, double softening2) {
  const Eigen::Index k = i + 1;
  const __m512d eps2 = _mm512_set1_pd(softening2);
  const Body8 a = body(c, i, G), b = body(c, k, G);
  Sums8 s_a{_mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd()}, s_b = s_a;
  const __mmask8 first_a = 0xFE, first_b = 0xFC;  // the first block's lanes: i's (i, i) off; k's (k, i), (k, k) off
  Eigen::Index j = i;
  if (j + 8 <= n) {
    const Block8 bodies_j = block(c, j);
    const Pairs8 p = eight_pairs(bodies_j, a, eps2, s_a, first_a), q = eight_pairs(bodies_j, b, eps2, s_b, first_b);
    subtract(c, j, p, q);
    for (j += 8; j + 8 <= n; j += 8) {
      const Block8 bodies_j = block(c, j);
      const Pairs8 p = eight_pairs(bodies_j, a, eps2, s_a), q = eight_pairs(bodies_j, b, eps2, s_b);
      subtract(c, j, p, q);
    }
  }
  if (j < n) {
    const __mmask8 lanes = lanes8(n - j);
    const Block8 bodies_j = block(c, j, lanes);
    const Pairs8 p = eight_pairs(bodies_j, a, eps2, s_a, j == i ? lanes & first_a : lanes);
    const Pairs8 q = eight_pairs(bodies_j, b, eps2, s_b, j == i ? lanes & first_b : lanes);
    subtract(c, j, p, q, lanes);
  }
  add_sums(c, i, s_a);
  add_sums(c, k, s_b);
}

// The bodies two at a time (two_bodies); where their count n − 1 of those with pairs is odd, the last one's single
// pair alone (one_pair: as a two_bodies block of two lanes it measured 1.05-1.06x the time at n = 24).
__attribute__((target("avx512f,avx2,fma"))) void add_pair_forces_avx512(Eigen::ArrayXXd& columns, Eigen::Index n,
                                                                        double G, double softening2) {
  const PairColumns c(columns);
  Eigen::Index i = 0;
  for (; i + 2 < n; i += 2) two_bodies(c, i, n, G, softening2);
  if (i + 1 < n) {  // the last pair (n − 2, n − 1) alone
    double t_x = 0.0, t_y = 0.0, t_z = 0.0;
    one_pair(c, i, i + 1, G * c.mass[i], softening2, t_x, t_y, t_z);
    c.f_x[i] += t_x, c.f_y[i] += t_y, c.f_z[i] += t_z;
  }
}

// The terms of each i eight pairs at a time, four by the division and four by the reciprocal square root (as the
// forces' mixed form; on the AMD EPYC that divides every pair of the forces faster, this form was still 1.0-1.2x
// faster than the division alone: 1/√r² needs no cube), then four by the division, then one at a time
__attribute__((target("avx2,fma"))) double pair_potential_avx2_fma(Eigen::ArrayXXd& columns, Eigen::Index n, double G,
                                                                   double softening2) {
  const PairColumns c(columns);
  const __m256d eps2 = _mm256_set1_pd(softening2);
  double V = 0.0;
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    __m256d sum = _mm256_setzero_pd();
    Eigen::Index j = i + 1;
    for (; j + 8 <= n; j += 8) {
      four_terms<mass_over_distance_by_division>(c, i, j, eps2, sum);
      four_terms<mass_over_distance_by_reciprocal_root>(c, i, j + 4, eps2, sum);
    }
    if (j + 4 <= n) four_terms<mass_over_distance_by_division>(c, i, j, eps2, sum), j += 4;
    V -= G * c.mass[i] * last_terms(c, i, j, n, softening2, lane_sum(sum));
  }
  return V;
}

// The bodies i two at a time, as the forces' two_bodies: their pair's term alone, then their terms with each block of
// eight bodies j > i + 1 (eight_terms), the block loaded once for both, the last block of fewer with its lanes beyond n
// off; the last body alone where their count n − 1 of those with pairs is odd (its one pair).
__attribute__((target("avx512f,avx2,fma"))) double pair_potential_avx512(Eigen::ArrayXXd& columns, Eigen::Index n,
                                                                         double G, double softening2) {
  const PairColumns c(columns);
  const __m512d eps2 = _mm512_set1_pd(softening2);
  double V = 0.0;
  Eigen::Index i = 0;
  for (; i + 2 < n; i += 2) {
    const Eigen::Index k = i + 1;
    const Body8 a = body(c, i, G), b = body(c, k, G);
    __m512d sum_a = _mm512_setzero_pd(), sum_b = _mm512_setzero_pd();
    Eigen::Index j = k + 1;
    for (; j + 8 <= n; j += 8) {
      const Block8 bodies_j = block(c, j);
      eight_terms(bodies_j, a, eps2, 0xFF, sum_a), eight_terms(bodies_j, b, eps2, 0xFF, sum_b);
    }
    if (j < n) {
      const __mmask8 lanes = lanes8(n - j);
      const Block8 bodies_j = block(c, j, lanes);
      eight_terms(bodies_j, a, eps2, lanes, sum_a), eight_terms(bodies_j, b, eps2, lanes, sum_b);
    }
    V -= G * c.mass[i] * last_terms(c, i, k, k + 1, softening2, lane_sum(halves_sum(sum_a)));
    V -= G * c.mass[k] * lane_sum(halves_sum(sum_b));
  }
  if (i + 1 < n) V -= G * c.mass[i] * last_terms(c, i, i + 1, n, softening2, 0.0);
  return V;
}

#else

void add_pair_forces_avx2_fma(Eigen::ArrayXXd&, Eigen::Index, double, double) {
  throw std::logic_error("add_pair_forces_avx2_fma: this build has no AVX2 kernels (cpu_has_avx2_fma() is false)");
}

void add_pair_forces_avx2_fma_mixed(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  add_pair_forces_avx2_fma(columns, n, G, softening2);
}

void add_pair_forces_avx2_fma_division(Eigen::ArrayXXd& columns, Eigen::Index n, double G, double softening2) {
  add_pair_forces_avx2_fma(columns, n, G, softening2);
}

void add_pair_forces_avx512(Eigen::ArrayXXd&, Eigen::Index, double, double) {
  throw std::logic_error("add_pair_forces_avx512: this build has no AVX-512 kernels (cpu_has_avx512() is false)");
}

double pair_potential_avx2_fma(Eigen::ArrayXXd&, Eigen::Index, double, double) {
  throw std::logic_error("pair_potential_avx2_fma: this build has no AVX2 kernels (cpu_has_avx2_fma() is false)");
}

double pair_potential_avx512(Eigen::ArrayXXd&, Eigen::Index, double, double) {
  throw std::logic_error("pair_potential_avx512: this build has no AVX-512 kernels (cpu_has_avx512() is false)");
}

#endif

}  // namespace rigiddyn::detail
