// V-curves between two trimming surfaces of a trimmed cell (issue 18): exact counts of arcs and
// closed loops, on cells whose boundary curves are known in closed form.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "exact/rational.hpp"
#include "region_helpers.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"
#include "vrep/topology/trimmed_curves.hpp"
#include "vrep/topology/trimmed_topology.hpp"

using namespace splinex;
using R = Rational;

namespace {

BSpline<R> cube2() { return box_cells<R>({R(0), R(0), R(0)}, {R(2), R(2), R(2)}).front(); }

const TrimmedCurves<R>::Pair& pair_of(const TrimmedCurves<R>& t, std::size_t i, std::size_t j) {
  for (const auto& p : t.pairs)
    if (p.i == i && p.j == j) return p;
  FAIL("no pair " << i << ", " << j);
  return t.pairs.front();
}

/// V with a knot of multiplicity p + 1 inserted inside along w (a C^-1 joint): its control net
/// doubled there, so the two halves may differ.
BSpline<R> test_spline_with_jump(const BSpline<R>& V) {
  BSpline<R> J = V;
  const int p = V.degrees[2];
  std::vector<R> k(V.knots[2].begin(), V.knots[2].begin() + p + 1);
  const R mid = (V.knots[2].front() + V.knots[2].back()) / 2;
  for (int i = 0; i <= p; ++i) k.push_back(mid);
  k.insert(k.end(), V.knots[2].end() - (p + 1), V.knots[2].end());
  J.knots[2] = k;
  std::vector<R> pts(V.points.begin(), V.points.end());
  pts.insert(pts.end(), V.points.begin(), V.points.end());
  J.points = pts;
  return J;
}

}  // namespace

TEST_CASE("vrep trimmed curves: planes meet in straight V-curves from V-points to the domain's faces") {
  const auto V = cube2();
  using test::above;
  // Two planes: the line x = 1/3, y = 1/4 runs from face z = 0 to face z = 2.
  const auto two = trimmed_curves(V, region_and<R>({above(0, R(1, 3)), above(1, R(1, 4))}));
  REQUIRE(two.decided);
  CHECK(two.arcs == 1);
  CHECK(two.loops == 0);
  CHECK(pair_of(two, 0, 1).ends_on_faces == 2);
  // Three planes: the box [1/3, 2] x [1/4, 2] x [1/5, 2]; each pair's line runs from the inner
  // corner (a V-point) to a face of the domain.
  const auto three = trimmed_curves(V, region_and<R>({above(0, R(1, 3)), above(1, R(1, 4)), above(2, R(1, 5))}));
  REQUIRE(three.decided);
  CHECK(three.arcs == 3);
  CHECK(three.loops == 0);
  for (const auto& p : three.pairs) {
    CHECK(p.ends_at_points == 1);
    CHECK(p.ends_on_faces == 1);
    CHECK(p.ends_on_identified_faces == 0);
  }
  // The complement of the first plane: the same lines, now on the other side of the V-point.
  const auto other = trimmed_curves(V, region_and<R>({region_not(above(0, R(1, 3))), above(1, R(1, 4)), above(2, R(1, 5))}));
  REQUIRE(other.decided);
  CHECK(other.arcs == 3);
}

