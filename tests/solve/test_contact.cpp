// The minimum distance of two surfaces (solve/contact.hpp) on cases with exact answers: a
// paraboloid over a plane (distance 1 at a rational pair), the exact sphere against a reflected
// copy (distance 3/sqrt(2) - 2, irrational), a paraboloid cut by a plane (a certified common
// point), corners that coincide; refusals; the same in double.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "exact/rational.hpp"
#include "float/rounding.hpp"
#include "io/json_io.hpp"
#include "solve/contact.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"
#include "tests/solve/solve_fixtures.hpp"

using namespace splinex;
using R = Rational;

namespace {

// z = x^2 + y^2 over [-1, 1]^2 (fixtures/solve_examples.hpp).
BSpline<R> paraboloid() { return quadric_patch(R(1), R(1), R(1)); }

BSpline<R> plane(const R& z) {  // over [-2, 2]^2
  const std::vector<R> k{R(-2), R(-2), R(2), R(2)};
  return make_spline<R>({1, 1}, {k, k}, 3, {R(-2), R(-2), z, R(2), R(-2), z, R(-2), R(2), z, R(2), R(2), z});
}

/// The exact sphere patch (tests/helpers.hpp), or its copy reflected: (c - x, c - y, z).
BSpline<R> sphere(const R& c) {
  auto S = test::stereographic_sphere();
  if (c != 0)
    for (std::size_t i = 0; i < S.size(); ++i) {
      S.points[3 * i] = c - S.points[3 * i];
      S.points[3 * i + 1] = c - S.points[3 * i + 1];
    }
  return S;
}

}  // namespace

TEST_CASE("contact: a paraboloid over a plane, distance 1 at an exact pair", "[solve]") {
  const auto r = surface_distance(paraboloid(), plane(R(-1)));
  CHECK_FALSE(r.intersecting);
  REQUIRE(r.closest_certified);
  CHECK(r.distance2_lo == 1);
  CHECK(r.distance2_hi == 1);
  const auto& c = r.points[r.closest[0]];
  CHECK(c.exact);
  CHECK(c.where == "interior-interior");
  CHECK(c.lo == std::vector<R>{R(0), R(0), R(0), R(0)});
  CHECK(c.p2 == std::vector<R>{R(0), R(0), R(-1)});
}

TEST_CASE("contact: the exact sphere and a reflected copy, an irrational distance enclosed", "[solve]") {
  // Centres 0 and (3/2, 3/2, 0): the closest points are (1, 1, 0)/sqrt 2 and (3/2, 3/2, 0) minus it,
  // d^2 = (3/sqrt 2 - 2)^2 = 17/2 - 6 sqrt 2, at u = v = r = t = 1/sqrt 2.
  const auto r = surface_distance(sphere(R(0)), sphere(R(3, 2)));
  REQUIRE(r.closest_certified);
  const auto& c = r.points[r.closest[0]];
  CHECK(c.unique);
  for (int l = 0; l < 4; ++l) {
    CHECK(c.lo[l] * c.lo[l] * 2 < 1);
    CHECK(c.hi[l] * c.hi[l] * 2 > 1);
  }
  // d2_lo <= 17/2 - 6 sqrt 2 <= d2_hi: (17/2 - d2)^2 against 72.
  CHECK((R(17, 2) - r.distance2_lo) * (R(17, 2) - r.distance2_lo) >= 72);
  CHECK((R(17, 2) - r.distance2_hi) * (R(17, 2) - r.distance2_hi) <= 72);
  CHECK(r.distance2_hi - r.distance2_lo < R(1, 1000000000));
}

TEST_CASE("contact: intersecting surfaces get a certified common point", "[solve]") {
  const auto r = surface_distance(paraboloid(), plane(R(1, 2)));
  REQUIRE(r.intersecting);
  CHECK(r.distance2_lo == 0);
  CHECK(r.distance2_hi == 0);
  // The common point's box meets the circle x^2 + y^2 = 1/2 (the box of (u, v) on the paraboloid,
  // whose parameters are x and y): its nearest corner inside, its farthest outside.
  const auto& lo = r.common_lo;
  const auto& hi = r.common_hi;
  R nearest(0), farthest(0);
  for (int d = 0; d < 2; ++d) {
    const R a = lo[d] * lo[d], b = hi[d] * hi[d];
    const bool straddles = lo[d] <= 0 && 0 <= hi[d];
    nearest += straddles ? R(0) : std::min(a, b);
    farthest += std::max(a, b);
  }
  CHECK(nearest <= R(1, 2));
  CHECK(farthest >= R(1, 2));
  // Surfaces sharing a corner exactly: the distance is exactly 0 there.
  const auto touching = surface_distance(sphere(R(0)), sphere(R(1)));
  CHECK(touching.intersecting);
  CHECK(touching.distance2_hi == 0);
}

