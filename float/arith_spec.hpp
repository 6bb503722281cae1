// The arithmetics, one table (issue 48 item 7): their names on the command line ("exact", "gmp",
// "flint", "double", "mpfr:BITS"), their types, which arithmetics each package runs in, and the one
// dispatcher from a name to generic code.
//
// "exact" is the best exact engine a package has: the fraction-free kernel (ExactFF,
// exact/exact_ff.hpp) where its operations are written, GMP mpq (Rational) elsewhere, with the
// same values. "gmp" and "flint" are the naive exact engines (one rational per coefficient), kept
// selectable so that benchmarks and reports can show what a naive exact kernel costs.
#pragma once
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

#include "base/errors.hpp"
#include "exact/exact_ff.hpp"
#include "exact/flint_rational.hpp"
#include "exact/rational.hpp"
#include "float/mpfr.hpp"

// One row per arithmetic: X(kind, name, type). ArithSpec::Kind, ArithSpec::name(), the parse of the
// names, the dispatch switch of with_arith and the lists of names in messages are generated from
// these rows. "mpfr:BITS" is a family: parse reads mpfr:24 ... mpfr:1000000, name() writes the bits,
// and with_arith runs the call inside Mpfr::Precision(bits).
// A new arithmetic is its type's file (ArithTraits, in exact/ or float/), one row here, and an entry
// in the lists below of the packages that run in it, with their instantiation files.
#define SPLINEX_ARITHMETICS(X)       \
  X(exact, "exact", ExactFF)         \
  X(gmp, "gmp", Rational)            \
  X(flint, "flint", FlintRational)   \
  X(dbl, "double", double)           \
  X(mpfr, "mpfr:BITS", Mpfr)

// The packages' arithmetics, one line each. A package's commands dispatch to exactly these (with
// with_arith<List>), and its instantiation files instantiate exactly these.
// Where a package's instances live in one file, that file reads the package's X-list here:
#define SPLINEX_HYBRID_ARITHMETICS(X) X(Rational) X(double) X(Mpfr)  // hybrid/instances.cpp
#define SPLINEX_VREP_ARITHMETICS(X) X(Rational) X(double) X(Mpfr)    // vrep/instances.cpp (VREP, TRIMMED)

namespace splinex {

struct ArithSpec {
#define SPLINEX_ARITH_KIND(kind, name, type) kind,
  enum class Kind { SPLINEX_ARITHMETICS(SPLINEX_ARITH_KIND) };
#undef SPLINEX_ARITH_KIND
  Kind kind = Kind::exact;
  long bits = 0;  // mpfr only

