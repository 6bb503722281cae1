// Dual numbers a + a' eps (eps^2 = 0) over any arithmetic T: forward-mode first derivatives with
// no rounding of their own, so Dual<Rational> gives exact derivatives of any generic evaluator.
//
// Satisfies the arithmetic concept (spline/arith.hpp) with two deliberate choices:
//  - a == b compares both parts. Generic code uses `x == T(0)` to skip terms that vanish or to
//    detect a 0/0 limit; a term whose value is 0 but whose derivative is not must not be skipped
//    (e.g. B_1^d(h) on h = 0), and a 0/0 is only taken for one when the derivative is 0/0 too;
//  - a < b compares values only (span search, side tests), so a point on a knot takes the knot
//    span A2.1 picks and the derivative is that span's one-sided derivative.
// Division by a dual whose value is 0 throws DomainError (the derivative does not exist there).
#pragma once
#include "base/errors.hpp"

namespace splinex {

template <class T>
struct Dual {
  T v{0}, d{0};  // value, derivative

  Dual() = default;
  Dual(int x) : v(x), d(0) {}   // NOLINT: the concept's T(int)
  Dual(long x) : v(x), d(0) {}  // NOLINT: the concept's T(long)
  explicit Dual(const T& value, const T& derivative = T(0)) : v(value), d(derivative) {}

  Dual& operator+=(const Dual& b) { return *this = *this + b; }
  Dual& operator-=(const Dual& b) { return *this = *this - b; }
  Dual& operator*=(const Dual& b) { return *this = *this * b; }
  Dual& operator/=(const Dual& b) { return *this = *this / b; }

  friend Dual operator+(const Dual& a, const Dual& b) { return Dual(T(a.v + b.v), T(a.d + b.d)); }
  friend Dual operator-(const Dual& a, const Dual& b) { return Dual(T(a.v - b.v), T(a.d - b.d)); }
  friend Dual operator-(const Dual& a) { return Dual(T(-a.v), T(-a.d)); }
  friend Dual operator*(const Dual& a, const Dual& b) { return Dual(T(a.v * b.v), T(a.d * b.v + a.v * b.d)); }
  friend Dual operator/(const Dual& a, const Dual& b) {
    if (b.v == T(0))
      throw DomainError("point", "is where a denominator of the evaluated function vanishes, so no derivative exists there",
                        "differentiate at a nearby point (corners of a hybrid patch have no derivative in general)");
    const T q = a.v / b.v;
    return Dual(q, T((a.d - q * b.d) / b.v));
  }
  friend bool operator==(const Dual& a, const Dual& b) { return a.v == b.v && a.d == b.d; }
  friend bool operator!=(const Dual& a, const Dual& b) { return !(a == b); }
  friend bool operator<(const Dual& a, const Dual& b) { return a.v < b.v; }
};

}  // namespace splinex
