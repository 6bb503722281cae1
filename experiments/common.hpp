// Small helpers shared by the experiments of `splinex report`.
#pragma once
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "exact/rational.hpp"

namespace splinex {

// A number for Markdown tables: `precision` significant digits.
inline std::string fmt(double v, int precision = 3) {
  std::ostringstream o;
  o << std::setprecision(precision) << v;
  return o.str();
}

// The clamped knot vector of degree p on [0, 1] with the interior knot u0 of multiplicity m.
inline std::vector<Rational> knots_with(int p, const Rational& u0, int m) {
  std::vector<Rational> U(p + 1, Rational(0));
  U.insert(U.end(), m, u0);
  U.insert(U.end(), p + 1, Rational(1));
  return U;
}

}  // namespace splinex
