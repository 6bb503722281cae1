// Rounding exact input into a floating arithmetic, checked: the rounded spline must have the
// structure of the exact one, or the float run would answer a different question (a knot
// 1e-400 next to 0 becomes 0 in double and raises a multiplicity past degree+1; a weight 1e-400
// becomes 0; 1e400 becomes infinite). Every such change is a RangeError naming the field.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>

#include "exact/rational.hpp"
#include "float/mpfr.hpp"
#include "spline/bspline.hpp"

namespace splinex {

inline bool is_finite_value(double x) { return std::isfinite(x); }
inline bool is_finite_value(const Mpfr& x) { return mpfr_number_p(x.get()) != 0; }
template <class T>
bool is_finite_value(const T&) { return true; }  // exact arithmetics

/// Whether every knot, point and weight of S is finite.
template <class T>
bool is_finite_spline(const BSpline<T>& S) {
  const auto finite = [](const T& x) { return is_finite_value(x); };
  for (const auto& K : S.knots)
    if (!std::all_of(K.begin(), K.end(), finite)) return false;
  return std::all_of(S.points.begin(), S.points.end(), finite) && std::all_of(S.weights.begin(), S.weights.end(), finite);
}

/// x rounded to F (correctly); RangeError if F cannot hold it (infinite), or if a non-zero x
/// becomes 0 where `nonzero_needed` (weights, denominators).
template <class F>
F round_checked(const Rational& x, const std::string& field, bool nonzero_needed = false) {
  F y = ArithTraits<F>::from_rational(x);
  if (!is_finite_value(y))
    throw RangeError(field, "is beyond the range of " + ArithTraits<F>::name() + " (rounds to infinity)",
                     "rescale the input, or use --arith exact or mpfr:BITS");
  if (nonzero_needed && y == F(0) && x != 0)
    throw RangeError(field, "is not zero but rounds to 0 in " + ArithTraits<F>::name(),
                     "rescale the weights, or use --arith exact or mpfr:BITS");
  return y;
}

/// The spline rounded to F, with every structural property of S kept: finite values, positive
/// weights, and the same order of every pair of neighbouring knots (distinct knots stay distinct,
/// so multiplicities and spans are those of S). `what` prefixes the field names ("outer", ...).
template <class F>
BSpline<F> round_spline(const BSpline<Rational>& S, const std::string& what = "") {
  const std::string pre = what.empty() ? "" : what + ".";
  BSpline<F> R;
  R.degrees = S.degrees;
  R.q = S.q;
  for (int d = 0; d < S.dim(); ++d) {
    const std::string f = pre + "knots[" + std::to_string(d) + "]";
    std::vector<F> K;
    K.reserve(S.knots[d].size());
    for (std::size_t i = 0; i < S.knots[d].size(); ++i) {
      K.push_back(round_checked<F>(S.knots[d][i], f + "[" + std::to_string(i) + "]"));
      if (i > 0 && S.knots[d][i - 1] < S.knots[d][i] && !(K[i - 1] < K[i]))
        throw RangeError(f + "[" + std::to_string(i) + "]",
                         "differs from the knot before it but rounds to the same value in " + ArithTraits<F>::name() +
                             " (the knot structure would change)",
                         "use --arith exact, or mpfr:BITS with more bits, or space the knots further apart");
    }
    R.knots.push_back(std::move(K));
  }
  R.points.reserve(S.points.size());
  for (std::size_t i = 0; i < S.points.size(); ++i)
    R.points.push_back(round_checked<F>(S.points[i], pre + "points[" + std::to_string(i / S.q) + "][" +
                                                          std::to_string(i % S.q) + "]"));
  R.weights.reserve(S.weights.size());
  for (std::size_t i = 0; i < S.weights.size(); ++i)
    R.weights.push_back(round_checked<F>(S.weights[i], pre + "weights[" + std::to_string(i) + "]", true));
  return R;
}

/// A parameter list rounded to F (each finite).
template <class F>
std::vector<F> round_values(const std::vector<Rational>& xs, const std::string& field) {
  std::vector<F> out;
  out.reserve(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) out.push_back(round_checked<F>(xs[i], field + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace splinex
