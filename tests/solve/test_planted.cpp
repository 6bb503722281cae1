// Planted bugs (issue 47, "Prove it"): every certificate of solve/ refutes an unsound variant of
// itself. Each plant (solve/testing.hpp) switches one certificate into a wrong decision: a
// skipped check (Krawczyk's contraction in a merged group of boxes and for a recognised exact
// root, the closest verdict's undecided boxes, the curve projection's completeness), the strict
// interior made closed, a wrong sign in K(X), the queue dropped at the budget, contact's branch
// and bound pruning by the wrong bound, an enclosure shrunk by one unit of its precision.
//
// Per plant, two tests:
//   - on an input chosen so that the mutated branch is reached and matters (plant_hits > 0), the
//     planted run gives a WRONG certified answer that an exact check independent of the solver
//     refutes (a second root the test knows to lie in a box called unique, a root outside every
//     box of a "complete" result, the exact distance at a known closer surface point, ...), and
//     the same input without the plant gives the right answer;
//   - the ordinary regression tests of tests/solve (test_solver.cpp, test_projection.cpp,
//     test_contact.cpp), run unchanged in a child process of this binary with the plant switched
//     on for the whole process (SPLINEX_SOLVE_PLANT=<name>), fail (without it they pass: they are
//     part of this suite).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "solve/contact.hpp"
#include "solve/curve_projection.hpp"
#include "solve/projection.hpp"
#include "solve/solver.hpp"
#include "solve/testing.hpp"
#include "spline/kernel.hpp"
#include "tests/helpers.hpp"
#include "tests/solve/solve_fixtures.hpp"

using namespace splinex;
using R = Rational;
using solve_testing::Plant;
using solve_testing::ScopedPlant;
using solve_fixtures::bivariate;
using solve_fixtures::from_roots;
using solve_fixtures::repro;
using solve_fixtures::univariate;

