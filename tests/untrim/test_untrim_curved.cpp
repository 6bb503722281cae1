// Exact untrimming of domains bounded by polynomial graph arcs (untrim/curved.hpp): hand-computed
// areas and integrals, Green's theorem, the cover certificate (and that it can fail), knot lines
// with rational and irrational crossings, composition into a surface, typed errors.
#include <catch2/catch.hpp>

#include "exact/rational.hpp"
#include "float/mpfr.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/sweep.hpp"
#include "untrim/tile_integrals.hpp"
#include "untrim/curved.hpp"
#include "untrim/loops.hpp"
#include "untrim/polygon.hpp"

using namespace splinex;

namespace {
using V = Point2<Rational>;
const Rational h(1, 2);

// The lens between y = 1/2 and the parabola y = 1/2 + x (1 - x) over [0, 1] (control (1/2, 1)).
TrimmedDomain lens() {
  TrimmedDomain D{{0, 0}, {1, 1}, {{{0, h}, {1, h}}}};
  D.controls = {{{{h, 1}}, {}}};
  validate_domain(D);
  return D;
}

// An outer loop of two cubic graphs with a triangular hole.
TrimmedDomain blob_with_hole() {
  TrimmedDomain D{{0, 0}, {1, 1}, {{{Rational(1, 10), h}, {Rational(9, 10), h}}, {{Rational(2, 5), Rational(9, 20)}, {Rational(3, 5), Rational(9, 20)}, {h, Rational(3, 5)}}}};
  // Edge 0 left to right below y = 1/2 (ordinates 1/2, 1/10, 1/5, 1/2), edge 1 right to left above it.
  D.controls = {{{{Rational(11, 30), Rational(1, 10)}, {Rational(19, 30), Rational(1, 5)}},
                 {{Rational(19, 30), Rational(19, 20)}, {Rational(11, 30), Rational(4, 5)}}},
                {{}, {}, {}}};
  validate_domain(D);
  return D;
}

Rational sum_areas(const std::vector<Tile<Rational>>& tiles) {
  Rational a = 0;
  for (const auto& t : tiles) a += tile_area(t);
  return a;
}
}  // namespace

TEST_CASE("curved untrimming: the parabolic lens by hand (area 1/6, int y = 1/10, int x = 1/12)") {
  const auto D = lens();
  CHECK(D.curved());
  CHECK(region_area(D) == Rational(1, 6));
  const auto tiles = untrim_curved(D);
  REQUIRE(tiles.size() == 1);
  const auto& t = tiles[0];
  CHECK(t.curved());
  CHECK(t.x == std::vector<Rational>{0, 1});
  CHECK(t.top[0] == std::vector<Rational>{h, 1, h});  // the curve itself is the tile's side
  CHECK(t.bottom[0] == std::vector<Rational>{h, h});
  CHECK(tile_area(t) == Rational(1, 6));
  CHECK(integrate_over_tile(monomial_density(0, 1, D), t)[0] == Rational(1, 10));
  CHECK(integrate_over_tile(monomial_density(1, 0, D), t)[0] == Rational(1, 12));
  CHECK(green_integral(D, monomial_density(0, 1, D)) == Rational(1, 10));
  // The Coons patch: degree (2, 1), its sides the chains.
  const auto Q = tile_spline(t);
  CHECK(Q.degrees == std::vector<int>{2, 1});
  CHECK(evaluate(Q, {Rational(1, 3), Rational(1)}) == std::vector<Rational>{Rational(1, 3), h + Rational(2, 9)});
  CHECK(evaluate(Q, {Rational(1, 3), Rational(1, 4)}) == std::vector<Rational>{Rational(1, 3), h + Rational(2, 9) / 4});
  const auto cc = certify_cover(D, tiles);
  CHECK(cc.ok);
  CHECK(cc.samples >= 1);
}

