#pragma once
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures/solve_examples.hpp"
#include "io/json_io.hpp"

namespace splinex::test {

inline Json doc(const std::string& text) {
  std::istringstream in(text);
  return read_json(in, "test");
}
inline BSpline<Rational> spline(const std::string& text, const Limits& limits = {}) {
  return spline_from_json(doc(text), limits);
}
inline Rational q(const char* s) { return parse_number(s, "test"); }

/// The field g(x) = a.x + d on a polynomial trivariate V: by affine invariance its control values
/// are g at V's control points, exactly, so it equals g at every point of the cell (an oracle
/// independent of the code that carries or integrates fields).
inline BSpline<Rational> affine_field(const BSpline<Rational>& V, const std::array<Rational, 3>& a, const Rational& d) {
  BSpline<Rational> F = V;
  F.q = 1;
  F.points.clear();
  for (std::size_t i = 0; i < V.size(); ++i)
    F.points.push_back(a[0] * V.points[i * V.q] + a[1] * V.points[i * V.q + 1] + a[2] * V.points[i * V.q + 2] + d);
  return F;
}

/// The exact sphere patch (fixtures/solve_examples.hpp).
inline BSpline<Rational> stereographic_sphere() { return splinex::stereographic_sphere(); }

/// A seeded xorshift64 stream of integers in [0, m): reproducible random cases without <random>'s
/// distributions, whose results differ between standard libraries.
struct XorShift {
  std::uint64_t state;
  int operator()(int m) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return static_cast<int>(state % static_cast<std::uint64_t>(m));
  }
};

}  // namespace splinex::test