namespace {

// SPLINEX_SOLVE_PLANT=<name> switches the plant on for this whole process (the child runs below;
// never set in an ordinary run). An unknown name is an error at start-up.
const bool process_plant = [] {
  if (const char* name = std::getenv("SPLINEX_SOLVE_PLANT")) solve_testing::active_plant = solve_testing::plant_from_name(name);
  return true;
}();

// ---- exact helpers, independent of the solver ----

/// The Bernstein form on [0, 1] of the power coefficients a.
/// sum a_k x^k and its derivative, by Horner (not through the Bernstein form).
R power_value(const std::vector<R>& a, const R& x) {
  R v(0);
  for (std::size_t k = a.size(); k-- > 0;) v = v * x + a[k];
  return v;
}
std::vector<R> power_derivative(const std::vector<R>& a) {
  std::vector<R> d;
  for (std::size_t k = 1; k < a.size(); ++k) d.push_back(a[k] * R(static_cast<long>(k)));
  return d;
}

bool inside(const std::vector<R>& x, const std::vector<R>& lo, const std::vector<R>& hi) {
  for (std::size_t l = 0; l < x.size(); ++l)
    if (x[l] < lo[l] || hi[l] < x[l]) return false;
  return true;
}

/// Whether x lies in a box the solver reported (a root, or an undecided box).
bool covered(const SolveResult<R>& s, const std::vector<R>& x) {
  for (const auto* list : {&s.roots, &s.undecided})
    for (const auto& r : *list)
      if (inside(x, r.lo, r.hi)) return true;
  return false;
}

/// Whether a box certified to hold exactly one root holds both a and b (two distinct roots).
bool unique_box_holds_both(const SolveResult<R>& s, const R& a, const R& b) {
  for (const auto& r : s.roots)
    if (r.unique && inside({a}, r.lo, r.hi) && inside({b}, r.lo, r.hi)) return true;
  return false;
}

/// |S(uv) - P|^2 exactly (the spline evaluated by its basis functions, not by the solver's forms).
R distance2_at(const BSpline<R>& S, const std::vector<R>& uv, const std::vector<R>& P) {
  const auto x = evaluate(S, uv);
  R d2(0);
  for (int c = 0; c < 3; ++c) d2 += (x[c] - P[c]) * (x[c] - P[c]);
  return d2;
}

/// The corners of the box [lo, hi] (2^n of them).
std::vector<std::vector<R>> corners(const std::vector<R>& lo, const std::vector<R>& hi) {
  std::vector<std::vector<R>> out;
  for (std::size_t m = 0; m < (std::size_t(1) << lo.size()); ++m) {
    std::vector<R> x(lo.size());
    for (std::size_t l = 0; l < lo.size(); ++l) x[l] = m >> l & 1 ? hi[l] : lo[l];
    out.push_back(std::move(x));
  }
  return out;
}

/// A lower bound of the feet of the vertical line (1/10, 0, t) on z = x^2 (u in [-1, 1]): the sign
/// changes of 2u^3 + (1 - 2t) u - 1/10 over u = -1, -7/8, ..., 1.
std::size_t feet_at_least(const R& t) {
  const auto g = [&](const R& u) -> R { return 2 * u * u * u + (1 - 2 * t) * u - R(1, 10); };
  std::size_t changes = 0;
  for (int k = -8; k < 8; ++k) changes += g(R(k, 8)) * g(R(k + 1, 8)) < 0;
  return changes;
}

BSpline<R> plane(const R& z) {  // over [-2, 2]^2
  const std::vector<R> k{R(-2), R(-2), R(2), R(2)};
  return make_spline<R>({1, 1}, {k, k}, 3, {R(-2), R(-2), z, R(2), R(-2), z, R(-2), R(2), z, R(2), R(2), z});
}

/// z = 1 + h(x) + y^2 over [-1, 1]^2 (x = u, y = v), h = (x + 1/2)^2 ((x - 1/3)^2 - 1/256): degree
/// (4, 2), h's Bernstein coefficients on [-1, 1] computed exactly (test_contact.cpp has the same).
BSpline<R> two_wells() {
  return test::spline(R"({"type": "bspline", "degrees": [4, 2], "knots": [[-1, -1, -1, -1, -1, 1, 1, 1, 1, 1], [-1, -1, -1, 1, 1, 1]],
    "points": [["-1", "-1", "22519/9216"], ["-1/2", "-1", "11273/9216"], ["0", "-1", "86537/27648"], ["1/2", "-1", "2551/3072"],
               ["1", "-1", "3063/1024"], ["-1", "0", "4087/9216"], ["-1/2", "0", "-7159/9216"], ["0", "0", "31241/27648"],
               ["1/2", "0", "-3593/3072"], ["1", "0", "1015/1024"], ["-1", "1", "22519/9216"], ["-1/2", "1", "11273/9216"],
               ["0", "1", "86537/27648"], ["1/2", "1", "2551/3072"], ["1", "1", "3063/1024"]]})");
}

R pow2(int e) {  // 2^e, e < 0 too
  using boost::multiprecision::mpz_int;
  return e >= 0 ? R(mpz_int(1) << e) : R(1) / R(mpz_int(1) << -e);
}

// ---- the ordinary tests under a plant, in a child process ----

struct ChildRun {
  int status = -1;  // the exit status (Catch2: the number of failed assertions, capped), -1: no normal exit
  std::string output;
};

/// This test binary run on the test cases matching `spec` (a Catch2 test spec; no commas), with
/// `plant` on for the whole process.
ChildRun run_ordinary(const std::string& plant, const std::string& spec) {
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string out = (std::filesystem::temp_directory_path() / ("splinex_plant_" + std::to_string(::getpid()) + "_" + plant + ".txt")).string();
  const std::string cmd = "env SPLINEX_SOLVE_PLANT=" + plant + " '" + exe + "' '" + spec + "' > '" + out + "' 2>&1";
  ChildRun r;
  const int st = std::system(cmd.c_str());
  if (st != -1 && WIFEXITED(st)) r.status = WEXITSTATUS(st);
  std::ifstream in(out);
  std::stringstream text;
  text << in.rdbuf();
  r.output = text.str();
  std::filesystem::remove(out);
  return r;
}

