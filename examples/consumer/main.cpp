// Uses an installed splinex: a quadratic Bezier curve composed with an affine reparametrization,
// exactly, then a knot inserted; prints the composed curve's value at 1/3 (exact fractions).
#include <iostream>

#include "compose/compose.hpp"
#include "exact/rational.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"
#include "spline/insert.hpp"

int main() {
  using splinex::BSpline;
  using splinex::Rational;
  // T(u) = Bezier curve in the plane on [0, 1] with control points (0,0), (1,2), (2,0).
  const auto T = splinex::bezier<Rational>({2}, 2, {0, 0, 1, 2, 2, 0});
  // S(t) = t / 2 on [0, 1]: a line inside T's domain.
  const auto S = splinex::bezier<Rational>({1}, 1, {0, Rational(1, 2)});
  const auto C = splinex::insert_knot(splinex::compose(T, S), 0, Rational(1, 2), 1);
  const auto p = splinex::evaluate(C, {Rational(1, 3)});
  // T(1/6) = (1/3, 5/9)
  std::cout << p[0] << " " << p[1] << "\n";
  return p[0] == Rational(1, 3) && p[1] == Rational(5, 9) ? 0 : 1;
}
