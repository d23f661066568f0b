// The N-body pair sums (scene/elements/pair_forces.hpp) on each of their paths, against long-double sums of the same
// pairs: the forces each within their stated bound (n + 24) u Σ_j |f_ij| per body and component (u = 2⁻⁵³), the
// potential within (2 n + 8) u Σ_{i<j} |V_ij|, so the portable, AVX2 + FMA and AVX-512 paths agree to twice that;
// Newton's third law pair by pair on each path; and the dispatch takes the path vector_instructions() names.
#include <gtest/gtest.h>

#include "rigiddyn/scene/elements/pair_forces.hpp"
#include "rigiddyn/vector_instructions.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace rigiddyn {
namespace {

constexpr double kU = 0x1p-53;  // unit round-off of double

// n bodies at normal positions (times `scale`) with masses in [0.1, 10] kg (rows 0..n-1 of an array with `extra` rows
// more, which the sum must not touch)
Eigen::ArrayXXd cluster(Eigen::Index n, Eigen::Index extra, unsigned seed, double scale = 1.0) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> mass(0.1, 10.0);
  Eigen::ArrayXXd columns = Eigen::ArrayXXd::Constant(n + extra, 8, 7.0);  // 7: a value no sum produces
  for (Eigen::Index i = 0; i < n; ++i) {
    columns(i, 0) = scale * normal(rng), columns(i, 1) = scale * normal(rng), columns(i, 2) = scale * normal(rng);
    columns(i, 7) = mass(rng);
    columns(i, 3) = columns(i, 4) = columns(i, 5) = 0.0;
  }
  return columns;
}

// The pair forces summed in long double (64-bit significand: its own error is 2¹¹ times smaller than the bound),
// and Σ_j |f_ij| per body and component
struct PairReference {
  std::vector<long double> f;    // (n x 3)
  std::vector<double> magnitude;  // (n x 3)
};
PairReference reference(const Eigen::ArrayXXd& c, Eigen::Index n, double G, double softening2) {
  PairReference r{std::vector<long double>(3 * n, 0.0L), std::vector<double>(3 * n, 0.0)};
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      if (j == i) continue;
      const long double d[3] = {static_cast<long double>(c(j, 0)) - c(i, 0), static_cast<long double>(c(j, 1)) - c(i, 1),
                                static_cast<long double>(c(j, 2)) - c(i, 2)};
      const long double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + softening2;
      const long double g = static_cast<long double>(G) * c(i, 7) * c(j, 7) / (r2 * std::sqrt(r2));
      for (int a = 0; a < 3; ++a) {
        r.f[3 * i + a] += g * d[a];
        r.magnitude[3 * i + a] += static_cast<double>(std::fabs(g * d[a]));
      }
    }
  }
  return r;
}

using Path = void (*)(Eigen::ArrayXXd&, Eigen::Index, double, double);

void expect_within_bound(Path path, Eigen::Index n, double softening2, unsigned seed, double scale = 1.0) {
  const double G = 0.7;
  Eigen::ArrayXXd c = cluster(n, 3, seed, scale);
  const PairReference r = reference(c, n, G, softening2);
  path(c, n, G, softening2);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      const double bound = static_cast<double>(n + 24) * kU * r.magnitude[3 * i + a];  // pair_forces.hpp
      EXPECT_LE(std::fabs(static_cast<double>(c(i, 3 + a) - r.f[3 * i + a])), bound)
          << "n = " << n << ", body " << i << ", component " << a;
    }
  }
  for (Eigen::Index i = n; i < n + 3; ++i) {
    for (int k = 0; k < 8; ++k) EXPECT_EQ(c(i, k), 7.0) << "row " << i << " beyond n was written";
  }
}

const Eigen::Index kCounts[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 16, 33, 100};

TEST(PairForces, PortablePathWithinItsBound) {
  for (const Eigen::Index n : kCounts) {
    for (const double softening2 : {0.0, 1e-2}) expect_within_bound(&detail::add_pair_forces_portable, n, softening2, 11u * n + 1);
  }
}

// both forms of the AVX2 path (of each eight pairs four or all eight by the division), and the one this CPU takes
TEST(PairForces, Avx2FmaPathWithinItsBound) {
  if (!cpu_has_avx2_fma()) GTEST_SKIP() << "this CPU (or build) has no AVX2 + FMA";
  for (const Path form : {&detail::add_pair_forces_avx2_fma_mixed, &detail::add_pair_forces_avx2_fma_division}) {
    for (const Eigen::Index n : kCounts) {
      for (const double softening2 : {0.0, 1e-2}) expect_within_bound(form, n, softening2, 11u * n + 1);
    }
  }
  const Path taken = detail::avx2_divides_every_pair() ? &detail::add_pair_forces_avx2_fma_division
                                                       : &detail::add_pair_forces_avx2_fma_mixed;
  for (const Eigen::Index n : {5, 13, 37}) {
    Eigen::ArrayXXd a = cluster(n, 0, 3), b = a;
    detail::add_pair_forces_avx2_fma(a, n, 1.0, 0.0);
    taken(b, n, 1.0, 0.0);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * a.size()), 0) << "n = " << n;
  }
}

