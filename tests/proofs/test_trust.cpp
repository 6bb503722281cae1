// Trust (issue 12): the five wrong results on legal input, the honesty of the proof checker, and
// planted bugs that every kernel and composition proof must refute.
#include <catch2/catch.hpp>
#include <random>

#include "fixtures/random_spline.hpp"
#include "float/rounding.hpp"
#include "tests/helpers.hpp"
#include "proofs/identity.hpp"
#include "proofs/suite.hpp"
#include "compose/trimmed_compose.hpp"
#include "spline/kernel.hpp"
#include "untrim/loops.hpp"

using namespace splinex;
using test::spline;

namespace {
std::vector<Rational> pts(const BSpline<Rational>& S) { return S.points; }
std::vector<Rational> qs(std::initializer_list<const char*> v) {
  std::vector<Rational> out;
  for (const char* s : v) out.push_back(test::q(s));
  return out;
}
}  // namespace

TEST_CASE("trust: Bezier extraction after a knot of multiplicity p+1 and at degree 0") {
  // 0, 1, 4 with 1/2 inserted three times: pieces (0, 1/2, 3/2) and (3/2, 5/2, 4) (de Casteljau by hand).
  const auto B = spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[0],[1],[4]]})");
  const auto C = insert_knot(B, 0, Rational(1, 2), 3);
  const auto pc = extract_bezier(C);
  REQUIRE(pc.size() == 2);
  CHECK(pts(pc[0].spline) == qs({"0", "1/2", "3/2"}));
  CHECK(pts(pc[1].spline) == qs({"3/2", "5/2", "4"}));
  // Degree 1, knots [0,0,1,1,2,2], points 0,1,5,7: pieces (0,1) on [0,1] and (5,7) on [1,2].
  const auto L = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1,2,2]],"points":[[0],[1],[5],[7]]})");
  const auto pl = extract_bezier(L);
  REQUIRE(pl.size() == 2);
  CHECK(pts(pl[1].spline) == qs({"5", "7"}));
  // Degree 0: one constant piece per span.
  const auto Z = spline(R"({"type":"bspline","degrees":[0],"knots":[[0,1,3,4]],"points":[[3],[5],[-1]]})");
  const auto pz = extract_bezier(Z);
  REQUIRE(pz.size() == 3);
  CHECK(pts(pz[2].spline) == qs({"-1"}));
  CHECK(pz[1].box[0] == std::pair<Rational, Rational>{1, 3});
}

TEST_CASE("trust: A5.9 elevation on C^-1 knots and degree 0 equals the blossom method and the input") {
  for (const char* doc : {R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,0.5,0.5,0.5,1,1,1]],"points":[[0],[1],[3],[3],[5],[4]]})",
                          R"({"type":"bspline","degrees":[0],"knots":[[0,1,2]],"points":[[3],[5]]})",
                          R"({"type":"bspline","degrees":[0],"knots":[[0,1]],"points":[[2]]})",
                          R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1,2,2]],"points":[[0],[1],[5],[7]]})",
                          R"({"type":"bspline","degrees":[3],"knots":[[0,0,0,0,0.25,0.5,0.5,0.5,0.5,1,1,1,1]],"points":[[0],[1],[3],[2],[6],[5],[4],[1],[2]]})"}) {
    const auto S = spline(doc);
    for (int t = 1; t <= 3; ++t) {
      const auto A = elevate_degree(S, 0, t, ElevationMethod::bezier_pieces);
      const auto B = elevate_degree(S, 0, t, ElevationMethod::blossom);
      INFO(doc << " by " << t);
      validate(A);
      CHECK(A.knots == B.knots);
      CHECK(A.points == B.points);
      CHECK(prove_same_function(S, A, "").holds);
      CHECK(A.count(0) == elevated_count(S, 0, t));
    }
  }
  const auto single = elevate_degree(spline(R"({"type":"bspline","degrees":[0],"knots":[[0,1]],"points":[[2]]})"), 0, 2);
  CHECK(pts(single) == qs({"2", "2", "2"}));
}

