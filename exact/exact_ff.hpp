// The arithmetic "exact": the fraction-free kernel (exact/ffnet.hpp) where an operation has been
// written for it, GMP mpq (Rational) everywhere else. ExactFF is a tag for the arithmetic table
// (float/arith_spec.hpp), not a scalar: the kernel's commands run its operations on an ff::FFNet
// converted from the exact input at the boundary, and every package without it falls back to
// Rational (ArithFallback), with identical values.
#pragma once
#include <string>

#include "spline/arith.hpp"

namespace splinex {

struct ExactFF {};

template <>
struct ArithTraits<ExactFF> {
  static constexpr bool exact = true;
  static std::string name() { return "exact"; }
  static int precision_bits() { return 0; }
};

}  // namespace splinex
