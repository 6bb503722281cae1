// Heap and resident-memory measurement for the benchmarks (issue 15, target 5): how many heap
// allocations one operation makes, how far its live heap rises above where it started, and the
// process's peak resident set size while it runs.
//
// The heap numbers come from malloc/free/realloc/calloc/memalign interposed in the benchmark
// executable (memory_probe.cpp; glibc's __libc_* functions do the work), so they count every
// allocation of every library: libstdc++ (operator new), GMP, MPFR, FLINT, SISL, OpenCASCADE.
// Counting is off while Google Benchmark times a case; measure() runs the operation once more with
// counting on, so the timings are not disturbed. Peak RSS: Linux resets VmHWM when "5" is written
// to /proc/self/clear_refs; measure() reads it back after the run (in KiB; -1 where the kernel
// refuses the reset).
#pragma once
#include <functional>

namespace memprobe {

struct Usage {
  long allocations = 0;  // calls to malloc, calloc, realloc, memalign, ... during the run
  long peak_heap = 0;    // bytes: the highest live heap during the run minus the live heap before
  long peak_rss_kib = -1;
};

/// Whether the allocator functions of this executable are the probe's (false under sanitizers).
bool available();

/// Runs f once with counting on.
Usage measure(const std::function<void()>& f);

}  // namespace memprobe
