// A heap-allocation counter for the C++ tests (included by one translation unit per test executable): the
// executable defines malloc, calloc, realloc and the aligned allocators itself (its definitions take
// precedence over the C library's for every shared library, libstdc++'s operator new and Eigen's
// aligned_malloc included) and forwards them to glibc's __libc_* entry points. Where the counting cannot
// be installed (not glibc, or under AddressSanitizer, which owns malloc) counts_allocations is false.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)
#define RIGIDDYN_COUNTS_ALLOCATIONS 1
#include <cerrno>

namespace {
std::atomic<std::int64_t> allocation_count{0};
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

void* malloc(std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  return __libc_realloc(pointer, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  void* pointer = __libc_memalign(alignment, size);
  if (pointer == nullptr) return ENOMEM;
  *out = pointer;
  return 0;
}
}
#endif

namespace rigiddyn::test {

// The heap allocations made while f runs.
template <class F>
std::int64_t allocations_during(F&& f) {
#ifdef RIGIDDYN_COUNTS_ALLOCATIONS
  const std::int64_t before = allocation_count.load();
  f();
  return allocation_count.load() - before;
#else
  f();
  return 0;
#endif
}

#ifdef RIGIDDYN_COUNTS_ALLOCATIONS
constexpr bool counts_allocations = true;
#else
constexpr bool counts_allocations = false;
#endif
constexpr const char* why_not_counted = "allocations are counted only with glibc and without AddressSanitizer";

}  // namespace rigiddyn::test
