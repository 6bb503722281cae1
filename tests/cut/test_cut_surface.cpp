// papers/004 Section 4 for d = 3: the cutting surface (domain polygon, the quadratic initial patch)
// and the exact certificates of its validity, on surfaces whose verdict is known by construction.
#include <catch2/catch.hpp>

#include "cut/examples.hpp"
#include "cut/surface_facet.hpp"
#include "exact/linear_solve.hpp"
#include "spline/errors.hpp"
#include "spline/evaluate.hpp"
#include "spline/factories.hpp"

using namespace splinex;

namespace {
Rational q(long a, long b = 1) { return Rational(a, b); }

struct Normalized {
  Solid3<Rational> solid;
  std::vector<LoopSide3> loop;
  std::vector<std::size_t> positive;
};

Normalized normalized(const std::string& name) {
  const auto e = cut_example3(name);
  Normalized n;
  n.solid = to_frame(e.solid, unit_frame(e.solid));
  n.loop = validate_cut(n.solid, e.cut);
  n.positive = e.cut.positive;
  return n;
}

// Greville abscissae of a cubic knot vector: (U[i+1] + U[i+2] + U[i+3]) / 3.
std::vector<Rational> greville(const std::vector<Rational>& U) {
  std::vector<Rational> g;
  for (std::size_t i = 0; i + 4 < U.size(); ++i) g.push_back((U[i + 1] + U[i + 2] + U[i + 3]) / 3);
  return g;
}

// p_u m_u + p_v m_v dotted with t at w, by finite means independent of the certificate: the
// derivative of the polynomial patch from evaluate's derivative orders.
Rational inward_derivative(const BSpline<Rational>& p, const std::array<Rational, 2>& w, const std::array<Rational, 2>& m,
                           const std::array<Rational, 3>& t) {
  const auto du = derivative(p, std::vector<Rational>{w[0], w[1]}, {1, 0});
  const auto dv = derivative(p, std::vector<Rational>{w[0], w[1]}, {0, 1});
  Rational s(0);
  for (int c = 0; c < 3; ++c) s += t[c] * (du[c] * m[0] + dv[c] * m[1]);
  return s;
}
}  // namespace

TEST_CASE("cut surface: Step 1, the domain polygon by projection or on the circle", "[cut]") {
  const auto cube = normalized("cube");
  const auto D = domain_polygon(cube.loop);
  CHECK(D.method == "projection");
  REQUIRE(D.vertices.size() == cube.loop.size());
  // the loop runs at z = 1/2 around [0,1]^2: its projection along z is the unit square's boundary
  for (std::size_t j = 0; j < D.vertices.size(); ++j) {
    CHECK(D.vertices[j][0] == cube.loop[j].start[D.axes[0]]);
    CHECK(D.vertices[j][1] == cube.loop[j].start[D.axes[1]]);
  }
  // counter-clockwise: twice the signed area is +2 (the unit square)
  Rational a2(0);
  for (std::size_t j = 0; j < D.vertices.size(); ++j) {
    const auto &p = D.vertices[j], &r = D.vertices[(j + 1) % D.vertices.size()];
    a2 += p[0] * r[1] - r[0] * p[1];
  }
  CHECK(a2 == 2);

  // the maiden's loop has vertical sides, which collapse in the projection along z: the circle
  const auto maiden = normalized("maiden");
  const auto M = domain_polygon(maiden.loop);
  CHECK(M.method == "circle");
  CHECK(M.why_not_projection.find("collapses") != std::string::npos);
  for (const auto& w : M.vertices) {
    const Rational r2 = (w[0] - q(1, 2)) * (w[0] - q(1, 2)) + (w[1] - q(1, 2)) * (w[1] - q(1, 2));
    CHECK(abs(r2 - q(1, 4)) < q(1, 1000));  // on the circle within the 2^-11 grid
  }
  CHECK_THROWS_AS(domain_polygon(maiden.loop, "projection"), DomainError);
  CHECK_THROWS_AS(domain_polygon(maiden.loop, "square"), UsageError);
}

