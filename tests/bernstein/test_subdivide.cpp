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

std::string text(const Interval& b) {
  std::string s = to_fraction_string(b.lo);
  s.insert(0, 1, '[');
  s.append(", ").append(to_fraction_string(b.hi)).push_back(']');
  return s;
}

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
  SECTION("boxes, depth first: the last box left is the one that would have been examined next") {
    // Depth first from [0, 1] examines [0, 1], [1/2, 1], [3/4, 1], [7/8, 1], ... ; after 3, [7/8, 1] is next.
    std::vector<std::string> left_boxes, seen;
    auto record = [&](const Interval& b, int) {
      seen.push_back(text(b));
      return Examined::split;
    };
    Budget b;
    b.max_boxes = 3;
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{Order::depth_first, 2, false}, b, record, halves,
                             [&](Interval&& x, Left) { left_boxes.push_back(text(x)); });
    CHECK(r.stop == Subdivision::Stop::boxes);
    CHECK(seen == std::vector<std::string>{"[0, 1]", "[1/2, 1]", "[3/4, 1]"});
    CHECK(left_boxes == std::vector<std::string>{"[0, 1/2]", "[1/2, 3/4]", "[3/4, 7/8]", "[7/8, 1]"});
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
  SECTION("reached: the goal of the whole, checked before each examination, ends the walk; the waiting boxes are dropped") {
    // Witnesses: boxes of width 1/4 (found in breadth-first order); three are enough.
    std::vector<std::string> found;
    auto find = [&](const Interval& b, int) {
      if (b.hi - b.lo != Rational(1, 4)) return Examined::split;
      found.push_back(text(b));
      return Examined::settled;
    };
    const auto r = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, Budget{}, find, halves, leave,
                             [&]() { return found.size() >= 3; });
    CHECK(r.stop == Subdivision::Stop::reached);
    CHECK(r.examined == 6);  // the root, two halves, three quarters
    CHECK(r.left == 0);
    CHECK(why.empty());
    CHECK(found == std::vector<std::string>{"[0, 1/4]", "[1/4, 1/2]", "[1/2, 3/4]"});
    // A goal that holds at once examines nothing; one never reached runs to completion.
    found.clear();
    const auto none = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, Budget{}, find, halves, leave, []() { return true; });
    CHECK(none.stop == Subdivision::Stop::reached);
    CHECK(none.examined == 0);
    const auto all = subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, Budget{}, find, halves, leave, []() { return false; });
    CHECK(all.stop == Subdivision::Stop::complete);
    CHECK(found.size() == 4);
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

namespace {

/// An enclosure of the integral of p over [0, 1] by a refinement of [0, 1]: per box its length
/// times p's extreme Bernstein coefficients there, best first by the width, until the summed
/// widths are at most `width`. `corners_only` plants the bug of bounding p by its end values.
struct Quadrature {
  explicit Quadrature(Bernstein<Rational> p_, bool corners_only_ = false) : p(std::move(p_)), corners_only(corners_only_) {}
  Bernstein<Rational> p;
  bool corners_only = false;
  Rational lo{0}, hi{0};
  std::vector<std::string> split_order;

  Subdivision run(const Rational& width, std::size_t max_boxes) {
    struct Piece {
      Bernstein<Rational> p;
      Interval x;
      Rational lo{0}, hi{0};
    };
    lo = hi = Rational(0);
    auto bounds = [&](Piece& b) {
      const Rational len = b.x.hi - b.x.lo;
      Rational mn = b.p.c.front(), mx = b.p.c.front();
      for (const auto& c : corners_only ? std::vector<Rational>{b.p.c.front(), b.p.c.back()} : b.p.c) {
        mn = std::min(mn, c);
        mx = std::max(mx, c);
      }
      b.lo = len * mn;
      b.hi = len * mx;
      lo += b.lo;
      hi += b.hi;
      return b.lo == b.hi ? Examined::settled : Examined::split;
    };
    auto split = [&](Piece&& b, int, auto&& emit) {
      lo -= b.lo;
      hi -= b.hi;
      split_order.push_back(text(b.x));
      auto [l, r] = bern_split(b.p, 0, Rational(1, 2));
      const Rational m = (b.x.lo + b.x.hi) / 2;
      emit(Piece{std::move(l), {b.x.lo, m}});
      emit(Piece{std::move(r), {m, b.x.hi}});
    };
    Budget budget;
    budget.max_boxes = max_boxes;
    return refine(std::vector<Piece>{Piece{p, {Rational(0), Rational(1)}}}, Order::best_first, budget, bounds, split,
                  [&]() { return hi - lo <= width; }, [](Piece&&, bool) {}, [](const Piece& b) -> Rational { return b.hi - b.lo; });
  }
};

}  // namespace

