// splinex::verify (issue 16): candidates whose error is known by construction.
#include <catch2/catch.hpp>
#include <random>

#include "crosscheck/verify.hpp"
#include "fixtures/random_spline.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"

using namespace splinex;

namespace {

BSpline<Rational> rounded_to_double(const BSpline<Rational>& S) {
  BSpline<Rational> R = S;
  for (auto& U : R.knots)
    for (auto& u : U) u = exact_from_double(to_double(u));
  for (auto& x : R.points) x = exact_from_double(to_double(x));
  for (auto& w : R.weights) w = exact_from_double(to_double(w));
  return R;
}

Operation elevate_by(int t) {
  Operation op = Operation::parse_kind("elevate");
  op.by = t;
  return op;
}

/// max over x of the B-spline basis function N_k of direction 0 (a curve), from its Bernstein
/// coefficients after inserting the knots of its support to full multiplicity: an upper bound,
/// attained at a Bezier end point or approached by it; here the true maximum is taken on a fine
/// exact grid, which is a lower bound, and the two are within the test's factor.
Rational basis_max_sampled(const BSpline<Rational>& S, std::size_t k, int samples) {
  BSpline<Rational> E = S;
  E.q = 1;
  E.points.assign(S.count(0), Rational(0));
  E.weights.clear();
  E.points[k] = 1;
  Rational m(0);
  for (int i = 0; i <= samples; ++i) {
    const Rational x = S.domain_lo(0) + (S.domain_hi(0) - S.domain_lo(0)) * Rational(i, samples);
    m = std::max(m, evaluate(E, {x})[0]);
  }
  return m;
}

}  // namespace

TEST_CASE("verify: the exact result itself is equal, error 0, proved") {
  std::mt19937_64 rng(16);
  for (int i = 0; i < 10; ++i) {
    StructuredOptions so;
    so.max_dim = 2;
    so.rational = false;
    const auto S = structured_case(rng, so).spline;
    const auto op = elevate_by(1);
    const auto R = run_operation(op, S, Limits{});
    const auto rep = verify(op, S, R);
    CHECK(rep.structure == "equal");
    CHECK(rep.coefficients_compared);
    CHECK(rep.control_points.max_abs == 0);
    CHECK(rep.function.certified);
    CHECK(rep.function.upper == 0);
    CHECK(rep.function.within_factor);
  }
}

TEST_CASE("verify: the exact result rounded to double loses at most a bit or two") {
  std::mt19937_64 rng(1616);
  for (int i = 0; i < 10; ++i) {
    RandomSplineSpec spec;
    spec.degrees = {1 + static_cast<int>(rng() % 6)};
    spec.counts = {static_cast<std::size_t>(spec.degrees[0] + 2 + rng() % 20)};
    spec.q = 2;
    const auto S = random_spline(spec, rng);  // decimal data: the rounding is real
    Operation op = Operation::parse_kind("insert-knots");
    op.knots = {Rational(1, 3), Rational(7, 10)};
    const auto R = run_operation(op, S, Limits{});
    const auto rep = verify(op, S, {rounded_to_double(R[0])});
    CHECK(rep.structure != "different");
    CHECK(rep.control_points.bits_lost(53) <= 1);
    // As a function the rounded knots count too: moving a knot by an ulp changes the function by
    // about |S'| times that ulp, which exceeds the coefficients' own rounding where knots are close
    // (up to 8 bits here). The bound is still certified and witnessed within the factor.
    CHECK(rep.function.certified);
    CHECK(rep.function.within_factor);
    CHECK(rep.function.lower <= rep.function.upper);
    // With the knots kept exact the function error is the coefficients' (convex hull): <= 1 bit.
    BSpline<Rational> coefficients_only = R[0];
    for (auto& x : coefficients_only.points) x = exact_from_double(to_double(x));
    const auto rep2 = verify(op, S, {coefficients_only});
    CHECK(rep2.structure == "equal");
    CHECK(rep2.function.upper <= rep2.control_points.max_abs);
    CHECK(rep2.document()["function"]["bits_lost"].get<double>() <= 1);
  }
}

