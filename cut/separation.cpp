#include "cut/separation.hpp"

#include <algorithm>
#include <optional>
#include <type_traits>

#include "bernstein/subdivide.hpp"
#include "compose/compose.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

namespace {

struct Ctx {
  const Solid2<Rational>& solid;
  const CutData2<Rational>& cut;
  const BSpline<Rational>& f;
  BezierForm<Rational> form;
  std::array<std::array<Rational, 2>, 2> ends;
  Rational strip;
  SeparationOptions options;
  SeparationResult result;
  std::size_t examined = 0;
};

// The verdict: a witness refutes; "certified" needs every piece decided and at least one certified
// (pieces all in the strip: nothing was checked).
template <class Result>
void decide(Result& r) {
  constexpr bool planar = std::is_same_v<Result, SeparationResult>;
  if (r.witness) {
    r.verdict = Verdict::refuted("f* has the wrong sign at the witness, an exact boundary point outside the strip");
  } else if (!r.undecided.empty()) {
    r.verdict = Verdict::undecided(std::to_string(r.undecided.size()) +
                                   " boundary piece(s) left undecided at the subdivision budget (listed); no violation was found");
  } else if (r.pieces == 0) {
    r.verdict = Verdict::undecided("nothing was checked: every boundary piece lies in the strip around the " + std::string(planar ? "cut points" : "loop") +
                                   " (" + std::to_string(r.excluded) + " excluded); narrow the strip");
  } else {
    r.verdict = Verdict::proved(planar ? "f* > 0 on all of b and f* < 0 on all of b-bar outside the strip, decided exactly"
                                       : "f* > 0 on all of b and f* < 0 on all of b-bar outside the strip around the loop, decided exactly");
  }
}

Rational absq(const Rational& x) { return x < 0 ? Rational(-x) : x; }

// The index range [first, last] of segments of `breaks` meeting [lo, hi] (closed).
std::pair<std::size_t, std::size_t> segments_meeting(const std::vector<Rational>& breaks, const Rational& lo, const Rational& hi) {
  std::size_t first = 0, last = breaks.size() - 2;
  while (first < last && breaks[first + 1] < lo) ++first;
  while (last > first && hi < breaks[last]) --last;
  return {first, last};
}

bool box_in_strip(const Ctx& c, const Rational* lo, const Rational* hi) {
  for (const auto& p : c.ends)
    if (p[0] - c.strip <= lo[0] && hi[0] <= p[0] + c.strip && p[1] - c.strip <= lo[1] && hi[1] <= p[1] + c.strip) return true;
  return false;
}

bool point_in_strip(const Ctx& c, const std::array<Rational, 2>& x) {
  for (const auto& p : c.ends)
    if (absq(x[0] - p[0]) <= c.strip && absq(x[1] - p[1]) <= c.strip) return true;
  return false;
}

// One boundary piece's certificate, depth first on the engine (bernstein/subdivide.hpp), halves in
// order: check(piece, depth) settles it (in the strip, or f*'s Bezier coefficients of the right
// sign on it), refutes it (a witness) or splits it at halve(piece, depth); a piece at
// options.max_depth is recorded undecided and the walk goes on. The budget of options.max_pieces
// counts the pieces of all boundary pieces (c.examined); the piece found over it is recorded
// undecided and ends the certificate. False when the certificate ends (a witness or the budget).
template <class C, class Check, class Halve, class Record>
bool walk_piece(C& c, const BSpline<Rational>& root, Check&& check, Halve&& halve, Record&& record) {
  Budget budget;
  budget.max_boxes = c.options.max_pieces - std::min(c.examined, c.options.max_pieces);
  budget.max_depth = c.options.max_depth;
  std::optional<BSpline<Rational>> next;  // the piece that would have been examined next
  auto leave = [&](BSpline<Rational>&& piece, Left why) {
    if (why == Left::boxes) next = std::move(piece);
    else record(piece);
  };
  const Subdivision run =
      subdivide(std::vector<BSpline<Rational>>{root}, Walk{Order::depth_first, 2, false}, budget, check, halve, leave);
  c.examined += run.examined;
  if (run.stop == Subdivision::Stop::boxes) {
    ++c.examined;
    record(*next);
    return false;
  }
  return run.stop != Subdivision::Stop::refuted;
}

// A Bezier piece of a facet on [s0, s1] (its own knots), on side `positive`.
Examined examine(Ctx& c, std::size_t facet, const BSpline<Rational>& piece, bool positive) {
  Rational lo[2], hi[2];
  for (int a = 0; a < 2; ++a) lo[a] = hi[a] = piece.points[a];
  for (std::size_t i = 0; i < piece.size(); ++i)
    for (int a = 0; a < 2; ++a) {
      const Rational& x = piece.points[2 * i + a];
      if (x < lo[a]) lo[a] = x;
      if (hi[a] < x) hi[a] = x;
    }
  if (box_in_strip(c, lo, hi)) {
    ++c.result.excluded;
    return Examined::settled;
  }
  const auto [x0, x1] = segments_meeting(c.form.breaks[0], lo[0], hi[0]);
  const auto [y0, y1] = segments_meeting(c.form.breaks[1], lo[1], hi[1]);
  const std::size_t nx = c.form.breaks[0].size() - 1;
  bool all = true;
  for (std::size_t j = y0; j <= y1 && all; ++j)
    for (std::size_t i = x0; i <= x1 && all; ++i) {
      const auto cell = c.form.piece(i + nx * j).spline;
      const auto g = compose_bezier(cell, piece);
      for (const auto& v : g.points)
        if (positive ? !(v > 0) : !(v < 0)) {
          all = false;
          break;
        }
    }
  if (all) {
    ++c.result.pieces;
    return Examined::settled;
  }
  // Witnesses: exact values at the ends and the middle.
  const Rational s0 = piece.domain_lo(0), s1 = piece.domain_hi(0), sm = (s0 + s1) / 2;
  for (const Rational& s : {s0, sm, s1}) {
    const auto p = evaluate(piece, std::vector<Rational>{s});
    const std::array<Rational, 2> x{p[0], p[1]};
    if (point_in_strip(c, x)) continue;
    const Rational v = evaluate(c.f, std::vector<Rational>{x[0], x[1]})[0];
    if (positive ? !(v > 0) : !(v < 0)) {
      c.result.witness = SeparationWitness{facet, s, x, v, positive};
      return Examined::refuted;
    }
  }
  return Examined::split;  // at max_depth: undecided, and the walk goes on (a violation elsewhere still decides)
}

// Depth first takes the last half emitted first: the first half, then the second.
const auto halve_curve = [](BSpline<Rational>&& piece, int, auto&& emit) {
  auto [a, b] = split_at(piece, 0, (piece.domain_lo(0) + piece.domain_hi(0)) / 2);
  emit(std::move(b));
  emit(std::move(a));
};

}  // namespace