TEST_CASE("vrep trimmed curves: closed loops and arcs cut at V-points") {
  const auto V = cube2();
  using test::ball;
  const auto b0 = ball({R(4, 5), R(1), R(1)}, R(1, 2)), b1 = ball({R(6, 5), R(1), R(1)}, R(1, 2));
  // The lens of two balls: its edge is one circle, a loop without V-points.
  const auto lens = trimmed_curves(V, region_and<R>({b0, b1}));
  REQUIRE(lens.decided);
  CHECK(lens.arcs == 0);
  CHECK(lens.loops == 1);
  // Cut by the plane z = 11/10: the circle's upper part and the plane's two circular arcs, each
  // from one V-point to the other.
  const auto cut = trimmed_curves(V, region_and<R>({b0, b1, test::above(2, R(11, 10))}));
  REQUIRE(cut.decided);
  CHECK(cut.arcs == 3);
  CHECK(cut.loops == 0);
  for (const auto& p : cut.pairs) {
    CHECK(p.arcs == 1);
    CHECK(p.ends_at_points == 2);
    CHECK(p.ends_on_faces == 0);
  }
  // The union of the balls: the same circle, now a concave edge.
  const auto both = trimmed_curves(V, region_or<R>({b0, b1}));
  REQUIRE(both.decided);
  CHECK(both.loops == 1);
  // A thin cylinder along z piercing a thick one along x: two closed loops, where the thin one
  // enters and leaves the thick one.
  const auto pierce = trimmed_curves(V, region_and<R>({test::cylinder(2, {R(1), R(1), R(0)}, R(1, 4)), test::cylinder(0, {R(0), R(1), R(1)}, R(1, 2))}));
  REQUIRE(pierce.decided);
  CHECK(pierce.loops == 2);
  CHECK(pierce.arcs == 0);
  // The thin cylinder cut off by the face z = 2 instead: its circle there is no V-curve between
  // trimming surfaces, the loop at the bottom is.
  const auto half = trimmed_curves(V, region_and<R>({test::cylinder(2, {R(1), R(1), R(0)}, R(1, 4)), test::above(2, R(3, 4))}));
  REQUIRE(half.decided);
  CHECK(half.loops == 1);
  CHECK(half.arcs == 0);
}

TEST_CASE("vrep trimmed curves: a cylinder cut by the domain's faces gives arcs ending on them") {
  const auto V = cube2();
  // A cylinder along z about the edge x = 0, y = 1 of the cube's face x = 0, and the plane z >= 1/3:
  // the circle on the plane is cut by the face x = 0 into one half circle, from face to face.
  const auto t = trimmed_curves(V, region_and<R>({test::cylinder(2, {R(0), R(1), R(0)}, R(1, 2)), test::above(2, R(1, 3))}));
  REQUIRE(t.decided);
  CHECK(t.arcs == 1);
  CHECK(t.loops == 0);
  CHECK(t.pairs.front().ends_on_faces == 2);
  // Coplanar contact: the plane z >= 0 lies on the face z = 0 of the domain. The circle where the
  // cylinder meets it lies on that face, outside the open domain: the one V-curve between
  // trimming surfaces is the circle on z = 1.
  const auto flush = trimmed_curves(V, region_and<R>({test::cylinder(2, {R(1), R(1), R(0)}, R(1, 2)), test::above(2, R(0)),
                                                      region_not(test::above(2, R(1)))}));
  REQUIRE(flush.decided);
  CHECK(flush.loops == 1);
  CHECK(flush.arcs == 0);
}

TEST_CASE("vrep trimmed curves: surfaces that do not meet give none, a ball cut by a plane one loop, double agrees") {
  const auto V = cube2();
  using test::ball;
  // A big ball around the lens of two balls: its sphere meets neither of theirs (the pairs with it
  // are decided empty), the lens's circle is one loop.
  const auto b0 = ball({R(4, 5), R(1), R(1)}, R(1, 2)), b1 = ball({R(6, 5), R(1), R(1)}, R(1, 2));
  const auto lens = trimmed_curves(V, region_and<R>({b0, b1, ball({R(1), R(1), R(1)}, R(3, 4))}));
  REQUIRE(lens.decided);
  CHECK(lens.loops == 1);
  CHECK(lens.arcs == 0);
  CHECK(pair_of(lens, 0, 2).loops + pair_of(lens, 0, 2).arcs + pair_of(lens, 1, 2).loops + pair_of(lens, 1, 2).arcs == 0);
  // A ball cut by a plane: the plane's circle is a loop.
  const auto t = trimmed_curves(V, region_and<R>({ball({R(1), R(1), R(1)}, R(3, 4)), test::above(2, R(5, 4))}));
  REQUIRE(t.decided);
  CHECK(t.loops == 1);
  CHECK(t.arcs == 0);
  // In double: the same steps, uncertified, here the same answer.
  const auto Vd = box_cells<double>({0, 0, 0}, {2, 2, 2}).front();
  Poly3<double> g, h;
  g.terms[{2, 0, 0}] = -1;
  g.terms[{0, 2, 0}] = -1;
  g.terms[{0, 0, 2}] = -1;
  g.terms[{1, 0, 0}] = 2;
  g.terms[{0, 1, 0}] = 2;
  g.terms[{0, 0, 1}] = 2;
  g.terms[{0, 0, 0}] = 9.0 / 16 - 3;
  h.terms[{0, 0, 1}] = 1;
  h.terms[{0, 0, 0}] = -1.25;
  const auto d = trimmed_curves(Vd, region_and<double>({region_leaf(g), region_leaf(h)}));
  CHECK(d.decided);
  CHECK(d.loops == 1);
}