/// The ordinary tests matching each spec fail with the plant on.
void ordinary_tests_catch(Plant p, const std::vector<std::string>& specs) {
  if (std::getenv("SPLINEX_SOLVE_PLANT")) return;  // already a child: no grandchildren
  const std::string name = solve_testing::plant_name(p);
  for (const auto& spec : specs) {
    // (Without the plant the same tests run, and pass, in this suite itself.)
    INFO("plant " << name << ", ordinary tests '" << spec << "'");
    const auto on = run_ordinary(name, spec);
    INFO(on.output);
    CHECK(on.output.find("No test cases matched") == std::string::npos);
    CHECK(on.status > 0);  // failed assertions, not a crash
    CHECK(on.output.find("FAILED") != std::string::npos);
  }
}

}  // namespace

TEST_CASE("planted: the seam is off by default and scoped", "[solve][planted]") {
  if (std::getenv("SPLINEX_SOLVE_PLANT")) return;
  CHECK(solve_testing::active_plant == Plant::none);
  {
    ScopedPlant p(Plant::closed_interior);
    CHECK(solve_testing::planted(Plant::closed_interior));
    CHECK(solve_testing::plant_hits == 0);
  }
  CHECK(solve_testing::active_plant == Plant::none);
  for (Plant p : {Plant::skip_krawczyk_contraction_merged, Plant::skip_krawczyk_contraction_known, Plant::closed_interior, Plant::krawczyk_wrong_sign,
                  Plant::drop_box, Plant::closest_ignores_undecided, Plant::shrink_enclosure, Plant::contact_prune_wrong_bound,
                  Plant::curve_counts_unchecked})
    CHECK(solve_testing::plant_from_name(solve_testing::plant_name(p)) == p);
  CHECK_THROWS_AS(solve_testing::plant_from_name("no_such_plant"), std::invalid_argument);
}

TEST_CASE("planted: Krawczyk uniqueness in a merged group without the contraction test", "[solve][planted]") {
  // f = (x - 1/3)(x - 1/3 - 2^-40): the roots are 2^-40 apart, closer than the depth limit's
  // boxes (2^-30), so they end in one merged group (a cluster hull) where 1/3 is recognised
  // exactly. The contraction test about 1/3 fails (f' vanishes between the roots); without it
  // the hull is reported as 1/3's box, unique, and the result complete.
  const R second = R(1, 3) + pow2(-40);
  const std::vector<R> a = from_roots({R(1, 3), second});
  const std::vector<Bernstein<R>> f{univariate(a)};
  REQUIRE(power_value(a, second) == 0);  // the test's own exact check: a second root
  {
    ScopedPlant plant(Plant::skip_krawczyk_contraction_merged);
    const auto s = solve_system<R>(f, {R(0)}, {R(1)});
    CHECK(solve_testing::plant_hits > 0);  // the merged-group branch decided it
    CHECK(s.complete());                   // the planted claim: every root listed, each simple
    // Refuted: a box certified to hold exactly one root holds the two the test knows.
    CHECK(unique_box_holds_both(s, R(1, 3), second));
  }
  const auto s = solve_system<R>(f, {R(0)}, {R(1)});
  CHECK_FALSE(s.complete());
  CHECK_FALSE(unique_box_holds_both(s, R(1, 3), second));
  CHECK(covered(s, {R(1, 3)}));
  CHECK(covered(s, {second}));

  // A double root: f = (x - 1/3)^2 (x - 3/4). Planted, 1/3 is "unique" (simple); exactly, f and
  // f' both vanish there.
  const std::vector<R> d = from_roots({R(1, 3), R(1, 3), R(3, 4)});
  REQUIRE(power_value(d, R(1, 3)) == 0);
  REQUIRE(power_value(power_derivative(d), R(1, 3)) == 0);
  {
    ScopedPlant plant(Plant::skip_krawczyk_contraction_merged);
    const auto s2 = solve_system<R>({univariate(d)}, {R(0)}, {R(1)});
    CHECK(solve_testing::plant_hits > 0);
    bool simple_claimed = false;
    for (const auto& r : s2.roots) simple_claimed = simple_claimed || (r.unique && r.exact && r.point == std::vector<R>{R(1, 3)});
    CHECK(simple_claimed);
  }
  const auto s2 = solve_system<R>({univariate(d)}, {R(0)}, {R(1)});
  for (const auto& r : s2.roots)
    if (r.exact && r.point == std::vector<R>{R(1, 3)}) CHECK_FALSE(r.unique);

  ordinary_tests_catch(Plant::skip_krawczyk_contraction_merged,
                       {"solver: a double root is exact but not certified unique*", "solver: two roots in one merged group*"});
}

