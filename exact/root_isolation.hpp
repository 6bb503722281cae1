// Exact real root isolation of univariate polynomials with rational coefficients, by CGAL's
// Algebraic_kernel_d_1 (Descartes' method on Gmpz polynomials, MPFI for refinement). The exact
// end points of trimming curves built on it live in compose/trimming_end_points.hpp.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bernstein.hpp"  // bernstein_to_power: the Bernstein form to the power form isolated here
#include "spline/bspline.hpp"

namespace splinex {

/// A real root inside an isolating interval [lo, hi] (lo == hi: the root is that rational).
struct IsolatedRoot {
  Rational lo, hi;
  unsigned multiplicity = 1;
};

/// The real roots in [a, b] of the polynomial sum_i c_i t^i (power basis, exact), each isolated
/// in an interval of width <= 2^-refine_bits (or exact). The zero polynomial throws DomainError.
std::vector<IsolatedRoot> isolate_real_roots(const std::vector<Rational>& power_coeffs, const Rational& a, const Rational& b,
                                             int refine_bits = 64);

/// The real roots in [a, b] with each rational root found exactly: a rational root p/q (lowest
/// terms) of the integer polynomial has q | lead, so q <= N = |lead|; two fractions with
/// denominators <= N differ by >= 1/N^2, so once an isolating interval is narrower than 1/N^2 the
/// simplest fraction in it (smallest denominator, by continued fractions) is the root if any
/// rational is, and one exact evaluation decides. exact is empty for irrational roots.
struct ClassifiedRoot {
  IsolatedRoot root;
  std::optional<Rational> exact;
};
std::vector<ClassifiedRoot> classify_real_roots(const std::vector<Rational>& power_coeffs, const Rational& a, const Rational& b);

/// The fraction with the smallest denominator in [lo, hi] (lo <= hi).
Rational simplest_rational(const Rational& lo, const Rational& hi);


}  // namespace splinex
