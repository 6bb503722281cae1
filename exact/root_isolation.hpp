// Exact real root isolation of univariate polynomials with rational coefficients, by CGAL's
// Algebraic_kernel_d_1 (Descartes' method on Gmpz polynomials, MPFI for refinement), and the
// exact end points of trimming curves on the edges of inner pieces (papers/000, Step 2).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"
#include "spline/trimmed_compose.hpp"

namespace splinex {

// A real root inside an isolating interval [lo, hi] (lo == hi: the root is that rational).
struct IsolatedRoot {
  Rational lo, hi;
  unsigned multiplicity = 1;
};

// The real roots in [a, b] of the polynomial sum_i c_i t^i (power basis, exact), each isolated
// in an interval of width <= 2^-refine_bits (or exact). The zero polynomial throws DomainError.
std::vector<IsolatedRoot> isolate_real_roots(const std::vector<Rational>& power_coeffs, const Rational& a, const Rational& b,
                                             int refine_bits = 64);

// The real roots in [a, b] with each rational root found exactly: a rational root p/q (lowest
// terms) of the integer polynomial has q | lead, so q <= N = |lead|; two fractions with
// denominators <= N differ by >= 1/N^2, so once an isolating interval is narrower than 1/N^2 the
// simplest fraction in it (smallest denominator, by continued fractions) is the root if any
// rational is, and one exact evaluation decides. exact is empty for irrational roots.
struct ClassifiedRoot {
  IsolatedRoot root;
  std::optional<Rational> exact;
};
std::vector<ClassifiedRoot> classify_real_roots(const std::vector<Rational>& power_coeffs, const Rational& a, const Rational& b);

// The fraction with the smallest denominator in [lo, hi] (lo <= hi).
Rational simplest_rational(const Rational& lo, const Rational& hi);

// Power-basis coefficients, in the local parameter t in [0, 1], of a univariate Bernstein
// polynomial with the given coefficients.
std::vector<Rational> bernstein_to_power(const std::vector<Rational>& bernstein);

// Where trimming curves of a patch meet the edges of its inner piece's box: for every region
// condition (s_c = bound) and every edge (one parameter free, the others at a box end), the
// isolated parameters of the crossings. For surfaces (k = 2) these are the end points of the
// trimming curves; for curves (k = 1) the trimming points themselves.
struct EdgeCrossing {
  int condition = 0;          // index into the patch's region
  bool at_upper_bound = false;  // s_c = hi (else s_c = lo)
  int free_dir = 0;           // the edge's free parameter
  std::vector<Rational> fixed;  // the other parameters' values (k entries, free_dir's unused)
  IsolatedRoot root;          // in the free parameter
};
std::vector<EdgeCrossing> trimming_edge_crossings(const TrimmedComposition<Rational>& C, std::size_t patch,
                                                  int refine_bits = 64);

}  // namespace splinex
