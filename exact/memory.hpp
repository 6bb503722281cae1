// Memory exhaustion as an exception, and a memory budget.
//
// GMP's default allocator prints "GNU MP: Cannot allocate memory" and aborts when malloc fails;
// MPFR allocates through GMP's functions and FLINT's aborts likewise. install_throwing_allocators()
// routes all three through functions that throw std::bad_alloc instead, so memory exhaustion
// unwinds to the caller like any other C++ allocation failure (GMP's C frames carry unwind
// tables on Debian's x86-64 and arm64 builds; a value being computed when the allocation fails is
// abandoned, its partial limbs leak, which is harmless for a process that then reports and exits).
//
// The budget is the process's address-space limit (RLIMIT_AS): every allocation, from GMP,
// FLINT, CGAL, nlohmann-json or the standard library, then fails before the memory is used, at
// no cost per allocation. It is an upper bound on virtual memory, so it counts the program's
// shared libraries (about 60 MB) and thread stacks too. Under AddressSanitizer (which reserves
// terabytes of shadow address space) the limit cannot be set; set_memory_budget says so.
#pragma once
#include <cstddef>
#include <string>

namespace splinex {

/// GMP, MPFR and FLINT allocate through functions that throw std::bad_alloc when malloc fails.
/// Call before the first GMP/MPFR/FLINT value is created (MPFR caches the functions).
void install_throwing_allocators();

/// Physical memory of the machine in bytes (sysconf), 0 if unknown.
std::size_t physical_memory_bytes();
/// Three quarters of physical memory, at most the current address-space limit.
std::size_t default_memory_budget();
/// "4G", "512M", "100000K", "1073741824" (binary units K, M, G, T; optional trailing "B", "iB").
/// UsageError naming `field` for anything else or below min_memory_budget.
std::size_t parse_memory_size(const std::string& text, const std::string& field);
constexpr std::size_t min_memory_budget = std::size_t(128) << 20;

struct MemoryBudget {
  std::size_t bytes = 0;   // the budget asked for
  bool enforced = false;   // RLIMIT_AS set to it
  std::string note;        // why not, when not enforced
};
/// Sets RLIMIT_AS to `bytes` (never above the hard limit). Not under AddressSanitizer.
MemoryBudget set_memory_budget(std::size_t bytes);
/// The budget set last (bytes 0 if none).
const MemoryBudget& current_memory_budget();
/// "3.5 GiB" style text for messages.
std::string format_bytes(std::size_t bytes);

}  // namespace splinex
