// See memory_probe.hpp.
#include "memory_probe.hpp"

#include <malloc.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

std::atomic<bool> g_on{false};
std::atomic<long> g_allocations{0}, g_live{0}, g_peak{0};

void note_alloc(void* p) {
  if (!p || !g_on.load(std::memory_order_relaxed)) return;
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  const long now = g_live.fetch_add(static_cast<long>(malloc_usable_size(p)), std::memory_order_relaxed) +
                   static_cast<long>(malloc_usable_size(p));
  long peak = g_peak.load(std::memory_order_relaxed);
  while (now > peak && !g_peak.compare_exchange_weak(peak, now, std::memory_order_relaxed)) {
  }
}

void note_free(void* p) {
  if (!p || !g_on.load(std::memory_order_relaxed)) return;
  g_live.fetch_sub(static_cast<long>(malloc_usable_size(p)), std::memory_order_relaxed);
}

long vm_hwm_kib() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

bool reset_hwm() {
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
#define SPLINEX_PROBE_OFF 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(memory_sanitizer)
#define SPLINEX_PROBE_OFF 1
#endif
#endif

#ifndef SPLINEX_PROBE_OFF
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_calloc(std::size_t, std::size_t);
void* __libc_realloc(void*, std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);

void* malloc(std::size_t n) {
  void* p = __libc_malloc(n);
  note_alloc(p);
  return p;
}
void* calloc(std::size_t k, std::size_t n) {
  void* p = __libc_calloc(k, n);
  note_alloc(p);
  return p;
}
void* realloc(void* q, std::size_t n) {
  note_free(q);
  void* p = __libc_realloc(q, n);
  if (p) note_alloc(p);
  else if (q && n) note_alloc(q);  // failed: q is still live
  return p;
}
void free(void* p) {
  note_free(p);
  __libc_free(p);
}
void* memalign(std::size_t a, std::size_t n) {
  void* p = __libc_memalign(a, n);
  note_alloc(p);
  return p;
}
void* aligned_alloc(std::size_t a, std::size_t n) { return memalign(a, n); }
int posix_memalign(void** out, std::size_t a, std::size_t n) {
  void* p = memalign(a, n);
  if (!p) return 12;  // ENOMEM
  *out = p;
  return 0;
}
}
#endif

namespace memprobe {

bool available() {
#ifdef SPLINEX_PROBE_OFF
  return false;
#else
  return true;
#endif
}

Usage measure(const std::function<void()>& f) {
  Usage u;
  const bool hwm = reset_hwm();
  g_allocations = 0;
  g_live = 0;
  g_peak = 0;
  g_on = true;
  f();
  g_on = false;
  u.allocations = g_allocations;
  u.peak_heap = g_peak;
  if (hwm) u.peak_rss_kib = vm_hwm_kib();
  return u;
}

}  // namespace memprobe
