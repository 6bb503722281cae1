// The hybrid patch (hybrid/hybrid.hpp): Wachspress coordinates against CGAL exactly, the rational
// form of s_i (Eq. 2.9 = Eq. 2.5), the limits at corners and at a triangle's opposite vertex,
// boundary interpolation (Theorem 3.1) spot checks, float vs exact, typed errors.
#include <catch2/catch.hpp>

#include <random>
#include <sstream>

#include "fixtures/hybrid_examples.hpp"
#include "hybrid/wachspress_check.hpp"
#include "io/hybrid_io.hpp"
#include "float/mpfr.hpp"
#include "hybrid/hybrid.hpp"
#include "hybrid/form.hpp"
#include "spline/kernel.hpp"

using namespace splinex;

namespace {
using P2 = std::array<Rational, 2>;

// Random rational points strictly inside the convex domain: convex combinations of the vertices.
std::vector<P2> interior_points(const HybridPatch<Rational>& P, std::size_t count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<P2> out;
  while (out.size() < count) {
    std::vector<Rational> w;
    Rational sum = 0;
    for (std::size_t k = 0; k < P.sides(); ++k) {
      w.push_back(Rational(static_cast<long>(rng() % 97 + 1)));
      sum += w.back();
    }
    P2 x{0, 0};
    for (std::size_t k = 0; k < P.sides(); ++k)
      for (int c = 0; c < 2; ++c) x[c] += w[k] / sum * P.vertices[k][c];
    out.push_back(x);
  }
  return out;
}

std::vector<HybridPatch<Rational>> examples() {
  auto tri = hybrid_dome({{0, 0}, {1, 0}, {Rational(1, 3), 1}}, 5, {2, 3, 1}, {uniform_clamped_knots(5, 2), uniform_clamped_knots(5, 3), uniform_clamped_knots(5, 1)});
  return {hybrid_example_2_1(), hybrid_example_3_1_hexagon(), hybrid_example_3_1_octagon(), tri};
}
}  // namespace

TEST_CASE("hybrid: Wachspress coordinates equal CGAL's exactly, reproduce linear functions, s_i of Eq. 2.9 = Eq. 2.5") {
  for (const auto& P : examples()) {
    const std::size_t n = P.sides();
    for (const auto& x : interior_points(P, 12, 7)) {
      const auto L = hybrid_local(P, x);
      CHECK(L.lambda == cgal_wachspress(P.vertices, x));
      Rational sum = 0, px = 0, py = 0;
      for (std::size_t k = 0; k < n; ++k) {
        sum += L.lambda[k];
        px += L.lambda[k] * P.vertices[k][0];
        py += L.lambda[k] * P.vertices[k][1];
      }
      CHECK(sum == 1);
      CHECK(px == x[0]);
      CHECK(py == x[1]);
      for (std::size_t i = 0; i < n; ++i) {
        const Rational &a = L.lambda[i], &b = L.lambda[(i + 1) % n];
        CHECK(L.s[i] == b / (a + b));  // the continuous rational form agrees with Eq. 2.5 inside
        CHECK(L.h[i] == 1 - a - b);
      }
    }
  }
}

TEST_CASE("hybrid: limits at corners and at a triangle's opposite vertex are the shared corner points") {
  for (const auto& P : examples()) {
    for (std::size_t k = 0; k < P.sides(); ++k) {
      // Corner V_k is the start of side k: S(V_k) = C^k_{0,0} = P_k(0) = P_{k-1}(1).
      const std::vector<Rational> corner(P.points.begin() + P.index(k, 0, 0), P.points.begin() + P.index(k, 0, 0) + P.q);
      CHECK(hybrid_evaluate(P, P.vertices[k]) == corner);
      CHECK(hybrid_boundary(P, k, Rational(0)) == corner);
      CHECK(hybrid_boundary(P, (k + P.sides() - 1) % P.sides(), Rational(1)) == corner);
      // Continuity: approaching V_k from inside (towards the centroid) the patch tends to the corner.
      P2 G{0, 0};
      for (const auto& v : P.vertices)
        for (int c = 0; c < 2; ++c) G[c] += v[c] / static_cast<long>(P.sides());
      Rational prev = -1;
      for (const Rational& eps : {Rational(1, 100), Rational(1, 10000), Rational(1, 1000000)}) {
        const P2 x{P.vertices[k][0] + eps * (G[0] - P.vertices[k][0]), P.vertices[k][1] + eps * (G[1] - P.vertices[k][1])};
        const auto S = hybrid_evaluate(P, x);
        Rational dist = 0;
        for (int c = 0; c < P.q; ++c) dist = std::max(dist, abs(Rational(S[c] - corner[c])));
        if (prev >= 0) CHECK(dist < prev);
        CHECK(dist < 200 * eps);
        prev = dist;
      }
    }
  }
}