TEST_CASE("trust: composition across discontinuities of the inner and the outer spline") {
  const auto id = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]]})");
  const auto S = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.5,0.5,1,1]],"points":[[0.1],[0.2],[0.7],[0.9]]})");
  const auto R = compose(id, S);
  CHECK(evaluate(R, {Rational(3, 4)}) == qs({"4/5"}));  // was 9/20
  CHECK(evaluate(R, {Rational(1, 2)}) == qs({"7/10"}));  // the upper piece at the jump
  CHECK(evaluate(R, {Rational(1, 4)}) == qs({"3/20"}));
  // T jumps at 1/2; S(r) = r (through its own knot 1/2): R jumps there too.
  const auto T = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.5,0.5,1,1]],"points":[[0],[1],[5],[6]]})");
  const auto Sr = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.5,1,1]],"points":[[0],[0.5],[1]]})");
  const auto RT = compose(T, Sr);
  CHECK(multiplicity(RT.knots[0], Rational(1, 2)) == 2);
  for (const char* x : {"0", "1/4", "1/2", "3/4", "1"})
    CHECK(evaluate(RT, {test::q(x)}) == evaluate(T, evaluate(Sr, {test::q(x)})));
  // A piece that reaches T's jump from below at a parameter it owns: a typed error, and Algorithm 1 is right.
  const auto touch = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0.5],[0.2]]})");
  CHECK_THROWS_AS(compose(T, touch), DomainError);
  const auto C = compose_trimmed(T, touch);
  for (const char* x : {"0", "1/3", "1"}) CHECK(C.evaluate({test::q(x)}) == evaluate(T, evaluate(touch, {test::q(x)})));
  // Algorithm 1 with a C^-1 (but continuous) outer curve: T(S(1)) = 21/8 (was 7/4).
  const auto Tq = spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,0.5,0.5,0.5,1,1,1]],"points":[[0],["1/2"],["3/2"],["3/2"],["5/2"],[4]]})");
  const auto Sq = spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[0.2],[0.9],[0.3]]})");
  const auto Cq = compose_trimmed(Tq, Sq);
  for (const char* x : {"0", "1/5", "1/2", "4/5", "1"}) CHECK(Cq.evaluate({test::q(x)}) == evaluate(Tq, evaluate(Sq, {test::q(x)})));
}

TEST_CASE("trust: rounding into a float arithmetic keeps the structure or says why not") {
  CHECK_THROWS_AS(round_spline<double>(spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,"1e-400",1,1]],"points":[[2],[1],[1]]})")), RangeError);
  CHECK_THROWS_AS(round_spline<double>(spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[["1e400"],[1]]})")), RangeError);
  CHECK_THROWS_AS(round_spline<double>(spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,1,1]],"points":[[0],[1]],"weights":["1e-400",1]})")), RangeError);
  const auto close = spline(R"({"type":"bspline","degrees":[1],"knots":[[0,0,0.5,"0.50000000000000000001",1,1]],"points":[[0],[1],[3],[2]]})");
  {
    Mpfr::Precision p64(64);
    CHECK_THROWS_AS(round_spline<Mpfr>(close), RangeError);
  }
  Mpfr::Precision p200(200);
  CHECK(round_spline<Mpfr>(close).knots[0][3] > round_spline<Mpfr>(close).knots[0][2]);
}

TEST_CASE("trust: untrimming into a surface splits tiles at its vertical knot lines") {
  TrimmedDomain D{{0, 0}, {1, 1}, {{{Rational(1, 4), Rational(1, 4)}, {Rational(3, 4), Rational(1, 4)}, {Rational(3, 4), Rational(3, 4)}, {Rational(1, 4), Rational(3, 4)}}}};
  validate_domain(D);
  std::array<std::vector<Rational>, 2> lines;
  lines[0] = {Rational(1, 2)};
  lines[1] = {Rational(1, 2)};
  const auto tiles = untrim_domain<Rational>(D, lines);
  Rational area = 0;
  for (const auto& t : tiles) {
    CHECK((t.x.back() <= Rational(1, 2) || t.x.front() >= Rational(1, 2)));
    area += tile_area(t);
  }
  CHECK(area == Rational(1, 4));
  CHECK(tiles.size() == 4);
}

