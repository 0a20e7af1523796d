#pragma once
// Counts heap allocations while g_counting is set, for tests that check a step loop never
// allocates: every global operator new is replaced and, on glibc, malloc, calloc and
// realloc are interposed too (Eigen allocates with malloc; GCC may turn malloc + memset
// into calloc). It defines the replacements, so include it in exactly one translation
// unit of a test binary.
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_news{0};
std::atomic<long> g_mallocs{0};

void* counted_new(std::size_t n) {
  if (g_counting.load(std::memory_order_relaxed)) g_news.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return counted_new(n); }
void* operator new[](std::size_t n) { return counted_new(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try { return counted_new(n); } catch (...) { return nullptr; }
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  try { return counted_new(n); } catch (...) { return nullptr; }
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

#if defined(__GLIBC__)
// glibc's own allocator entry points. GCC may turn malloc + memset into calloc, so all
// three allocating functions are counted.
extern "C" void* __libc_malloc(std::size_t n);                  // NOLINT
extern "C" void* __libc_calloc(std::size_t n, std::size_t size);  // NOLINT
extern "C" void* __libc_realloc(void* p, std::size_t n);        // NOLINT
namespace {
void count_malloc() {
  if (g_counting.load(std::memory_order_relaxed)) g_mallocs.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace
extern "C" void* malloc(std::size_t n) noexcept {
  count_malloc();
  return __libc_malloc(n);
}
extern "C" void* calloc(std::size_t n, std::size_t size) noexcept {
  count_malloc();
  return __libc_calloc(n, size);
}
extern "C" void* realloc(void* p, std::size_t n) noexcept {
  count_malloc();
  return __libc_realloc(p, n);
}
#endif
