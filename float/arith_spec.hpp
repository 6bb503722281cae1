// Naming an arithmetic on the command line ("exact", "flint", "double", "mpfr:BITS") and dispatching
// generic code to it.
#pragma once
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "exact/flint_rational.hpp"
#include "exact/rational.hpp"
#include "float/mpfr.hpp"

namespace splinex {

struct ArithSpec {
  enum class Kind { exact, flint, dbl, mpfr };
  Kind kind = Kind::exact;
  long bits = 0;  // mpfr only

  static ArithSpec parse(const std::string& text, const std::string& field = "arith");
  std::string name() const;
  bool is_exact() const { return kind == Kind::exact || kind == Kind::flint; }
};

template <class T>
struct ArithTag {
  using type = T;
};

/// The one arithmetic dispatcher: calls f(ArithTag<T>{}) with T the arithmetic named by spec (MPFR
/// inside a precision scope). A module instantiated for exact (GMP), double and MPFR but not FLINT
/// says so with WithFlint = false: then flint is a UsageError naming `what`, and f is never
/// instantiated for FlintRational.
template <bool WithFlint = true, class F>
decltype(auto) dispatch_arith(const ArithSpec& spec, const std::string& what, F&& f) {
  switch (spec.kind) {
    case ArithSpec::Kind::exact: return f(ArithTag<Rational>{});
    case ArithSpec::Kind::flint:
      if constexpr (WithFlint) return f(ArithTag<FlintRational>{});
      break;
    case ArithSpec::Kind::dbl: return f(ArithTag<double>{});
    case ArithSpec::Kind::mpfr: {
      Mpfr::Precision scope(spec.bits);
      return f(ArithTag<Mpfr>{});
    }
  }
  throw UsageError("arith", what + " runs in exact, double or mpfr:BITS (not flint)", "use --arith exact, double or mpfr:BITS");
}

/// Every arithmetic (the kernel and composition are instantiated for all four).
template <class F>
decltype(auto) with_arith(const ArithSpec& spec, F&& f) {
  return dispatch_arith<true>(spec, "", std::forward<F>(f));
}

/// Exact (GMP), double and MPFR: untrimming, Algorithm 2 and the hybrid patch.
template <class F>
decltype(auto) with_arith_except_flint(const ArithSpec& spec, const std::string& what, F&& f) {
  return dispatch_arith<false>(spec, what, std::forward<F>(f));
}

}  // namespace splinex
