#include "cut/solid.hpp"

#include <algorithm>
#include <optional>
#include <sstream>

#include "base/errors.hpp"
#include "bernstein/subdivide.hpp"
#include "base/point.hpp"
#include "spline/bernstein.hpp"
#include "spline/bezier.hpp"
#include "spline/evaluate.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace {

std::string facet_field(std::size_t i) { return "facets[" + std::to_string(i) + "]"; }

std::array<Rational, 2> start_of(const BSpline<Rational>& F) { return {F.points[0], F.points[1]}; }
std::array<Rational, 2> end_of(const BSpline<Rational>& F) {
  const std::size_t n = F.size();
  return {F.points[2 * (n - 1)], F.points[2 * (n - 1) + 1]};
}

// The one-sided derivative at s: from the right (side > 0) or the left. The first non-zero
// derivative of order <= degree, so that a vanishing first derivative still gives the direction.
std::array<Rational, 2> direction(const BSpline<Rational>& F, const Rational& s, int side, const std::string& field) {
  // Split at s and read the control polygon: the first control point differing from the end
  // point gives the one-sided direction (exact; equal control points are skipped).
  const Rational lo = F.domain_lo(0), hi = F.domain_hi(0);
  BSpline<Rational> part = F;
  if (side > 0) {
    if (lo < s) part = split_at(F, 0, s).second;
    const auto p0 = start_of(part);
    for (std::size_t i = 1; i < part.size(); ++i) {
      std::array<Rational, 2> d{part.points[2 * i] - p0[0], part.points[2 * i + 1] - p0[1]};
      if (d[0] != 0 || d[1] != 0) return d;
    }
  } else {
    if (s < hi) part = split_at(F, 0, s).first;
    const auto p1 = end_of(part);
    for (std::size_t i = part.size() - 1; i-- > 0;) {
      std::array<Rational, 2> d{p1[0] - part.points[2 * i], p1[1] - part.points[2 * i + 1]};
      if (d[0] != 0 || d[1] != 0) return d;
    }
  }
  throw ValidationError(field, "the facet is a single point near the cut point (no direction)",
                        "give facets that are curves, not points");
}


// t strictly inside the solid's angle at a point with incoming direction ein and outgoing eout
// (counter-clockwise loop: the solid is on the left).
bool points_inside(const std::array<Rational, 2>& ein, const std::array<Rational, 2>& eout, const std::array<Rational, 2>& t) {
  const Rational turn = cross(ein, eout);
  if (turn > 0) return cross(ein, t) > 0 && cross(eout, t) > 0;      // convex corner
  if (turn < 0) return cross(ein, t) > 0 || cross(eout, t) > 0;      // reflex corner
  if (dot(ein, eout) > 0) return cross(eout, t) > 0;                 // smooth
  // A cusp: the solid's angle is 0 (the facets turn back) or 2 pi; refuse either way.
  return false;
}

}  // namespace