TEST_CASE("hybrid: Theorem 3.1 spot check, boundary points equal P_i(t) exactly") {
  const auto P = hybrid_example_3_1_hexagon();
  for (std::size_t i = 0; i < P.sides(); ++i)
    for (const Rational& t : {Rational(1, 7), Rational(1, 2), Rational(5, 6), Rational(99, 100)}) {
      const auto &A = P.vertices[i], &B = P.vertices[(i + 1) % P.sides()];
      const P2 x{A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1])};
      CHECK(hybrid_evaluate(P, x) == hybrid_boundary(P, i, t));
    }
  // Inside, the patch is not its boundary curve: the check can fail.
  const auto G = interior_points(P, 1, 3)[0];
  CHECK(hybrid_evaluate(P, G) != hybrid_boundary(P, 0, hybrid_local(P, G).s[0]));
}

TEST_CASE("hybrid: double and MPFR evaluation measured exactly against the rational patch") {
  const auto P = hybrid_example_2_1();
  const auto Pd = convert_hybrid<double>(P, [](const Rational& r) { return to_double(r); });
  Mpfr::Precision scope(200);
  const auto Pm = convert_hybrid<Mpfr>(P, [](const Rational& r) { return Mpfr(r); });
  for (const auto& x : interior_points(P, 8, 11)) {
    const auto E = hybrid_evaluate(P, x);
    const auto D = hybrid_evaluate(Pd, std::array<double, 2>{to_double(x[0]), to_double(x[1])});
    const auto M = hybrid_evaluate(Pm, std::array<Mpfr, 2>{Mpfr(x[0]), Mpfr(x[1])});
    for (int c = 0; c < 3; ++c) {
      CHECK(abs(Rational(exact_from_double(D[c]) - E[c])) < Rational(1, 1000000000000LL));
      CHECK(abs(Rational(to_rational(M[c]) - E[c])) < Rational(1, Integer(1) << 180));
    }
  }
}

TEST_CASE("hybrid: the literal factor of Eq. 2.11 divides by zero at j = 0 for clamped knots") {
  auto P = hybrid_example_2_1();
  P.ribbon = RibbonFactor::eq_2_11;
  // Near side 0's start, N_0 != 0: the literal ribbon needs p / (U_2 - U_0) = 2 / 0.
  CHECK_THROWS_AS(hybrid_cross_tangent(P, 0, Rational(1, 10)), DomainError);
  CHECK_THROWS_WITH(hybrid_cross_tangent(P, 0, Rational(1, 10)), Catch::Contains("p / (U_{p+j} - U_j) is p/0 at j = 0"));
  // Beyond the first span only j >= 1 enter, and there it is defined.
  CHECK_NOTHROW(hybrid_cross_tangent(P, 0, Rational(1, 2)));
}

