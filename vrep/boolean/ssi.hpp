// Surface-surface intersection in floating point, judged exactly (issue 18, What to build 1: the
// freeform boundaries without an implicit form, such as the teapot's handle and body of papers/002
// Figures 10 and 14).
//
// What a CAD kernel does: `intersect_surfaces` finds the intersection curves of two parametric
// surfaces in double by sampling seeds (a grid of cells per surface, bounding boxes compared
// through a spatial hash, Newton from the centres of overlapping cells), then traces each branch by
// marching: a predictor along the tangent n1 x n2 with a chord of `step` model units, a corrector
// (Newton on S1(u, v) - S2(s, t) = 0 plus the step plane), stopping at the domain boundary (the
// last point put on it) or when the branch closes. Newton stops at |S1 - S2| <= `tolerance`.
// Nothing in it is certified: seeds can miss small loops, steps can jump between branches, the
// surfaces are the exact data rounded to double.
//
// `judge_point` measures a computed point (u, v, s, t) against the exact surfaces: its gap
// |S1(u, v) - S2(s, t)|^2 exactly (the parameters are the doubles as exact dyadic numbers), and a
// certificate that a true intersection point lies near it. The certificate is Krawczyk's test on
// the square system F = (S1(u, v) - S2(s, t), a.(x - x~)) over the box x~ +- r (a: the curve's
// parameter-space tangent, fixing the point along the curve), in exact rational interval
// arithmetic: the value ranges of the partial derivatives on the box are the ranges of the
// Bernstein / B-spline coefficients of the hodographs of the exactly restricted surfaces (the
// convex hull property; across a C^0 knot line they hold both one-sided derivatives, which the
// mean value inclusion needs), Y is the inverse of F'(x~) computed in double and taken exactly, and
// K(X) = x~ - Y F(x~) + (I - Y F'(X)) (X - x~) inside the open box proves a unique zero x* in it
// (Krawczyk 1969; Moore, Kearfott and Cloud, Introduction to Interval Analysis, Section 8.2). The
// zero also lies in K(X), so the true point S1(u*, v*) lies in the convex hull of S1's control
// points on K(X)'s (u, v) box (restricted exactly once more), which bounds its
// distance from the computed point S1(u, v): a certified upper bound of how far the computed
// trimming point is from the true intersection curve. A point on a domain boundary (a branch's
// end) is judged with that parameter fixed: Krawczyk on S1 - S2 = 0 in the other three. Boxes
// that leave a domain, and points where the test fails for every tried r (near tangency, a wrong
// branch), are reported uncertified.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

struct SsiOptions {
  double step = 1.0 / 16;        // marching chord, model units
  double tolerance = 1e-12;      // Newton stops at |S1 - S2| <= tolerance
  int grid = 48;                 // seed cells per direction of each surface (1..128)
  std::size_t max_points = 100000;
  std::size_t max_starts = 50000;  // Newton starts from overlapping cell pairs (the rest are skipped and counted)
};

using SsiParams = std::array<double, 4>;  // (u, v) on S1, (s, t) on S2

struct SsiBranch {
  std::vector<SsiParams> points;
  bool closed = false;           // the marching came back to its start
  bool ends_meet = false;        // open in the parameters, but its two ends are one point in space (a seam)
  bool tangential_stop = false;  // stopped where the normals became parallel
};

struct SsiResult {
  std::vector<SsiBranch> branches;
  std::size_t candidates = 0;       // overlapping cell pairs
  std::size_t seeds = 0;            // converged seeds not on a branch already
  std::size_t known = 0;            // converged starts on a traced branch
  std::size_t newton_failures = 0;  // candidate starts that did not converge inside the domains
  std::size_t skipped = 0;          // candidates beyond max_starts, not tried
};

/// Both surfaces: dim 2, points in R^3 (ValidationError otherwise).
SsiResult intersect_surfaces(const BSpline<double>& S1, const BSpline<double>& S2, const SsiOptions& options = {});

struct SsiJudgement {
  Rational gap2;               // |S1(u, v) - S2(s, t)|^2, exactly
  bool certified = false;      // a unique true intersection point in the box x~ +- radius (Krawczyk)
  Rational radius;             // the box's half width in every parameter
  Rational distance2_bound;    // |S1(u, v) - true point|^2 <= this (certified only)
  std::string why_not;         // what stopped the certificate
};

/// The exact judgement of one point; `direction` is the curve's tangent in (u, v, s, t) (any
/// non-zero length; its rounding does not matter to the certificate).
SsiJudgement judge_point(const BSpline<Rational>& S1, const BSpline<Rational>& S2, const SsiParams& x, const SsiParams& direction,
                         const Limits& limits = {});

}  // namespace splinex
