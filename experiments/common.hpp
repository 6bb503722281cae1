// Small helpers shared by the experiments of `splinex report`.
#pragma once
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// A number for Markdown tables: `precision` significant digits.
inline std::string fmt(double v, int precision = 3) {
  std::ostringstream o;
  o << std::setprecision(precision) << v;
  return o.str();
}

/// The clamped knot vector of degree p on [0, 1] with the interior knot u0 of multiplicity m.
inline std::vector<Rational> knots_with(int p, const Rational& u0, int m) {
  std::vector<Rational> U(p + 1, Rational(0));
  U.insert(U.end(), m, u0);
  U.insert(U.end(), p + 1, Rational(1));
  return U;
}

/// The inner surface of the surface tolerance studies: degrees (1, 2) on [0, 1]^2 with
/// s_u = 1/5 + 3/5 r + 1/5 t(1-t) and s_v = 1/10 + 4/5 t, so the trimming curve s_u = 1/2 is the
/// parabola r*(t) = (3/10 - 1/5 t(1-t)) / (3/5) = 1/2 - t(1-t)/3, rational at rational t.
inline BSpline<Rational> parabola_trimming_inner() {
  BSpline<Rational> S;
  S.degrees = {1, 2};
  S.q = 2;
  S.knots = {{0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}};
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 1; ++i) {
      S.points.push_back(Rational(1, 5) + Rational(3, 5) * i + (j == 1 ? Rational(1, 10) : Rational(0)));
      S.points.push_back(Rational(1, 10) + Rational(2, 5) * j);
    }
  validate(S);
  return S;
}

}  // namespace splinex
