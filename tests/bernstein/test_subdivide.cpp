// The subdivision engine (bernstein/subdivide.hpp) and the one Verdict (base/verdict.hpp): the order
// boxes are examined in, every budget and the reason it names, early stops; and a certificate of
// positivity on it that refutes planted wrong examinations.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "base/verdict.hpp"
#include "bernstein/subdivide.hpp"
#include "bernstein/tensor.hpp"
#include "exact/rational.hpp"

using namespace splinex;

namespace {

struct Interval {
  Rational lo, hi;
};

auto halves = [](Interval&& b, int, auto&& emit) {
  const Rational m = (b.lo + b.hi) / 2;
  emit(Interval{b.lo, m});
  emit(Interval{m, b.hi});
};

std::string text(const Interval& b) { return "[" + to_fraction_string(b.lo) + ", " + to_fraction_string(b.hi) + "]"; }

/// p > 0 on [0, 1], decided by Bernstein signs on halves: proved, refuted at a box whose midpoint
/// value is <= 0, or undecided when the depth runs out. `corners_only` plants the classic bug of
/// trusting the end coefficients alone.
struct Positivity {
  Bernstein<Rational> p;
  bool corners_only = false;
  Rational witness{-1};

  Verdict decide(const Budget& budget) {
    struct Piece {
      Bernstein<Rational> p;
      Interval x;
    };
    auto examine = [&](const Piece& b, int) {
      if (corners_only ? (b.p.c.front() > 0 && b.p.c.back() > 0) : bern_sign(b.p) > 0) return Examined::settled;
      if (!(bern_value(b.p, {Rational(1, 2)}) > 0)) {
        witness = (b.x.lo + b.x.hi) / 2;
        return Examined::refuted;
      }
      return Examined::split;
    };
    auto split = [](Piece&& b, int, auto&& emit) {
      auto [l, r] = bern_split(b.p, 0, Rational(1, 2));
      const Rational m = (b.x.lo + b.x.hi) / 2;
      emit(Piece{std::move(l), {b.x.lo, m}});
      emit(Piece{std::move(r), {m, b.x.hi}});
    };
    const Subdivision run = subdivide(std::vector<Piece>{Piece{p, {Rational(0), Rational(1)}}}, Walk{}, budget, examine, split,
                                      [](Piece&&, Left) {});
    if (run.stop == Subdivision::Stop::refuted) return Verdict::refuted("p(" + to_fraction_string(witness) + ") <= 0");
    if (run.decided()) return Verdict::proved("every Bernstein coefficient positive on " + std::to_string(run.examined) + " boxes");
    return Verdict::undecided("coefficients of both signs at depth " + std::to_string(budget.max_depth));
  }
};

/// The Bernstein form on [0, 1] of a + b x + c x^2.
Bernstein<Rational> quadratic(const Rational& a, const Rational& b, const Rational& c) {
  return Bernstein<Rational>{{2}, {a, a + b / 2, a + b + c}};
}

}  // namespace

TEST_CASE("subdivide: breadth-first and depth-first orders, depth and counts") {
  std::vector<std::string> seen;
  auto record = [&](const Interval& b, int depth) {
    seen.push_back(text(b));
    return depth < 2 ? Examined::split : Examined::settled;
  };
  const auto bfs = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{Order::breadth_first, 2, false}, Budget{}, record,
                             halves, [](Interval&&, Left) { FAIL("nothing is left"); });
  CHECK(bfs.decided());
  CHECK(bfs.examined == 7);
  CHECK(bfs.deepest == 2);
  CHECK(seen == std::vector<std::string>{"[0, 1]", "[0, 1/2]", "[1/2, 1]", "[0, 1/4]", "[1/4, 1/2]", "[1/2, 3/4]", "[3/4, 1]"});
  seen.clear();
  const auto dfs = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{Order::depth_first, 2, false}, Budget{}, record,
                             halves, [](Interval&&, Left) {});
  CHECK(dfs.examined == 7);
  CHECK(seen == std::vector<std::string>{"[0, 1]", "[1/2, 1]", "[3/4, 1]", "[1/2, 3/4]", "[0, 1/2]", "[1/4, 1/2]", "[0, 1/4]"});
}

