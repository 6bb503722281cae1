// Small helpers shared by the experiments of `splinex report`.
#pragma once
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"
#include "fixtures/trimming_examples.hpp"
#include "spline/factories.hpp"

namespace splinex {

/// A number for Markdown tables: `precision` significant digits.
inline std::string fmt(double v, int precision = 3) {
  std::ostringstream o;
  o << std::setprecision(precision) << v;
  return o.str();
}

/// The clamped knot vector of degree p on [0, 1] with the interior knot u0 of multiplicity m.
inline std::vector<Rational> knots_with(int p, const Rational& u0, int m) {
  return clamped_knots(p, Rational(0), Rational(1), std::vector<Rational>(m, u0));
}

}  // namespace splinex