SeparationResult certify_separation(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const BSpline<Rational>& f,
                                    const Rational& strip, const SeparationOptions& options) {
  Ctx c{solid, cut, f, bezier_form(f), {}, strip, options, {}, 0};
  for (int e = 0; e < 2; ++e) {
    const auto p = evaluate(solid.facets[cut.ends[e].facet], std::vector<Rational>{cut.ends[e].param});
    c.ends[e] = {p[0], p[1]};
  }
  bool go = true;
  for (const auto& P : split_at_cut_points(solid, cut)) {
    for (const auto& bz : extract_bezier(P.curve)) {
      const Rational mid = (bz.spline.domain_lo(0) + bz.spline.domain_hi(0)) / 2;
      const bool positive = on_arc(P.facet, mid, cut.ends[0], cut.ends[1]);
      const std::size_t facet = P.facet;
      if (!walk_piece(
              c, bz.spline, [&](const BSpline<Rational>& piece, int) { return examine(c, facet, piece, positive); }, halve_curve,
              [&](const BSpline<Rational>& piece) { c.result.undecided.push_back({facet, piece.domain_lo(0), piece.domain_hi(0)}); })) {
        go = false;
        break;
      }
    }
    if (!go) break;
  }
  decide(c.result);
  return c.result;
}


namespace {

struct Ctx3 {
  const std::vector<LoopSide3>& loop;
  const BSpline<Rational>& f;
  BezierForm<Rational> form;
  Rational strip;
  SeparationOptions options;
  SeparationResult3 result;
  std::size_t examined = 0;
};

Examined examine3(Ctx3& c, std::size_t facet, const BSpline<Rational>& piece, bool positive) {
  const std::array<Rational, 2> plo{piece.domain_lo(0), piece.domain_lo(1)}, phi{piece.domain_hi(0), piece.domain_hi(1)};
  const auto box = control_bounds(piece);
  const std::array<Rational, 3> lo{box[0], box[1], box[2]}, hi{box[3], box[4], box[5]};
  if (box_in_loop_strip(c.loop, lo, hi, c.strip)) {
    ++c.result.excluded;
    return Examined::settled;
  }
  std::array<std::pair<std::size_t, std::size_t>, 3> range;
  for (int a = 0; a < 3; ++a) range[a] = segments_meeting(c.form.breaks[a], lo[a], hi[a]);
  const std::size_t nx = c.form.breaks[0].size() - 1, ny = c.form.breaks[1].size() - 1;
  bool all = true;
  for (std::size_t k = range[2].first; k <= range[2].second && all; ++k)
    for (std::size_t j = range[1].first; j <= range[1].second && all; ++j)
      for (std::size_t i = range[0].first; i <= range[0].second && all; ++i) {
        const auto g = compose_bezier(c.form.piece(i + nx * (j + ny * k)).spline, piece);
        for (const auto& v : g.points)
          if (positive ? !(v > 0) : !(v < 0)) {
            all = false;
            break;
          }
      }
  if (all) {
    ++c.result.pieces;
    return Examined::settled;
  }
  // Witnesses: exact values at the corners and the middle.
  const std::array<Rational, 2> mid{(plo[0] + phi[0]) / 2, (plo[1] + phi[1]) / 2};
  for (int m = 0; m < 5; ++m) {
    const std::array<Rational, 2> s = m == 4 ? mid : std::array<Rational, 2>{(m & 1) ? phi[0] : plo[0], (m & 2) ? phi[1] : plo[1]};
    const auto p = evaluate(piece, std::vector<Rational>{s[0], s[1]});
    const std::array<Rational, 3> x{p[0], p[1], p[2]};
    if (in_loop_strip(c.loop, x, c.strip)) continue;
    const Rational v = evaluate(c.f, std::vector<Rational>{x[0], x[1], x[2]})[0];
    if (positive ? !(v > 0) : !(v < 0)) {
      c.result.witness = SeparationWitness3{facet, s, x, v, positive};
      return Examined::refuted;
    }
  }
  return Examined::split;
}

// Halved across s and t in turn; the first half first.
const auto halve_patch = [](BSpline<Rational>&& piece, int depth, auto&& emit) {
  const int d = depth % 2;
  auto [a, b] = split_at(piece, d, (piece.domain_lo(d) + piece.domain_hi(d)) / 2);
  emit(std::move(b));
  emit(std::move(a));
};

}  // namespace

SeparationResult3 certify_separation(const Solid3<Rational>& solid, const std::vector<LoopSide3>& loop, const std::vector<std::size_t>& positive,
                                     const BSpline<Rational>& f, const Rational& strip, const SeparationOptions& options) {
  Ctx3 c{loop, f, bezier_form(f), strip, options, {}, 0};
  std::vector<char> in_b(solid.facets.size(), 0);
  for (auto i : positive) in_b.at(i) = 1;
  bool go = true;
  for (std::size_t i = 0; i < solid.facets.size() && go; ++i)
    for (const auto& bz : extract_bezier(solid.facets[i]))
      if (!walk_piece(
              c, bz.spline, [&](const BSpline<Rational>& piece, int) { return examine3(c, i, piece, in_b[i]); }, halve_patch,
              [&](const BSpline<Rational>& piece) {
                c.result.undecided.push_back({i, {piece.domain_lo(0), piece.domain_lo(1)}, {piece.domain_hi(0), piece.domain_hi(1)}});
              })) {
        go = false;
        break;
      }
  decide(c.result);
  return c.result;
}

}  // namespace splinex
