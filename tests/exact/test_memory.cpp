// Memory exhaustion inside GMP, MPFR and FLINT throws std::bad_alloc (exact/memory.hpp) instead
// of aborting with "GNU MP: Cannot allocate memory". Each case runs in a forked child under an
// address-space budget, so the limit cannot leak into other tests.
#include <flint/fmpz.h>
#include <gmp.h>
#include <mpfr.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <functional>
#include <new>

#include "base/errors.hpp"
#include "exact/flint_rational.hpp"
#include "exact/memory.hpp"

namespace sx = splinex;

namespace {

// Child exit codes: 0 bad_alloc caught, 1 the allocation succeeded, 3 another exception,
// 4 budget not enforced. A GMP abort ends the child by SIGABRT.
int in_child_under_budget(std::size_t budget, const std::function<void()>& work) {
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    sx::install_throwing_allocators();
    if (!sx::set_memory_budget(budget).enforced) _exit(4);
    try {
      work();
    } catch (const std::bad_alloc&) {
      _exit(0);
    } catch (...) {
      _exit(3);
    }
    _exit(1);
  }
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  if (WIFSIGNALED(status)) return 100 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

}  // namespace

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer reserves terabytes of shadow address space, so RLIMIT_AS cannot be set: these
// cases run in the release build only (README, reliability).
#else
TEST_CASE("memory exhaustion in GMP throws bad_alloc") {
  CHECK(in_child_under_budget(std::size_t(256) << 20, [] {
          mpz_t z;
          mpz_init(z);
          mpz_ui_pow_ui(z, 10, 1ul << 30);  // 3.6e9 bits, 445 MB
          mpz_clear(z);
        }) == 0);
}

TEST_CASE("memory exhaustion in Boost's mpq_rational throws bad_alloc") {
  CHECK(in_child_under_budget(std::size_t(256) << 20, [] {
          sx::Rational x(3);
          for (int i = 0; i < 40; ++i) x = x * x;  // 2^40 * 1.58 bits: far beyond the budget
        }) == 0);
}

TEST_CASE("memory exhaustion in MPFR throws bad_alloc") {
  CHECK(in_child_under_budget(std::size_t(256) << 20, [] {
          mpfr_t x;
          mpfr_init2(x, mpfr_prec_t(1) << 32);  // 512 MB of mantissa
          mpfr_clear(x);
        }) == 0);
}

TEST_CASE("memory exhaustion in FLINT throws bad_alloc") {
  CHECK(in_child_under_budget(std::size_t(256) << 20, [] {
          fmpz_t z;
          fmpz_init(z);
          fmpz_set_ui(z, 10);
          fmpz_pow_ui(z, z, 1ul << 30);
          fmpz_clear(z);
        }) == 0);
  CHECK(in_child_under_budget(std::size_t(256) << 20, [] {
          sx::FlintRational x(3);
          for (int i = 0; i < 40; ++i) x = x * x;
        }) == 0);
}

TEST_CASE("memory exhaustion in the standard library throws bad_alloc under the budget") {
  CHECK(in_child_under_budget(std::size_t(256) << 20, [] {
          std::vector<char> v(std::size_t(1) << 30, 1);
          (void)v;
        }) == 0);
}
#endif

TEST_CASE("memory sizes parse in binary units and refuse nonsense") {
  CHECK(sx::parse_memory_size("128M", "m") == (std::size_t(128) << 20));
  CHECK(sx::parse_memory_size("4G", "m") == (std::size_t(4) << 30));
  CHECK(sx::parse_memory_size("4GiB", "m") == (std::size_t(4) << 30));
  CHECK(sx::parse_memory_size("4GB", "m") == (std::size_t(4) << 30));
  CHECK(sx::parse_memory_size("1T", "m") == (std::size_t(1) << 40));
  CHECK(sx::parse_memory_size("1073741824", "m") == (std::size_t(1) << 30));
  CHECK_THROWS_AS(sx::parse_memory_size("127M", "m"), sx::UsageError);
  CHECK_THROWS_AS(sx::parse_memory_size("", "m"), sx::UsageError);
  CHECK_THROWS_AS(sx::parse_memory_size("4X", "m"), sx::UsageError);
  CHECK_THROWS_AS(sx::parse_memory_size("-4G", "m"), sx::UsageError);
  CHECK_THROWS_AS(sx::parse_memory_size("99999999999999999999", "m"), sx::UsageError);
  CHECK_THROWS_AS(sx::parse_memory_size("20000000000T", "m"), sx::UsageError);
  CHECK(sx::default_memory_budget() > 0);
}