TEST_CASE("hybrid patch documents: round trip and typed errors") {
  const auto P = hybrid_example_2_1();
  const Json doc = hybrid_to_json(P);
  const auto reparse = [](const Json& j) {
    std::istringstream in(j.dump());
    return read_json(in, "test");
  };
  const auto Q = hybrid_from_json(reparse(doc));
  CHECK(Q.points == P.points);
  CHECK(Q.knots == P.knots);
  auto expect = [&](const std::function<void(Json&)>& edit, const std::string& what) {
    Json d = reparse(doc);
    edit(d);
    INFO(what);
    try {
      hybrid_from_json(d);
      FAIL("no error");
    } catch (const Error& e) {
      CHECK_THAT(std::string(e.what()), Catch::Contains(what));
    }
  };
  expect([](Json& d) { std::swap(d["domain"][1], d["domain"][2]); }, "not convex");
  expect([](Json& d) {
    Json r = Json::array();
    for (std::size_t k = d["domain"].size(); k-- > 0;) r.push_back(d["domain"][k]);
    d["domain"] = r;
  }, "domain: is clockwise");
  expect([](Json& d) { d["domain"][2] = d["domain"][1]; }, "is degenerate");
  expect([](Json& d) { d["sides"][2]["knots"].erase(3); }, "sides[2].knots: has 9 knots");
  expect([](Json& d) { d["sides"][1]["layers"][0][0][2] = "7"; }, "disagrees with sides[0]");
  expect([](Json& d) { d["degree"] = "2"; }, "layers");
  expect([](Json& d) { d["sides"].erase(4); }, "sides: has 4 entries for 5 domain sides");
  expect([](Json& d) { d["sides"][0]["knots"][0] = "-1/2"; }, "not clamped on [0, 1]");
  expect([](Json& d) { d["ribbon_factor"] = "other"; }, "ribbon_factor");
}

TEST_CASE("hybrid: exact derivatives converge like symmetric difference quotients, s_i is constant along its iso-line") {
  const auto P = hybrid_example_3_1_hexagon();
  for (const auto& x : interior_points(P, 4, 7)) {
    const auto D = hybrid_derivatives(P, x);
    REQUIRE(D.point == hybrid_evaluate(P, x));
    for (int dir = 0; dir < 2; ++dir) {
      const auto& exact = dir == 0 ? D.du : D.dv;
      // (S(x + e) - S(x - e)) / 2e - S' = O(e^2): the error must drop by about 4 when e halves.
      auto err = [&](const Rational& e) {
        P2 a = x, b = x;
        a[dir] += e;
        b[dir] -= e;
        const auto Sa = hybrid_evaluate(P, a), Sb = hybrid_evaluate(P, b);
        Rational m = 0;
        for (std::size_t c = 0; c < Sa.size(); ++c) m = std::max(m, Rational(abs(Rational((Sa[c] - Sb[c]) / (2 * e) - exact[c]))));
        return m;
      };
      const Rational e1 = err(Rational(1, 1000)), e2 = err(Rational(1, 2000));
      REQUIRE(e1 > 0);
      REQUIRE(e2 * 3 < e1);
      REQUIRE(e2 * 5 > e1);
    }
    for (std::size_t i = 0; i < P.sides(); ++i) {
      const auto C = hybrid_cross_derivative(P, i, x);
      const auto J = hybrid_jet(P, x, C.direction);
      REQUIRE(J.local_derivative.s[i] == 0);
      REQUIRE(J.local_derivative.h[i] != 0);
    }
  }
  REQUIRE_THROWS_AS(hybrid_derivatives(P, P.vertices[2]), DomainError);
  const auto Pd = convert_hybrid<double>(P, [](const Rational& r) { return to_double(r); });
  const P2 x = interior_points(P, 1, 3)[0];
  const auto De = hybrid_derivatives(P, x);
  const auto Df = hybrid_derivatives(Pd, std::array<double, 2>{to_double(x[0]), to_double(x[1])});
  for (std::size_t c = 0; c < 3; ++c) REQUIRE(abs(Rational(Rational(Df.du[c]) - De.du[c])) < Rational(1, 1000000000));
}

TEST_CASE("hybrid: Theorem 3.2 holds exactly on open sides and fails at corners with unequal end factors") {
  const auto P = hybrid_example_3_1_hexagon();
  for (std::size_t i = 0; i < P.sides(); ++i) {
    const auto& A = P.vertices[i];
    const auto& B = P.vertices[(i + 1) % P.sides()];
    for (const Rational& t : {Rational(1, 7), Rational(1, 2), Rational(5, 6)}) {
      const P2 x{A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1])};
      REQUIRE(hybrid_cross_derivative(P, i, x).value == hybrid_cross_tangent(P, i, t));
    }
  }
  // Corner V_1: side 0 has p = 5 (end factor 5 / (1/2) = 10), side 1 p = 3 (ribbon factor 3 / (1/4) = 12).
  auto along = derivative(hybrid_boundary_spline(P, 0), {Rational(1)}, {1});
  for (auto& c : along) c = -c;
  const auto T1 = hybrid_cross_tangent(P, 1, Rational(0));
  REQUIRE(along != T1);
  for (std::size_t c = 0; c < 3; ++c) REQUIRE(along[c] * 12 == T1[c] * 10);
  // The cross derivative near the corner tends to T_1(0), not to the corner's value.
  const auto& A = P.vertices[1];
  const auto& B = P.vertices[2];
  const Rational t(1, 100000);
  const auto near = hybrid_cross_derivative(P, 1, P2{A[0] + t * (B[0] - A[0]), A[1] + t * (B[1] - A[1])}).value;
  REQUIRE(near == hybrid_cross_tangent(P, 1, t));
}

