#include "allocation_counter.h"

#include <atomic>
#include <cstddef>

namespace {
std::atomic<long> g_allocations{0};
}

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

namespace ik::test {
long heap_allocations() { return g_allocations.load(); }
}  // namespace ik::test