void validate_solid(const Solid2<Rational>& S) {
  if (S.facets.size() < 2) throw ValidationError("facets", "has " + std::to_string(S.facets.size()) + " facet(s)", "give at least two facets forming a closed loop");
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const auto& F = S.facets[i];
    const std::string f = facet_field(i);
    validate(F);
    if (F.dim() != 1) throw ValidationError(f, "is not a curve (" + std::to_string(F.dim()) + " parameters)", "give curves with one parameter");
    if (F.q != 2) throw ValidationError(f, "has " + std::to_string(F.q) + " coordinates", "give planar curves (2 coordinates)");
    if (F.is_rational()) throw ValidationError(f, "is rational", "give polynomial facets (rational facets are not supported yet)");
    if (F.degrees[0] < 1) throw ValidationError(f, "has degree 0", "give curves of degree >= 1 (a loop of facets must be continuous)");
    bool one_point = true;
    for (std::size_t j = 1; j < F.size() && one_point; ++j) one_point = F.points[2 * j] == F.points[0] && F.points[2 * j + 1] == F.points[1];
    if (one_point)
      throw ValidationError(f, "is a single point (" + to_fraction_string(F.points[0]) + ", " + to_fraction_string(F.points[1]) + "): a facet of zero length",
                            "remove the facet (let its neighbours meet there), or give it distinct control points");
    if (!is_clamped(F.knots[0], F.degrees[0], F.count(0)))
      throw ValidationError(f + ".knots", "is not clamped", "clamp the knot vector (end knots of multiplicity degree + 1) so the facet starts and ends at control points");
    // An inner knot of multiplicity degree + 1 (C^-1) may be a jump: the loop must be continuous.
    const auto pieces = extract_bezier(F);
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
      if (end_of(pieces[k].spline) != start_of(pieces[k + 1].spline))
        throw ValidationError(f, "jumps at its inner knot " + to_fraction_string(pieces[k].spline.domain_hi(0)) + " (a C^-1 knot with a gap)",
                              "split the facet there into two facets joined end to start, or close the gap");
  }
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const std::size_t j = (i + 1) % S.facets.size();
    if (end_of(S.facets[i]) != start_of(S.facets[j]))
      throw ValidationError(facet_field(i), "ends where " + facet_field(j) + " does not start",
                            "order the facets along the boundary so each ends exactly where the next starts (the last where the first starts)");
  }
  check_simple_loop(S);
  const Rational a = signed_area(S);
  if (a == 0) throw ValidationError("facets", "enclose zero signed area", "give a loop around a solid");
  if (a < 0) throw ValidationError("facets", "run clockwise (signed area " + to_fraction_string(a) + ")",
                                   "list the facets counter-clockwise (the solid on the left), or reverse the loop");
}

// ---- The loop is simple (papers/004 Section 2: the boundary of a solid) --------------------------
//
// Exact throughout. The facets' Bezier pieces become elements, each injective: its control polygon
// is monotone in some direction d (d . (P_{i+1} - P_i) >= 0, one > 0: d . C' > 0 inside the piece),
// else it is halved. Pairs of elements whose boxes meet (a bounding-volume tree: near-linear for
// loops that do not pile up) are decided by
//  - boxes or convex hulls of the control points strictly separated (separating axis): disjoint;
//  - loop neighbours (the end of one is the start of the other, V): a line through V with the one's
//    control points strictly on one side and the other's on the other (V excepted): they meet at V only;
//  - two straight elements (control points collinear, monotone: the curve is the segment P_0 P_p):
//    exact segment intersection, so straight-sided loops are decided exactly, whatever the sizes;
//  - a crossing: B monotone along its chord d is a graph over the d axis inside its strip (the hull's
//    extent across d); A inside B's open slab (0 < d . (x - B_0) < d . d) with its ends strictly on
//    the two sides of the strip must cross B (intermediate values): an intersection, proved;
//  - otherwise the larger element is halved. At the depth or work budget (curves touching
//    tangentially, or closer than 2^-depth of their size) the loop is refused: it could not be
//    proved simple.

namespace {

using P2 = Point2<Rational>;

P2 perp(const P2& a) { return {Rational(-a[1]), a[0]}; }
bool is_zero(const P2& a) { return a[0] == 0 && a[1] == 0; }

struct LoopElem {
  std::vector<P2> p;          // Bezier control points
  Rational a, b;              // loop parameter: Bezier piece k of the loop covers [k, k + 1]
  std::size_t facet = 0;
  Rational s0, s1;            // the facet's parameters
  P2 lo, hi;                  // the control points' box
  bool straight = false;      // collinear and monotone along P_p - P_0: the curve is that segment
  int depth = 0;
};

// d . (P_{i+1} - P_i) >= 0 for all i and > 0 for one.
bool monotone_along(const std::vector<P2>& p, const P2& d) {
  bool some = false;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    const Rational s = dot(d, sub(p[i + 1], p[i]));
    if (s < 0) return false;
    if (s > 0) some = true;
  }
  return some;
}

bool injective(const std::vector<P2>& p) {
  if (monotone_along(p, sub(p.back(), p.front()))) return true;
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    if (monotone_along(p, sub(p[i + 1], p[i]))) return true;
  return false;
}