TEST_CASE("subdivide: every budget names itself, and the walk goes on or stops as asked") {
  auto always_split = [](const Interval&, int) { return Examined::split; };
  std::vector<Left> why;
  auto leave = [&](Interval&&, Left w) { why.push_back(w); };

  SECTION("depth: the boxes at max_depth are left, the others still examined") {
    Budget b;
    b.max_depth = 3;
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, b, always_split, halves, leave);
    CHECK(r.stop == Subdivision::Stop::complete);
    CHECK_FALSE(r.decided());
    CHECK(r.examined == 15);
    CHECK(r.left == 8);
    CHECK(r.left_depth == 8);
    CHECK(why == std::vector<Left>(8, Left::depth));
  }
  SECTION("depth with stop_at_first_left: the first box left ends the walk") {
    Budget b;
    b.max_depth = 3;
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{Order::breadth_first, 2, true}, b, always_split,
                             halves, leave);
    CHECK(r.stop == Subdivision::Stop::left);
    CHECK(r.examined == 8);
    CHECK(r.left == 1);
  }
  SECTION("boxes: after max_boxes examinations every waiting box is left") {
    Budget b;
    b.max_boxes = 5;
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, b, always_split, halves, leave);
    CHECK(r.stop == Subdivision::Stop::boxes);
    CHECK(r.examined == 5);
    CHECK(r.left == 6);  // the root and 10 children made, 5 of them examined: 6 waiting
    CHECK(why == std::vector<Left>(6, Left::boxes));
  }
  SECTION("alive: a split that would make too many boxes wait leaves the box instead") {
    Budget b;
    b.max_alive = 4;
    b.max_depth = 10;
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, b, always_split, halves, leave);
    CHECK(r.left_alive > 0);
    CHECK(r.stop == Subdivision::Stop::complete);
    CHECK(std::count(why.begin(), why.end(), Left::alive) == static_cast<long>(r.left_alive));
  }
  SECTION("alive: a fanout beyond every budget leaves the box, without wrapping around") {
    Budget b;
    b.max_alive = 10;
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{Order::breadth_first, SIZE_MAX, false}, b, always_split,
                             halves, leave);
    CHECK(r.examined == 1);
    CHECK(r.left_alive == 1);
  }
  SECTION("refuted: the walk stops at once, nothing more is examined or left") {
    auto refute_second = [](const Interval& b, int) { return b.lo == 0 && b.hi == Rational(1, 2) ? Examined::refuted : Examined::split; };
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, Budget{}, refute_second, halves, leave);
    CHECK(r.stop == Subdivision::Stop::refuted);
    CHECK(r.examined == 2);
    CHECK(r.left == 0);
  }
}

TEST_CASE("subdivide: a positivity certificate on the engine, and the planted bug it refutes") {
  Budget deep;
  deep.max_depth = 20;
  // (x - 1/3)^2 + 1/100 > 0: its first Bernstein form has a negative coefficient; halves prove it.
  Positivity pos{quadratic(Rational(1, 9) + Rational(1, 100), Rational(-2, 3), Rational(1))};
  REQUIRE(bern_sign(pos.p) == 0);
  const Verdict v = pos.decide(deep);
  CHECK(v.is_proved());
  CHECK(v.make_certain("p > 0"));
  // (x - 1/2)^2 - 1/100 is negative on (2/5, 3/5): refuted, with an exact witness where p <= 0.
  Positivity neg{quadratic(Rational(1, 4) - Rational(1, 100), Rational(-1), Rational(1))};
  const Verdict w = neg.decide(deep);
  REQUIRE(w.is_refuted());
  CHECK_FALSE(w.make_certain("p > 0"));
  CHECK(bern_value(neg.p, {neg.witness}) <= 0);
  // Planted: trusting the end coefficients "proves" the false claim; the true examination refutes it.
  Positivity planted{neg.p, true};
  CHECK(planted.decide(deep).is_proved());
  // Too shallow: undecided, and make_certain refuses to guess.
  Positivity close{quadratic(Rational(1, 9) + Rational(1, 1000000), Rational(-2, 3), Rational(1))};  // (x - 1/3)^2 + 10^-6
  Budget shallow;
  shallow.max_depth = 2;
  const Verdict u = close.decide(shallow);
  CHECK(u.is_undecided());
  CHECK_THROWS_AS(u.make_certain("p > 0"), UndecidedError);
  CHECK(close.decide(deep).is_proved());
}

TEST_CASE("Verdict: one spelling of the three answers") {
  CHECK(std::string(status_name(Status::proved)) == "proved");
  CHECK(std::string(status_name(Status::refuted)) == "refuted");
  CHECK(std::string(status_name(Status::undecided)) == "undecided");
  const Verdict d;
  CHECK(d.is_undecided());
  CHECK(d.reason() == "not examined");
  CHECK(Verdict::proved("checked") == Verdict::proved("checked"));
  CHECK_FALSE(Verdict::proved("checked") == Verdict::refuted("checked"));
}

TEST_CASE("Uncertain<E>: a decided value compares equal to it, an undecided one to none and refuses make_certain", "[verdict]") {
  enum Kind { whole, empty, cut };
  const Uncertain<Kind> decided = cut;
  CHECK(decided.is_certain());
  CHECK(decided == cut);
  CHECK(decided != whole);
  CHECK(decided.make_certain("the cell's kind") == cut);
  const auto open = Uncertain<Kind>::undecided("mixed boxes left at the budget");
  CHECK_FALSE(open.is_certain());
  for (Kind k : {whole, empty, cut}) CHECK(open != k);
  CHECK(open.reason() == "mixed boxes left at the budget");
  CHECK_THROWS_AS(open.make_certain("the cell's kind"), UndecidedError);
}
