// Counts every call into the C allocator (malloc, calloc, realloc, the aligned variants) while
// armed: operator new, Eigen's aligned_malloc and everything else end there. Include in exactly ONE
// translation unit of a test program; the others read the count through allocation_count.hpp.
//
// In a plain build the program defines the allocator's entry points, which forward to glibc's
// __libc_* (glibc lets an executable define them). Under AddressSanitizer the allocator is the
// sanitizer's and must stay so: the count comes from the sanitizer's own allocation hook instead.
#pragma once

#include <cstddef>

#include "tests/support/allocation_count.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define NEEDLE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NEEDLE_ASAN 1
#endif
#endif

#ifdef NEEDLE_ASAN
#include <sanitizer/allocator_interface.h>

namespace needle::test::allocation_counter {
inline const int kHookInstalled = __sanitizer_install_malloc_and_free_hooks(
    [](const volatile void*, size_t) { note(); }, [](const volatile void*) {});
}  // namespace needle::test::allocation_counter

#else
extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);

void* malloc(size_t size) noexcept {
  needle::test::allocation_counter::note();
  return __libc_malloc(size);
}
void* calloc(size_t n, size_t size) noexcept {
  needle::test::allocation_counter::note();
  return __libc_calloc(n, size);
}
void* realloc(void* p, size_t size) noexcept {
  needle::test::allocation_counter::note();
  return __libc_realloc(p, size);
}
void* memalign(size_t alignment, size_t size) noexcept {
  needle::test::allocation_counter::note();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(size_t alignment, size_t size) noexcept { return memalign(alignment, size); }
int posix_memalign(void** out, size_t alignment, size_t size) noexcept {
  *out = memalign(alignment, size);
  return *out ? 0 : 12;  // ENOMEM
}
void free(void* p) noexcept { __libc_free(p); }
}
#endif
