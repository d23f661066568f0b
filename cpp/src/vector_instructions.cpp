#include "rigiddyn/vector_instructions.hpp"

#include <cstdlib>
#include <cstring>

namespace rigiddyn {

bool cpu_has_avx2_fma() {
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
  return false;
#endif
}

bool cpu_has_avx512() {
#if (defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__)
  // libgcc's and compiler-rt's CPU model checks the operating system's XSAVE state (XGETBV) for the ZMM registers
  return cpu_has_avx2_fma() && __builtin_cpu_supports("avx512f");
#else
  return false;
#endif
}

namespace {

VectorInstructions choose() {
  const char* portable = std::getenv("RIGIDDYN_PORTABLE");
  const bool forced = portable != nullptr && *portable != '\0' && std::strcmp(portable, "0") != 0;
  if (forced) return VectorInstructions::portable;
  if (cpu_has_avx512()) return VectorInstructions::avx512;
  return cpu_has_avx2_fma() ? VectorInstructions::avx2_fma : VectorInstructions::portable;
}

}  // namespace

VectorInstructions vector_instructions() {
  static const VectorInstructions path = choose();  // once per process (thread-safe initialisation)
  return path;
}

bool runs_avx2_fma(VectorInstructions path) { return path != VectorInstructions::portable; }

const char* vector_instructions_name(VectorInstructions path) {
  switch (path) {
    case VectorInstructions::avx512: return "avx512";
    case VectorInstructions::avx2_fma: return "avx2_fma";
    case VectorInstructions::portable: return "portable";
  }
  return "portable";
}

}  // namespace rigiddyn