TEST_CASE("vrep trimmed curves: coincident trimming surfaces and bad input are refused or said undecided") {
  const auto V = cube2();
  using test::ball;
  const auto b = ball({R(1), R(1), R(1)}, R(1, 2));
  CurveOptions small;
  small.max_boxes = 400;
  const auto t = trimmed_curves(V, region_and<R>({b, b}), small);
  CHECK_FALSE(t.decided);
  REQUIRE(t.pairs.size() == 1);
  CHECK_FALSE(t.pairs.front().undecided_reason.empty());
  // The cell's total budget: the pairs after it is spent are undecided, not computed.
  CurveOptions tight;
  tight.max_total_boxes = 2;  // each pair of planes takes one box
  const auto three = trimmed_curves(V, region_and<R>({test::above(0, R(1, 3)), test::above(1, R(1, 4)), test::above(2, R(1, 5))}), tight);
  CHECK_FALSE(three.decided);
  REQUIRE(three.pairs.size() == 3);
  CHECK(three.pairs.back().undecided_reason.find("total box budget") != std::string::npos);
  // Inputs at the edges, refused before the work: an unclamped trivariate, a non-positive weight,
  // an inner knot of multiplicity p + 1 (C^-1: the cell is not closed), degree 0, a region whose
  // composition exceeds the limits.
  auto open = V;
  open.knots[0] = {R(-1), R(0), R(1), R(2)};
  CHECK_THROWS_AS(trimmed_curves(open, region_and<R>({b, b})), ValidationError);
  auto heavy = V;
  heavy.weights.assign(heavy.size(), R(1));
  heavy.weights[0] = R(0);
  CHECK_THROWS_AS(trimmed_curves(heavy, region_and<R>({b, b})), Error);
  const auto jump = test_spline_with_jump(V);
  CHECK_THROWS_AS(trimmed_curves(jump, region_and<R>({b, b})), DomainError);
  CHECK_THROWS_AS(trimmed_topology(jump, region_and<R>({b, b}), 64), DomainError);
  auto flat = V;
  flat.degrees[2] = 0;
  flat.knots[2] = {R(0), R(2)};
  CHECK_THROWS_AS(trimmed_curves(flat, region_and<R>({b, b})), Error);
  Limits tiny;
  tiny.max_control_points = 20;
  CHECK_THROWS_AS(trimmed_curves(V, region_and<R>({b, b}), {}, tiny), SizeLimitError);
  CurveOptions bad;
  bad.max_boxes = 2;
  CHECK_THROWS_AS(trimmed_curves(V, region_and<R>({b, b}), bad), ValidationError);
}