TEST_CASE("proof checker: nothing compared is never proved") {
  const auto S = spline(R"({"type":"bspline","degrees":[2],"knots":[[0,0,0,1,1,1]],"points":[[0],[1],[4]]})");
  const auto inverted = prove_equal_on_box(S, S, {{Rational(1), Rational(0)}}, {}, "");
  CHECK_FALSE(inverted.decided());
  const auto empty = prove_equal_on_box(S, S, {{Rational(1, 2), Rational(1, 2)}}, {}, "");
  CHECK_FALSE(empty.decided());
  CHECK(prove_same_function(S, S, "").decided());
  const auto none = prove_by_samples({}, {}, [](const std::vector<Rational>&) { return std::string(); }, "");
  CHECK(none.points == 1);  // zero directions: one (empty) point, the constant case
  const auto r0 = run_proofs({"knot-insertion-boehm"}, 0).at(0);
  CHECK(r0.is_undecided());
  CHECK_FALSE(r0.as_expected());
  CHECK(r0.verdict() == "undecided: no case was run (--cases 0)");
  const auto sampled = run_proofs({"compose-trimmed"}, 2).at(0);
  CHECK(sampled.verdict_word().rfind("checked at ", 0) == 0);
  ProofReport surprise;
  surprise.expect_proved = false;
  surprise.points = 3;
  CHECK(surprise.verdict() == "proved (UNEXPECTED: expected to be refuted)");
  CHECK_FALSE(surprise.as_expected());
}

TEST_CASE("proof checker: a degree bound one too small would accept a wrong result, the real one refutes it") {
  // A cubic S and R = S + c (x - x_0)(x - x_1)(x - x_2) with x_i the sample points a bound of 2
  // would use: R agrees with S there, so only the bound max(p, p') = 3 (4 points) sees it.
  const auto S = spline(R"({"type":"bspline","degrees":[3],"knots":[[0,0,0,0,1,1,1,1]],"points":[[0],[1],[-1],[2]]})");
  // In Bernstein form on [0, 1]: (x - 1/4)(x - 1/2)(x - 3/4) = x^3 - 3/2 x^2 + 11/16 x - 3/32,
  // coefficients (-3/32, 13/96, -13/96, 3/32).
  auto R = S;
  const auto add = qs({"-3/32", "13/96", "-13/96", "3/32"});
  for (int i = 0; i < 4; ++i) R.points[i] += add[i];
  const auto wrong = prove_by_samples({{Rational(0), Rational(1)}}, {2},
                                      [&](const std::vector<Rational>& x) { return evaluate(S, x) == evaluate(R, x) ? "" : "differ"; }, "");
  CHECK(wrong.holds);  // what a too-small bound would say
  const auto right = prove_same_function(S, R, "");
  CHECK_FALSE(right.holds);
  CHECK(right.degree_bound == std::vector<int>{3});
}