TEST_CASE("refine: breadth first, every box examined when made, the partition's budget and the goal") {
  std::vector<std::string> made, closed, open;
  auto wide_split = [&](const Interval& b) {
    made.push_back(text(b));
    return b.hi - b.lo > Rational(1, 4) ? Examined::split : Examined::settled;
  };
  auto close = [&](Interval&& b, bool is_open) { (is_open ? open : closed).push_back(text(b)); };
  auto never = []() { return false; };
  SECTION("complete: every box settled") {
    const auto r = refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::breadth_first, Budget{}, wide_split, halves, never, close);
    CHECK(r.stop == Subdivision::Stop::complete);
    CHECK(r.examined == 7);
    CHECK(r.boxes == 4);
    CHECK(r.left == 0);
    CHECK(made == std::vector<std::string>{"[0, 1]", "[0, 1/2]", "[1/2, 1]", "[0, 1/4]", "[1/4, 1/2]", "[1/2, 3/4]", "[3/4, 1]"});
    CHECK(closed == std::vector<std::string>{"[0, 1/4]", "[1/4, 1/2]", "[1/2, 3/4]", "[3/4, 1]"});
  }
  SECTION("boxes: the partition may not grow past max_boxes; the open boxes are handed over in order") {
    Budget b;
    b.max_boxes = 3;
    const auto r = refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::breadth_first, b, wide_split, halves, never, close);
    CHECK(r.stop == Subdivision::Stop::boxes);
    CHECK(r.boxes == 3);
    CHECK(r.left == 1);
    CHECK(closed == std::vector<std::string>{"[0, 1/4]", "[1/4, 1/2]"});
    CHECK(open == std::vector<std::string>{"[1/2, 1]"});
  }
  SECTION("reached: the goal of the whole ends it before the next split") {
    const auto r = refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::breadth_first, Budget{}, wide_split, halves,
                          [&]() { return made.size() >= 3; }, close);
    CHECK(r.stop == Subdivision::Stop::reached);
    CHECK(r.examined == 3);
    CHECK(open == std::vector<std::string>{"[0, 1/2]", "[1/2, 1]"});
  }
  SECTION("depth: an open box at max_depth is kept open, not split") {
    Budget b;
    b.max_depth = 1;
    const auto r = refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::breadth_first, b, wide_split, halves, never, close);
    CHECK(r.stop == Subdivision::Stop::complete);
    CHECK(r.left == 2);
    CHECK(r.left_depth == 2);
    CHECK(open == std::vector<std::string>{"[0, 1/2]", "[1/2, 1]"});
  }
  SECTION("replace: a replaced box is split at once and is no part of the partition; refuted stops") {
    auto replace_root = [&](const Interval& b) {
      made.push_back(text(b));
      if (b.hi - b.lo == 1) return Examined::replace;
      return b.lo == Rational(1, 2) ? Examined::refuted : Examined::split;
    };
    const auto r = refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::breadth_first, Budget{}, replace_root, halves, never, close);
    CHECK(r.stop == Subdivision::Stop::refuted);
    CHECK(made == std::vector<std::string>{"[0, 1]", "[0, 1/2]", "[1/2, 1]"});
    CHECK(r.boxes == 2);
    CHECK(closed == std::vector<std::string>{"[1/2, 1]"});
    CHECK(open == std::vector<std::string>{"[0, 1/2]"});
  }
  SECTION("a depth-first refinement is refused, as are a best-first subdivision and a replaced box in one") {
    CHECK_THROWS_AS(refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::depth_first, Budget{}, wide_split, halves, never, close),
                    std::invalid_argument);
    CHECK_THROWS_AS(subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{Order::best_first, 2, false}, Budget{},
                              [](const Interval&, int) { return Examined::split; }, halves, [](Interval&&, Left) {}),
                    std::invalid_argument);    CHECK_THROWS_AS(subdivide(std::vector<Interval>{{Rational(0), Rational(1)}}, Walk{}, Budget{},
                              [](const Interval&, int) { return Examined::replace; }, halves, [](Interval&&, Left) {}),
                    std::invalid_argument);
  }
}