TEST_CASE("planted: an exact root taken as its box's only root without the contraction test", "[solve][planted]") {
  // Roots 1/2 and 1/2 + 2^-20: 1/2 is recognised at depth 2 in the box [1/4, 3/4] around it, which
  // holds the other root too. Planted, the boxes inside are skipped and 1/2 + 2^-20 is lost from
  // a result that says it is complete.
  const R other = R(1, 2) + pow2(-20);
  const std::vector<R> a = from_roots({R(1, 2), other});
  REQUIRE(power_value(a, other) == 0);
  {
    ScopedPlant plant(Plant::skip_krawczyk_contraction_known);
    const auto s = solve_system<R>({univariate(a)}, {R(0)}, {R(1)});
    CHECK(solve_testing::plant_hits > 0);
    CHECK(s.complete());  // claimed: every root listed, each the only one of its box
    CHECK(unique_box_holds_both(s, R(1, 2), other));
  }
  const auto s = solve_system<R>({univariate(a)}, {R(0)}, {R(1)});
  CHECK(s.complete());
  CHECK(s.roots.size() == 2);
  CHECK_FALSE(unique_box_holds_both(s, R(1, 2), other));
  CHECK(covered(s, {other}));
  ordinary_tests_catch(Plant::skip_krawczyk_contraction_known, {"solver: a double root is exact but not certified unique*"});
}

TEST_CASE("planted: the strict interior test made closed", "[solve][planted]") {
  // x = 1/2 and (y - 1/4)(y - 3/4) = 0: exactly two roots, both on the first split line x = 1/2.
  // The linear equation pins K(X) to the line exactly (a point on the face of both boxes beside
  // it): "inside" a closed box, never inside an open one. Closed, both boxes certify the same
  // root: four "unique" roots of a system that has two.
  const auto f1 = bivariate(1, 0, {{{1, 0}, R(1)}, {{0, 0}, R(-1, 2)}});
  const auto f2 = bivariate(0, 2, {{{0, 2}, R(1)}, {{0, 1}, R(-1)}, {{0, 0}, R(3, 16)}});
  for (bool recognise : {true, false}) {
    INFO("recognize_rationals " << recognise);
    SolveOptions o;
    o.recognize_rationals = recognise;
    {
      ScopedPlant plant(Plant::closed_interior);
      const auto s = solve_system<R>({f1, f2}, {R(0), R(0)}, {R(1), R(1)}, o);
      CHECK(solve_testing::plant_hits > 0);
      std::size_t unique = 0;
      for (const auto& r : s.roots) unique += r.unique;
      CHECK(unique > 2);  // the test knows: x = 1/2, y in {1/4, 3/4}, two roots
    }
    const auto s = solve_system<R>({f1, f2}, {R(0), R(0)}, {R(1), R(1)}, o);
    CHECK(s.complete());
    CHECK(s.roots.size() == 2);
  }
  ordinary_tests_catch(Plant::closed_interior, {"solver: roots on a split line pinned by a linear equation*"});
}

TEST_CASE("planted: a wrong sign in Krawczyk's operator", "[solve][planted]") {
  // (x - 1/3)(2 x^2 - 1): the roots 1/3 and 1/sqrt 2 in [0, 1]. With c + Y F(c) for c - Y F(c),
  // K(X) lies on the wrong side of c: boxes holding a root are excluded or certified around no
  // root. Exact check: every root known to the test lies in a box, and a certified box around an
  // irrational root has f of opposite signs at its ends.
  const std::vector<R> a = {R(1, 3), R(-1), R(-2, 3), R(2)};  // (x - 1/3)(2x^2 - 1) = 2x^3 - 2/3 x^2 - x + 1/3
  REQUIRE(power_value(a, R(1, 3)) == 0);
  const auto wrong = [&](const SolveResult<R>& s) {
    if (!covered(s, {R(1, 3)})) return true;
    bool irrational_found = false;
    for (const auto& r : s.roots) {
      if (r.exact) continue;
      if (!(power_value(a, r.lo[0]) * power_value(a, r.hi[0]) < 0)) return true;  // no sign change: no certified root
      irrational_found = irrational_found || (2 * r.lo[0] * r.lo[0] < 1 && 1 < 2 * r.hi[0] * r.hi[0]);
    }
    return !irrational_found;
  };
  {
    ScopedPlant plant(Plant::krawczyk_wrong_sign);
    const auto s = solve_system<R>({univariate(a)}, {R(0)}, {R(1)});
    CHECK(solve_testing::plant_hits > 0);
    CHECK(wrong(s));
  }
  CHECK_FALSE(wrong(solve_system<R>({univariate(a)}, {R(0)}, {R(1)})));
  ordinary_tests_catch(Plant::krawczyk_wrong_sign, {"solver: rational roots exact*"});
}

