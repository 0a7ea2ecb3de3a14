#include "allocation_counter.h"

#include <atomic>
#include <cstddef>

#include "sanitizers.h"

namespace {
std::atomic<long> g_allocations{0};
}

#ifdef IK_UNDER_ASAN
// Under AddressSanitizer every allocation (malloc, calloc, realloc, operator new) goes through
// its allocator, which calls a hook for each; malloc itself must stay AddressSanitizer's, or the
// blocks it did not allocate would reach its free() (a fatal "bad free").
// AddressSanitizer's runtime has this function; GCC ships no header for it (LLVM's is
// <sanitizer/allocator_interface.h>).
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*, std::size_t),
                                                         void (*free_hook)(const volatile void*));
namespace {
void count_allocation(const volatile void*, std::size_t) { ++g_allocations; }
void ignore_free(const volatile void*) {}
// Installed before main (both hooks are needed: it refuses a null one; no_allocation_test.cpp
// checks that a fresh Eigen vector is counted).
struct CountingHook {
  CountingHook() { __sanitizer_install_malloc_and_free_hooks(count_allocation, ignore_free); }
} g_counting_hook;
}  // namespace
#else
// glibc lets a program replace malloc; forward to its internal allocator and count.
extern "C" void* __libc_malloc(std::size_t);
extern "C" void* __libc_calloc(std::size_t, std::size_t);
extern "C" void* __libc_realloc(void*, std::size_t);
extern "C" void* malloc(std::size_t size) {
  ++g_allocations;
  return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t n, std::size_t size) {
  ++g_allocations;
  return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t size) {
  ++g_allocations;
  return __libc_realloc(p, size);
}
#endif

namespace ik::test {
long heap_allocations() { return g_allocations.load(); }
}  // namespace ik::test