TEST_CASE("curved untrimming: knot lines split tiles at rational crossings, irrational ones are typed errors") {
  const auto D = lens();
  // y = 11/16 meets 1/2 + x - x^2 at x = 1/4 and 3/4; x = 1/3 is vertical.
  const std::array<std::vector<Rational>, 2> kl{{{Rational(1, 3)}, {Rational(11, 16)}}};
  const auto tiles = untrim_curved(D, kl);
  CHECK(tiles.size() == 2);
  CHECK(sum_areas(tiles) == Rational(1, 6));
  for (const auto& t : tiles) {
    // Each chain piece lies on one side of the knot line (convex hull of its ordinates).
    for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
      Rational lo = t.bottom[i][0], hi = t.top[i][0];
      for (const auto& v : t.bottom[i]) lo = std::min(lo, v);
      for (const auto& v : t.top[i]) hi = std::max(hi, v);
      CHECK((hi <= Rational(11, 16) || lo >= Rational(11, 16)));
      CHECK((t.x[i + 1] <= Rational(1, 3) || t.x[i] >= Rational(1, 3)));
    }
  }
  CHECK(certify_cover(D, tiles).ok);
  // y = 5/8: x - x^2 = 1/8 at x = (1 +- sqrt(1/2)) / 2, irrational.
  CHECK_THROWS_AS(untrim_curved(D, {{{}, {Rational(5, 8)}}}), DomainError);
  try {
    untrim_curved(D, {{{}, {Rational(5, 8)}}});
  } catch (const DomainError& e) {
    CHECK_THAT(std::string(e.what()), Catch::Contains("loops[0] edge 0: crosses the knot line y = 5/8 at an irrational x"));
  }
  // The tangent line y = 3/4 touches at the rational double root x = 1/2.
  const auto tangent = untrim_curved(D, {{{}, {Rational(3, 4)}}});
  CHECK(sum_areas(tangent) == Rational(1, 6));
  CHECK(certify_cover(D, tangent).ok);
}

TEST_CASE("curved untrimming: cubic loop with a hole, integrals equal Green's theorem exactly") {
  const auto D = blob_with_hole();
  const std::array<std::vector<Rational>, 2> kl{{{Rational(1, 4), h, Rational(2, 3)}, {h}}};
  const auto tiles = untrim_curved(D, kl);
  const auto cc = certify_cover(D, tiles);
  INFO(cc.failure);
  CHECK(cc.ok);
  CHECK(cc.tile_area_sum == region_area(D));
  CHECK(cc.pair_checks > 0);
  CHECK(cc.edge_checks > 0);
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; b <= 2; ++b) {
      const auto f = monomial_density(a, b, D);
      Rational sum = 0;
      for (const auto& t : tiles) sum += integrate_over_tile(f, t)[0];
      INFO("x^" << a << " y^" << b);
      CHECK(sum == green_integral(D, f));
    }
  // Composition: every tile patch equals S(Q) (S biquadratic with the knot lines above).
  const auto S = spline_from<Rational>({2, 1}, {{0, 0, 0, Rational(1, 4), h, Rational(2, 3), 1, 1, 1}, {0, 0, h, 1, 1}}, 3,
                                       [](const std::vector<std::size_t>& ij) {
                                         const int i = static_cast<int>(ij[0]), j = static_cast<int>(ij[1]);
                                         return std::vector<Rational>{Rational(i, 5), Rational(j, 2), Rational((i * 5 + j * 3) % 7, 4)};
                                       });
  CompositionOptions co;
  co.expand = true;
  for (const auto& t : tiles) {
    const auto Q = tile_spline(t);
    const auto R = compose(S, Q, co);
    for (const Rational& l : {Rational(0), Rational(1, 3), Rational(1)})
      for (std::size_t i = 0; i + 1 < t.x.size(); ++i) {
        const Rational x = (2 * t.x[i] + t.x[i + 1]) / 3;
        CHECK(evaluate(R, {x, l}) == evaluate(S, evaluate(Q, {x, l})));
      }
  }
}

TEST_CASE("curved untrimming agrees with the straight sweep and CGAL on a polygonal domain") {
  TrimmedDomain D{{0, 0}, {2, 1},
                  {{{Rational(1, 10), Rational(1, 10)}, {Rational(19, 10), Rational(1, 5)}, {Rational(3, 2), Rational(9, 10)}, {Rational(1, 5), Rational(4, 5)}},
                   {{h, Rational(3, 10)}, {1, Rational(2, 5)}, {Rational(7, 10), Rational(2, 3)}}}};
  validate_domain(D);
  const auto tiles = untrim_curved(D, {{{1}, {h}}});
  CHECK(sum_areas(tiles) == region_area(D));  // region_area: CGAL for polygons
  const auto cc = certify_cover(D, tiles);
  INFO(cc.failure);
  CHECK(cc.ok);
}

