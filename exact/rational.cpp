#include <algorithm>
#include "exact/rational.hpp"

#include <gmp.h>
#include <mpfr.h>

#include <cctype>
#include <cmath>

#include "base/errors.hpp"

namespace splinex {

namespace {

bool all_digits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

[[noreturn]] void bad_number(std::string_view text, const std::string& field, const std::string& why) {
  throw ParseError(field, "\"" + std::string(text) + "\" is not a number: " + why,
                   "write an integer (\"-3\"), a fraction (\"22/7\") or a decimal (\"0.784\", \"1e-3\")");
}

// Boost reads "0784" as octal; decimal digits must reach it without leading zeros.
Integer decimal_integer(std::string_view digits) {
  while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
  return Integer(std::string(digits.empty() ? "0" : digits));
}

Integer pow10(long e) {
  Integer r;
  mpz_ui_pow_ui(r.backend().data(), 10, static_cast<unsigned long>(e));
  return r;
}

}  // namespace

Rational parse_number(std::string_view text, const std::string& field) {
  std::string_view s = text;
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  if (s.empty()) bad_number(text, field, "it is empty");
  bool negative = false;
  if (s.front() == '+' || s.front() == '-') {
    negative = s.front() == '-';
    s.remove_prefix(1);
  }
  Rational value;
  if (auto slash = s.find('/'); slash != std::string_view::npos) {
    std::string_view num = s.substr(0, slash), den = s.substr(slash + 1);
    if (!all_digits(num) || !all_digits(den)) bad_number(text, field, "a fraction needs digits on both sides of '/'");
    const Integer n = decimal_integer(num), d = decimal_integer(den);
    if (d == 0) bad_number(text, field, "the denominator is zero");
    value = Rational(n, d);
  } else {
    std::string_view mant = s, exps;
    if (auto e = s.find_first_of("eE"); e != std::string_view::npos) {
      mant = s.substr(0, e);
      exps = s.substr(e + 1);
      if (exps.empty()) bad_number(text, field, "the exponent is empty");
    }
    std::string_view ip = mant, fp;
    if (auto dot = mant.find('.'); dot != std::string_view::npos) {
      ip = mant.substr(0, dot);
      fp = mant.substr(dot + 1);
    }
    if ((ip.empty() && fp.empty()) || (!ip.empty() && !all_digits(ip)) || (!fp.empty() && !all_digits(fp)))
      bad_number(text, field, "expected digits with at most one '.' and an optional exponent");
    long exponent = 0;
    if (!exps.empty()) {
      bool eneg = false;
      if (exps.front() == '+' || exps.front() == '-') {
        eneg = exps.front() == '-';
        exps.remove_prefix(1);
      }
      if (!all_digits(exps)) bad_number(text, field, "the exponent must be an integer");
      if (exps.size() > 6) bad_number(text, field, "the exponent is beyond +-100000");
      exponent = std::stol(std::string(exps));
      if (exponent > 100000) bad_number(text, field, "the exponent is beyond +-100000");
      if (eneg) exponent = -exponent;
    }
    std::string digits = std::string(ip) + std::string(fp);
    const Integer mantissa = decimal_integer(digits);
    const long scale = exponent - static_cast<long>(fp.size());
    if (scale >= 0) value = Rational(mantissa * pow10(scale));
    else value = Rational(mantissa, pow10(-scale));
  }
  return negative ? Rational(-value) : value;
}

Rational exact_from_double(double x, const std::string& field) {
  if (!std::isfinite(x))
    throw ParseError(field, "is " + std::string(std::isnan(x) ? "NaN" : "infinite"), "give a finite number");
  Rational r;
  mpq_set_d(r.backend().data(), x);  // exact: a double is a dyadic rational
  return r;
}

double to_double(const Rational& x) {
  mpfr_t t;
  mpfr_init2(t, 53);
  mpfr_set_q(t, x.backend().data(), MPFR_RNDN);
  const double d = mpfr_get_d(t, MPFR_RNDN);
  mpfr_clear(t);
  return d;
}

std::string to_fraction_string(const Rational& x) {
  // Boost's mpq_rational is always canonical (lowest terms, positive denominator).
  return x.str();
}

std::size_t bit_size(const Rational& x) {
  auto bits = [](const Integer& z) -> std::size_t { return z == 0 ? 0 : boost::multiprecision::msb(z < 0 ? Integer(-z) : z) + 1; };
  return std::max(bits(numerator(x)), bits(denominator(x)));
}

double log2_abs(const Rational& x) {
  mpfr_t t;
  mpfr_init2(t, 64);
  mpfr_set_q(t, x.backend().data(), MPFR_RNDN);
  mpfr_abs(t, t, MPFR_RNDN);
  mpfr_log2(t, t, MPFR_RNDN);
  const double d = mpfr_get_d(t, MPFR_RNDN);
  mpfr_clear(t);
  return d;
}

Rational abs(const Rational& x) { return x < 0 ? Rational(-x) : x; }

}  // namespace splinex