// every remainder of the eight lanes (n − i − 1 mod 8 for each i: a block of four and single pairs after the blocks
// of eight), none of which may add or store beyond n (the rows after n hold 7); and a body at the origin without
// softening
TEST(PairForces, Avx512PathWithinItsBound) {
  if (!cpu_has_avx512()) GTEST_SKIP() << "this CPU (or build) has no AVX-512F";
  for (const Eigen::Index n : kCounts) {
    for (const double softening2 : {0.0, 1e-2}) {
      expect_within_bound(&detail::add_pair_forces_avx512, n, softening2, 11u * n + 1);
    }
  }
  Eigen::ArrayXXd c = cluster(11, 3, 9);
  c(0, 0) = c(0, 1) = c(0, 2) = 0.0;
  detail::add_pair_forces_avx512(c, 11, 1.0, 0.0);
  EXPECT_TRUE(c.topRows(11).allFinite());
}

// clusters whose squared distances r² lie beyond the range of floats (above 2¹²⁰ and below 2⁻¹²⁰, where the AVX2
// path's reciprocal square root gives way to the division) or straddle it (a cluster of 10¹⁸ m: r² from ~10³⁴ to
// ~10³⁷ m²), on every path
TEST(PairForces, PathsWithinTheirBoundAtDistancesBeyondTheRangeOfFloats) {
  std::vector<Path> paths{&detail::add_pair_forces_portable};
  if (cpu_has_avx2_fma()) {
    for (const Path form : {&detail::add_pair_forces_avx2_fma_mixed, &detail::add_pair_forces_avx2_fma_division}) {
      paths.push_back(form);
    }
  }
  if (cpu_has_avx512()) paths.push_back(&detail::add_pair_forces_avx512);
  for (const Path path : paths) {
    for (const double scale : {1e-20, 1e18, 1e20}) {
      for (const Eigen::Index n : {9, 33}) expect_within_bound(path, n, 0.0, 5u * n + 3, scale);
    }
  }
}

// f_i and f_j of one pair are the same rounded g d, added and subtracted: two bodies' forces are exact negatives
TEST(PairForces, ThirdLawPairByPairOnEachPath) {
  std::vector<Path> paths{&detail::add_pair_forces_portable};
  if (cpu_has_avx2_fma()) {
    for (const Path form : {&detail::add_pair_forces_avx2_fma_mixed, &detail::add_pair_forces_avx2_fma_division}) {
      paths.push_back(form);
    }
  }
  if (cpu_has_avx512()) paths.push_back(&detail::add_pair_forces_avx512);
  for (const Path path : paths) {
    Eigen::ArrayXXd c = cluster(2, 0, 5);
    path(c, 2, 1.3, 0.0);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(c(0, 3 + a), -c(1, 3 + a));
  }
}

// the path of vector_instructions(), AVX2's in place of AVX-512's below 24 bodies (pair_forces.hpp)
TEST(PairForces, DispatchTakesThePathOfVectorInstructions) {
  for (const Eigen::Index n : {5, 23, 24, 37}) {
    const VectorInstructions path = vector_instructions() == VectorInstructions::avx512 && n < 24
                                        ? VectorInstructions::avx2_fma
                                        : vector_instructions();
    const Path expected = path == VectorInstructions::avx512     ? &detail::add_pair_forces_avx512
                          : path == VectorInstructions::avx2_fma ? &detail::add_pair_forces_avx2_fma
                                                                 : &detail::add_pair_forces_portable;
    Eigen::ArrayXXd a = cluster(n, 0, 3), b = a;
    detail::add_pair_forces(a, n, 1.0, 0.0);
    expected(b, n, 1.0, 0.0);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), sizeof(double) * a.size()), 0) << "n = " << n;
  }
  const char* portable = std::getenv("RIGIDDYN_PORTABLE");
  if (portable != nullptr && std::strcmp(portable, "1") == 0) {
    EXPECT_EQ(vector_instructions(), VectorInstructions::portable);
  }
  if (!cpu_has_avx2_fma()) {
    EXPECT_EQ(vector_instructions(), VectorInstructions::portable);
  }
  if (cpu_has_avx512() && !(portable != nullptr && *portable != '\0' && std::strcmp(portable, "0") != 0)) {
    EXPECT_EQ(vector_instructions(), VectorInstructions::avx512);  // the widest path the CPU has
  }
}

