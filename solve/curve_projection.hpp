// Orthogonal projection of a curve onto a surface (papers/002 Section 5.2, Eq. 3, Figure 12;
// issue 19, What to build 3).
//
// (C(t) - S(u, v)).S_u = (C(t) - S(u, v)).S_v = 0: two equations in (u, v, t), whose solutions are
// curves. Per pair (Bezier piece of S, Bezier piece of C), in the pair's box:
//   end points: where a solution curve meets a face of the box, two equations in the two other
//     unknowns (the curve's ends, the surface's boundary, and the joints at knots where a curve
//     goes on into the neighbouring box);
//   turning points: where a curve's tangent has no t component, the two equations and
//     det d(F1, F2)/d(u, v) = 0 (three in three); singular points of the solution set are among
//     them;
// all certified by the subdivision solver. Between consecutive critical values of t (those of
// the special points), the solution set is a union of t-monotone regular branches, as many as the
// roots of F(., ., t*) = 0 at any t* in the gap: that count is certified by solving the slice.
// The branches are traced in double from the slice roots (Newton in (u, v) at steps of t) to the
// critical values at both sides and joined there to the nearest special point or to the branch
// going on, in double; every traced point is measured exactly: the cosines of the angles between
// C - S and S_u, S_v, which are 0 on a true solution (their squares are rational). The joins are
// checked for consistency (one branch at an end, two at a turning point, one from each side at a
// joint); a consistent result has its special points and counts certified and its connections
// traced, which the verdict says.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "exact/rational.hpp"
#include "solve/solver.hpp"
#include "spline/bspline.hpp"

namespace splinex {

struct CurveProjectionOptions {
  SolveOptions solve;
  int steps = 48;  // tracing steps in t per gap between critical values
};

struct ProjectionSpecialPoint {
  std::string kind;              // "curve end", "surface boundary", "joint", "turning point"
  std::string where;             // in words
  std::vector<Rational> lo, hi;  // (u, v, t); lo == hi when exact
  bool exact = false, unique = false;
  int branches = 0;  // traced branches joined to it
};

struct ProjectionBranch {
  std::vector<std::array<double, 3>> points;  // (u, v, t) along one monotone branch
  int component = -1;
};

struct ProjectionSlice {
  Rational t;            // the sample
  std::size_t roots = 0; // solution points at t: the branches in this gap of this pair of pieces
  bool certified = false;
};

struct CurveProjectionResult {
  std::vector<ProjectionSpecialPoint> special;
  std::vector<ProjectionSpecialPoint> undecided;  // boxes the solver left open
  std::vector<ProjectionSlice> slices;
  std::vector<ProjectionBranch> branches;
  std::size_t segments = 0;  // components with ends (on the curve's ends or the surface's boundary)
  std::size_t loops = 0;     // closed components
  bool certified_counts = false;  // every special point and slice solved completely
  bool consistent = false;        // every join as the special points require
  double max_cosine = 0;          // max over traced points of |cos| between C - S and S_u, S_v (exactly, then rounded)
  std::size_t traced_points = 0;
  std::size_t boxes = 0;
};

/// The projection of the curve C (dim 1, points in R^q, q >= 3) onto the surface S (dim 2), both
/// polynomial or rational, degree >= 1.
CurveProjectionResult project_curve(const BSpline<Rational>& C, const BSpline<Rational>& S, const CurveProjectionOptions& options = {},
                                    const Limits& limits = {});

}  // namespace splinex