TEST_CASE("contact: refusals, and the same subdivision in double", "[solve]") {
  const auto flat = make_spline<R>({0, 1}, {{R(0), R(1)}, {R(0), R(0), R(1), R(1)}}, 3, {R(0), R(0), R(0), R(0), R(1), R(0)});
  CHECK_THROWS_AS(surface_distance(flat, plane(R(0))), ValidationError);
  const auto curve = make_spline<R>({1}, {{R(0), R(0), R(1), R(1)}}, 3, {R(0), R(0), R(0), R(1), R(0), R(0)});
  CHECK_THROWS_AS(surface_distance(plane(R(0)), curve), ValidationError);
  const auto d = surface_distance(round_spline<double>(paraboloid()), round_spline<double>(plane(R(-1))));
  CHECK_FALSE(d.closest_certified);
  CHECK(std::abs(d.distance2_hi - 1.0) < 1e-12);
}

// Issue 47 (reproducers in tests/data/repro/solver): double enclosures, nearly touching surfaces.
using solve_fixtures::repro;

TEST_CASE("contact in double: intersecting surfaces are never 'not intersecting' with a negative distance", "[solve]") {
  // A bicubic surface cut by the plane z = 1/16 (exact arithmetic certifies a common point). In
  // double a round-to-nearest |D|^2 went below 0 (-1.49e-16) and became the minimum.
  const auto d = surface_distance(round_spline<double>(repro("bicubic2.json")), round_spline<double>(repro("cut_plane.json")));
  CHECK(0 <= d.distance2_lo);
  CHECK(d.distance2_lo <= d.distance2_hi);
  CHECK((d.intersecting || d.intersection_undecided));
  for (const auto& p : d.points) CHECK((0 <= p.d2_lo && p.d2_lo <= p.d2_hi));
  for (const auto& p : d.undecided) CHECK((0 <= p.d2_lo && p.d2_lo <= p.d2_hi));
  CHECK_FALSE(d.closest_certified);
}

TEST_CASE("contact: surfaces 2^-20 apart end in a certified pair, not in an empty verdict", "[solve]") {
  // The paraboloid's vertex over a plane 2^-20 below it: within 2^-16 of the model's size the
  // search looked for a common point, found none, and stopped with nothing listed.
  const auto d = surface_distance(repro("paraboloid.json"), repro("pl_m2e20.json"));
  const R d2 = R(1) / R(boost::multiprecision::mpz_int(1) << 40);
  CHECK_FALSE(d.intersecting);
  CHECK_FALSE(d.intersection_undecided);
  CHECK(d.distance2_lo == d2);
  CHECK(d.distance2_hi == d2);
  REQUIRE(d.closest.size() == 1);
  CHECK(d.closest_certified);
  CHECK(d.points[d.closest[0]].p1 == std::vector<R>{R(0), R(0), R(0)});
}

// Issue 47 (planted bugs, tests/solve/test_planted.cpp): the certificates' regression checks.
TEST_CASE("contact: two wells over a plane, the deeper inside boxes whose corners are all farther", "[solve]") {
  // z = 1 + h(x) + y^2 over the plane z = 0, h = (x + 1/2)^2 ((x - 1/3)^2 - 1/256): the well at
  // x = -1/2 (a split point) has d^2 = 1 exactly and is met first; the deeper one near x = 1/3 lies
  // in boxes whose corners are all farther than 1 (h > 0 at x = 0, 1/4, 1/2, 1): only the boxes'
  // lower bounds may prune them. The pair at (1/3, 0) has d^2 = (9191/9216)^2, an exact upper
  // bound of the minimum.
  const auto S = test::spline(R"({"type": "bspline", "degrees": [4, 2], "knots": [[-1, -1, -1, -1, -1, 1, 1, 1, 1, 1], [-1, -1, -1, 1, 1, 1]],
    "points": [["-1", "-1", "22519/9216"], ["-1/2", "-1", "11273/9216"], ["0", "-1", "86537/27648"], ["1/2", "-1", "2551/3072"],
               ["1", "-1", "3063/1024"], ["-1", "0", "4087/9216"], ["-1/2", "0", "-7159/9216"], ["0", "0", "31241/27648"],
               ["1/2", "0", "-3593/3072"], ["1", "0", "1015/1024"], ["-1", "1", "22519/9216"], ["-1/2", "1", "11273/9216"],
               ["0", "1", "86537/27648"], ["1/2", "1", "2551/3072"], ["1", "1", "3063/1024"]]})");
  REQUIRE(evaluate(S, {R(-1, 2), R(0)}) == std::vector<R>{R(-1, 2), R(0), R(1)});
  REQUIRE(evaluate(S, {R(1, 3), R(0)}) == std::vector<R>{R(1, 3), R(0), R(9191, 9216)});
  const R closer = R(9191, 9216) * R(9191, 9216);
  const auto r = surface_distance(S, plane(R(0)));
  CHECK_FALSE(r.intersecting);
  CHECK(r.distance2_lo <= closer);
  CHECK(r.distance2_hi <= closer);
  REQUIRE(r.closest_certified);
  const auto& c = r.points[r.closest[0]];
  CHECK(c.unique);
  CHECK(R(1, 4) < c.lo[0]);  // the deeper well, near x = 1/3
  CHECK(c.hi[0] < R(1, 2));
}
