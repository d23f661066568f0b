// Stacks of rotations a block of items at a time, one item per lane of a vector register: entry c of every item
// of the block in one register (structure of arrays), so that a formula written once, for double or for lanes,
// runs once per block. Two paths, chosen once per process (rigiddyn/vector_instructions.hpp): the portable one,
// 2 items per 128-bit register (SSE2, the x86-64 baseline; one item at a time elsewhere), and where the CPU has
// AVX2 and FMA, 4 items per 256-bit register. Both evaluate the same operations in the same order, the AVX2 one
// compiled for "avx2" alone (no fused multiply–add): their results are the same bits.
#pragma once
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <utility>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "for_each_item.hpp"
#include "rigiddyn/always_inline.hpp"
#include "rigiddyn/vector_instructions.hpp"

namespace rigiddyn::bindings {

// Lanes of doubles, one item each: GCC / Clang vector extensions, whose +, -, *, / and comparisons act lane by
// lane (a comparison gives a Mask, every bit of a lane set where it holds), a double standing for every lane.
typedef double Lanes2 __attribute__((vector_size(16)));
typedef double Lanes4 __attribute__((vector_size(32)));
template <typename T>
using Mask = decltype(T{} < T{});
template <typename T>
constexpr int lanes = sizeof(T) / sizeof(double);

// Entries 0..size-1 of the block's items, entry c of item j in e[c][j].
template <typename T, int size>
struct Entries {
  T e[size];
};

// A block's items lie one after the other in memory, size doubles each: entry c of item j at p[size * j + c].
// Two items are 2 × size doubles, read and written as size pairs of doubles, pair m at p + 2 m; entry c of item
// j is lane (size j + c) % 2 of pair (size j + c) / 2. The 256-bit registers hold the pairs of items 0, 1 in
// their low half and those of items 2, 3 in their high half, which every shuffle below treats alike.
#if defined(__SSE2__)

// Entries of two items from the size pairs P: E_c = (lane c % 2 of P_{c/2}, lane (size + c) % 2 of
// P_{(size + c)/2}).
template <int size, std::size_t... c>
RIGIDDYN_ALWAYS_INLINE void load_entries(const double* p, Entries<Lanes2, size>& E, std::index_sequence<c...>) {
  Lanes2 P[size];
  for (int m = 0; m < size; ++m) P[m] = _mm_loadu_pd(p + 2 * m);
  ((E.e[c] = _mm_shuffle_pd(P[c / 2], P[(size + c) / 2], c % 2 | (size + c) % 2 << 1)), ...);
}

// Pair m of two items from their entries: (lane 2m / size of E_{2m % size}, lane (2m + 1) / size of
// E_{(2m + 1) % size}).
template <int size, std::size_t... m>
RIGIDDYN_ALWAYS_INLINE void store_entries(const Entries<Lanes2, size>& E, double* p, std::index_sequence<m...>) {
  (_mm_storeu_pd(p + 2 * m, _mm_shuffle_pd(E.e[2 * m % size], E.e[(2 * m + 1) % size], 2 * m / size | (2 * m + 1) / size << 1)), ...);
}

template <int in_size, int out_size, typename Block>
pybind11::ssize_t run_blocks_portable(const double* in, double* out, pybind11::ssize_t i, pybind11::ssize_t n, const Block& block) {
  for (; i + 2 <= n; i += 2) {
    Entries<Lanes2, in_size> a;
    Entries<Lanes2, out_size> b;
    Mask<Lanes2> ok;
    load_entries(in + in_size * i, a, std::make_index_sequence<in_size>{});
    block(a, b, ok);
    if (_mm_movemask_pd(reinterpret_cast<__m128d>(ok)) != 0x3) break;
    store_entries(b, out + out_size * i, std::make_index_sequence<out_size>{});
  }
  return i;
}

#else

// one item at a time (map_blocks)
template <int in_size, int out_size, typename Block>
pybind11::ssize_t run_blocks_portable(const double*, double*, pybind11::ssize_t i, pybind11::ssize_t, const Block&) {
  return i;
}

#endif

#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
#define RIGIDDYN_HAS_AVX2_BLOCKS 1

// As load_entries of two items, on both halves.
template <int size, std::size_t... c>
__attribute__((target("avx2"), always_inline)) inline void load_entries(const double* p, Entries<Lanes4, size>& E, std::index_sequence<c...>) {
  Lanes4 P[size];
  for (int m = 0; m < size; ++m) P[m] = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p + 2 * m)), _mm_loadu_pd(p + 2 * size + 2 * m), 1);
  ((E.e[c] = _mm256_shuffle_pd(P[c / 2], P[(size + c) / 2], (c % 2 | (size + c) % 2 << 1) * 0x5)), ...);
}