namespace {

/// A circle p(t) = c + r (cos t a + sin t b) and what cuts it: the cube (0, 2)^3, half-spaces
/// x_e > h and balls |x - q| < rho (each kept side given), all in double.
struct Circle {
  std::array<double, 3> c, a, b;
  double r;
  std::array<double, 3> at(double t) const {
    std::array<double, 3> p;
    for (int e = 0; e < 3; ++e) p[e] = c[e] + r * (std::cos(t) * a[e] + std::sin(t) * b[e]);
    return p;
  }
};
struct Cut {
  bool ball;  // else the plane x_axis = h
  int axis;
  double h;
  std::array<double, 3> q;
  double rho;
  bool inside;  // the kept side: x_axis > h, or |x - q| < rho
};

/// The pieces of the circle inside the cube and on the kept side of every cut, from the angles
/// where it crosses their surfaces (A cos t + B sin t = C, closed form): -1 when it is within 1e-6
/// of touching one or of a point where two surfaces cross it (the case is skipped), else the
/// number of pieces (1 and `whole` when the whole circle is kept).
int circle_pieces(const Circle& k, const std::vector<Cut>& cuts_in, bool& whole) {
  const double pi = std::acos(-1.0);
  std::vector<Cut> cuts = cuts_in;
  for (int e = 0; e < 3; ++e) {
    cuts.push_back({false, e, 0.0, {}, 0.0, true});
    cuts.push_back({false, e, 2.0, {}, 0.0, false});
  }
  std::vector<double> angles;
  for (const auto& x : cuts) {
    double A, B, C;
    if (!x.ball) {
      A = k.r * k.a[x.axis];
      B = k.r * k.b[x.axis];
      C = x.h - k.c[x.axis];
    } else {  // |c - q|^2 + r^2 + 2 r (cos t a + sin t b).(c - q) = rho^2
      double cq2 = 0, ad = 0, bd = 0;
      for (int e = 0; e < 3; ++e) {
        const double dq = k.c[e] - x.q[e];
        cq2 += dq * dq;
        ad += k.a[e] * dq;
        bd += k.b[e] * dq;
      }
      A = 2 * k.r * ad;
      B = 2 * k.r * bd;
      C = x.rho * x.rho - cq2 - k.r * k.r;
    }
    const double R = std::hypot(A, B);
    if (std::abs(std::abs(C) - R) < 1e-6) return -1;
    if (std::abs(C) > R) continue;
    const double base = std::atan2(B, A), delta = std::acos(C / R);
    for (double t : {base + delta, base - delta}) angles.push_back(std::fmod(t + 4 * pi, 2 * pi));
  }
  auto kept = [&](double t) {
    const auto p = k.at(t);
    for (const auto& x : cuts) {
      bool in;
      if (!x.ball) in = p[x.axis] > x.h;
      else {
        double d2 = 0;
        for (int e = 0; e < 3; ++e) d2 += (p[e] - x.q[e]) * (p[e] - x.q[e]);
        in = d2 < x.rho * x.rho;
      }
      if (in != x.inside) return false;
    }
    return true;
  };
  std::sort(angles.begin(), angles.end());
  for (std::size_t i = 1; i < angles.size(); ++i)
    if (angles[i] - angles[i - 1] < 1e-6) return -1;
  if (!angles.empty() && angles.front() + 2 * pi - angles.back() < 1e-6) return -1;
  whole = angles.empty() && kept(0);
  if (angles.empty()) return whole ? 1 : 0;
  int runs = 0;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const double from = angles[i], to = i + 1 < angles.size() ? angles[i + 1] : angles.front() + 2 * pi;
    const double next_to = i + 2 < angles.size() ? angles[i + 2] : angles[(i + 2) % angles.size()] + 2 * pi * (i + 2 >= angles.size() ? 1 : 0);
    (void)next_to;
    runs += kept((from + to) / 2);
  }
  // Runs that continue across a cut where nothing changes (a surface crossed where the kept set
  // does not change) would be counted twice: joined here.
  std::size_t n = angles.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double before = (i == 0 ? angles[n - 1] - 2 * pi + angles[0] : angles[i - 1] + angles[i]) / 2;
    const double after = (i + 1 < n ? angles[i] + angles[i + 1] : angles[i] + angles[0] + 2 * pi) / 2;
    if (kept(before) && kept(after)) --runs;
  }
  if (runs == 0 && kept(0)) {
    whole = true;
    return 1;
  }
  return runs;
}

/// The circle where the spheres of two balls meet: 1, 0 when they do not meet, -1 when they
/// nearly touch (within 1e-3).
int sphere_circle(const std::array<double, 3>& c0, double r0, const std::array<double, 3>& c1, double r1, Circle& k) {
  std::array<double, 3> n;
  double dist = 0;
  for (int e = 0; e < 3; ++e) {
    n[e] = c1[e] - c0[e];
    dist += n[e] * n[e];
  }
  dist = std::sqrt(dist);
  if (std::abs(dist - std::abs(r0 - r1)) <= 1e-3 || std::abs(dist - (r0 + r1)) <= 1e-3) return -1;
  if (!(std::abs(r0 - r1) < dist && dist < r0 + r1)) return 0;
  for (auto& x : n) x /= dist;
  const double t = (dist * dist + r0 * r0 - r1 * r1) / (2 * dist);
  k.r = std::sqrt(r0 * r0 - t * t);
  for (int e = 0; e < 3; ++e) k.c[e] = c0[e] + t * n[e];
  int m = 0;
  for (int e = 1; e < 3; ++e)
    if (std::abs(n[e]) < std::abs(n[m])) m = e;
  std::array<double, 3> u{};
  u[m] = 1;
  k.a = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
  const double an = std::sqrt(k.a[0] * k.a[0] + k.a[1] * k.a[1] + k.a[2] * k.a[2]);
  for (auto& x : k.a) x /= an;
  k.b = {n[1] * k.a[2] - n[2] * k.a[1], n[2] * k.a[0] - n[0] * k.a[2], n[0] * k.a[1] - n[1] * k.a[0]};
  return 1;
}

