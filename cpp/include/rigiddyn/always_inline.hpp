// RIGIDDYN_ALWAYS_INLINE: for the small functions that integrators call once per stage or step
// (models, Euler's equations, the SO(3) exponential). Forced inline so that a step compiles to one
// straight-line loop body: GCC otherwise outlines rate(), Rk4::step and rotvec_to_quat, which
// measured up to 2x slower than a hand-written loop.
#pragma once

#if defined(__GNUC__) || defined(__clang__)
#define RIGIDDYN_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define RIGIDDYN_ALWAYS_INLINE inline
#endif