// As store_entries of two items, on both halves.
template <int size>
__attribute__((target("avx2"), always_inline)) inline void store_pair(const Lanes4& P, double* p) {
  _mm_storeu_pd(p, _mm256_castpd256_pd128(P));
  _mm_storeu_pd(p + 2 * size, _mm256_extractf128_pd(P, 1));
}
template <int size, std::size_t... m>
__attribute__((target("avx2"), always_inline)) inline void store_entries(const Entries<Lanes4, size>& E, double* p, std::index_sequence<m...>) {
  (store_pair<size>(_mm256_shuffle_pd(E.e[2 * m % size], E.e[(2 * m + 1) % size], (2 * m / size | (2 * m + 1) / size << 1) * 0x5),
                    p + 2 * m),
   ...);
}

template <int in_size, int out_size, typename Block>
__attribute__((target("avx2"))) pybind11::ssize_t run_blocks_avx2(const double* in, double* out, pybind11::ssize_t i,
                                                                  pybind11::ssize_t n, const Block& block) {
  for (; i + 4 <= n; i += 4) {
    Entries<Lanes4, in_size> a;
    Entries<Lanes4, out_size> b;
    Mask<Lanes4> ok;
    load_entries(in + in_size * i, a, std::make_index_sequence<in_size>{});
    block(a, b, ok);
    if (_mm256_movemask_pd(reinterpret_cast<__m256d>(ok)) != 0xf) break;
    store_entries(b, out + out_size * i, std::make_index_sequence<out_size>{});
  }
  return i;
}

#endif

// out item i (out_size doubles) from in item i (in_size doubles) for i in [0, n), without the GIL: blocks of
// items by run_blocks on the path of this process, and item(i) for the items of a block that run_blocks stopped
// at (an item its quick check refused, which item(i) computes exactly or throws for) and for the last items. A
// std::invalid_argument from item i of a stack names the item (throw_for_item).
template <int in_size, int out_size, typename Block, typename Item>
void map_blocks(const double* in, double* out, pybind11::ssize_t n, bool stacked, const Block& block, const Item& item) {
#ifdef RIGIDDYN_HAS_AVX2_BLOCKS
  const bool avx2 = runs_avx2_fma(vector_instructions());
#else
  const bool avx2 = false;
#endif
  const pybind11::ssize_t block_size = avx2 ? lanes<Lanes4> : lanes<Lanes2>;
  pybind11::gil_scoped_release release;
  pybind11::ssize_t i = 0;
  try {
    while (i < n) {
#ifdef RIGIDDYN_HAS_AVX2_BLOCKS
      i = avx2 ? run_blocks_avx2<in_size, out_size>(in, out, i, n, block) : run_blocks_portable<in_size, out_size>(in, out, i, n, block);
#else
      i = run_blocks_portable<in_size, out_size>(in, out, i, n, block);
#endif
      for (const pybind11::ssize_t end = std::min(n, i + block_size); i < end; ++i) item(i);
    }
  } catch (const std::invalid_argument& e) {
    if (!stacked) throw;
    throw_for_item(e, i);
  }
}

}  // namespace rigiddyn::bindings
