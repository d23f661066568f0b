// RIGIDDYN_ALWAYS_INLINE: for the small functions that integrators call once per stage or step
// (models, Euler's equations, the SO(3) exponential); RIGIDDYN_ALWAYS_INLINE_LAMBDA the same for a lambda (after its
// parameter list), e.g. the run loop's check for a due record. Forced inline so that a step compiles to one
// straight-line loop body: GCC otherwise outlines rate(), Rk4::step and rotvec_to_quat, which
// measured up to 2x slower than a hand-written loop.
//
// A build under AddressSanitizer only asks GCC to inline (plain `inline`): instrumented, the forced inlining of a
// one-body layout's run took a translation unit from 51 s to 4 min to compile and measures nothing there.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define RIGIDDYN_SANITIZED_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RIGIDDYN_SANITIZED_BUILD 1
#endif
#endif

#if (defined(__GNUC__) || defined(__clang__)) && !defined(RIGIDDYN_SANITIZED_BUILD)
#define RIGIDDYN_ALWAYS_INLINE inline __attribute__((always_inline))
#define RIGIDDYN_ALWAYS_INLINE_LAMBDA __attribute__((always_inline))
#else
#define RIGIDDYN_ALWAYS_INLINE inline
#define RIGIDDYN_ALWAYS_INLINE_LAMBDA
#endif