TEST_CASE("hybrid: improved elevation (Eq. 4.5, 4.6) and knot insertion (Eq. 4.8-4.12) keep the patch, Salvi's moves it") {
  const auto P = hybrid_example_2_1();
  const auto F = hybrid_form(P);
  const auto xs = interior_points(P, 12, 11);
  for (const auto& x : xs) REQUIRE(hybrid_form_evaluate(F, x) == hybrid_evaluate(P, x));
  auto G = F;
  for (int r = 0; r < 3; ++r) {
    const auto c = make_spline<Rational>({G.sides[1].p}, {G.sides[1].Ub}, 3, G.sides[1].Tbar);
    const auto k = elevate_degree(c, 0, 1);
    G = hybrid_elevate(G);
    REQUIRE(k.points == G.sides[1].Tbar);
  }
  REQUIRE(G.sides[0].du == 21);  // Example 4.1: S^{6,2} -> S^{21,5}
  REQUIRE(G.sides[0].p == 5);
  REQUIRE(G.sides[0].count_b() == 22);
  for (const auto& x : xs) REQUIRE(hybrid_form_evaluate(G, x) == hybrid_evaluate(P, x));
  auto R = F;
  for (int k = 0; k < 5; ++k) R = hybrid_insert(R, Rational(k + 1, 6), Rational(k + 1, 6), Rational(2 * k + 1, 10));
  REQUIRE(R.sides[0].count_u() == 12);
  REQUIRE(R.sides[0].count_b() == 12);
  for (const auto& x : xs) REQUIRE(hybrid_form_evaluate(R, x) == hybrid_evaluate(P, x));
  REQUIRE_THROWS_AS(hybrid_elevate(R), DomainError);                                       // interior no longer Bernstein
  REQUIRE_THROWS_AS(hybrid_insert(F, Rational(0), Rational(1, 2), Rational(1, 2)), DomainError);  // not inside (0, 1)
  auto M = hybrid_insert(F, Rational(1, 2), Rational(1, 2), Rational(1, 5));  // U^b's 1/5 now twice = p
  REQUIRE_THROWS_AS(hybrid_insert(M, Rational(1, 3), Rational(1, 3), Rational(1, 5)), DomainError);  // would be 3 > p = 2
  REQUIRE_THROWS_AS(hybrid_elevate_salvi(P), DomainError);                                 // d = 6 even, B-spline sides
  const auto B = hybrid_dome(P.vertices, 5, std::vector<int>(5, 5), std::vector<std::vector<Rational>>(5, uniform_clamped_knots(5, 5)));
  const auto Q = hybrid_elevate_salvi(B);
  const auto E = hybrid_elevate(hybrid_form(B));
  bool moved = false;
  for (const auto& x : xs) {
    moved = moved || hybrid_evaluate(Q, x) != hybrid_evaluate(B, x);
    REQUIRE(hybrid_form_evaluate(E, x) == hybrid_evaluate(B, x));
  }
  REQUIRE(moved);
}

TEST_CASE("hybrid: Example 3.2 holes share their corner points exactly and meet the neighbours' boundaries") {
  for (int n : {5, 6}) {
    const auto H = hybrid_hole_example_3_2(n);
    REQUIRE(H.conflicts == static_cast<std::size_t>(n));  // one disagreeing twist per corner
    for (std::size_t i = 0; i < H.patch.sides(); ++i)
      for (const Rational& t : {Rational(0), Rational(1, 3), Rational(1)})
        REQUIRE(hybrid_boundary(H.patch, i, t) == evaluate(H.neighbours[i], {t, Rational(0)}));
  }
  REQUIRE_THROWS_AS(hybrid_hole_example_3_2(7), UsageError);
}
