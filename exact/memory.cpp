#include "exact/memory.hpp"

#include <flint/flint.h>
#include <gmp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <atomic>
#include <mutex>
#include <new>

#include "base/errors.hpp"

// Address and thread sanitizers reserve terabytes of shadow address space: no RLIMIT_AS under them.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SPLINEX_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SPLINEX_ASAN 1
#endif
#endif

namespace splinex {

namespace {

// Headroom for unwinding. Destructors run while a std::bad_alloc unwinds, and some of them allocate
// (nlohmann's json destroys a large tree through a std::vector stack, inside a noexcept destructor:
// a failure there is std::terminate, an abort instead of the typed line). So the budget keeps a
// headroom below the hard limit, and the first failed allocation raises the soft limit by it
// before throwing: the work stops at the budget, the unwinding has memory to finish.
// Every exhaustion releases a headroom (under a lock, before its exception is thrown), so a
// process that goes on after one (sweep jobs on threads) can unwind the next one too; the soft
// limit then grows by a headroom per exhaustion, never beyond the hard limit.
std::atomic<std::size_t> unwind_headroom{0};
std::mutex headroom_lock;

void release_headroom() {
#ifndef SPLINEX_ASAN
  std::lock_guard<std::mutex> g(headroom_lock);
  rlimit rl{};
  if (getrlimit(RLIMIT_AS, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY) return;
  rlim_t raised = rl.rlim_cur + static_cast<rlim_t>(unwind_headroom.load());
  if (rl.rlim_max != RLIM_INFINITY && raised > rl.rlim_max) raised = rl.rlim_max;
  rl.rlim_cur = raised;
  setrlimit(RLIMIT_AS, &rl);
#endif
}

[[noreturn]] void out_of_memory() {
  release_headroom();
  throw std::bad_alloc();
}

// operator new's handler: the same headroom, then the exception (not a retry: the work stops).
void new_handler() { out_of_memory(); }

void* throwing_malloc(std::size_t n) {
  void* p = std::malloc(n == 0 ? 1 : n);
  if (!p) out_of_memory();
  return p;
}
void* throwing_calloc(std::size_t k, std::size_t n) {
  void* p = std::calloc(k == 0 ? 1 : k, n == 0 ? 1 : n);
  if (!p) out_of_memory();
  return p;
}
void* throwing_realloc(void* old, std::size_t n) {
  void* p = std::realloc(old, n == 0 ? 1 : n);
  if (!p) out_of_memory();  // `old` stays valid and owned by its GMP/FLINT value
  return p;
}
// GMP's signatures carry the old size.
void* gmp_alloc(std::size_t n) { return throwing_malloc(n); }
void* gmp_realloc(void* old, std::size_t, std::size_t n) { return throwing_realloc(old, n); }
void gmp_free(void* p, std::size_t) { std::free(p); }

MemoryBudget& budget_state() {
  static MemoryBudget b;
  return b;
}

}  // namespace

void install_throwing_allocators() {
  std::set_new_handler(new_handler);
  mp_set_memory_functions(gmp_alloc, gmp_realloc, gmp_free);
  __flint_set_memory_functions(throwing_malloc, throwing_calloc, throwing_realloc, std::free);
}

std::size_t physical_memory_bytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || size <= 0) return 0;
  return static_cast<std::size_t>(pages) * static_cast<std::size_t>(size);
}

std::size_t default_memory_budget() {
  std::size_t b = physical_memory_bytes() / 4 * 3;
  if (b == 0) b = std::size_t(4) << 30;
  rlimit rl{};
  if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < b) b = rl.rlim_cur;
  return b;
}

std::size_t parse_memory_size(const std::string& text, const std::string& field) {
  const std::string fix = "give a size such as 512M, 4G or 1073741824 (bytes), at least 128M";
  std::size_t i = 0;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  if (i == 0 || i > 19) throw UsageError(field, "\"" + text + "\" is not a memory size", fix);
  unsigned long long v = std::strtoull(text.substr(0, i).c_str(), nullptr, 10);
  std::string unit = text.substr(i);
  if (unit.size() == 3 && unit.compare(1, 2, "iB") == 0) unit.resize(1);
  else if (!unit.empty() && unit.back() == 'B') unit.pop_back();
  int shift = 0;
  if (unit == "K" || unit == "k") shift = 10;
  else if (unit == "M" || unit == "m") shift = 20;
  else if (unit == "G" || unit == "g") shift = 30;
  else if (unit == "T" || unit == "t") shift = 40;
  else if (!unit.empty()) throw UsageError(field, "\"" + text + "\" has an unknown unit", fix);
  if (shift > 0 && v > (~0ULL >> shift)) throw UsageError(field, "\"" + text + "\" is too large", fix);
  const std::size_t bytes = static_cast<std::size_t>(v << shift);
  if (bytes < min_memory_budget)
    throw UsageError(field, "\"" + text + "\" is below the minimum of 128M (the program and its libraries need it)", fix);
  return bytes;
}

MemoryBudget set_memory_budget(std::size_t bytes) {
  MemoryBudget& b = budget_state();
  b = MemoryBudget{bytes, false, ""};
#ifdef SPLINEX_ASAN
  b.note = "not enforced under AddressSanitizer or ThreadSanitizer (they reserve terabytes of shadow address space)";
#else
  rlimit rl{};
  if (getrlimit(RLIMIT_AS, &rl) != 0) {
    b.note = std::string("getrlimit failed: ") + std::strerror(errno);
    return b;
  }
  // The headroom (an eighth of the budget, 16 MiB to 256 MiB) is kept below the hard limit, so it can
  // be released when the budget runs out (release_headroom); under an external cap (ulimit -v) the
  // budget shrinks by it instead.
  const std::size_t headroom = std::min<std::size_t>(std::max<std::size_t>(bytes / 8, std::size_t(16) << 20), std::size_t(256) << 20);
  rlim_t want = static_cast<rlim_t>(bytes);
  if (rl.rlim_max != RLIM_INFINITY && want + headroom > rl.rlim_max)
    want = rl.rlim_max > 2 * headroom ? rl.rlim_max - headroom : rl.rlim_max / 2;
  unwind_headroom = headroom;
  rl.rlim_cur = want;
  if (setrlimit(RLIMIT_AS, &rl) != 0) {
    b.note = std::string("setrlimit failed: ") + std::strerror(errno);
    return b;
  }
  b.bytes = static_cast<std::size_t>(want);
  b.enforced = true;
#endif
  return b;
}

const MemoryBudget& current_memory_budget() { return budget_state(); }

std::string format_bytes(std::size_t bytes) {
  char buf[64];
  const double b = static_cast<double>(bytes);
  if (bytes >= (std::size_t(1) << 30)) std::snprintf(buf, sizeof buf, "%.1f GiB", b / (1u << 30));
  else if (bytes >= (std::size_t(1) << 20)) std::snprintf(buf, sizeof buf, "%.0f MiB", b / (1u << 20));
  else std::snprintf(buf, sizeof buf, "%zu bytes", bytes);
  return buf;
}

}  // namespace splinex