TEST_CASE("cut surface: the cube's patch is the plane z = 1/2 with linear precision, certified valid", "[cut]") {
  const auto cube = normalized("cube");
  const auto R = cutting_surface<Rational>(cube.loop);
  CHECK(R.kkt_holds);
  CHECK(R.active_inequalities == 0);
  // The planar patch p(u, v) = (u, v, 1/2) interpolates every boundary sample with zero thin-plate
  // energy and zero normal term, so it is the unique minimizer: control points at the Greville
  // abscissae, exactly.
  const auto g = greville(R.patch.knots[0]);
  const std::size_t n = g.size();
  REQUIRE(R.patch.points.size() == 3 * n * n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t k = 3 * (i + n * j);
      CHECK(R.patch.points[k] == g[i]);
      CHECK(R.patch.points[k + 1] == g[j]);
      CHECK(R.patch.points[k + 2] == q(1, 2));
    }
  const auto V = certify_cutting_surface(cube.solid, cube.loop, R.domain, R.patch);
  CHECK(V.verdict == "valid");
  CHECK(V.vertices_exact);
  CHECK(V.boundary_deviation == 0);
  CHECK(V.tangents == "certified");
  CHECK(V.regular == "proved");
  CHECK(V.injective == "proved");
  CHECK(V.collision_undecided == 0);
  CHECK(V.collision_pieces > 0);

  // double: the same program in double, judged exactly against the exact patch
  const auto D = cutting_surface<double>(cube.loop);
  REQUIRE(D.coefficients.size() == R.coefficients.size());
  for (std::size_t i = 0; i < D.coefficients.size(); ++i) CHECK(abs(D.coefficients[i] - R.coefficients[i]) < Rational(1, 1LL << 40));

  // the split: b's facets and b-bar's, every facet in exactly one part
  const auto sp = split_by_surface(cube.solid, cube.positive);
  CHECK(sp.part1.size() + sp.part2.size() == cube.solid.facets.size());
  CHECK(sp.part1.size() == cube.positive.size());
}

TEST_CASE("cut surface: a patch whose inward derivative opposes the tangents is refuted with an exact witness", "[cut]") {
  const auto cube = normalized("cube");
  const auto D = domain_polygon(cube.loop);
  // x(u) = y(u) = the cubic Bezier 0, -2/3, 5/3, 1: x(0) = 0, x(1) = 1, x'(0) = x'(1) = -2 < 0;
  // z = 1/2. It passes through the loop's vertices but leaves the boundary outwards.
  const std::array<Rational, 4> b{q(0), q(-2, 3), q(5, 3), q(1)};
  const auto p = bezier_from<Rational>({3, 3}, 3, [&](const std::vector<std::size_t>& idx) {
    return std::vector<Rational>{b[idx[0]], b[idx[1]], q(1, 2)};
  });
  const auto V = certify_cutting_surface(cube.solid, cube.loop, D, p);
  CHECK(V.verdict == "invalid");
  CHECK(V.tangents == "violated");
  REQUIRE(V.witness);
  CHECK(V.witness->condition == "tangent");
  CHECK(V.witness->value <= 0);
  // the witness, recomputed from the patch's derivatives at the witness parameters: on an edge of
  // Omega (the unit square) whose loop side has the tangent the certificate used
  const auto& w = V.witness->param;
  bool confirmed = false;
  for (std::size_t j = 0; j < D.vertices.size(); ++j) {
    const auto &a = D.vertices[j], &c = D.vertices[(j + 1) % D.vertices.size()];
    const std::array<Rational, 2> e{c[0] - a[0], c[1] - a[1]};
    if ((w[0] - a[0]) * e[1] != (w[1] - a[1]) * e[0]) continue;  // not on this edge's line
    const Rational em = std::max(abs(Rational(e[0])), abs(Rational(e[1])));
    const Rational g = inward_derivative(p, w, {-e[1] / em, e[0] / em}, cube.loop[j].tangent);
    if (g == V.witness->value) confirmed = g <= 0;
  }
  CHECK(confirmed);
}

TEST_CASE("cut surface: a patch bulging into the slot collides, and the witness lies in the empty slot", "[cut]") {
  const auto s = normalized("slotted");  // block [0,1] x [0,2/5] x [0,2/5] (scale 5), slot [1/5,2/5] x [0,2/5] x [1/5,2/5]
  const auto R = cutting_surface<Rational>(s.loop);
  const auto V = certify_cutting_surface(s.solid, s.loop, R.domain, R.patch);
  CHECK(V.verdict == "valid");
  // raise the interior control points by 3/10 in z: the middle of the patch rises into the slot
  auto bulged = R.patch;
  const std::size_t n = bulged.count(0);
  for (std::size_t j = 1; j + 1 < n; ++j)
    for (std::size_t i = 1; i + 1 < n; ++i) bulged.points[3 * (i + n * j) + 2] += q(3, 10);
  const auto B = certify_cutting_surface(s.solid, s.loop, R.domain, bulged);
  CHECK(B.verdict == "invalid");
  REQUIRE(B.witness);
  CHECK(B.witness->condition == "collision");
  const auto& x = B.witness->point;
  const auto px = evaluate(bulged, std::vector<Rational>{B.witness->param[0], B.witness->param[1]});
  CHECK(px == std::vector<Rational>{x[0], x[1], x[2]});
  // independently of ray parity: in the slot's open box (empty), or above the block
  const bool in_slot = x[0] > q(1, 5) && x[0] < q(2, 5) && x[1] > 0 && x[1] < q(2, 5) && x[2] > q(1, 5);
  CHECK(in_slot);
  CHECK(point_in_solid(s.solid, x) == Membership::outside);
}

