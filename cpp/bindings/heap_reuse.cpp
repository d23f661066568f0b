// The process's heap kept for reuse: glibc's malloc settings as the extension module sets them when it is imported.
//
// glibc gives the top of its heap back to the system once more than M_TRIM_THRESHOLD bytes of it are free (128 KiB
// by default), and serves a block above M_MMAP_THRESHOLD (128 KiB at first) from a fresh mapping that it unmaps when
// the block is freed. It raises both on its own (up to 32 MiB and 64 MiB) only after freeing a mapped block: never in
// a process whose blocks are all below 128 KiB, as a run's record columns are (one column of 2 713 records of three
// numbers: 65 KiB). Each run then faulted its records' pages in anew: the shipped pendulum recording each of 2 712
// rk4 steps took 187 minor page faults a call and 462 µs, 0 and 304 µs with the settings below (2-core x86-64, glibc
// 2.36; `python3 bench/python/bench_heap_reuse.py`). Set here to those highest values glibc reaches itself: the
// process then keeps up to 64 MiB of freed heap for its next blocks, and blocks up to 32 MiB come from the heap (a
// numpy temporary of 2.4 MB as well: 20 of them took 110 ms with glibc's defaults, 90 ms with these). Setting
// M_TRIM_THRESHOLD alone would have stopped glibc raising M_MMAP_THRESHOLD: every block above 128 KiB would then have
// been mapped and faulted in anew.
//
// Left as they are where the user chose them (MALLOC_MMAP_THRESHOLD_, MALLOC_TRIM_THRESHOLD_, MALLOC_TOP_PAD_ or
// MALLOC_MMAP_MAX_ in the environment, or a glibc.malloc tunable in GLIBC_TUNABLES), where RIGIDDYN_KEEP_MALLOC=1 asks
// it, and on a C library other than glibc.
#include "bindings.hpp"

#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rigiddyn::bindings {

namespace {

// Whether the user set the environment variable `name` (to anything).
bool is_set(const char* name) { return std::getenv(name) != nullptr; }

// Whether the user chose glibc's malloc settings, or asked that they be kept.
bool malloc_settings_chosen() {
  for (const char* name : {"MALLOC_MMAP_THRESHOLD_", "MALLOC_TRIM_THRESHOLD_", "MALLOC_TOP_PAD_", "MALLOC_MMAP_MAX_"}) {
    if (is_set(name)) return true;
  }
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables != nullptr && std::strstr(tunables, "glibc.malloc.") != nullptr) return true;
  const char* keep = std::getenv("RIGIDDYN_KEEP_MALLOC");
  return keep != nullptr && std::strcmp(keep, "1") == 0;
}

}  // namespace

void keep_freed_heap_for_reuse() {
#if defined(__GLIBC__)
  if (malloc_settings_chosen()) return;
  constexpr int mmap_threshold = 32 << 20, trim_threshold = 64 << 20;  // [bytes]: glibc's own highest
  mallopt(M_MMAP_THRESHOLD, mmap_threshold);
  mallopt(M_TRIM_THRESHOLD, trim_threshold);
#endif
}

}  // namespace rigiddyn::bindings
