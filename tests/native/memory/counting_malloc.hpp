// Peak-tracking malloc interposer (glibc): every allocation of the process (operator new and
// Eigen's malloc alike) goes through these, counted by malloc_usable_size.
#pragma once
#include <malloc.h>
#include <mm_malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
extern "C" {
void* __libc_malloc(size_t);
void __libc_free(void*);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
}
namespace counting {
inline std::atomic<int64_t> live{0}, peak{0};
inline void add(void* p) {
  if (!p) return;
  const int64_t now =
      live.fetch_add(int64_t(malloc_usable_size(p))) + int64_t(malloc_usable_size(p));
  int64_t pk = peak.load();
  while (now > pk && !peak.compare_exchange_weak(pk, now)) {
  }
}
inline void sub(void* p) {
  if (p) live.fetch_sub(int64_t(malloc_usable_size(p)));
}
inline void resetPeak() { peak.store(live.load()); }
}  // namespace counting
extern "C" {
void* malloc(size_t n) noexcept {
  void* p = __libc_malloc(n);
  counting::add(p);
  return p;
}
void free(void* p) noexcept {
  counting::sub(p);
  __libc_free(p);
}
void* calloc(size_t a, size_t b) noexcept {
  void* p = __libc_calloc(a, b);
  counting::add(p);
  return p;
}
void* realloc(void* q, size_t n) noexcept {
  counting::sub(q);
  void* p = __libc_realloc(q, n);
  counting::add(p ? p : (n ? nullptr : nullptr));
  if (!p && n) counting::add(q);
  return p;
}
void* memalign(size_t a, size_t n) noexcept {
  void* p = __libc_memalign(a, n);
  counting::add(p);
  return p;
}
void* aligned_alloc(size_t a, size_t n) noexcept {
  void* p = __libc_memalign(a, n);
  counting::add(p);
  return p;
}
int posix_memalign(void** out, size_t a, size_t n) noexcept {
  void* p = __libc_memalign(a, n);
  if (!p) return 12;
  counting::add(p);
  *out = p;
  return 0;
}
}
