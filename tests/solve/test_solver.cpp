// The subdivision solver (solve/solver.hpp): roots known in closed form (rational ones must come
// out exact, irrational ones in certified boxes that contain them, checked by exact squares), roots
// on the lines where boxes are split and on the box's sides, a double root, roots 2^-40 apart, a
// degenerate system, and the solver in double beside the exact one.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>

#include "exact/rational.hpp"
#include "solve/solver.hpp"
#include "tests/solve/solve_fixtures.hpp"

using namespace splinex;
using R = Rational;
using solve_fixtures::bivariate;
using solve_fixtures::from_roots;
using solve_fixtures::univariate;

namespace {

std::vector<R> mul(const std::vector<R>& a, const std::vector<R>& b) {
  std::vector<R> c(a.size() + b.size() - 1, R(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

const RootBox<R>* exact_root(const SolveResult<R>& s, const std::vector<R>& x) {
  for (const auto& r : s.roots)
    if (r.exact && r.point == x) return &r;
  return nullptr;
}

}  // namespace

TEST_CASE("solver: rational roots exact (one on the first split), an irrational one in a certified box", "[solve]") {
  // (t - 1/2)(t - 1/3)(2 t^2 - 1): roots 1/2, 1/3, 1/sqrt(2) in [0, 1] (and -1/sqrt(2) outside).
  const auto f = univariate(mul(from_roots({R(1, 2), R(1, 3)}), {R(-1), R(0), R(2)}));
  const auto s = solve_system<R>({f}, {R(0)}, {R(1)});
  REQUIRE(s.roots.size() == 3);
  REQUIRE(s.complete());
  REQUIRE(exact_root(s, {R(1, 2)}));
  REQUIRE(exact_root(s, {R(1, 3)}));
  CHECK(exact_root(s, {R(1, 2)})->unique);
  int irrational = 0;
  for (const auto& r : s.roots)
    if (!r.exact) {
      ++irrational;
      CHECK(r.unique);
      CHECK(r.lo[0] * r.lo[0] * 2 < 1);  // lo < 1/sqrt(2) < hi, exactly
      CHECK(r.hi[0] * r.hi[0] * 2 > 1);
      CHECK(r.hi[0] - r.lo[0] <= R(1) / R(boost::multiprecision::mpz_int(1) << 50));
    }
  CHECK(irrational == 1);
}

TEST_CASE("solver: roots on the box's sides, on a shifted box, and no roots", "[solve]") {
  const auto ends = solve_system<R>({univariate(from_roots({R(0), R(1)}))}, {R(0)}, {R(1)});
  REQUIRE(ends.roots.size() == 2);
  CHECK(ends.complete());
  CHECK(exact_root(ends, {R(0)}));
  CHECK(exact_root(ends, {R(1)}));
  // The same polynomial standing for [2, 6]: its roots are 2 and 6.
  const auto shifted = solve_system<R>({univariate(from_roots({R(0), R(1)}))}, {R(2)}, {R(6)});
  CHECK(exact_root(shifted, {R(2)}));
  CHECK(exact_root(shifted, {R(6)}));
  const auto none = solve_system<R>({univariate({R(1), R(0), R(1)})}, {R(0)}, {R(1)});
  CHECK(none.roots.empty());
  CHECK(none.complete());
  CHECK(none.boxes == 1);
}

TEST_CASE("solver: a double root is exact but not certified unique, roots 2^-40 apart are separated", "[solve]") {
  const auto dbl = solve_system<R>({univariate(from_roots({R(1, 3), R(1, 3), R(3, 4)}))}, {R(0)}, {R(1)});
  const auto* r = exact_root(dbl, {R(1, 3)});
  REQUIRE(r);
  CHECK_FALSE(r->unique);
  REQUIRE(exact_root(dbl, {R(3, 4)}));
  CHECK(exact_root(dbl, {R(3, 4)})->unique);
  CHECK_FALSE(dbl.complete());
  const R e20 = R(1) / R(1 << 20), e40 = e20 * e20;
  const auto close = solve_system<R>({univariate(from_roots({R(1, 2), R(1, 2) + e20, R(1, 2) - e40}))}, {R(0)}, {R(1)},
                                     SolveOptions{50, 200000, 60, true, {}});
  REQUIRE(close.roots.size() == 3);
  CHECK(close.complete());
  for (const R& x : {R(1, 2), R(1, 2) + e20, R(1, 2) - e40}) CHECK(exact_root(close, {x}));
}

TEST_CASE("solver: a circle and a line, rational and irrational intersections", "[solve]") {
  // x^2 + y^2 = 1/2 and x = y on [0, 1]^2: (1/2, 1/2), on the first split in both directions.
  const auto line = bivariate(1, 1, {{{1, 0}, R(1)}, {{0, 1}, R(-1)}});
  const auto c1 = bivariate(2, 2, {{{2, 0}, R(1)}, {{0, 2}, R(1)}, {{0, 0}, R(-1, 2)}});
  const auto s1 = solve_system<R>({c1, line}, {R(0), R(0)}, {R(1), R(1)});
  REQUIRE(s1.roots.size() == 1);
  CHECK(s1.complete());
  CHECK(exact_root(s1, {R(1, 2), R(1, 2)}));
  // x^2 + y^2 = 1/4 and x = y: x = y = 1/(2 sqrt 2), i.e. x^2 = 1/8.
  const auto c2 = bivariate(2, 2, {{{2, 0}, R(1)}, {{0, 2}, R(1)}, {{0, 0}, R(-1, 4)}});
  const auto s2 = solve_system<R>({c2, line}, {R(0), R(0)}, {R(1), R(1)});
  REQUIRE(s2.roots.size() == 1);
  const auto& r = s2.roots[0];
  CHECK(r.unique);
  CHECK_FALSE(r.exact);
  for (int d = 0; d < 2; ++d) {
    CHECK(r.lo[d] * r.lo[d] * 8 < 1);
    CHECK(r.hi[d] * r.hi[d] * 8 > 1);
  }
  // The same circle and line standing for [-1, 1]^2 (x = 2s - 1): both intersection points.
  // In s: (2s-1)^2 + (2t-1)^2 - 1/4 = 4s^2 - 4s + 4t^2 - 4t + 7/4, and 2s - 2t.
  const auto c3 = bivariate(2, 2, {{{2, 0}, R(4)}, {{1, 0}, R(-4)}, {{0, 2}, R(4)}, {{0, 1}, R(-4)}, {{0, 0}, R(7, 4)}});
  const auto s3 = solve_system<R>({c3, line}, {R(-1), R(-1)}, {R(1), R(1)});
  REQUIRE(s3.roots.size() == 2);
  CHECK(s3.complete());
  CHECK(s3.roots[0].lo[0] * s3.roots[1].lo[0] < 0);  // one on each side of 0
}

TEST_CASE("solver: degenerate and malformed systems are refused, a curve of solutions stays undecided", "[solve]") {
  const auto line = bivariate(1, 1, {{{1, 0}, R(1)}, {{0, 1}, R(-1)}});
  const Bernstein<R> zero{{1, 1}, std::vector<R>(4, R(0))};
  CHECK_THROWS_AS(solve_system<R>({line, zero}, {R(0), R(0)}, {R(1), R(1)}), ValidationError);
  CHECK_THROWS_AS(solve_system<R>({line}, {R(0), R(0)}, {R(1), R(1)}), ValidationError);
  CHECK_THROWS_AS(solve_system<R>({univariate({R(1), R(1)})}, {R(1)}, {R(1)}), ValidationError);
  // x - y = 0 twice over: a whole segment of solutions. Nothing may be claimed unique.
  const auto sq = bern_product(line, line);
  const auto s = solve_system<R>({line, sq}, {R(0), R(0)}, {R(1), R(1)}, SolveOptions{10, 3000, 60, true, {}});
  CHECK_FALSE(s.complete());
  CHECK_FALSE(s.undecided.empty());
  for (const auto& r : s.roots) CHECK_FALSE(r.unique);
}

TEST_CASE("solver: the same subdivision in double finds the simple roots near the exact ones", "[solve]") {
  const auto f = univariate(mul(from_roots({R(1, 2), R(1, 3)}), {R(-1), R(0), R(2)}));
  Bernstein<double> fd{f.deg, {}};
  for (const auto& c : f.c) fd.c.push_back(to_double(c));
  const auto s = solve_system<double>({fd}, {0.0}, {1.0});
  REQUIRE(s.roots.size() == 3);
  std::vector<double> xs;
  for (const auto& r : s.roots) xs.push_back(0.5 * (r.lo[0] + r.hi[0]));
  std::sort(xs.begin(), xs.end());
  CHECK(std::abs(xs[0] - 1.0 / 3) < 1e-12);
  CHECK(std::abs(xs[1] - 0.5) < 1e-12);
  CHECK(std::abs(xs[2] - std::sqrt(0.5)) < 1e-12);
}

TEST_CASE("simplest rational between two numbers", "[solve]") {
  CHECK(simplest_rational_between(R(3, 10), R(4, 10)) == R(1, 3));
  CHECK(simplest_rational_between(R(-4, 10), R(-3, 10)) == R(-1, 3));
  CHECK(simplest_rational_between(R(-1, 10), R(1, 10)) == R(0));
  CHECK(simplest_rational_between(R(5, 2), R(7, 2)) == R(3));
  CHECK(simplest_rational_between(R(7, 5), R(7, 5)) == R(7, 5));
}

TEST_CASE("solver: random rational roots, many on split lines, found exactly once each", "[solve]") {
  // 40 univariate cases: 1-4 distinct roots k/8 or k/6 in [0, 1] (0, 1/2, 1/4, ... lie where boxes
  // are split), some doubled. 20 bivariate cases: (x - a)(x - b) = 0, (y - c)(y - d) = 0 on
  // [0, 1]^2, a grid of four roots.
  std::uint32_t seed = 12345;
  auto next = [&](int m) {
    seed = seed * 1664525u + 1013904223u;
    return static_cast<int>((seed >> 8) % static_cast<std::uint32_t>(m));
  };
  auto root = [&] { return next(2) ? R(next(9), 8) : R(next(7), 6); };
  for (int c = 0; c < 40; ++c) {
    std::vector<R> distinct;
    const int k = 1 + next(4);
    while (static_cast<int>(distinct.size()) < k) {
      const R r = root();
      if (std::find(distinct.begin(), distinct.end(), r) == distinct.end()) distinct.push_back(r);
    }
    std::vector<R> all = distinct;
    const bool doubled = next(3) == 0;
    if (doubled) all.push_back(distinct[0]);
    const auto s = solve_system<R>({univariate(from_roots(all))}, {R(0)}, {R(1)});
    INFO("case " << c);
    CHECK(s.roots.size() == distinct.size());
    for (std::size_t i = 0; i < distinct.size(); ++i) {
      const auto* r = exact_root(s, {distinct[i]});
      REQUIRE(r);
      CHECK(r->unique == !(doubled && i == 0));
    }
    CHECK(s.complete() == !doubled);
  }
  for (int c = 0; c < 20; ++c) {
    R a = root(), b = root(), cc = root(), d = root();
    while (b == a) b = root();
    while (d == cc) d = root();
    const auto fx = bivariate(2, 0, {{{2, 0}, R(1)}, {{1, 0}, -(a + b)}, {{0, 0}, a * b}});
    const auto fy = bivariate(0, 2, {{{0, 2}, R(1)}, {{0, 1}, -(cc + d)}, {{0, 0}, cc * d}});
    const auto s = solve_system<R>({fx, fy}, {R(0), R(0)}, {R(1), R(1)});
    INFO("grid case " << c);
    CHECK(s.complete());
    REQUIRE(s.roots.size() == 4);
    for (const R& x : {a, b})
      for (const R& y : {cc, d}) CHECK(exact_root(s, {x, y}));
  }
}

// Issue 47 (planted bugs, tests/solve/test_planted.cpp): the certificates' regression checks.
TEST_CASE("solver: roots on a split line pinned by a linear equation are each reported once", "[solve]") {
  // x = 1/2 and (y - 1/4)(y - 3/4) = 0: two roots on the first split line. K(X) of the linear
  // equation is the line itself, a face of both boxes beside it: inside neither open box (a
  // closed test would certify each root twice).
  const auto f1 = bivariate(1, 0, {{{1, 0}, R(1)}, {{0, 0}, R(-1, 2)}});
  const auto f2 = bivariate(0, 2, {{{0, 2}, R(1)}, {{0, 1}, R(-1)}, {{0, 0}, R(3, 16)}});
  for (bool recognise : {true, false}) {
    INFO("recognize_rationals " << recognise);
    SolveOptions o;
    o.recognize_rationals = recognise;
    const auto s = solve_system<R>({f1, f2}, {R(0), R(0)}, {R(1), R(1)}, o);
    CHECK(s.complete());
    REQUIRE(s.roots.size() == 2);
    // One root per box: the two boxes are disjoint, one holds (1/2, 1/4), the other (1/2, 3/4).
    for (const R& y : {R(1, 4), R(3, 4)}) {
      int holding = 0;
      for (const auto& r : s.roots)
        holding += !(R(1, 2) < r.lo[0]) && !(r.hi[0] < R(1, 2)) && !(y < r.lo[1]) && !(r.hi[1] < y);
      CHECK(holding == 1);
    }
    if (recognise) {
      CHECK(exact_root(s, {R(1, 2), R(1, 4)}));
      CHECK(exact_root(s, {R(1, 2), R(3, 4)}));
    }
  }
}

TEST_CASE("solver: two roots in one merged group are not one unique root", "[solve]") {
  // 1/3 and 1/3 + 2^-40: closer than the boxes at the depth limit (2^-30), they end in one
  // cluster hull, where 1/3 is recognised exactly; the contraction test about it fails (f'
  // vanishes between them), so the hull stays undecided and the result incomplete.
  const R second = R(1, 3) + R(1) / R(boost::multiprecision::mpz_int(1) << 40);
  const auto s = solve_system<R>({univariate(from_roots({R(1, 3), second}))}, {R(0)}, {R(1)});
  CHECK_FALSE(s.complete());
  for (const auto& r : s.roots)
    if (r.unique) CHECK_FALSE((r.lo[0] <= R(1, 3) && second <= r.hi[0]));
  bool held = false;  // an undecided box holds both
  for (const auto& u : s.undecided) held = held || (u.lo[0] <= R(1, 3) && second <= u.hi[0]);
  CHECK(held);
}
