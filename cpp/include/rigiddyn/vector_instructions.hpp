// The vector instructions the hot kernels run on (the N-body pair sum of MutualGravity, and the rotation array
// functions of the Python package in blocks of items: AVX2 without FMA there, so the same bits on both paths): the
// portable path, built for the x86-64 baseline (SSE2) like the rest of the library, or AVX2 with FMA where the CPU
// has them (four doubles per instruction, a fused multiply–add rounding once). The path is chosen once per process, at the
// first call of a kernel; the environment variable RIGIDDYN_PORTABLE=1, read then, forces the portable path, whose
// results are the same bits on every x86-64 machine (the AVX2 path agrees with it to the bound each kernel states).
#pragma once

namespace rigiddyn {

enum class VectorInstructions { portable, avx2_fma };

// True when this build has the AVX2 + FMA kernels (GCC or Clang on x86-64) and this CPU runs them.
bool cpu_has_avx2_fma();

// The path of this process: avx2_fma where cpu_has_avx2_fma() and RIGIDDYN_PORTABLE is unset (or "0"), else portable.
VectorInstructions vector_instructions();

// "portable" or "avx2_fma"
const char* vector_instructions_name(VectorInstructions path);

}  // namespace rigiddyn
