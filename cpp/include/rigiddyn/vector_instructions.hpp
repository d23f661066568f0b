// The vector instructions the hot kernels run on (the N-body pair sum of MutualGravity, and the rotation array
// functions of the Python package in blocks of items: AVX2 without FMA there, so the same bits on every path): the
// portable path, built for the x86-64 baseline (SSE2) like the rest of the library; AVX2 with FMA where the CPU has
// them (four doubles per instruction, a fused multiply–add rounding once); or AVX-512 where the CPU (and the
// operating system) has AVX-512F besides (eight doubles per instruction: the pair sum; the kernels without an
// AVX-512 form run their AVX2 one on that path). The path is chosen once per process, at the first call of a kernel;
// the environment variable RIGIDDYN_PORTABLE=1, read then, forces the portable path, whose results are the same bits
// on every x86-64 machine (the other paths agree with it to the bound each kernel states).
#pragma once

namespace rigiddyn {

enum class VectorInstructions { portable, avx2_fma, avx512 };

// True when this build has the AVX2 + FMA kernels (GCC or Clang on x86-64) and this CPU runs them.
bool cpu_has_avx2_fma();

// True when this build has the AVX-512 kernels and this CPU and operating system run AVX-512F (and AVX2 + FMA).
bool cpu_has_avx512();

// The path of this process: avx512 where cpu_has_avx512(), else avx2_fma where cpu_has_avx2_fma(), else portable;
// portable whenever RIGIDDYN_PORTABLE is set (and not "0").
VectorInstructions vector_instructions();

// True on the paths that run the AVX2 + FMA kernels (avx2_fma, and avx512 for the kernels it has no form of).
bool runs_avx2_fma(VectorInstructions path);

// "portable", "avx2_fma" or "avx512"
const char* vector_instructions_name(VectorInstructions path);

}  // namespace rigiddyn