void finish(LoopElem& e) {
  e.lo = e.hi = e.p[0];
  for (const auto& x : e.p)
    for (int a = 0; a < 2; ++a) {
      if (x[a] < e.lo[a]) e.lo[a] = x[a];
      if (e.hi[a] < x[a]) e.hi[a] = x[a];
    }
  const P2 d = sub(e.p.back(), e.p.front());
  e.straight = monotone_along(e.p, d);
  for (std::size_t i = 1; e.straight && i + 1 < e.p.size(); ++i) e.straight = cross(d, sub(e.p[i], e.p[0])) == 0;
}

// de Casteljau at 1/2.
std::pair<LoopElem, LoopElem> halves(const LoopElem& e) {
  std::vector<P2> w = e.p;
  LoopElem l, r;
  const std::size_t n = w.size();
  l.p.resize(n), r.p.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    l.p[k] = w[0];
    r.p[n - 1 - k] = w[n - 1 - k];
    for (std::size_t i = 0; i + 1 < n - k; ++i) w[i] = {(w[i][0] + w[i + 1][0]) / 2, (w[i][1] + w[i + 1][1]) / 2};
  }
  const Rational am = (e.a + e.b) / 2, sm = (e.s0 + e.s1) / 2;
  l.a = e.a, l.b = am, r.a = am, r.b = e.b;
  l.s0 = e.s0, l.s1 = sm, r.s0 = sm, r.s1 = e.s1;
  l.facet = r.facet = e.facet;
  l.depth = r.depth = e.depth + 1;
  finish(l), finish(r);
  return {std::move(l), std::move(r)};
}

Rational extent(const LoopElem& e) {
  Rational w = e.hi[0] - e.lo[0], h = e.hi[1] - e.lo[1];
  return w < h ? h : w;
}

bool boxes_meet(const LoopElem& A, const LoopElem& B) {
  for (int a = 0; a < 2; ++a)
    if (A.hi[a] < B.lo[a] || B.hi[a] < A.lo[a]) return false;
  return true;
}

// The convex hulls of the control points strictly apart: an axis perpendicular to a difference of
// two of the points (the separating axis theorem: edge normals suffice, the box test covers the
// collinear case).
bool hulls_apart(const LoopElem& A, const LoopElem& B) {
  std::vector<const P2*> all;
  for (const auto& x : A.p) all.push_back(&x);
  for (const auto& x : B.p) all.push_back(&x);
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const P2 n = perp(sub(*all[j], *all[i]));
      if (is_zero(n)) continue;
      Rational amin = dot(n, A.p[0]), amax = amin, bmin = dot(n, B.p[0]), bmax = bmin;
      for (const auto& x : A.p) {
        const Rational v = dot(n, x);
        if (v < amin) amin = v;
        if (amax < v) amax = v;
      }
      for (const auto& x : B.p) {
        const Rational v = dot(n, x);
        if (v < bmin) bmin = v;
        if (bmax < v) bmax = v;
      }
      if (amax < bmin || bmax < amin) return true;
    }
  return false;
}