/// The circle where a sphere meets the plane z = h: 1, 0 when they do not meet, -1 when they
/// nearly touch.
int plane_circle(const std::array<double, 3>& c, double r, double h, Circle& k) {
  const double d = h - c[2];
  if (std::abs(std::abs(d) - r) <= 1e-3) return -1;
  if (!(std::abs(d) < r)) return 0;
  k.c = {c[0], c[1], h};
  k.r = std::sqrt(r * r - d * d);
  k.a = {1, 0, 0};
  k.b = {0, 1, 0};
  return 1;
}

}  // namespace

TEST_CASE("vrep trimmed curves: random spheres and a plane, against the circles' closed forms") {
  // Two balls (centres and radii in sixteenths, in and around the cube [0, 2]^3) and the half-space
  // z >= h: the cell's V-curves between trimming surfaces lie on three circles (sphere-sphere and
  // each sphere with the plane), each cut by the cube and the third surface. Their pieces (closed
  // form, in double) must be the V-curves found, per pair: loops where a circle is whole, arcs
  // otherwise.
  const auto V = cube2();
  std::mt19937 rng(20261204);
  std::uniform_int_distribution<int> pos(2, 30), rad(5, 18), height(4, 28);
  int checked = 0, skipped = 0, loops = 0, arcs = 0, vpoints = 0;
  std::size_t faces = 0, face_curves = 0;
  for (int trial = 0; trial < 200 && checked < 24; ++trial) {
    std::array<R, 3> c0, c1;
    std::array<double, 3> d0, d1;
    for (int e = 0; e < 3; ++e) {
      c0[e] = R(pos(rng), 16);
      c1[e] = R(pos(rng), 16);
      d0[e] = to_double(c0[e]);
      d1[e] = to_double(c1[e]);
    }
    const R r0(rad(rng), 16), r1(rad(rng), 16), h(height(rng), 16);
    const double q0 = to_double(r0), q1 = to_double(r1), hd = to_double(h);
    const bool with_plane = trial % 2 == 1;
    // Expected pieces per pair (0, 1), (0, 2), (1, 2).
    std::array<int, 3> want{0, 0, 0};
    std::array<bool, 3> whole{false, false, false};
    Circle k;
    bool skip = false;
    int meets = sphere_circle(d0, q0, d1, q1, k);
    skip = meets < 0;
    if (meets > 0) {
      std::vector<Cut> cuts;
      if (with_plane) cuts.push_back({false, 2, hd, {}, 0.0, true});
      want[0] = circle_pieces(k, cuts, whole[0]);
    }
    if (with_plane) {
      meets = plane_circle(d0, q0, hd, k);
      skip = skip || meets < 0;
      if (meets > 0) want[1] = circle_pieces(k, {{true, 0, 0.0, d1, q1, true}}, whole[1]);
      meets = plane_circle(d1, q1, hd, k);
      skip = skip || meets < 0;
      if (meets > 0) want[2] = circle_pieces(k, {{true, 0, 0.0, d0, q0, true}}, whole[2]);
    }
    for (int w : want) skip = skip || w < 0;
    // A sphere touching a face of the cube (a tangency the curves on that face cannot decide).
    for (int e = 0; e < 3; ++e)
      for (const auto& [c, q] : {std::pair{d0[e], q0}, std::pair{d1[e], q1}})
        skip = skip || std::abs(std::abs(c - 0) - q) < 1e-3 || std::abs(std::abs(c - 2) - q) < 1e-3;
    // The plane on a face, or through an edge where a sphere crosses it, is not chosen (h in (0, 2)).
    if (skip || want[0] + want[1] + want[2] == 0) {
      skipped += skip;
      continue;
    }
    std::vector<Region<R>> parts{test::ball(c0, r0), test::ball(c1, r1)};
    if (with_plane) parts.push_back(test::above(2, h));
    const auto got = trimmed_curves(V, region_and<R>(parts));
    INFO("trial " << trial << ": balls (" << d0[0] << ", " << d0[1] << ", " << d0[2] << ") r " << q0 << " and (" << d1[0] << ", " << d1[1] << ", "
                  << d1[2] << ") r " << q1 << (with_plane ? ", z >= " + std::to_string(hd) : std::string()) << "; closed form per pair: " << want[0]
                  << (whole[0] ? " (whole)" : "") << ", " << want[1] << (whole[1] ? " (whole)" : "") << ", " << want[2] << (whole[2] ? " (whole)" : ""));
    std::string reasons;
    for (const auto& x : got.pairs)
      if (!x.decided) reasons += " (" + std::to_string(x.i) + ", " + std::to_string(x.j) + "): " + x.undecided_reason;
    INFO("undecided:" << reasons);
    REQUIRE(got.decided);
    const auto topo = trimmed_topology(V, region_and<R>(parts), 256);
    REQUIRE(topo.points_undecided == 0);
    const std::pair<std::size_t, std::size_t> ids[3] = {{0, 1}, {0, 2}, {1, 2}};
    for (int p = 0; p < 3; ++p) {
      std::size_t got_arcs = 0, got_loops = 0, ends = 0;
      for (const auto& x : got.pairs)
        if (x.i == ids[p].first && x.j == ids[p].second) {
          got_arcs = x.arcs;
          got_loops = x.loops;
          ends = x.ends_at_points;
        }
      CHECK(got_loops == (whole[p] ? 1u : 0u));
      // The arcs' ends on the domain's faces are the face V-points trimmed_topology finds for the
      // same pair by its own systems (2x2 on the whole faces of the pieces).
      std::size_t face_points = 0;
      for (const auto& q : topo.inner_points)
        face_points += q.dir >= 0 && q.leaves == std::vector<std::size_t>{ids[p].first, ids[p].second};
      std::size_t face_ends = 0;
      for (const auto& x : got.pairs)
        if (x.i == ids[p].first && x.j == ids[p].second) face_ends = x.ends_on_faces;
      CHECK(face_ends == face_points);
      faces += face_ends;
      CHECK(got_arcs == (whole[p] ? 0u : static_cast<std::size_t>(want[p])));
      loops += whole[p];
      arcs += whole[p] ? 0 : want[p];
      vpoints += static_cast<int>(ends);
    }
    // At a corner where three trimming surfaces of an intersection meet, each pair's curve goes on
    // into the cell on one side only: three arc ends per inside V-point.
    std::size_t ends_at_points = 0;
    for (const auto& x : got.pairs) ends_at_points += x.ends_at_points;
    CHECK(ends_at_points == 3 * topo.interior_points);
    // The trimming surfaces' curves on the cube's faces, exact: each edge V-point ends one on each
    // of its two faces, each face V-point (two surfaces meeting on a face of an intersection) two.
    std::size_t edge_points = 0, on_edges = 0, at_face_points = 0;
    for (const auto& e : topo.edges) edge_points += e.points;
    for (const auto& f : topo.face_curves) {
      CHECK(f.decided);
      on_edges += f.ends_on_edges;
      at_face_points += f.ends_at_points;
      face_curves += f.arcs + f.loops;
    }
    CHECK(on_edges == 2 * edge_points);
    CHECK(at_face_points == 2 * topo.face_points);
    ++checked;
  }
  INFO("checked " << checked << ", skipped near tangency " << skipped << ": loops " << loops << ", arcs " << arcs << ", arc ends at V-points " << vpoints
                    << ", on faces " << faces << "; curves on the faces " << face_curves);
  CHECK(checked == 24);
  CHECK(loops >= 4);  // the sample covers loops, arcs and V-points
  CHECK(arcs >= 8);
  CHECK(vpoints >= 4);
  CHECK(faces >= 8);
  CHECK(face_curves >= 16);
}