  static ArithSpec parse(const std::string& text, const std::string& field = "arith");
  std::string name() const;
  bool is_exact() const;  // an exact arithmetic (ArithTraits<T>::exact)
};

/// The table's rows as values: each arithmetic's kind and its name (mpfr's is "mpfr:BITS").
struct ArithRow {
  ArithSpec::Kind kind;
  const char* name;
};
#define SPLINEX_ARITH_ROW(kind, name, type) ArithRow{ArithSpec::Kind::kind, name},
inline constexpr ArithRow arith_rows[] = {SPLINEX_ARITHMETICS(SPLINEX_ARITH_ROW)};
#undef SPLINEX_ARITH_ROW

/// The row of a type: ArithOf<double>::kind, ArithOf<double>::name.
template <class T>
struct ArithOf;
#define SPLINEX_ARITH_OF(k, n, T)                                 \
  template <>                                                    \
  struct ArithOf<T> {                                            \
    static constexpr ArithSpec::Kind kind = ArithSpec::Kind::k;  \
    static constexpr const char* name = n;                       \
  };
SPLINEX_ARITHMETICS(SPLINEX_ARITH_OF)
#undef SPLINEX_ARITH_OF

inline bool ArithSpec::is_exact() const {
#define SPLINEX_ARITH_EXACT(k, n, T) (kind == Kind::k && ArithTraits<T>::exact) ||
  return SPLINEX_ARITHMETICS(SPLINEX_ARITH_EXACT) false;
#undef SPLINEX_ARITH_EXACT
}

template <class T>
struct ArithTag {
  using type = T;
};

/// The type a row's name runs in a package that lacks the row's own type: "exact" runs Rational
/// where the fraction-free kernel is not written (void: no fallback).
template <class T>
struct ArithFallback {
  using type = void;
};
template <>
struct ArithFallback<ExactFF> {
  using type = Rational;
};

/// A list of arithmetics (a package's): has<T>, and their names for messages ("exact, double or
/// mpfr:BITS"). add<U> appends, so a list is derived from a package's X-list above.
template <class... T>
struct Arithmetics {
  template <class U>
  static constexpr bool has = (std::is_same_v<T, U> || ...);
  template <class U>
  using add = Arithmetics<T..., U>;
  /// Whether the name of the row of type R is accepted (its type, or its fallback, is listed).
  template <class R>
  static constexpr bool accepts = has<R> || has<typename ArithFallback<R>::type>;
  /// The accepted names in the table's order: "exact, gmp, double or mpfr:BITS".
  static std::string names() {
#define SPLINEX_ARITH_NAME(k, n, R) \
  if (accepts<R>) all.push_back(n);
    std::vector<const char*> all;
    SPLINEX_ARITHMETICS(SPLINEX_ARITH_NAME)
#undef SPLINEX_ARITH_NAME
    std::string out;
    for (std::size_t k = 0; k < all.size(); ++k)
      out += (k == 0 ? "" : k + 1 == all.size() ? " or " : ", ") + std::string(all[k]);
    return out;
  }
};
#define SPLINEX_ARITH_ADD(T) ::add<T>
/// The kernel (spline/), in every arithmetic: eval, the operations, crosscheck, bench_document. Split
/// one TU per arithmetic (build time; exact/ may not include float/): exact/kernel_rational.cpp,
/// exact/kernel_flint.cpp, float/kernel_double.cpp, float/kernel_mpfr.cpp.
/// "exact" is the fraction-free kernel here (ExactFF; the call sites convert at the boundary and fall
/// back to Rational for the operations it lacks: crosscheck/operations_ff.hpp).
using KernelArithmetics = Arithmetics<ExactFF, Rational, FlintRational, double, Mpfr>;
/// Composition (compose/: compose --method symbolic, interpolation, trimmed), in every arithmetic.
/// Split by build time: compose/instances_exact.cpp (Rational, FlintRational) and
/// compose/instances_float.cpp (double, Mpfr).
using ComposeArithmetics = Arithmetics<Rational, FlintRational, double, Mpfr>;
/// Tensor composition, Algorithm 2 (compose --method tensor): untrim/algorithm2.cpp.
using TensorArithmetics = Arithmetics<Rational, double, Mpfr>;
/// Untrimming (splinex untrim): untrim/run.hpp, untrim/loops.cpp.
using UntrimArithmetics = Arithmetics<Rational, double, Mpfr>;
/// The hybrid patch (hybrid eval).
using HybridArithmetics = Arithmetics<> SPLINEX_HYBRID_ARITHMETICS(SPLINEX_ARITH_ADD);
/// The V-rep (vrep construct, certify, primitive).
using VrepArithmetics = Arithmetics<> SPLINEX_VREP_ARITHMETICS(SPLINEX_ARITH_ADD);
#undef SPLINEX_ARITH_ADD

namespace detail {
template <class T, class F>
decltype(auto) call_in(const ArithSpec& spec, F& f) {
  if constexpr (std::is_same_v<T, Mpfr>) {
    Mpfr::Precision scope(spec.bits);
    return f(ArithTag<T>{});
  } else {
    return f(ArithTag<T>{});
  }
}
}  // namespace detail

/// The one arithmetic dispatcher: calls f(ArithTag<T>{}) with T the arithmetic named by spec, for
/// T in List (MPFR inside a precision scope); f is never instantiated for a T outside List. A spec
/// outside List is a UsageError naming `what` and the list ("untrim runs in exact, double or
/// mpfr:BITS (not flint)").
template <class List, class F>
decltype(auto) with_arith(const ArithSpec& spec, const std::string& what, F&& f) {
  switch (spec.kind) {
#define SPLINEX_ARITH_CASE(k, n, T)                                                          \
  case ArithSpec::Kind::k:                                                                   \
    if constexpr (List::template has<T>) return detail::call_in<T>(spec, f);                 \
    else if constexpr (List::template has<typename ArithFallback<T>::type>)                  \
      return detail::call_in<typename ArithFallback<T>::type>(spec, f);                      \
    break;
    SPLINEX_ARITHMETICS(SPLINEX_ARITH_CASE)
#undef SPLINEX_ARITH_CASE
  }
  throw UsageError("arith", what + " runs in " + List::names() + " (not " + spec.name() + ")",
                   "use --arith " + List::names());
}

}  // namespace splinex
