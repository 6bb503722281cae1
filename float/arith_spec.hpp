// Naming an arithmetic on the command line ("exact", "flint", "double", "mpfr:BITS") and dispatching
// generic code to it.
#pragma once
#include <string>

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

// Calls f(ArithTag<T>{}) with T the arithmetic named by spec; MPFR runs inside a precision scope.
template <class F>
decltype(auto) with_arith(const ArithSpec& spec, F&& f) {
  switch (spec.kind) {
    case ArithSpec::Kind::exact: return f(ArithTag<Rational>{});
    case ArithSpec::Kind::flint: return f(ArithTag<FlintRational>{});
    case ArithSpec::Kind::dbl: return f(ArithTag<double>{});
    case ArithSpec::Kind::mpfr: break;
  }
  Mpfr::Precision scope(spec.bits);
  return f(ArithTag<Mpfr>{});
}

}  // namespace splinex