TEST_CASE("planted: the queue dropped when the budget runs out", "[solve][planted]") {
  // The parabolic cylinder z = x^2 and P = (1/10, 1/2, 3/4) with 10 boxes per system: the foot
  // near (0.58, 1/2) stays in the queue of the interior and of the edges v = 0, 1. Dropped instead
  // of reported undecided, the edge point (1, 1/2, 1) at d^2 = 349/400 is certified closest; the
  // surface point (1/2, 1/2, 1/4) is exactly closer (d^2 = 41/100).
  const auto S = repro("pcyl.json");
  const std::vector<R> P{R(1, 10), R(1, 2), R(3, 4)};
  const R closer = distance2_at(S, {R(1, 2), R(1, 2)}, P);
  REQUIRE(closer == R(41, 100));
  SolveOptions small;
  small.max_boxes = 10;
  {
    ScopedPlant plant(Plant::drop_box);
    const auto q = project_point<R>(S, P, small);
    CHECK(solve_testing::plant_hits > 0);
    REQUIRE(q.closest_certified);
    CHECK(closer < q.critical[q.closest[0]].d2_lo);  // a certified closest point that is not the closest
    CHECK(closer < q.distance2_lo);                 // and an enclosure of the minimum that misses it
  }
  const auto q = project_point<R>(S, P, small);
  CHECK_FALSE(q.closest_certified);
  CHECK_FALSE(closer < q.distance2_lo);
  // In the solver alone: a root outside every box of a result that lists no undecided box.
  {
    const std::vector<R> a = from_roots({R(1, 3), R(1, 5), R(5, 7)});
    SolveOptions tiny;
    tiny.max_boxes = 3;
    ScopedPlant plant(Plant::drop_box);
    const auto s = solve_system<R>({univariate(a)}, {R(0)}, {R(1)}, tiny);
    CHECK(solve_testing::plant_hits > 0);
    CHECK(s.undecided.empty());
    CHECK_FALSE((covered(s, {R(1, 3)}) && covered(s, {R(1, 5)}) && covered(s, {R(5, 7)})));
  }
  ordinary_tests_catch(Plant::drop_box, {"projection: a budget too small to finish*"});
}

TEST_CASE("planted: the closest point certified although an undecided box may hold a closer one", "[solve][planted]") {
  const R e = R(1) / R(boost::multiprecision::pow(boost::multiprecision::mpz_int(10), 25));
  const auto S = repro("pcyl.json");
  const std::vector<R> P{e, R(1, 2), R(3, 4)};
  const R closer = distance2_at(S, {R(1, 2), R(1, 2)}, P);
  SolveOptions small;
  small.max_boxes = 40;
  {
    ScopedPlant plant(Plant::closest_ignores_undecided);
    const auto q = project_point<R>(S, P, small);
    CHECK(solve_testing::plant_hits > 0);
    REQUIRE(q.closest_certified);
    CHECK(closer < q.critical[q.closest[0]].d2_lo);
  }
  const auto q = project_point<R>(S, P, small);
  CHECK_FALSE(q.closest_certified);
  CHECK_FALSE(q.undecided_closest.empty());
  ordinary_tests_catch(Plant::closest_ignores_undecided, {"projection: no candidate that an undecided box may beat*"});
}