TEST_CASE("the cover certificate fails on a wrong tiling") {
  const auto D = blob_with_hole();
  auto tiles = untrim_curved(D, {{{h}, {}}});
  REQUIRE(tiles.size() >= 2);
  SECTION("a missing tile is a gap") {
    tiles.pop_back();
    const auto cc = certify_cover(D, tiles);
    CHECK_FALSE(cc.ok);
    CHECK_THAT(cc.failure, Catch::Contains("tile areas add up to"));
  }
  SECTION("a repeated tile is an overlap") {
    tiles.push_back(tiles.front());
    const auto cc = certify_cover(D, tiles);
    CHECK_FALSE(cc.ok);
    CHECK_THAT(cc.failure, Catch::Contains("overlap"));
  }
  SECTION("a tile pushed across the hole's edge") {
    for (auto& t : tiles)
      for (auto& c : t.top)
        for (auto& v : c) v += Rational(1, 100);
    for (auto& t : tiles)
      for (auto& v : t.yt) v += Rational(1, 100);
    const auto cc = certify_cover(D, tiles);
    CHECK_FALSE(cc.ok);
  }
}

TEST_CASE("curved untrimming in double and MPFR: exact tiles rounded, errors measured exactly") {
  const auto D = blob_with_hole();
  const auto f = monomial_density(1, 2, D);
  const Rational exact = green_integral(D, f);
  const auto td = untrim_domain<double>(D);
  const auto fd = convert<double>(f, [](const Rational& x) { return to_double(x); });
  double sd = 0;
  for (const auto& t : td) sd += integrate_over_tile(fd, t)[0];
  const Rational ed = abs(Rational(exact_from_double(sd) - exact));
  CHECK(ed < Rational(1, 1000000000000000LL));
  Mpfr::Precision scope(200);
  const auto tm = untrim_domain<Mpfr>(D);
  const auto fm = convert<Mpfr>(f, [](const Rational& x) { return ArithTraits<Mpfr>::from_rational(x); });
  Mpfr sm(0);
  for (const auto& t : tm) sm = sm + integrate_over_tile(fm, t)[0];
  const Rational em = abs(Rational(ArithTraits<Mpfr>::to_rational(sm) - exact));
  CHECK(em < ed);
  CHECK(em < Rational(1, Integer(1) << 180));
}

TEST_CASE("curved trimmed domains: typed errors") {
  auto expect = [](TrimmedDomain D, std::vector<std::vector<Polygon>> controls, const std::string& what) {
    D.controls = std::move(controls);
    INFO(what);
    try {
      validate_domain(D);
      FAIL("no error");
    } catch (const Error& e) {
      CHECK_THAT(std::string(e.what()), Catch::Contains(what));
    }
  };
  const TrimmedDomain L{{0, 0}, {1, 1}, {{{0, h}, {1, h}}}};
  expect(L, {{{{Rational(1, 3), 1}}, {}}}, "loops[0] edge 0: is not a graph y = f(x): control point 1 has x = 1/3, not 1/2");
  expect(L, {{{{h, 2}}, {}}}, "loops[0] edge 0: leaves the domain");
  expect(L, {{{{h, 1}}, {{h, 1}}}}, "loops[0]: is self-intersecting (edge 0 and edge 1 meet)");
  expect({{0, 0}, {1, 1}, {{{h, Rational(1, 4)}, {h, Rational(3, 4)}}}}, {{{{1, h}}, {}}},
         "loops[0] edge 0: is curved with both end points at x = 1/2");
  // The parabola's lens and a triangle whose edge crosses the parabola.
  expect({{0, 0}, {1, 1}, {{{0, h}, {1, h}}, {{h, Rational(7, 10)}, {Rational(9, 10), Rational(9, 10)}, {h, Rational(9, 10)}}}},
         {{{{h, 1}}, {}}, {{}, {}, {}}}, "loops[1]: meets loops[0]");
  // Touching at one point (the parabola's apex (1/2, 3/4) on the triangle's edge y = 3/4) also meets.
  expect({{0, 0}, {1, 1}, {{{0, h}, {1, h}}, {{Rational(1, 4), Rational(3, 4)}, {Rational(3, 4), Rational(3, 4)}, {h, Rational(9, 10)}}}},
         {{{{h, 1}}, {}}, {{}, {}, {}}}, "loops[1]: meets loops[0]");
}