using PotentialPath = double (*)(Eigen::ArrayXXd&, Eigen::Index, double, double);

std::vector<PotentialPath> potential_paths() {
  std::vector<PotentialPath> paths{&detail::pair_potential_portable};
  if (cpu_has_avx2_fma()) paths.push_back(&detail::pair_potential_avx2_fma);
  if (cpu_has_avx512()) paths.push_back(&detail::pair_potential_avx512);
  return paths;
}

// V = −Σ_{i<j} G m_i m_j / √(|d|² + ε²) summed in long double, and Σ_{i<j} |V_ij|
struct PotentialReference {
  long double V = 0.0L;
  double magnitude = 0.0;
};
PotentialReference reference_potential(const Eigen::ArrayXXd& c, Eigen::Index n, double G, double softening2) {
  PotentialReference r;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i + 1; j < n; ++j) {
      long double r2 = softening2;
      for (int a = 0; a < 3; ++a) {
        const long double d = static_cast<long double>(c(j, a)) - c(i, a);
        r2 += d * d;
      }
      const long double V_ij = -static_cast<long double>(G) * c(i, 7) * c(j, 7) / std::sqrt(r2);
      r.V += V_ij;
      r.magnitude += static_cast<double>(-V_ij);
    }
  }
  return r;
}

// every count of pairs per body (the blocks of eight and four and the single pairs after them), with and without
// softening, at distances within and beyond the range of floats (where the AVX2 path's reciprocal square root gives
// way to the division); the rows after n (which hold 7) untouched
TEST(PairPotential, EveryPathWithinItsBound) {
  const double G = 0.7;
  for (const PotentialPath path : potential_paths()) {
    for (const double scale : {1.0, 1e-20, 1e18, 1e20}) {
      for (const Eigen::Index n : kCounts) {
        for (const double softening2 : {0.0, 1e-2}) {
          Eigen::ArrayXXd c = cluster(n, 3, 7u * n + 2, scale);
          const PotentialReference r = reference_potential(c, n, G, softening2);
          const double V = path(c, n, G, softening2);
          const double bound = static_cast<double>(2 * n + 8) * kU * r.magnitude;  // pair_forces.hpp
          EXPECT_LE(std::fabs(static_cast<double>(V - r.V)), bound) << "n = " << n << ", scale " << scale;
          for (Eigen::Index i = n; i < n + 3; ++i) {
            for (int k = 0; k < 8; ++k) EXPECT_EQ(c(i, k), 7.0) << "row " << i << " beyond n was written";
          }
        }
      }
    }
  }
}

// two coincident bodies without softening: V = −∞ on every path (the division's m_j / 0, where the reciprocal
// square root's Newton steps would give a NaN), whichever block of lanes the pair falls in
TEST(PairPotential, CoincidentBodiesWithoutSofteningGiveMinusInfinityOnEveryPath) {
  for (const PotentialPath path : potential_paths()) {
    for (const Eigen::Index coincident : {1, 5, 9, 14, 16}) {
      Eigen::ArrayXXd c = cluster(17, 0, 4);
      for (int a = 0; a < 3; ++a) c(coincident, a) = c(0, a);
      EXPECT_EQ(path(c, 17, 1.0, 0.0), -std::numeric_limits<double>::infinity()) << "body " << coincident;
    }
  }
}

// the path of vector_instructions() from 12 bodies on (AVX-512) or 20 (AVX2), the portable one below (pair_forces.hpp)
TEST(PairPotential, DispatchTakesThePathOfVectorInstructions) {
  for (const Eigen::Index n : {5, 11, 12, 19, 20, 37}) {
    const VectorInstructions vectors = vector_instructions();
    const bool wide =
        (vectors == VectorInstructions::avx512 && n >= 12) || (vectors == VectorInstructions::avx2_fma && n >= 20);
    const PotentialPath expected = !wide                                    ? &detail::pair_potential_portable
                                   : vectors == VectorInstructions::avx512 ? &detail::pair_potential_avx512
                                                                           : &detail::pair_potential_avx2_fma;
    Eigen::ArrayXXd a = cluster(n, 0, 3), b = a;
    const double V = detail::pair_potential(a, n, 1.0, 0.0);
    EXPECT_EQ(V, expected(b, n, 1.0, 0.0)) << "n = " << n;
  }
}

}  // namespace
}  // namespace rigiddyn
