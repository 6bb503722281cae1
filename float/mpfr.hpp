// MPFR at any binary precision (>= 24 bits here), as a value type for the generic kernel.
//
// Why not boost::multiprecision::mpfr_float: in Boost 1.74 (Debian 12) its variable precision is
// set in decimal digits and converted to bits by digits10_2_2, so "113 bits" cannot be asked for
// exactly and temporaries take a rounded-up precision. Measuring bits lost needs the exact
// precision, so this thin wrapper calls MPFR directly: every value is created at the thread's
// current precision (Mpfr::Precision scope), every operation is correctly rounded to nearest.
#pragma once
#include <mpfr.h>

#include <nlohmann/json.hpp>
#include <cmath>
#include <string>
#include <utility>

#include "exact/rational.hpp"

namespace splinex {

class Mpfr {
 public:
  static mpfr_prec_t& current_bits() {
    thread_local mpfr_prec_t bits = 53;
    return bits;
  }
  /// RAII: values created in this scope have `bits` bits.
  class Precision {
   public:
    explicit Precision(long bits);
    ~Precision() { current_bits() = old_; }
    Precision(const Precision&) = delete;
    Precision& operator=(const Precision&) = delete;

   private:
    mpfr_prec_t old_;
  };

  Mpfr() { mpfr_init2(v_, current_bits()); mpfr_set_zero(v_, 1); }
  Mpfr(int i) { mpfr_init2(v_, current_bits()); mpfr_set_si(v_, i, MPFR_RNDN); }
  Mpfr(long i) { mpfr_init2(v_, current_bits()); mpfr_set_si(v_, i, MPFR_RNDN); }
  explicit Mpfr(const Rational& q) { mpfr_init2(v_, current_bits()); mpfr_set_q(v_, q.backend().data(), MPFR_RNDN); }
  Mpfr(const Mpfr& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)); mpfr_set(v_, o.v_, MPFR_RNDN); }
  // Not noexcept: the moved-from value needs limbs of its own (mpfr_init2 allocates), and that
  // allocation may throw std::bad_alloc (exact/memory.hpp); a noexcept frame would terminate.
  Mpfr(Mpfr&& o) { mpfr_init2(v_, mpfr_get_prec(o.v_)); mpfr_swap(v_, o.v_); }
  Mpfr& operator=(const Mpfr& o) {
    if (this != &o) mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  Mpfr& operator=(Mpfr&& o) noexcept {
    mpfr_swap(v_, o.v_);
    return *this;
  }
  ~Mpfr() { mpfr_clear(v_); }

  Mpfr& operator+=(const Mpfr& o) { mpfr_add(v_, v_, o.v_, MPFR_RNDN); return *this; }
  Mpfr& operator-=(const Mpfr& o) { mpfr_sub(v_, v_, o.v_, MPFR_RNDN); return *this; }
  Mpfr& operator*=(const Mpfr& o) { mpfr_mul(v_, v_, o.v_, MPFR_RNDN); return *this; }
  Mpfr& operator/=(const Mpfr& o) { mpfr_div(v_, v_, o.v_, MPFR_RNDN); return *this; }
  friend Mpfr operator+(const Mpfr& a, const Mpfr& b) { Mpfr r; mpfr_add(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Mpfr operator-(const Mpfr& a, const Mpfr& b) { Mpfr r; mpfr_sub(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Mpfr operator*(const Mpfr& a, const Mpfr& b) { Mpfr r; mpfr_mul(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Mpfr operator/(const Mpfr& a, const Mpfr& b) { Mpfr r; mpfr_div(r.v_, a.v_, b.v_, MPFR_RNDN); return r; }
  friend Mpfr operator-(const Mpfr& a) { Mpfr r; mpfr_neg(r.v_, a.v_, MPFR_RNDN); return r; }
  friend bool operator==(const Mpfr& a, const Mpfr& b) { return mpfr_equal_p(a.v_, b.v_); }
  friend bool operator!=(const Mpfr& a, const Mpfr& b) { return !mpfr_equal_p(a.v_, b.v_); }
  friend bool operator<(const Mpfr& a, const Mpfr& b) { return mpfr_less_p(a.v_, b.v_); }
  friend bool operator>(const Mpfr& a, const Mpfr& b) { return mpfr_greater_p(a.v_, b.v_); }
  friend bool operator<=(const Mpfr& a, const Mpfr& b) { return mpfr_lessequal_p(a.v_, b.v_); }
  friend bool operator>=(const Mpfr& a, const Mpfr& b) { return mpfr_greaterequal_p(a.v_, b.v_); }

  mpfr_srcptr get() const { return v_; }
  mpfr_ptr get() { return v_; }
  long bits() const { return mpfr_get_prec(v_); }

 private:
  mpfr_t v_;
};

[[noreturn]] void throw_not_finite(const std::string& arith);

/// Exact value of a finite MPFR number (mantissa * 2^exponent).
Rational to_rational(const Mpfr& x);
/// All the significant digits needed to read the value back at its precision ("d.ddde-X").
std::string to_decimal_string(const Mpfr& x);

static_assert(Arithmetic<Mpfr>, "Mpfr must model the arithmetic concept (spline/arith.hpp)");
/// An Mpfr keeps its precision on assignment: no scratch values across calls (spline/arith.hpp).
template <>
inline constexpr bool reusable_scratch<Mpfr> = false;
template <>
inline int cache_precision_key<Mpfr>() {
  return static_cast<int>(Mpfr::current_bits());
}

template <>
struct ArithTraits<Mpfr> {
  static constexpr bool exact = false;
  static std::string name() { return "mpfr:" + std::to_string(Mpfr::current_bits()); }
  static int precision_bits() { return static_cast<int>(Mpfr::current_bits()); }
  static Mpfr from_rational(const Rational& x) { return Mpfr(x); }
  static Rational to_rational(const Mpfr& x) { return splinex::to_rational(x); }
  static nlohmann::json to_json(const Mpfr& x) { return to_decimal_string(x); }
  static std::string to_string(const Mpfr& x) { return to_decimal_string(x); }
};

template <>
struct ArithTraits<double> {
  static constexpr bool exact = false;
  static std::string name() { return "double"; }
  static int precision_bits() { return 53; }
  static double from_rational(const Rational& x) { return to_double(x); }
  static Rational to_rational(double x) { return exact_from_double(x); }
  /// nlohmann prints the shortest round-trip text; it would print inf and NaN as null.
  static nlohmann::json to_json(double x) {
    if (!std::isfinite(x)) throw_not_finite("double");
    return x;
  }
  static std::string to_string(double x) { return nlohmann::json(x).dump(); }
};

}  // namespace splinex
