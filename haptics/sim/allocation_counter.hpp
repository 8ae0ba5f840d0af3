// Counts every call into the C allocator (malloc, calloc, realloc, the aligned variants) while
// armed: operator new, Eigen's aligned_malloc and everything else end there. glibc lets the
// executable define these symbols; they forward to __libc_*.
// Include in exactly ONE translation unit of an executable (it defines malloc and friends); the
// others read the count through haptics/sim/allocation_count.hpp.
#pragma once

#include <cstddef>

#include "haptics/sim/allocation_count.hpp"

extern "C" {
void* __libc_malloc(size_t);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void __libc_free(void*);

void* malloc(size_t size) noexcept {
  needle::haptics::allocation_counter::note();
  return __libc_malloc(size);
}
void* calloc(size_t n, size_t size) noexcept {
  needle::haptics::allocation_counter::note();
  return __libc_calloc(n, size);
}
void* realloc(void* p, size_t size) noexcept {
  needle::haptics::allocation_counter::note();
  return __libc_realloc(p, size);
}
void* memalign(size_t alignment, size_t size) noexcept {
  needle::haptics::allocation_counter::note();
  return __libc_memalign(alignment, size);
}
void* aligned_alloc(size_t alignment, size_t size) noexcept { return memalign(alignment, size); }
int posix_memalign(void** out, size_t alignment, size_t size) noexcept {
  *out = memalign(alignment, size);
  return *out ? 0 : 12;  // ENOMEM
}
void free(void* p) noexcept { __libc_free(p); }
}