// A ends at V where B starts: a line through V with A's control points (V excepted) on one side,
// its first strictly, and B's on the other, its last strictly. The feasible normals form a cone
// whose boundary rays are perpendicular to one of the vectors; the sum of two boundary rays lies
// inside it, unless the cone is a half-plane (all vectors on one ray), when that ray is inside.
bool meet_only_at_vertex(const LoopElem& A, const LoopElem& B) {
  const P2& V = B.p.front();
  std::vector<P2> w;  // n . w >= 0 wanted for all; strictly for the first two
  w.push_back(sub(V, A.p.front()));
  w.push_back(sub(B.p.back(), V));
  for (std::size_t i = 1; i + 1 < A.p.size(); ++i) w.push_back(sub(V, A.p[i]));
  for (std::size_t j = 1; j + 1 < B.p.size(); ++j) w.push_back(sub(B.p[j], V));
  if (is_zero(w[0]) || is_zero(w[1])) return false;
  auto holds = [&](const P2& n, bool strict) {
    for (std::size_t k = 0; k < w.size(); ++k) {
      const Rational s = dot(n, w[k]);
      if (s < 0 || (strict && k < 2 && s == 0)) return false;
    }
    return true;
  };
  std::vector<P2> rays;
  for (const auto& v : w) {
    if (is_zero(v)) continue;
    for (const P2& n : {v, perp(v), P2{v[1], Rational(-v[0])}})  // v itself: the cone is a half-plane (a straight continuation)
      if (holds(n, false)) {
        if (holds(n, true)) return true;
        rays.push_back(n);
      }
  }
  for (std::size_t i = 0; i < rays.size(); ++i)
    for (std::size_t j = i + 1; j < rays.size(); ++j)
      if (holds({rays[i][0] + rays[j][0], rays[i][1] + rays[j][1]}, true)) return true;
  return false;
}

int orient(const P2& a, const P2& b, const P2& c) {
  const Rational v = cross(sub(b, a), sub(c, a));
  return v > 0 ? 1 : v < 0 ? -1 : 0;
}
bool on_segment(const P2& a, const P2& b, const P2& x) {  // x collinear with a, b
  for (int k = 0; k < 2; ++k) {
    const Rational& lo = a[k] < b[k] ? a[k] : b[k];
    const Rational& hi = a[k] < b[k] ? b[k] : a[k];
    if (x[k] < lo || hi < x[k]) return false;
  }
  return true;
}

// Closed segments ab and cd: a common point, exactly, or none.
std::optional<P2> segments_meet(const P2& a, const P2& b, const P2& c, const P2& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    const P2 r = sub(b, a), s = sub(d, c);
    const Rational t = cross(sub(c, a), s) / cross(r, s);
    return P2{a[0] + t * r[0], a[1] + t * r[1]};
  }
  if (o1 == 0 && on_segment(a, b, c)) return c;
  if (o2 == 0 && on_segment(a, b, d)) return d;
  if (o3 == 0 && on_segment(c, d, a)) return a;
  if (o4 == 0 && on_segment(c, d, b)) return b;
  return std::nullopt;
}

// A crosses B (see above): proved by the intermediate value theorem.
bool crosses(const LoopElem& A, const LoopElem& B) {
  const P2& B0 = B.p.front();
  const P2 d = sub(B.p.back(), B0);
  if (!monotone_along(B.p, d)) return false;
  const P2 n = perp(d);
  Rational wlo(0), whi(0);
  for (const auto& x : B.p) {
    const Rational v = dot(n, sub(x, B0));
    if (v < wlo) wlo = v;
    if (whi < v) whi = v;
  }
  const Rational dd = dot(d, d);
  for (const auto& x : A.p) {
    const Rational t = dot(d, sub(x, B0));
    if (!(0 < t && t < dd)) return false;
  }
  const Rational s0 = dot(n, sub(A.p.front(), B0)), s1 = dot(n, sub(A.p.back(), B0));
  return (s0 < wlo && whi < s1) || (s1 < wlo && whi < s0);
}

std::string point_text(const P2& x, bool exact) {
  if (exact) return "(" + to_fraction_string(x[0]) + ", " + to_fraction_string(x[1]) + ")";
  std::ostringstream o;
  o << "(" << to_double(x[0]) << ", " << to_double(x[1]) << ")";
  return o.str();
}
std::string range_text(const LoopElem& e) {
  std::ostringstream o;
  o << to_double(e.s0) << " .. " << to_double(e.s1);
  return o.str();
}