TEST_CASE("verify: another representation of the same function has function error 0 and a different structure") {
  const auto S = test::spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,0.25,0.5,1,1,1]],"points":[[0,1],[1,3],[2,0],[4,4],[5,1]]})");
  const auto op = elevate_by(1);
  const auto R = run_operation(op, S, Limits{});
  // Extra knots, and one degree more again: the same function.
  const auto C = elevate_degree(refine_knots(R[0], 0, {Rational(1, 8), Rational(3, 4)}), 0, 1);
  const auto rep = verify(op, S, {C});
  CHECK(rep.structure == "different");
  CHECK_FALSE(rep.coefficients_compared);
  CHECK(rep.function.certified);
  CHECK(rep.function.upper == 0);
  // A different domain is a finding, not an error.
  const auto shifted = reparametrize(R[0], 0, Rational(0), Rational(2));
  const auto rep2 = verify(op, S, {shifted});
  CHECK(rep2.structure == "different");
  CHECK(rep2.function.method.find("different domains") != std::string::npos);
  // Another point size cannot be the result: a typed error naming the field.
  BSpline<Rational> bad = R[0];
  bad.q = 1;
  bad.points.resize(bad.points.size() / 2);
  CHECK_THROWS_AS(verify(op, S, {bad}), ValidationError);
}

TEST_CASE("verify: a control point moved by 2^-40 is found, bounded within a factor of 2, at the right place") {
  std::mt19937_64 rng(40);
  for (int i = 0; i < 6; ++i) {
    RandomSplineSpec spec;
    spec.degrees = {2 + static_cast<int>(rng() % 4)};
    spec.counts = {static_cast<std::size_t>(spec.degrees[0] + 4 + rng() % 12)};
    spec.q = 3;
    spec.dyadic = true;
    const auto S = random_spline(spec, rng);
    const auto op = elevate_by(1);
    const auto R = run_operation(op, S, Limits{});
    BSpline<Rational> C = R[0];
    const std::size_t k = 1 + rng() % (C.count(0) - 2), coord = rng() % 3;
    const Rational eps = Rational(1) / (Integer(1) << 40);
    C.points[k * 3 + coord] += eps;
    const auto rep = verify(op, S, {C});
    CHECK(rep.structure == "equal");
    CHECK(rep.control_points.max_abs == eps);
    // The difference is eps * N_k: its sup is eps * max N_k.
    const Rational truth = eps * basis_max_sampled(C, k, 4096);
    CHECK(rep.function.certified);
    CHECK(rep.function.within_factor);
    CHECK(rep.function.upper >= truth);           // a bound (up to the sampling of the truth)
    CHECK(rep.function.upper <= 2 * rep.function.lower);
    CHECK(rep.function.lower <= rep.function.upper);
    CHECK(rep.function.upper <= 2 * truth);
    // Where: inside the support of N_k.
    REQUIRE(rep.function.at.size() == 1);
    CHECK(C.knots[0][k] <= rep.function.at[0]);
    CHECK(rep.function.at[0] <= C.knots[0][k + C.degrees[0] + 1]);
  }
}

TEST_CASE("verify: a planted error in a surface is bounded within the factor, inside its support") {
  std::mt19937_64 rng(4040);
  for (int i = 0; i < 4; ++i) {
    RandomSplineSpec spec;
    spec.degrees = {2 + static_cast<int>(rng() % 2), 1 + static_cast<int>(rng() % 3)};
    spec.counts = {static_cast<std::size_t>(spec.degrees[0] + 3 + rng() % 4), static_cast<std::size_t>(spec.degrees[1] + 3 + rng() % 4)};
    spec.q = 2;
    spec.dyadic = true;
    const auto S = random_spline(spec, rng);
    Operation op = elevate_by(1);
    op.dir = 1;
    const auto R = run_operation(op, S, Limits{});
    BSpline<Rational> C = R[0];
    const std::size_t n0 = C.count(0), i0 = 1 + rng() % (n0 - 2), i1 = 1 + rng() % (C.count(1) - 2);
    const Rational eps = Rational(1) / (Integer(1) << 40);
    C.points[(i1 * n0 + i0) * 2 + rng() % 2] -= eps;
    const auto rep = verify(op, S, {C});
    CHECK(rep.function.certified);
    CHECK(rep.function.within_factor);
    CHECK(rep.function.upper <= eps);  // the largest coefficient of eps * N_i0 N_i1 is eps at most
    CHECK(rep.function.upper <= 2 * rep.function.lower);
    REQUIRE(rep.function.at.size() == 2);
    CHECK(C.knots[0][i0] <= rep.function.at[0]);
    CHECK(rep.function.at[0] <= C.knots[0][i0 + C.degrees[0] + 1]);
    CHECK(C.knots[1][i1] <= rep.function.at[1]);
    CHECK(rep.function.at[1] <= C.knots[1][i1 + C.degrees[1] + 1]);
  }
}

