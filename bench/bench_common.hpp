// Shared pieces of the C++ benchmarks.
//
// Naming: register each measured case twice, as "<case>:rigiddyn" and "<case>:baseline" (a plain
// hand-written loop doing the same work); arguments are appended by Google Benchmark as usual.
// bench_main.cpp then prints, after the normal table, one line per case:
//   ratio <case>/<args>: rigiddyn X ns/op, baseline Y ns/op, rigiddyn/baseline = X/Y
// "op" is one item: set state.SetItemsProcessed(n) so the reporter can divide by it.
#pragma once
#include <cstdlib>
#include <cstdint>

// A function the compiler must not inline: a measured loop, so that callgrind's counts name it
#if defined(__GNUC__) || defined(__clang__)
#define BENCH_NOINLINE __attribute__((noinline))
#else
#define BENCH_NOINLINE
#endif

namespace rigiddyn::bench {

// The problem size to use: `full` when run by hand, `small` when ctest runs the benchmark
// (ctest sets RIGIDDYN_BENCH_SMALL=1, to keep CI fast).
inline std::int64_t bench_size(std::int64_t full, std::int64_t small) {
  const char* env = std::getenv("RIGIDDYN_BENCH_SMALL");
  return (env != nullptr && env[0] == '1') ? small : full;
}

}  // namespace rigiddyn::bench
