// The arithmetic concept. Generic code in spline/ is written against a scalar type T with
//   T(int), T(long), copy/move, + - * / (and the compound forms), unary -, == and <,
// and nothing else: no literal double, no std::abs, no sqrt. A constant is written T(1) / T(3).
// Comparisons appear only where the algorithm needs them (span search, multiplicities, the
// alpha == 0 test of A5.4); they are exact in exact arithmetic.
//
// Each concrete arithmetic specializes ArithTraits<T> (exact/: Rational; float/: double, Mpfr):
//   static constexpr bool exact;            // no rounding anywhere
//   static std::string name();              // "exact", "double", "mpfr:113"
//   static int precision_bits();            // significand bits (0 for exact)
//   static T from_rational(const Rational&);     // correctly rounded (exact for Rational)
//   static Rational to_rational(const T&);       // exact: every binary float is a dyadic rational
//   static nlohmann::json to_json(const T&);     // fractions / round-trip numbers / all digits
//   static std::string to_string(const T&);      // the same text, for messages
// Conversions are therefore explicit and named, and a float result can always be measured
// exactly against the exact one (crosscheck/).
// An exact arithmetic may also offer, optionally, seven inner loops of bernstein/tensor.hpp done
// fraction-free (bern_product, composition's weighted_sums and product_sums, bern_split,
// bern_halves, bern_value and bern_derivative use them when present; the values are the same,
// only the gcds per term are gone):
//   static void tensor_convolve(const std::vector<T>& f, const std::vector<T>& fb,
//                               const std::vector<T>& g, const std::vector<T>& gb,
//                               const std::vector<std::size_t>& fo, const std::vector<std::size_t>& go,
//                               const std::vector<T>& hb, std::vector<T>& h);
//     // h[i] = (sum over fo[a] + go[b] = i of f[a] fb[a] g[b] gb[b]) / hb[i]; fb, gb, hb are
//     // positive integers, h has its final size.
//   static void weighted_sums(const std::vector<const std::vector<T>*>& v, const std::vector<T>& a,
//                             const std::vector<T>& b, std::size_t cols, std::vector<T>& out);
//     // out[i*cols + c] += sum over t of v[t][i] a[t] b[t*cols + c] (composition's sum over the
//     // outer control points); out has its final size.
//   static void product_sums(const std::vector<const std::vector<T>*>& f, const std::vector<T>& fb,
//                            const std::vector<const std::vector<T>*>& g, const std::vector<T>& gb,
//                            const std::vector<std::size_t>& fo, const std::vector<std::size_t>& go,
//                            const std::vector<T>& hb, const std::vector<T>& a, const std::vector<T>& b,
//                            std::size_t cols, std::vector<T>& out);
//     // weighted_sums of the products h_t = f[t] g[t] (each as tensor_convolve makes it, every f[t]
//     // and every g[t] of one size): out[i*cols + c] += sum over t of h_t[i] a[t] b[t*cols + c],
//     // without forming the h_t as values of T.
//   static void de_casteljau(const std::vector<T>& c, std::size_t stride, int p, const T& t,
//                            std::vector<T>* left, std::vector<T>* right);
//     // every line of one direction (values c[base + i*stride], i = 0..p, base over the blocks of
//     // stride*(p+1)) split at t: left[base + r*stride] = w^r_0, right[base + (p-r)*stride] =
//     // w^r_{p-r} of the de Casteljau triangle (either pointer may be null; sizes as c).
//   static T tensor_value(const std::vector<T>& c, const std::vector<int>& deg, const std::vector<T>& x);
//     // the value at x of the tensor Bernstein polynomial of degrees deg (direction 0 fastest).
//   static void differences(const std::vector<T>& c, std::size_t stride, int p, std::vector<T>& out);
//     // every line of one direction (as de_casteljau's, p >= 1) differenced and scaled by p:
//     // out[ob + j] = p (c[b + j + stride] - c[b + j]) for j < stride*p, b over the blocks of
//     // stride*(p+1) of c and ob over those of stride*p of out (out has its final size).
//   static void halves(const std::vector<T>& c, const std::vector<int>& deg, std::vector<std::vector<T>>& out);
//     // the 2^k parts (k = deg.size()) of the tensor polynomial halved at 1/2 in every direction,
//     // each on [0, 1]^k: out[K], K = sum over l of side_l 2^(k-1-l) (side 0 the lower half),
//     // every out[K] of c's size.
//
// The concept is checked by the compiler twice: `Arithmetic` below (a C++20 concept) constrains
// BSpline<T>, so a scalar without an operation of the list is rejected where a spline of it is
// named; and tests/spline/test_arith_concept.cpp instantiates the kernel, composition, the hybrid
// patch and the untrimming sweep for a scalar that has these operations and no others (>, <=, >=,
// != are deleted), so generic code that steps outside the list fails to build.
#pragma once
#include <concepts>

namespace splinex {

/// The operations generic code may use on a scalar (see above). A concept constrains what a type
/// offers, not what generic code uses; the Strict scalar of tests/spline/test_arith_concept.cpp
/// checks the other direction.
template <class T>
concept Arithmetic = std::copy_constructible<T> && std::default_initializable<T> && std::constructible_from<T, int> &&
                     std::constructible_from<T, long> && requires(T a, const T& b) {
                       { a + b } -> std::convertible_to<T>;
                       { a - b } -> std::convertible_to<T>;
                       { a * b } -> std::convertible_to<T>;
                       { a / b } -> std::convertible_to<T>;
                       { -b } -> std::convertible_to<T>;
                       a += b;
                       a -= b;
                       a *= b;
                       a /= b;
                       a = b;
                       { b == b } -> std::convertible_to<bool>;
                       { b < b } -> std::convertible_to<bool>;
                     };

template <class T>
struct ArithTraits;  // specialized per arithmetic; see above

/// Whether scratch values of T may be kept between calls on one thread (evaluation's workspace).
/// False for arithmetics whose values carry state that an assignment does not replace (MPFR's
/// precision: a value made at 128 bits stays at 128 bits when a later call runs at 256).
template <class T>
inline constexpr bool reusable_scratch = true;

/// A key for values of T cached across calls on one thread: 0 where a value means the same at
/// every call; MPFR (float/mpfr.hpp) gives the current precision, so a cache made at 53 bits is
/// not handed to a call running at 256.
template <class T>
inline int cache_precision_key() {
  return 0;
}

/// 0 and 1 made once: assigning them (`x = zero_value<T>()`) reuses x's storage, where `x = T(0)`
/// makes a temporary and, for GMP through Boost, hands x the temporary's fresh allocation. Both
/// are exact at any precision, so the MPFR precision rule above does not concern them.
template <class T>
const T& zero_value() {
  static const T z(0);
  return z;
}
template <class T>
const T& one_value() {
  static const T o(1);
  return o;
}

}  // namespace splinex
