#include <catch2/catch.hpp>

#include "fixtures/random_spline.hpp"
#include "exact/rational.hpp"
#include "spline/kernel.hpp"

using namespace splinex;

namespace {
BSpline<Rational> bezier1(std::vector<Rational> coefs, Rational lo, Rational hi) {
  const int p = static_cast<int>(coefs.size()) - 1;
  return make_spline<Rational>({p}, {clamped_knots(p, lo, hi)}, 1, std::move(coefs));
}
}  // namespace

TEST_CASE("integrate: closed form of the basis integrals, exact") {
  // t^2 on [0, 2]: with t = 2s the Bernstein coefficients are 0, 0, 4; the integral is 8/3.
  const auto f = bezier1({0, 0, 4}, 0, 2);
  CHECK(integrate(f)[0] == Rational(8, 3));
  // Refinement and elevation do not change the function, so not the integral.
  const auto g = elevate_degree(refine_knots(f, 0, {Rational(1, 3), Rational(1, 3), Rational(7, 5)}), 0, 2);
  CHECK(integrate(g)[0] == Rational(8, 3));
  // A surface x * y^2 on [0,1] x [0,3]: integral 1/2 * 9 = 9/2.
  // y^2 on [0, 3]: coefficients 0, 0, 9; times x: coefficients 0 at x = 0 and those at x = 1.
  const auto s = make_spline<Rational>({1, 2}, {{0, 0, 1, 1}, {0, 0, 0, 3, 3, 3}}, 1, {0, 0, 0, 0, 0, 9});
  CHECK(integrate(s)[0] == Rational(9, 2));
}

TEST_CASE("integrate_abs: exact where the sign is certified, an enclosure elsewhere") {
  // t - 1/2 on [0, 1]: one halving separates the signs; int |f| = 1/4 exactly.
  const auto f = bezier1({Rational(-1, 2), Rational(1, 2)}, 0, 1);
  const auto a = integrate_abs(f, 4);
  CHECK(a.exact());
  CHECK(a.lower == Rational(1, 4));
  // t - 1/3: the root is never a dyadic split point, so an enclosure of 5/18 remains whose width
  // shrinks by about half per level.
  const auto h = bezier1({Rational(-1, 3), Rational(2, 3)}, 0, 1);
  Rational last_width(1);
  for (int depth : {0, 4, 8, 16}) {
    const auto e = integrate_abs(h, depth);
    INFO("depth " << depth);
    CHECK(e.lower <= Rational(5, 18));
    CHECK(Rational(5, 18) <= e.upper);
    CHECK(!e.exact());
    CHECK(e.undecided == 1);
    const Rational width = e.upper - e.lower;
    CHECK(width <= Rational(1, 1 << depth));
    CHECK(width < last_width);
    last_width = width;
  }
  // x - y on the unit square: int |x - y| = 1/3; the diagonal is never resolved exactly.
  const auto s = bezier<Rational>({1, 1}, 1, {0, 1, -1, 0});
  const auto e = integrate_abs(s, 12);
  CHECK(e.lower <= Rational(1, 3));
  CHECK(Rational(1, 3) <= e.upper);
  CHECK(e.upper - e.lower < Rational(1, 30));
  // A spline of one sign everywhere: exact at depth 0.
  CHECK(integrate_abs(bezier1({1, 3, 2}, 0, 1), 0).lower == Rational(2));
}

TEST_CASE("difference: one spline equal to A - B on the common domain") {
  std::mt19937_64 rng(7);
  for (int k = 1; k <= 2; ++k)
    for (int c = 0; c < 4; ++c) {
      RandomSplineSpec sa, sb;
      sa.q = sb.q = 2;
      sa.clamped = c % 2 == 0;
      for (int d = 0; d < k; ++d) {
        sa.degrees.push_back(1 + (c + d) % 3);
        sa.counts.push_back(sa.degrees.back() + 1 + c);
        sb.degrees.push_back(1 + (c + 2 * d + 1) % 4);
        sb.counts.push_back(sb.degrees.back() + 2);
      }
      const auto A = random_spline(sa, rng);
      auto B = random_spline(sb, rng);
      for (int d = 0; d < k; ++d) B = reparametrize(B, d, A.domain_lo(d), A.domain_hi(d));
      const auto D = difference(A, B);
      for (int s = 0; s < 10; ++s) {
        std::vector<Rational> r;
        for (int d = 0; d < k; ++d) r.push_back(random_inside(A.domain_lo(d), A.domain_hi(d), rng));
        const auto a = evaluate(A, r), b = evaluate(B, r), d = evaluate(D, r);
        for (int i = 0; i < 2; ++i) CHECK(d[i] == a[i] - b[i]);
      }
    }
  auto A = bezier1({0, 1}, 0, 1), B = bezier1({0, 1}, 0, 2);
  CHECK_THROWS_AS(difference(A, B), DomainError);
}

TEST_CASE("integrate_abs: a relative target, checked against the antiderivative") {
  // f = (t - 1/3)(t - 3/4) = t^2 - 13/12 t + 1/4, Bernstein 1/4, -7/24, 1/6 on [0, 1].
  // F = t^3/3 - 13/24 t^2 + t/4; int |f| = F(1/3) - F(0) - (F(3/4) - F(1/3)) + F(1) - F(3/4).
  const auto F = [](const Rational& t) { return Rational(t * t * t / 3 - Rational(13, 24) * t * t + t / 4); };
  const Rational truth = F(Rational(1, 3)) - F(0) - (F(Rational(3, 4)) - F(Rational(1, 3))) + F(1) - F(Rational(3, 4));
  const auto f = bezier1({Rational(1, 4), Rational(-7, 24), Rational(1, 6)}, 0, 1);
  for (const Rational& rel : {Rational(1, 1000), Rational(1, 1000000000000LL)}) {
    const auto e = integrate_abs(f, 60, rel);
    INFO("rel " << rel);
    CHECK(e.lower <= truth);
    CHECK(truth <= e.upper);
    CHECK(e.upper - e.lower <= rel * e.lower);
    CHECK(e.cells < 200);  // the control-polygon split converges fast (midpoints would need ~40 levels)
  }
  CHECK_THROWS_AS(integrate_abs(f, 10, Rational(-1)), ValidationError);
}
