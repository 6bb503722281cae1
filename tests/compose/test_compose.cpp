#include <catch2/catch.hpp>

#include "base/errors.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"

using namespace splinex;
using test::spline;

TEST_CASE("composed degree is inner degree times the sum of outer degrees") {
  // Surface S (degrees 2, 1) into a trivariate T (degrees 1, 2, 3): degrees (12, 6).
  const auto S = spline(R"({"type":"bspline","degrees":[2,1],"knots":[[0,0,0,1,1,1],[0,0,1,1]],
      "points":[[0.1,0.2,0.3],[0.5,0.1,0.2],[0.9,0.3,0.1],[0.2,0.8,0.4],[0.6,0.7,0.9],[0.8,0.9,0.5]]})");
  std::vector<Rational> coefs;
  for (int i = 0; i < 2 * 3 * 4; ++i) coefs.emplace_back(i * i - 7 * i, 5);
  const auto T = bezier<Rational>({1, 2, 3}, 1, coefs);
  const auto R = compose_bezier(T, S);
  CHECK(R.degrees == std::vector<int>{12, 6});
  CHECK(compose_bezier(T, S, CompositionMethod::interpolation).points == R.points);
  // A hand value: T(S(1/2, 1/3)) through pointwise evaluation.
  const std::vector<Rational> x{Rational(1, 2), Rational(1, 3)};
  CHECK(evaluate(R, x) == evaluate(T, evaluate(S, x)));
}

TEST_CASE("a line into a cubic: the composed curve matches a hand computation") {
  // T(u) = (u, ...) Bezier on [0,1]; S(r) = r/2 + 1/4 (linear): T(S(r)) is T restricted to
  // [1/4, 3/4], i.e. de Casteljau subdivision, so the end points are T(1/4) and T(3/4).
  const auto T = spline(R"({"type":"bspline","degrees":[3],"knots":[[0,0,0,0,1,1,1,1]],"points":[[0,0],[1,3],[2,-1],[3,1]]})");
  const auto S = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0.25],[0.75]]})");
  const auto R = compose(T, S);
  CHECK(R.degrees == std::vector<int>{3});
  CHECK(std::vector<Rational>(R.points.begin(), R.points.begin() + 2) == evaluate(T, {Rational(1, 4)}));
  CHECK(std::vector<Rational>(R.points.end() - 2, R.points.end()) == evaluate(T, {Rational(3, 4)}));
  // u(t) = t + 0*... : x-coordinate of T is u itself (control x = 0,1,2,3 /3 scaled): x(1/4) = 3/4.
  CHECK(R.points[0] == Rational(3, 4));
}

TEST_CASE("composition errors are typed and say what to do") {
  const auto T = spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,0.5,1,1,1]],"points":[[0],[1],[0],[2]]})");
  const auto crossing = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0.25],[0.75]]})");
  CHECK_THROWS_AS(compose(T, crossing), DomainError);
  const auto outside = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[-0.5],[0.25]]})");
  try {
    compose(T, outside);
    FAIL("no exception");
  } catch (const DomainError& e) {
    CHECK(std::string(e.what()).find("by up to 1/2") != std::string::npos);
  }
  CompositionOptions expand;
  expand.expand = true;
  const auto R = compose(T, outside, expand);  // Observation 1: the first piece as a polynomial
  CHECK(evaluate(R, {Rational(0)}) == evaluate_bezier_anywhere(extract_bezier(T)[0].spline, {Rational(-1, 2)}));
  const auto two_d = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0.1,0.2],[0.3,0.4]]})");
  CHECK_THROWS_AS(compose(T, two_d), ValidationError);
  CHECK_THROWS_AS(compose_bezier(T, outside), UsageError);  // T has an interior knot
  // Rational outer with the inner leaving the box: composed weights are not all positive.
  const auto W = spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[0],[1],[0]],"weights":[1,3,1]})");
  const auto far = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[-3],[0.5]]})");
  CHECK_THROWS_AS(compose(W, far, expand), DomainError);
}
