// Implicit regions for the trimmed-cell tests: balls, half-spaces (exact rational coefficients).
#pragma once
#include <array>

#include "exact/rational.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex::test {

/// r^2 - |x - c|^2 >= 0.
inline Region<Rational> ball(std::array<Rational, 3> c, Rational r) { return ball_region(c, r); }

/// x_axis - at >= 0.
inline Region<Rational> above(int axis, Rational at) {
  Poly3<Rational> g;
  std::array<int, 3> e{};
  e[axis] = 1;
  g.terms[e] = Rational(1);
  g.terms[{0, 0, 0}] = -at;
  return region_leaf(g, "plane");
}

/// A solid cylinder along `axis`: r^2 - (x_a - c_a)^2 - (x_b - c_b)^2 >= 0 for the other axes.
inline Region<Rational> cylinder(int axis, std::array<Rational, 3> c, Rational r) {
  Poly3<Rational> g;
  Rational k = r * r;
  for (int d = 0; d < 3; ++d) {
    if (d == axis) continue;
    std::array<int, 3> e{}, e2{};
    e[d] = 1;
    e2[d] = 2;
    g.terms[e2] = Rational(-1);
    g.terms[e] = Rational(2) * c[d];
    k -= c[d] * c[d];
  }
  g.terms[{0, 0, 0}] = k;
  return region_leaf(g, "cylinder");
}

}  // namespace splinex::test
