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

namespace {

VectorInstructions choose() {
  const char* portable = std::getenv("RIGIDDYN_PORTABLE");
  const bool forced = portable != nullptr && *portable != '\0' && std::strcmp(portable, "0") != 0;
  return !forced && cpu_has_avx2_fma() ? VectorInstructions::avx2_fma : VectorInstructions::portable;
}

}  // namespace

VectorInstructions vector_instructions() {
  static const VectorInstructions path = choose();  // once per process (thread-safe initialisation)
  return path;
}

const char* vector_instructions_name(VectorInstructions path) {
  return path == VectorInstructions::avx2_fma ? "avx2_fma" : "portable";
}

}  // namespace rigiddyn