// "facets[i]: crosses facets[j] at (x, y) (parameters a .. b of the one, c .. d of the other)"; `at`
// says where: an exact point, or the box of the element that crosses.
[[noreturn]] void not_simple(const LoopElem& A, const LoopElem& B, const std::string& how, const std::string& at) {
  const LoopElem& first = A.facet < B.facet || (A.facet == B.facet && A.s0 < B.s0) ? A : B;
  const LoopElem& second = &first == &A ? B : A;
  const bool self = first.facet == second.facet;
  throw ValidationError(facet_field(first.facet),
                        how + " " + (self ? std::string("itself") : facet_field(second.facet)) + " " + at + " (parameters " + range_text(first) +
                            (self ? " and " : " of the one, " + range_text(second) + " of the other") + (self ? range_text(second) : std::string()) +
                            "): the loop is not simple",
                        "give a simple closed loop: facets meet only where one ends and the next starts");
}
std::string at_point(const P2& x) { return "at " + point_text(x, true); }
std::string within_box(const LoopElem& e) {
  std::ostringstream o;
  o << "within [" << to_double(e.lo[0]) << ", " << to_double(e.hi[0]) << "] x [" << to_double(e.lo[1]) << ", " << to_double(e.hi[1]) << "]";
  return o.str();
}

struct LoopChecker {
  const SimpleLoopOptions& options;
  Rational length;  // the loop parameter's period: the number of Bezier pieces
  std::size_t tests = 0;

  bool follows(const LoopElem& A, const LoopElem& B) const { return A.b == B.a || (A.b == length && B.a == 0); }

  [[noreturn]] void undecided(const LoopElem& A, const LoopElem& B, const std::string& why) const {
    const LoopElem& first = A.facet <= B.facet ? A : B;
    const LoopElem& second = A.facet <= B.facet ? B : A;
    throw ValidationError(facet_field(first.facet),
                          "could not be proved apart from " + (first.facet == second.facet ? std::string("itself") : facet_field(second.facet)) + " near " +
                              point_text(first.p.front(), false) + " (" + why + "): the loop is not certified simple",
                          "make facets that do not touch apart by more than 2^-" + std::to_string(options.max_depth) +
                              " of their size, and avoid cusps at vertices; facets touching elsewhere than at shared vertices are not a simple loop");
  }

  // Decides one pair of elements; throws when they meet elsewhere than at a shared vertex. The
  // larger element of an undecided pair is halved (depth first); the budget of tests is shared by
  // every pair of the loop.
  void resolve(const LoopElem& A0, const LoopElem& B0) {
    using Pair = std::pair<LoopElem, LoopElem>;
    auto examine = [&](const Pair& pr, int) {
      const LoopElem &A = pr.first, &B = pr.second;
      if (!boxes_meet(A, B)) return Examined::settled;
      const bool ab = follows(A, B), ba = follows(B, A);
      if (ab != ba) {
        const LoopElem& first = ab ? A : B;
        const LoopElem& second = ab ? B : A;
        if (meet_only_at_vertex(first, second)) return Examined::settled;
        if (first.straight && second.straight)  // both from V along the same ray
          not_simple(first, second, "turns back along", at_point(second.p.front()));
      } else if (!ab) {
        if (hulls_apart(A, B)) return Examined::settled;
        if (A.straight && B.straight) {
          if (const auto x = segments_meet(A.p.front(), A.p.back(), B.p.front(), B.p.back())) not_simple(A, B, "meets", at_point(*x));
          return Examined::settled;
        }
        if (A.straight || B.straight) {  // an end point of the other exactly on the segment: they touch
          const LoopElem& seg = A.straight ? A : B;
          const LoopElem& other = A.straight ? B : A;
          for (const P2* x : {&other.p.front(), &other.p.back()})
            if (orient(seg.p.front(), seg.p.back(), *x) == 0 && on_segment(seg.p.front(), seg.p.back(), *x)) not_simple(A, B, "meets", at_point(*x));
        }
        if (crosses(A, B)) not_simple(A, B, "crosses", within_box(A));
        if (crosses(B, A)) not_simple(A, B, "crosses", within_box(B));
      }
      if (A.depth >= options.max_depth && B.depth >= options.max_depth)
        undecided(A, B, "no decision after " + std::to_string(options.max_depth) + " halvings");
      return Examined::split;
    };
    auto split = [&](Pair&& pr, int, auto&& emit) {
      auto& [A, B] = pr;
      const bool a_can = A.depth < options.max_depth, b_can = B.depth < options.max_depth;
      const Rational sa = extent(A), sb = extent(B);
      if (a_can && (!b_can || !(sa < sb))) {
        auto [l, r] = halves(A);
        emit(Pair{std::move(l), B});
        emit(Pair{std::move(r), std::move(B)});
      } else {
        auto [l, r] = halves(B);
        emit(Pair{A, std::move(l)});
        emit(Pair{std::move(A), std::move(r)});
      }
    };
    std::optional<Pair> next;  // the pair the spent budget stopped at: the next one depth first
    auto leave = [&](Pair&& pr, Left) { next = std::move(pr); };
    Budget budget;
    budget.max_boxes = options.max_tests - std::min(tests, options.max_tests);
    const Subdivision run = subdivide(std::vector<Pair>{Pair{A0, B0}}, Walk{Order::depth_first, 2, false}, budget, examine, split, leave);
    tests += run.examined;
    if (run.stop == Subdivision::Stop::boxes)
      undecided(next->first, next->second, "the work budget of " + std::to_string(options.max_tests) + " tests is spent");
  }
};