TEST_CASE("verify: rational candidates get a certified bound too, within the factor") {
  // The exact quarter circle (weights 1, 1, 2 on (1,0), (1,1), (0,1)), elevated; the candidate
  // has one weight off by 2^-30.
  const auto S = test::spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[1,0],[1,1],[0,1]],"weights":[1,1,2]})");
  const auto op = elevate_by(1);
  const auto R = run_operation(op, S, Limits{});
  const auto same = verify(op, S, R);
  CHECK(same.function.certified);
  CHECK(same.function.upper == 0);
  BSpline<Rational> C = R[0];
  C.weights[1] += Rational(1, 1 << 30);
  const auto rep = verify(op, S, {C});
  CHECK(rep.structure == "equal");
  CHECK(rep.function.certified);
  CHECK(rep.function.within_factor);
  CHECK(rep.function.upper > 0);
  CHECK(rep.function.lower <= rep.function.upper);
  CHECK(rep.function.upper <= 2 * rep.function.lower);
  // The bound holds at sampled points (a necessary check of a bound).
  for (int i = 0; i <= 64; ++i) {
    const Rational x(i, 64);
    const auto a = evaluate(C, {x}), b = evaluate(R[0], {x});
    for (std::size_t c = 0; c < a.size(); ++c) CHECK(abs(Rational(a[c] - b[c])) <= rep.function.upper);
  }
  // A rational candidate against a polynomial reference: another structure, still a bound.
  const auto P = test::spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[1,0],[1,1],[0,1]]})");
  const auto mixed = verify_splines("identity", {P}, {S});
  CHECK(mixed.structure == "different");
  CHECK(mixed.function.certified);
  CHECK(mixed.function.upper >= mixed.function.lower);
  CHECK(mixed.function.lower > 0);
}

TEST_CASE("verify: values at points, and candidate numbers read as the doubles a program printed") {
  const auto S = test::spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[0,0],[1,2],[4,0]]})");
  // B(1/2) = (3/2, 1): exact candidate, then one off by 2^-30.
  const auto ok = verify_values(S, {{Rational(1, 2)}}, {{Rational(3, 2), Rational(1)}});
  CHECK(ok.values.max_abs == 0);
  const auto off = verify_values(S, {{Rational(1, 2)}}, {{Rational(3, 2) + Rational(1, 1 << 30), Rational(1)}});
  CHECK(off.values.max_abs == Rational(1, 1 << 30));
  CHECK_THROWS_AS(verify_values(S, {{Rational(1, 2)}}, {}), ValidationError);
  CHECK_THROWS_AS(verify_values(S, {{Rational(1, 2)}}, {{Rational(1)}}), ValidationError);
  // "0.1" printed by a float program is the double nearest 1/10; "1/3" stays exact.
  const Json doc = candidate_numbers_as_doubles(Json{{"points", Json::array({"0.1", "1/3", 5})}, {"degrees", Json::array({3})}});
  CHECK(json_number(doc["points"][0], "x") == exact_from_double(0.1));
  CHECK(json_number(doc["points"][0], "x") != Rational(1, 10));
  CHECK(json_number(doc["points"][1], "x") == Rational(1, 3));
  CHECK(json_number(doc["points"][2], "x") == 5);
  CHECK_THROWS_AS(candidate_numbers_as_doubles(Json{{"points", Json::array({"1e400"})}}), RangeError);
}
