// Orthogonal projection of a point onto a surface (papers/002 Section 5.2, Eq. 3 with C a point;
// issue 19, What to build 2), by the subdivision solver of solve/solver.hpp.
//
// The squared distance d(u, v) = |S(u, v) - P|^2 is minimised where its gradient vanishes on one
// of the strata of the parameter domain:
//   interior: on every (closed) Bezier piece, (S - P).S_u = (S - P).S_v = 0. For a rational
//     S = X / W the equations are multiplied by W^3: (X - P W).(X_u W - X W_u) = 0 and the same
//     with v, polynomial in the piece's local parameters;
//   edge: on the domain's boundary and on every knot line where S is not C^1 (multiplicity >= the
//     degree: the paper's C^1 discontinuities), the derivative along the edge;
//   corner: the ends of those edges.
// A continuous function on the compact domain takes its minimum at one of these points, so the
// candidates hold the closest point: each comes with an enclosure of its squared distance (exact
// for exact roots and corners, from the Bernstein coefficients of |X - P W|^2 and W^2 on the
// certified box otherwise). The closest point is certified when one candidate's upper bound is
// below every other candidate's lower bound, undecided boxes included.
//
// A root on a line where pieces meet is found from both sides; exact roots are merged by
// equality, certified boxes that overlap across such a line are merged into one entry that says
// so. Degree 0 in a direction (no tangent plane) is refused with a typed error.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "solve/solver.hpp"
#include "spline/bspline.hpp"

namespace splinex {

template <class T>
struct CriticalPoint {
  std::string where;     // "interior", "edge" or "corner"
  std::string stratum;   // which piece, edge or corner, in words
  std::vector<T> lo, hi; // (u, v) box; lo == hi for exact points
  bool exact = false;    // lo == hi is the critical point (a rational root or a corner)
  bool unique = false;   // exactly one simple root of the stratum's equations in the box (Krawczyk)
  bool merged = false;   // boxes from two sides of a knot line that overlap: one point, or two very close ones
  T d2_lo, d2_hi;        // |S - P|^2 over the box, enclosed (equal when exact)
  std::vector<T> point;  // S at the exact point, else at the box's centre
  std::vector<int> along;  // parameters along which the distance is constant (a segment of critical points, [lo, hi] in them)
  bool collapsed = false;  // that segment is one point in space (a pole)
};

template <class T>
struct ProjectionResult {
  std::vector<CriticalPoint<T>> critical;   // the candidates, ordered by d2_lo
  std::vector<CriticalPoint<T>> undecided;  // boxes the solver left open (multiple roots, limits)
  std::vector<std::size_t> closest;         // candidates whose distance can be the smallest (none above an undecided box's upper bound)
  std::vector<std::size_t> undecided_closest;  // undecided boxes that may hold a point as close (or closer)
  bool closest_certified = false;           // exactly one such candidate and no undecided box below it
  std::string reason;                       // when not certified: why, in words
  T distance2_lo, distance2_hi;             // the smallest squared distance, enclosed
  std::size_t boxes = 0;                    // solver boxes examined
  bool complete = false;                    // every stratum solved without undecided boxes
};

/// The critical points of |S - P|^2 and the closest point of the surface S (dim 2, points in R^q,
/// q >= 3: the first three coordinates) to P (three coordinates).
template <class T>
ProjectionResult<T> project_point(const BSpline<T>& S, const std::vector<T>& P, const SolveOptions& options = {},
                                  const Limits& limits = {});

/// What a CAD kernel does (issue 19, What to build 5): Newton in double on (S - P).S_u =
/// (S - P).S_v = 0 (Jacobian from the second derivatives) from a grid x grid of starts over the
/// domain; the points it converges to inside the domain, each kept once (within 1e-9 of the
/// domain's size). Nothing is certified: roots between starts' basins are missed, nearby roots
/// merge, and a start may converge to a saddle or a maximum as well as to a minimum.
std::vector<std::array<double, 2>> project_point_sampled(const BSpline<double>& S, const std::array<double, 3>& P, int grid = 16);

}  // namespace splinex
