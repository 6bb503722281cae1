// Krawczyk's test on a box (the solver's step 2, docs/solve.md), and the arithmetic helpers the
// solver's steps share: internal to solve/ (solver.cpp and krawczyk.cpp). krawczyk is defined and
// instantiated in krawczyk.cpp, for Rational, double and MPFR.
#pragma once
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "bernstein/tensor.hpp"
#include "exact/rational.hpp"

namespace splinex::solve_detail {

template <class T>
double dbl(const T& x) {
  if constexpr (std::is_same_v<T, double>)
    return x;
  else
    return to_double(ArithTraits<T>::to_rational(x));
}

/// floor(log2 |x|) within one (x != 0), from the exact value: numbers beyond double's range too.
template <class T>
long exponent_of(const T& x) {
  const Rational q = ArithTraits<T>::to_rational(x);
  return static_cast<long>(boost::multiprecision::msb(abs(boost::multiprecision::numerator(q)))) -
         static_cast<long>(boost::multiprecision::msb(boost::multiprecision::denominator(q)));
}

/// 2^e exactly (rounded into a float arithmetic).
template <class T>
T pow2(long e) {
  using boost::multiprecision::mpz_int;
  const Rational q = e >= 0 ? Rational(mpz_int(1) << e) : Rational(1) / Rational(mpz_int(1) << -e);
  return ArithTraits<T>::from_rational(q);
}

/// The scale 2^-e that brings the largest |x_i| near 1 (1 when all are 0).
template <class T>
long scale_exponent(const std::vector<T>& xs) {
  long e = 0;
  bool any = false;
  for (const auto& x : xs)
    if (!(x == T(0))) {
      const long k = exponent_of(x);
      e = any ? std::max(e, k) : k;
      any = true;
    }
  return e;
}

template <class T>
const T& tmin(const T& a, const T& b) {
  return b < a ? b : a;
}
template <class T>
const T& tmax(const T& a, const T& b) {
  return a < b ? b : a;
}

/// Krawczyk's test on [0, 1]^n (the polynomials' own box).
template <class T>
struct KrawczykResult {
  enum Outcome { unknown, excluded, unique } outcome = unknown;
  std::vector<T> lo, hi;  // K(X) (meaningful unless unknown)
  bool contraction = false;  // ||I - Y J(X)||_inf < 1
  bool inside_closed = false;  // K(X) inside the closed box (meaningful unless unknown)
};

/// With the centre c (default: the box's centre); c - Y F(c) + (I - Y J(X)) (X - c).
template <class T>
KrawczykResult<T> krawczyk(const std::vector<Bernstein<T>>& f, std::size_t neq, bool strict, std::vector<T> c = {});

}  // namespace splinex::solve_detail