// A bounding-volume tree over the elements' boxes (median splits on the larger side).
struct BoxTree {
  struct Node {
    P2 lo, hi;
    std::size_t begin = 0, end = 0;
    int left = -1, right = -1;
  };
  const std::vector<LoopElem>& elems;
  std::vector<std::size_t> order;
  std::vector<Node> nodes;

  explicit BoxTree(const std::vector<LoopElem>& e) : elems(e), order(e.size()) {
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    if (!e.empty()) build(0, e.size());
  }
  int build(std::size_t begin, std::size_t end) {
    Node nd;
    nd.begin = begin, nd.end = end;
    nd.lo = elems[order[begin]].lo, nd.hi = elems[order[begin]].hi;
    for (std::size_t k = begin; k < end; ++k)
      for (int a = 0; a < 2; ++a) {
        if (elems[order[k]].lo[a] < nd.lo[a]) nd.lo[a] = elems[order[k]].lo[a];
        if (nd.hi[a] < elems[order[k]].hi[a]) nd.hi[a] = elems[order[k]].hi[a];
      }
    const int id = static_cast<int>(nodes.size());
    nodes.push_back(nd);
    if (end - begin > 8) {
      const int axis = nd.hi[0] - nd.lo[0] < nd.hi[1] - nd.lo[1] ? 1 : 0;
      const std::size_t mid = begin + (end - begin) / 2;
      std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end, [&](std::size_t i, std::size_t j) {
        return elems[i].lo[axis] + elems[i].hi[axis] < elems[j].lo[axis] + elems[j].hi[axis];
      });
      const int l = build(begin, mid), r = build(mid, end);
      nodes[id].left = l, nodes[id].right = r;
    }
    return id;
  }
  // Calls f(j) for every element j > i whose box meets element i's.
  template <class F>
  void query(std::size_t i, F&& f) const {
    const LoopElem& e = elems[i];
    std::vector<int> stack{0};
    while (!stack.empty()) {
      const Node& nd = nodes[stack.back()];
      stack.pop_back();
      if (nd.hi[0] < e.lo[0] || e.hi[0] < nd.lo[0] || nd.hi[1] < e.lo[1] || e.hi[1] < nd.lo[1]) continue;
      if (nd.left < 0) {
        for (std::size_t k = nd.begin; k < nd.end; ++k)
          if (order[k] > i && boxes_meet(e, elems[order[k]])) f(order[k]);
      } else {
        stack.push_back(nd.left), stack.push_back(nd.right);
      }
    }
  }
};