TEST_CASE("planted: a distance enclosure shrunk by one unit of its precision", "[solve][planted]") {
  // The paraboloid z = x^2 + y^2 and P = (1, 1/3, 0): the foot is irrational, in a certified box;
  // every enclosure must hold the exact squared distance at each corner of its box (points of
  // the surface), evaluated here from the spline itself.
  const auto S = quadric_patch(R(1), R(1), R(1));
  const std::vector<R> P{R(1), R(1, 3), R(0)};
  const auto violations = [&](const ProjectionResult<R>& p) {
    std::size_t bad = 0;
    for (const auto* list : {&p.critical, &p.undecided})
      for (const auto& c : *list) {
        if (c.lo == c.hi) continue;  // exact points: d2 exact
        for (const auto& x : corners(c.lo, c.hi)) {
          const R d2 = distance2_at(S, x, P);
          bad += d2 < c.d2_lo || c.d2_hi < d2;
        }
      }
    return bad;
  };
  {
    ScopedPlant plant(Plant::shrink_enclosure);
    const auto p = project_point<R>(S, P);
    CHECK(solve_testing::plant_hits > 0);
    CHECK(violations(p) > 0);
  }
  const auto p = project_point<R>(S, P);
  CHECK(p.closest_certified);
  CHECK(violations(p) == 0);
  ordinary_tests_catch(Plant::shrink_enclosure, {"projection: every distance enclosure holds*"});
}

TEST_CASE("planted: contact's branch and bound prunes by the wrong bound", "[solve][planted]") {
  // Two wells over the plane z = 0: z = 1 + h(x) + y^2, h = (x + 1/2)^2 ((x - 1/3)^2 - 1/256), a
  // well of depth exactly 1 at x = -1/2 (a split point, reached first) and a deeper one near
  // x = 1/3 inside boxes whose corners are all farther than 1 (h > 0 at x = 0, 1/4, 1/2, 1).
  // Pruned by their upper bound, those boxes are dropped and the pair at x = -1/2 (d^2 = 1) is
  // certified closest; the pair at (1/3, 0) is exactly closer.
  const auto S1 = two_wells();
  const auto S2 = plane(R(0));
  const auto p1 = evaluate(S1, {R(1, 3), R(0)}), p2 = evaluate(S2, {R(1, 3), R(0)});
  R closer(0);
  for (int c = 0; c < 3; ++c) closer += (p1[c] - p2[c]) * (p1[c] - p2[c]);
  REQUIRE(p1[2] == R(9191, 9216));
  REQUIRE(evaluate(S1, {R(-1, 2), R(0)})[2] == 1);
  {
    ScopedPlant plant(Plant::contact_prune_wrong_bound);
    const auto r = surface_distance(S1, S2);
    CHECK(solve_testing::plant_hits > 0);
    REQUIRE(r.closest_certified);
    CHECK(r.distance2_lo == 1);
    CHECK(closer < r.distance2_lo);  // a pair of surface points closer than the certified minimum
  }
  const auto r = surface_distance(S1, S2);
  CHECK(r.closest_certified);
  CHECK_FALSE(closer < r.distance2_lo);
  CHECK(r.distance2_hi < 1);
  ordinary_tests_catch(Plant::contact_prune_wrong_bound, {"contact: two wells*"});
}

TEST_CASE("planted: curve projection counts certified without the solver's completeness", "[solve][planted]") {
  // The vertical line (1/10, 0, t) over z = x^2 (test_projection.cpp's fold) with 2 boxes per
  // system: nothing is solved. Planted, the slices' counts are certified although they miss feet
  // that the test finds by exact sign changes of the foot equation 2u^3 + (1 - 2t) u - 1/10 = 0
  // (v = 0) on a grid of u in [-1, 1].
  const auto S = solve_fixtures::fold_surface();
  const auto C = solve_fixtures::fold_line();
  CurveProjectionOptions o;
  o.solve.max_boxes = 2;
  const auto refuted = [&](const CurveProjectionResult& r) {
    bool any = false;
    for (const auto& sl : r.slices) any = any || (sl.certified && sl.roots < feet_at_least(sl.t));
    return any;
  };
  {
    ScopedPlant plant(Plant::curve_counts_unchecked);
    const auto r = project_curve(C, S, o);
    CHECK(solve_testing::plant_hits > 0);
    CHECK(r.certified_counts);
    CHECK(refuted(r));
  }
  const auto r = project_curve(C, S, o);
  CHECK_FALSE(r.certified_counts);
  CHECK_FALSE(refuted(r));
  ordinary_tests_catch(Plant::curve_counts_unchecked, {"curve projection: a budget too small to finish*"});
}