namespace {
// The kinds of planted bugs (issue 12): each applied to every result the proofs check.
void offset_after_jump(BSpline<Rational>& R) {
  for (int d = 0; d < R.dim(); ++d) {
    const int p = R.degrees[d];
    for (std::size_t i = p + 1; i < R.count(d); ++i)
      if (multiplicity(R.knots[d], R.knots[d][i]) == static_cast<std::size_t>(p) + 1 && R.knots[d][i - 1] < R.knots[d][i]) {
        const auto f = fibre_layout(R, d);
        R.points[i * f.before * R.q] += Rational(1, 7);  // the first control point after the jump
        return;
      }
  }
  R.points.back() += Rational(1, 7);
}
void skip_a_knot(BSpline<Rational>& R) {
  for (int d = 0; d < R.dim(); ++d) {
    const int p = R.degrees[d];
    const std::size_t n = R.count(d);
    if (n <= static_cast<std::size_t>(p) + 1) continue;
    const std::size_t k = p + 1;  // the first interior knot and control point k go
    std::vector<Rational> U = R.knots[d];
    U.erase(U.begin() + static_cast<std::ptrdiff_t>(k));
    const auto f = fibre_layout(R, d);
    BSpline<Rational> Q = slice_direction(R, d, 0, n - 1, U);
    for (std::size_t a = 0; a < f.after; ++a)  // control point k-1 of every fibre replaced by k
      for (std::size_t b = 0; b < f.before; ++b)
        for (int c = 0; c < R.q; ++c)
          Q.points[((a * (n - 1) + k - 1) * f.before + b) * R.q + c] = R.points[((a * n + k) * f.before + b) * R.q + c];
    R = Q;
    return;
  }
  R.points.front() += Rational(1, 9);
}
void drop_weights(BSpline<Rational>& R) {
  if (R.is_rational()) R.weights.clear();
  else R.points.front() += Rational(1, 11);
}
// A spike between sample points: two new knots of multiplicity p+1 at a + w/1000 and a + 2w/1000 of
// the first span of direction 0, and the piece between them changed. Only a proof whose cells
// include the result's own breakpoints sees it.
void spike(BSpline<Rational>& R) {
  const int p = R.degrees[0];
  const Rational a = R.domain_lo(0), b = breakpoints(R.knots[0], p, R.count(0))[1], w = b - a;
  const Rational m1 = a + w / 1000, m2 = a + w / 500;
  R = insert_knot(insert_knot(R, 0, m1, p + 1), 0, m2, p + 1);
  const std::size_t first = find_span(R.knots[0], p, R.count(0), m1) - p;
  const auto f = fibre_layout(R, 0);
  for (std::size_t i = first; i <= first + p; ++i) R.points[i * f.before * R.q] += Rational(3);
}
}  // namespace

TEST_CASE("planted bugs: every kernel, composition, untrimming and teapot proof refutes them with an exact counterexample") {
  using proof_detail::ScopedPlantedBug;
  const std::vector<std::pair<const char*, proof_detail::PlantedBug>> bugs{
      {"offset after a C^-1 knot", offset_after_jump}, {"skipped knot", skip_a_knot}, {"dropped weight", drop_weights}, {"spike cell", spike}};
  for (const char* name : {"knot-insertion-boehm", "knot-refinement-a54", "insertion-agreement", "degree-elevation-a59",
                           "degree-elevation-blossom", "bezier-extraction", "split", "reparametrize", "reverse", "clamp",
                           "derivative-hodograph", "compose-methods-agree", "compose-identity", "compose-bspline",
                           "elevation-agreement", "evaluation-deboor", "flint-agreement", "ff-agreement", "compose-trimmed", "untrim-cover",
                           "untrim-curved-cover", "teapot-merge"}) {
    for (const auto& [what, bug] : bugs) {
      // compose-trimmed is a sampled check ("checked at N points"): a spike narrower than its grid
      // is exactly what it cannot see, and why it does not say "proved".
      if (std::string(name) == "compose-trimmed" && std::string(what) == "spike cell") continue;
      ScopedPlantedBug planted(bug);
      const auto r = run_proofs({name}, std::string(name) == "teapot-merge" ? 1 : 6).at(0);
      INFO(name << " with a " << what << ": " << r.verdict());
      CHECK(r.refuted());
      CHECK(r.counterexample.find("case ") == 0);
    }
  }
  // The hybrid-patch theorems: the patch or form under test with side 0 moved.
  for (const char* name : {"hybrid-thm-3.1", "hybrid-thm-3.2-corrected", "hybrid-thm-4.1", "hybrid-thm-4.2"}) {
    proof_detail::ScopedPlantedHybridBug planted;
    const auto r = run_proofs({name}, 3).at(0);
    INFO(name << ": " << r.verdict());
    CHECK(r.refuted());
  }
  // Without a bug they hold (the registry test runs more cases).
  const auto ok = run_proofs({"bezier-extraction"}, 6).at(0);
  CHECK(ok.verdict() == "proved");
}

