#include "float/mpfr.hpp"

#include <cstdlib>
#include <memory>

#include "base/errors.hpp"
#include "base/parallel.hpp"

namespace splinex {

namespace {
// MPFR keeps constants (pi, log 2, ...) in caches local to each thread: a pool's worker frees them
// as it ends (base/parallel.hpp), so no thread leaves them behind.
const bool kMpfrCachesFreedPerThread = [] {
  thread_exit_hooks().push_back([] { mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE); });
  return true;
}();
}  // namespace

Mpfr::Precision::Precision(long bits) : old_(current_bits()) {
  // Above 65536 bits (about 19,700 digits) exact arithmetic is the better tool, and a precision of
  // 10^6 bits made ordinary commands run for minutes.
  if (bits < 24 || bits > 65536)
    throw UsageError("arith", "MPFR precision " + std::to_string(bits) + " bits is out of range",
                     "use mpfr:BITS with 24 <= BITS <= 65536, or --arith exact");
  current_bits() = bits;
}

Rational to_rational(const Mpfr& x) {
  if (!mpfr_number_p(x.get()))
    throw ParseError("value", "an MPFR result is NaN or infinite", "check the input for divisions by zero");
  if (mpfr_zero_p(x.get())) return Rational(0);
  Integer m;
  const mpfr_exp_t e = mpfr_get_z_2exp(m.backend().data(), x.get());
  Rational r(m);
  Integer p2;
  mpz_ui_pow_ui(p2.backend().data(), 2, static_cast<unsigned long>(e < 0 ? -e : e));
  return e < 0 ? Rational(r / Rational(p2)) : Rational(r * Rational(p2));
}

void throw_not_finite(const std::string& arith) {
  throw RangeError("result", "a computed value is infinite or NaN in " + arith + " (beyond its range)",
                   "use --arith exact, or mpfr:BITS (its exponent range is far wider), or rescale the input");
}

std::string to_decimal_string(const Mpfr& x) {
  if (!mpfr_number_p(x.get())) throw_not_finite("mpfr:" + std::to_string(x.bits()));
  if (mpfr_zero_p(x.get())) return "0";
  mpfr_exp_t exp10 = 0;
  // n = 0: MPFR chooses enough digits that reading them back at this precision round-trips.
  std::unique_ptr<char, void (*)(char*)> s(mpfr_get_str(nullptr, &exp10, 10, 0, x.get(), MPFR_RNDN), mpfr_free_str);
  std::string digits(s.get());
  std::string sign;
  if (!digits.empty() && digits[0] == '-') { sign = "-"; digits.erase(0, 1); }
  // value = 0.DIGITS * 10^exp10 = D.IGITS * 10^(exp10-1)
  std::string out = sign + digits.substr(0, 1);
  if (digits.size() > 1) out += "." + digits.substr(1);
  return out + "e" + std::to_string(static_cast<long>(exp10) - 1);
}

}  // namespace splinex
