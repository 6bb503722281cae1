// Exact rationals: GMP's mpq through Boost.Multiprecision, and the exact conversions.
#pragma once
#include <boost/multiprecision/gmp.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "spline/arith.hpp"

namespace splinex {

using Rational = boost::multiprecision::mpq_rational;
using Integer = boost::multiprecision::mpz_int;

/// Exact value of number text: an integer ("-3"), a fraction ("22/7") or a decimal with optional
/// exponent ("0.784" = 98/125, "1e-3", "-2.5E+4"). Anything else (NaN, Inf, hex, empty, a zero
/// denominator, an exponent beyond +-100000) throws ParseError naming `field`.
Rational parse_number(std::string_view text, const std::string& field);

/// Every finite double is a dyadic rational; this is it. NaN/Inf throw ParseError naming `field`.
Rational exact_from_double(double x, const std::string& field = "value");

/// Correctly rounded (to nearest, ties to even) double of an exact rational.
double to_double(const Rational& x);

/// "p/q" in lowest terms, or "p" when q = 1.
std::string to_fraction_string(const Rational& x);

/// The size of x in bits: the larger of its numerator's and denominator's (0 for 0). Exact
/// commands check their inputs against a limit on it before the work.
std::size_t bit_size(const Rational& x);

/// log2|x| (x != 0), to about 50 bits: for reporting error magnitudes and bits lost.
double log2_abs(const Rational& x);

Rational abs(const Rational& x);

static_assert(Arithmetic<Rational>, "Rational must model the arithmetic concept (spline/arith.hpp)");

template <>
struct ArithTraits<Rational> {
  static constexpr bool exact = true;
  static std::string name() { return "exact"; }
  static int precision_bits() { return 0; }
  static Rational from_rational(const Rational& x) { return x; }
  static Rational to_rational(const Rational& x) { return x; }
  static nlohmann::json to_json(const Rational& x) { return to_fraction_string(x); }
  static std::string to_string(const Rational& x) { return to_fraction_string(x); }
  /// The Bernstein product's loop on integers (spline/arith.hpp; exact/rational_bernstein.cpp).
  static void tensor_convolve(const std::vector<Rational>& f, const std::vector<Rational>& fb, const std::vector<Rational>& g,
                              const std::vector<Rational>& gb, const std::vector<std::size_t>& fo,
                              const std::vector<std::size_t>& go, const std::vector<Rational>& hb, std::vector<Rational>& h);
  /// Sums of weighted vectors on integers (spline/arith.hpp; exact/rational_bernstein.cpp).
  static void weighted_sums(const std::vector<const std::vector<Rational>*>& v, const std::vector<Rational>& a,
                            const std::vector<Rational>& b, std::size_t cols, std::vector<Rational>& out);
  /// Composition's outer sum with its last Bernstein product fused, on integers (spline/arith.hpp).
  static void product_sums(const std::vector<const std::vector<Rational>*>& f, const std::vector<Rational>& fb,
                           const std::vector<const std::vector<Rational>*>& g, const std::vector<Rational>& gb,
                           const std::vector<std::size_t>& fo, const std::vector<std::size_t>& go,
                           const std::vector<Rational>& hb, const std::vector<Rational>& a, const std::vector<Rational>& b,
                           std::size_t cols, std::vector<Rational>& out);
  /// de Casteljau at t on every line of one direction, on integers (spline/arith.hpp).
  static void de_casteljau(const std::vector<Rational>& c, std::size_t stride, int p, const Rational& t,
                           std::vector<Rational>* left, std::vector<Rational>* right);
  /// A tensor Bernstein polynomial's value on integers, one reduction (spline/arith.hpp).
  static Rational tensor_value(const std::vector<Rational>& c, const std::vector<int>& deg, const std::vector<Rational>& x);
  /// p times the differences along every line of one direction, on integers (spline/arith.hpp).
  static void differences(const std::vector<Rational>& c, std::size_t stride, int p, std::vector<Rational>& out);
  /// The 2^k halves in every direction on integers, one reduction per coefficient (spline/arith.hpp).
  static void halves(const std::vector<Rational>& c, const std::vector<int>& deg, std::vector<std::vector<Rational>>& out);
};

}  // namespace splinex