TEST_CASE("refine: best first, equal keys by slot, and an integral's enclosure on it refutes a planted bug") {
  // p = (x - 1/2)^2 on [0, 1], its integral exactly 1/12.
  const Bernstein<Rational> p = quadratic(Rational(1, 4), Rational(-1), Rational(1));
  const Rational exact(1, 12);
  Quadrature q{p};
  const auto r = q.run(Rational(1, 1000), 1000);
  CHECK(r.stop == Subdivision::Stop::reached);
  CHECK(q.lo <= exact);
  CHECK(exact <= q.hi);
  CHECK(q.hi - q.lo <= Rational(1, 1000));
  // The widest box first; of the two equal halves of [0, 1] the one made last (the higher slot).
  REQUIRE(q.split_order.size() >= 3);
  CHECK(q.split_order[0] == "[0, 1]");
  CHECK(q.split_order[1] == "[1/2, 1]");
  CHECK(q.split_order[2] == "[0, 1/2]");
  // Planted: the end values bound nothing in between: the enclosure misses the exact integral.
  Quadrature planted{p, true};
  planted.run(Rational(1, 1000), 1000);
  CHECK_FALSE((planted.lo <= exact && exact <= planted.hi));
  // The budget: at most 5 boxes, the width not reached.
  Quadrature small{p};
  const auto s = small.run(Rational(0), 5);
  CHECK(s.stop == Subdivision::Stop::boxes);
  CHECK(s.boxes == 5);
  CHECK(small.lo <= exact);
  CHECK(exact <= small.hi);
}

TEST_CASE("refine: equal keys go to the higher slot, freed slots are taken last freed first") {
  // Every box has key 1; boxes longer than 1/8 are split. The order of splits is the pool's rule:
  // [0, 1] in slot 0 makes [0, 1/2] (slot 0 again) and [1/2, 1] (slot 1); slot 1 first: its halves
  // take slots 1 and 2; [3/4, 1] (slot 2), then [1/2, 3/4] (slot 1), whose halves are settled,
  // leave slots 2 and 1 free; [0, 1/2] frees slot 0 and its halves take 0 ([0, 1/4]) and 1
  // ([1/4, 1/2]), so [1/4, 1/2] comes first (slots taken first freed first would put [0, 1/4] in
  // slot 2, ahead of it).
  std::vector<std::string> order;
  auto examine = [](const Interval& b) { return b.hi - b.lo > Rational(1, 8) ? Examined::split : Examined::settled; };
  auto split = [&](Interval&& b, int d, auto&& emit) {
    order.push_back(text(b));
    halves(std::move(b), d, emit);
  };
  const auto r = refine(std::vector<Interval>{{Rational(0), Rational(1)}}, Order::best_first, Budget{}, examine, split, []() { return false; },
                        [](Interval&&, bool) {}, [](const Interval&) { return 1; });
  CHECK(r.stop == Subdivision::Stop::complete);
  CHECK(order == std::vector<std::string>{"[0, 1]", "[1/2, 1]", "[3/4, 1]", "[1/2, 3/4]", "[0, 1/2]", "[1/4, 1/2]", "[0, 1/4]"});
  CHECK(r.boxes == 8);
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