// The facets' Bezier pieces as injective elements (zero-length pieces refused).
std::vector<LoopElem> loop_elements(const Solid2<Rational>& S, const SimpleLoopOptions& o, Rational& length) {
  std::vector<LoopElem> out;
  std::size_t k = 0;
  for (std::size_t i = 0; i < S.facets.size(); ++i)
    for (const auto& piece : extract_bezier(S.facets[i])) {
      LoopElem e;
      for (std::size_t j = 0; j < piece.spline.size(); ++j) e.p.push_back({piece.spline.points[2 * j], piece.spline.points[2 * j + 1]});
      e.a = Rational(k), e.b = Rational(k + 1), ++k;
      e.facet = i, e.s0 = piece.box[0].first, e.s1 = piece.box[0].second;
      finish(e);
      if (e.lo == e.hi)
        throw ValidationError(facet_field(i), "has a piece of zero length on parameters [" + to_fraction_string(e.s0) + ", " + to_fraction_string(e.s1) +
                                                  "] (all its control points are " + point_text(e.p[0], true) + ")",
                              "remove the repeated control points or knots, so every piece of the facet is a curve");
      // Halved depth first on the engine until every piece is injective; one that is not at
      // o.max_depth turns back on itself.
      Budget depth_only;
      depth_only.max_depth = o.max_depth;
      auto examine = [&](LoopElem& x, int) {
        if (!injective(x.p)) return Examined::split;
        out.push_back(std::move(x));
        return Examined::settled;
      };
      auto split = [](LoopElem&& x, int, auto&& emit) {
        auto [l, r] = halves(x);
        emit(std::move(r));  // depth first: the left half first
        emit(std::move(l));
      };
      auto leave = [&](LoopElem&& x, Left) {
        throw ValidationError(facet_field(i), "turns back on itself (a cusp, its direction reversing) near parameter " + to_fraction_string(x.s0) + ": the loop is not simple",
                              "give facets whose direction does not reverse");
      };
      subdivide(std::vector<LoopElem>{std::move(e)}, Walk{Order::depth_first, 2, true}, depth_only, examine, split, leave);
    }
  length = Rational(k);
  return out;
}

}  // namespace

void check_simple_loop(const Solid2<Rational>& S, const SimpleLoopOptions& options) {
  LoopChecker c{options, Rational(0)};
  const std::vector<LoopElem> elems = loop_elements(S, options, c.length);
  const BoxTree tree(elems);
  for (std::size_t i = 0; i < elems.size(); ++i) tree.query(i, [&](std::size_t j) { c.resolve(elems[i], elems[j]); });
}

Rational signed_area(const Solid2<Rational>& S) {
  // 1/2 sum over Bezier pieces of the integral of x y' - y x' over [0, 1]: products of Bernstein
  // polynomials integrate to the mean of their coefficients.
  Rational twice(0);
  for (const auto& F : S.facets) {
    for (const auto& piece : extract_bezier(F)) {
      const int p = piece.spline.degrees[0];
      std::vector<Rational> x(p + 1), y(p + 1);
      for (int i = 0; i <= p; ++i) x[i] = piece.spline.points[2 * i], y[i] = piece.spline.points[2 * i + 1];
      // derivative coefficients (degree p - 1) of the piece on [0, 1]
      std::vector<Rational> dx(p), dy(p);
      for (int i = 0; i < p; ++i) dx[i] = p * (x[i + 1] - x[i]), dy[i] = p * (y[i + 1] - y[i]);
      // integral of B_i^p B_j^{p-1} over [0,1] = C(p,i) C(p-1,j) / (C(2p-1, i+j) * 2p)
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j < p; ++j) {
          const Rational w = detail::binomial<Rational>(p, i) * detail::binomial<Rational>(p - 1, j) / (detail::binomial<Rational>(2 * p - 1, i + j) * (2 * p));
          twice += w * (x[i] * dy[j] - y[i] * dx[j]);
        }
    }
  }
  return twice / 2;
}

