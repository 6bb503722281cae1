// Exact rationals on FLINT's fmpq: the same numbers as Rational (GMP mpq via Boost), with a
// different representation. FLINT keeps integers below 2^62 inline in the word (no heap
// allocation), so copying and combining the small numbers typical of spline data (decimal or
// dyadic inputs, their first few products) costs a few machine operations, not a malloc. That
// is where the kernel's exact cost goes (copying untouched control points, short combinations),
// so `--arith flint` is the fast exact arithmetic; `--arith exact` stays the GMP reference, and
// tests require the two to give identical results.
#pragma once
#include <flint/fmpq.h>

#include <nlohmann/json.hpp>
#include <string>

#include "exact/rational.hpp"

namespace splinex {

class FlintRational {
 public:
  FlintRational() { fmpq_init(v_); }
  FlintRational(int i) { fmpq_init(v_); fmpq_set_si(v_, i, 1); }
  FlintRational(long i) { fmpq_init(v_); fmpq_set_si(v_, i, 1); }
  explicit FlintRational(const Rational& q) { fmpq_init(v_); fmpq_set_mpq(v_, q.backend().data()); }
  FlintRational(const FlintRational& o) { fmpq_init(v_); fmpq_set(v_, o.v_); }
  FlintRational(FlintRational&& o) noexcept { fmpq_init(v_); fmpq_swap(v_, o.v_); }
  FlintRational& operator=(const FlintRational& o) { fmpq_set(v_, o.v_); return *this; }
  FlintRational& operator=(FlintRational&& o) noexcept { fmpq_swap(v_, o.v_); return *this; }
  ~FlintRational() { fmpq_clear(v_); }

  FlintRational& operator+=(const FlintRational& o) { fmpq_add(v_, v_, o.v_); return *this; }
  FlintRational& operator-=(const FlintRational& o) { fmpq_sub(v_, v_, o.v_); return *this; }
  FlintRational& operator*=(const FlintRational& o) { fmpq_mul(v_, v_, o.v_); return *this; }
  FlintRational& operator/=(const FlintRational& o) { div_checked(v_, v_, o.v_); return *this; }
  friend FlintRational operator+(const FlintRational& a, const FlintRational& b) { FlintRational r; fmpq_add(r.v_, a.v_, b.v_); return r; }
  friend FlintRational operator-(const FlintRational& a, const FlintRational& b) { FlintRational r; fmpq_sub(r.v_, a.v_, b.v_); return r; }
  friend FlintRational operator*(const FlintRational& a, const FlintRational& b) { FlintRational r; fmpq_mul(r.v_, a.v_, b.v_); return r; }
  friend FlintRational operator/(const FlintRational& a, const FlintRational& b) { FlintRational r; div_checked(r.v_, a.v_, b.v_); return r; }
  friend FlintRational operator-(const FlintRational& a) { FlintRational r; fmpq_neg(r.v_, a.v_); return r; }
  friend bool operator==(const FlintRational& a, const FlintRational& b) { return fmpq_equal(a.v_, b.v_); }
  friend bool operator!=(const FlintRational& a, const FlintRational& b) { return !fmpq_equal(a.v_, b.v_); }
  friend bool operator<(const FlintRational& a, const FlintRational& b) { return fmpq_cmp(a.v_, b.v_) < 0; }
  friend bool operator>(const FlintRational& a, const FlintRational& b) { return fmpq_cmp(a.v_, b.v_) > 0; }
  friend bool operator<=(const FlintRational& a, const FlintRational& b) { return fmpq_cmp(a.v_, b.v_) <= 0; }
  friend bool operator>=(const FlintRational& a, const FlintRational& b) { return fmpq_cmp(a.v_, b.v_) >= 0; }

  Rational to_rational() const {
    Rational r;
    fmpq_get_mpq(r.backend().data(), v_);
    return r;
  }

 private:
  /// FLINT aborts the process on division by zero; a typed error is what the kernel promises.
  static void div_checked(fmpq_t r, const fmpq_t a, const fmpq_t b);
  fmpq_t v_;
};

static_assert(Arithmetic<FlintRational>, "FlintRational must model the arithmetic concept (spline/arith.hpp)");

template <>
struct ArithTraits<FlintRational> {
  static constexpr bool exact = true;
  static std::string name() { return "flint"; }
  static int precision_bits() { return 0; }
  static FlintRational from_rational(const Rational& x) { return FlintRational(x); }
  static Rational to_rational(const FlintRational& x) { return x.to_rational(); }
  static nlohmann::json to_json(const FlintRational& x) { return to_fraction_string(x.to_rational()); }
  static std::string to_string(const FlintRational& x) { return to_fraction_string(x.to_rational()); }
};

}  // namespace splinex