TEST_CASE("the structured generator reaches the edges of the input space") {
  std::mt19937_64 rng(42);
  std::vector<std::string> seen;
  for (int i = 0; i < 400; ++i)
    for (const auto& t : structured_case(rng).structures)
      if (std::find(seen.begin(), seen.end(), t) == seen.end()) seen.push_back(t);
  for (const char* t : {"degree 0", "degree >= 5", "C^-1 knot", "single span", "unclamped", "gap 2^-60", "gap 2^-1100",
                        "shifted domain", "coordinates ~1e30", "coordinates ~1e-30", "rational", "weights 1e-6..1e6"})
    CHECK(std::find(seen.begin(), seen.end(), std::string(t)) != seen.end());
}

TEST_CASE("ranges of a proof's cases, run apart and merged, equal the whole run (the proofs sweep)") {
  const auto entry_of = [](const std::string& name) -> const ProofEntry& {
    for (const auto& e : proof_registry())
      if (e.name == name) return e;
    FAIL("no proof " << name);
    throw;
  };
  // a proved, a refuted (expected) and a sampled proof; each range through its JSON, as a job's result
  for (const char* name : {"knot-insertion-boehm", "hybrid-thm-3.2", "compose-trimmed"}) {
    const auto& e = entry_of(name);
    const auto whole = e.run(5);
    std::vector<std::pair<std::size_t, ProofReport>> ranges;
    for (const auto& [first, count] : std::vector<std::pair<std::size_t, std::size_t>>{{0, 2}, {2, 1}, {3, 2}})
      ranges.emplace_back(first, proof_range_from_json(e, proof_range_json(e.run_range(first, count))));
    INFO(name);
    CHECK(proof_report_json(merge_proof_ranges(e, ranges)) == proof_report_json(whole));
    // a case runs alone: case 3 from its own range equals case 3 of the ranges above
    CHECK(proof_range_json(e.run_range(3, 1)).at("points") ==
          proof_range_json(e.run_range(3, 2)).at("points").get<std::size_t>() - proof_range_json(e.run_range(4, 1)).at("points").get<std::size_t>());
  }
  // the first counterexample in case order wins, also when an earlier range holds
  ProofEntry e;
  e.name = "synthetic";
  e.finish = [](ProofReport& r) { r.degree_bound = "largest used: " + std::to_string(r.largest_degree); };
  ProofReport a, b, c;
  a.cases = 3, a.points = 10, a.largest_degree = 2, a.structures = {"x"};
  b.cases = 2, b.points = 4, b.holds = false, b.counterexample = "case 3: wrong", b.structures = {"y", "x"};
  c.cases = 2, c.points = 5, c.holds = false, c.counterexample = "case 6: also wrong", c.largest_degree = 7, c.undecided = "case 5: empty";
  const auto m = merge_proof_ranges(e, {{0, a}, {3, b}, {5, c}});
  CHECK(m.cases == 7);
  CHECK(m.points == 19);
  CHECK_FALSE(m.holds);
  CHECK(m.counterexample == "case 3: wrong");
  CHECK(m.undecided == "case 5: empty");
  CHECK(m.structures == std::vector<std::string>{"x", "y"});
  CHECK(m.degree_bound == "largest used: 7");
  // a gap, an overlap or a start after case 0 is no merge
  CHECK_THROWS_AS(merge_proof_ranges(e, {{0, a}, {4, b}}), std::logic_error);
  CHECK_THROWS_AS(merge_proof_ranges(e, {{0, a}, {2, b}}), std::logic_error);
  CHECK_THROWS_AS(merge_proof_ranges(e, {{1, a}}), std::logic_error);
}