CutData2<Rational> validate_cut(const Solid2<Rational>& S, const CutData2<Rational>& cut) {
  CutData2<Rational> out = cut;
  const std::size_t n = S.facets.size();
  for (int e = 0; e < 2; ++e) {
    auto& c = out.ends[e];
    const std::string f = "points[" + std::to_string(e) + "]";
    if (c.facet >= n) throw ValidationError(f + ".facet", "is " + std::to_string(c.facet) + ", the solid has " + std::to_string(n) + " facets", "give a facet index from 0 to " + std::to_string(n - 1));
    const auto& F = S.facets[c.facet];
    if (c.param < F.domain_lo(0) || F.domain_hi(0) < c.param)
      throw ValidationError(f + ".parameter", "is outside the facet's domain [" + to_fraction_string(F.domain_lo(0)) + ", " + to_fraction_string(F.domain_hi(0)) + "]", "give a parameter of the facet's domain");
    if (c.tangent[0] == 0 && c.tangent[1] == 0) throw ValidationError(f + ".tangent", "is zero", "give a non-zero tangent pointing into the solid");
    if (c.param == F.domain_hi(0)) {
      c.facet = (c.facet + 1) % n;
      c.param = S.facets[c.facet].domain_lo(0);
    }
    const auto& G = S.facets[c.facet];
    std::array<Rational, 2> ein, eout;
    if (c.param == G.domain_lo(0)) {
      const auto& P = S.facets[(c.facet + n - 1) % n];
      ein = direction(P, P.domain_hi(0), -1, f);
    } else {
      ein = direction(G, c.param, -1, f);
    }
    eout = direction(G, c.param, +1, f);
    if (!points_inside(ein, eout, c.tangent))
      throw ValidationError(f + ".tangent", "does not point strictly into the solid", "give a tangent that points into the solid (the solid lies left of the counter-clockwise facets)");
  }
  if (out.ends[0].facet == out.ends[1].facet && out.ends[0].param == out.ends[1].param)
    throw ValidationError("points", "are the same point of the boundary", "give two distinct points");
  return out;
}

Frame2 unit_frame(const Solid2<Rational>& S) {
  Frame2 f;
  std::array<Rational, 2> hi;
  bool first = true;
  for (const auto& F : S.facets)
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int a = 0; a < 2; ++a) {
        const Rational& x = F.points[2 * i + a];
        if (first || x < f.lo[a]) f.lo[a] = x;
        if (first || hi[a] < x) hi[a] = x;
        if (a == 1) first = false;
      }
  f.scale = hi[0] - f.lo[0];
  if (f.scale < hi[1] - f.lo[1]) f.scale = hi[1] - f.lo[1];
  if (f.scale == 0) throw ValidationError("facets", "lie in one point", "give a solid with an interior");
  return f;
}

Solid2<Rational> to_frame(const Solid2<Rational>& S, const Frame2& f) {
  Solid2<Rational> out = S;
  for (auto& F : out.facets)
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int a = 0; a < 2; ++a) F.points[2 * i + a] = (F.points[2 * i + a] - f.lo[a]) / f.scale;
  return out;
}

bool on_arc(std::size_t facet, const Rational& param, const CutPoint2<Rational>& from, const CutPoint2<Rational>& to) {
  auto less = [](std::size_t f1, const Rational& p1, std::size_t f2, const Rational& p2) { return f1 < f2 || (f1 == f2 && p1 < p2); };
  const bool after_from = less(from.facet, from.param, facet, param);
  const bool before_to = less(facet, param, to.facet, to.param);
  if (less(from.facet, from.param, to.facet, to.param)) return after_from && before_to;
  return after_from || before_to;
}

std::vector<BoundaryPiece> split_at_cut_points(const Solid2<Rational>& S, const CutData2<Rational>& cut) {
  std::vector<BoundaryPiece> parts;
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    std::vector<Rational> cuts;
    for (const auto& e : cut.ends)
      if (e.facet == i && S.facets[i].domain_lo(0) < e.param && e.param < S.facets[i].domain_hi(0)) cuts.push_back(e.param);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    BSpline<Rational> rest = S.facets[i];
    for (const auto& c : cuts) {
      auto [a, b] = split_at(rest, 0, c);
      parts.push_back({std::move(a), i});
      rest = std::move(b);
    }
    parts.push_back({std::move(rest), i});
  }
  return parts;
}

}  // namespace splinex