TEST_CASE("cut surface: exact point membership by ray parity", "[cut]") {
  const auto t = cut_example3("tower");  // [0,1]^2 x [0,2]
  CHECK(point_in_solid(t.solid, {q(1, 2), q(1, 2), q(1)}) == Membership::inside);
  CHECK(point_in_solid(t.solid, {q(1, 3), q(2, 7), q(19, 10)}) == Membership::inside);
  CHECK(point_in_solid(t.solid, {q(2), q(0), q(0)}) == Membership::outside);
  CHECK(point_in_solid(t.solid, {q(1, 2), q(1, 2), q(21, 10)}) == Membership::outside);
  CHECK(point_in_solid(t.solid, {q(0), q(1, 2), q(1, 2)}) == Membership::boundary);
  CHECK(point_in_solid(t.solid, {q(1), q(1), q(1)}) == Membership::boundary);  // on an edge
  // the slotted block: a point in the slot is outside, a point in a tooth inside
  const auto s = cut_example3("slotted");
  CHECK(point_in_solid(s.solid, {q(3, 2), q(1), q(3, 2)}) == Membership::outside);
  CHECK(point_in_solid(s.solid, {q(5, 2), q(1), q(3, 2)}) == Membership::inside);
}

TEST_CASE("cut surface: the maiden's initial patch (the paper's quadratic solution) is refuted", "[cut]") {
  // The wave-shaped loop cannot be followed by a 7 x 7 bicubic net: the initial solution's
  // prescribed tangents fail somewhere, which the certificate finds with an exact witness.
  const auto m = normalized("maiden");
  const auto R = cutting_surface<Rational>(m.loop);
  CHECK(R.kkt_holds);
  CHECK(R.domain.method == "circle");
  const auto V = certify_cutting_surface(m.solid, m.loop, R.domain, R.patch);
  CHECK(V.verdict == "invalid");
  REQUIRE(V.witness);
  CHECK(V.vertices_exact);
  CHECK(V.boundary_deviation > q(1, 16));
}

TEST_CASE("cut surface: bad options and bad surfaces get typed errors", "[cut]") {
  const auto cube = normalized("cube");
  SurfaceFacetOptions o;
  o.inner_knots = 16;
  CHECK_THROWS_AS(cutting_surface<Rational>(cube.loop, o), UsageError);
  o = {};
  o.weight_boundary = 0;
  CHECK_THROWS_AS(cutting_surface<Rational>(cube.loop, o), UsageError);
  o = {};
  o.strip = 0;
  CHECK_THROWS_AS(validate_surface_options(o), UsageError);
  // a clockwise domain, and one vertex short
  auto D = domain_polygon(cube.loop);
  const auto R = cutting_surface<Rational>(cube.loop);
  auto rev = D;
  std::reverse(rev.vertices.begin(), rev.vertices.end());
  CHECK_THROWS_AS(certify_cutting_surface(cube.solid, cube.loop, rev, R.patch), DomainError);
  auto shorter = D;
  shorter.vertices.pop_back();
  CHECK_THROWS_AS(certify_cutting_surface(cube.solid, cube.loop, shorter, R.patch), UsageError);
}

TEST_CASE("exact linear solves and ranks (FLINT) against hand results", "[cut]") {
  // [2 1; 1 3] x = [1; 2]: x = (1/5, 3/5) by Cramer's rule (det 5)
  const auto X = solve_linear_exact({q(2), q(1), q(1), q(3)}, 2, {q(1), q(2)}, 1);
  REQUIRE(X);
  CHECK(*X == std::vector<Rational>{q(1, 5), q(3, 5)});
  // two right-hand sides, rational entries: [1/2 0; 0 1/3] X = [1 2; 3 4] gives [2 4; 9 12]
  const auto Y = solve_linear_exact({q(1, 2), q(0), q(0), q(1, 3)}, 2, {q(1), q(2), q(3), q(4)}, 2);
  REQUIRE(Y);
  CHECK(*Y == std::vector<Rational>{q(2), q(4), q(9), q(12)});
  CHECK_FALSE(solve_linear_exact({q(1), q(2), q(2), q(4)}, 2, {q(1), q(1)}, 1));
  CHECK(exact_rank({q(1), q(2), q(3), q(2), q(4), q(6)}, 2, 3) == 1);
  CHECK(exact_rank({q(1, 3), q(2), q(3), q(2), q(4, 7), q(6)}, 2, 3) == 2);
  CHECK(exact_rank({q(0), q(0), q(0), q(0)}, 2, 2) == 0);
}
