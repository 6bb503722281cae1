// The minimum distance between two surfaces and their contact (papers/002 Section 5.3, Eq. 4;
// issue 19, What to build 4), by the subdivision solver of solve/solver.hpp.
//
// The squared distance |S1(u, v) - S2(r, t)|^2 takes its minimum at a stationary point of one of
// the pairs of strata of the two parameter domains (the paper's three cases):
//   interior-interior: Eq. 4, four equations (S1 - S2).S1_u = (S1 - S2).S1_v = (S1 - S2).S2_r =
//     (S1 - S2).S2_t = 0 in (u, v, r, t) on every pair of Bezier pieces;
//   edge-interior, interior-edge, edge-edge: the same with the edge's parameter fixed (boundary
//     curves, and knot lines where a surface is not C^1: the paper's C^1 discontinuities);
//   corner-anything: the corner as a point (point projection), corner-corner by evaluation.
// For rational surfaces X / W the difference is (X1 W2 - X2 W1) / (W1 W2) and each tangent's
// numerator X_u W - X W_u: the equations are polynomial in the pieces' local parameters.
//
// Branch and bound: the smallest squared distance found so far, U, starts at the closest pair of
// corners and falls to the upper bound max(|X1 W2 - X2 W1|^2) / min((W1 W2)^2) of every box
// examined (every box holds real pairs of points). A pair of strata whose control-point boxes are
// farther apart than sqrt(U), and a box whose lower bound exceeds U, cannot hold the minimum and
// are skipped. The minimum is then enclosed between the smallest lower bound of what is left
// (certified roots and undecided boxes) and U.
//
// Surfaces that intersect have a curve of zero distance, where Eq. 4 has no isolated solutions.
// When U falls below 2^-32 of the squared model size, a common point is sought: S1 - S2 = 0 with
// one parameter fixed (three equations in three unknowns) by the same solver; a certified root
// proves the intersection (distance exactly 0). Then the penetration: the stationary pairs of the
// same strata away from the intersection (boxes whose distance is surely below 2^-8 of the model's
// size are skipped: shallower penetrations are not searched; the paper's "extreme penetration of one surface into another"), each with the
// side of the other surface its point lies on (the sign of (p1 - p2) against S2's normal
// S_r x S_t, evaluated exactly at the pair's box centre), and the deepest certified pair with S1's
// point behind S2 (and the other way round). Which side is "inside" is the orientation of the
// surfaces' parametrizations.
#pragma once
#include <string>
#include <vector>

#include "base/limits.hpp"
#include "solve/solver.hpp"
#include "spline/bspline.hpp"

namespace splinex {

template <class T>
struct ContactPoint {
  std::string where;      // "interior-interior", "edge-interior", ..., "corner-corner"
  std::string strata;     // the two strata in words
  std::vector<T> lo, hi;  // (u, v, r, t) box; lo == hi when exact
  bool exact = false;     // lo is the stationary pair (a rational root, or corners)
  bool unique = false;    // exactly one simple root of the strata's equations in the box (Krawczyk)
  bool merged = false;    // boxes of neighbouring strata that overlap: one pair, or two very close ones
  bool degenerate = false;  // an equation of the strata vanishes identically (undecided: the solutions are not isolated)
  int side1 = 0, side2 = 0;  // extremes: the sign of (p2 - p1).(S_u x S_v) and of (p1 - p2).(S_r x S_t) at the box's centre
  T d2_lo, d2_hi;         // |S1 - S2|^2 over the box
  std::vector<T> p1, p2;  // the points (at lo when exact, else at the box's centre)
  /// Parameters (indices into (u, v, r, t)) along which the distance is constant on the strata (an
  /// equation vanished identically): the entry is the segment [lo, hi] in them, each of its
  /// parameters a stationary pair of the same distance; `collapsed`: the segment is one point in
  /// space (a pole, a collapsed edge; decided exactly).
  std::vector<int> along;
  bool collapsed = false;
};

template <class T>
struct ContactResult {
  std::vector<ContactPoint<T>> points;     // stationary pairs that can matter to the minimum, by d2_lo
  std::vector<ContactPoint<T>> undecided;  // boxes left open
  std::vector<std::size_t> closest;        // pairs whose distance can be the smallest
  std::vector<std::size_t> undecided_closest;  // undecided boxes that may hold a pair as close (or closer)
  bool closest_certified = false;          // one such pair and no undecided box below it
  std::string reason;                      // when not certified: why, in words
  T distance2_lo, distance2_hi;            // the minimum squared distance, enclosed
  bool intersecting = false;               // a common point is certified: the minimum is exactly 0
  bool intersection_undecided = false;     // not intersecting, but the enclosure of the minimum reaches 0
  std::vector<T> common_lo, common_hi;     // its (u, v, r, t) box
  std::size_t strata_pairs = 0, pairs_solved = 0, pairs_skipped = 0, boxes = 0;
  /// Intersecting surfaces: the stationary pairs away from the intersection (the paper's extreme
  /// penetration), and the deepest pair whose first point lies behind the second surface
  /// (against its normal S_r x S_t) and the other way round (-1: none).
  std::vector<ContactPoint<T>> extremes;
  bool extremes_complete = false;
  long deepest_1_in_2 = -1, deepest_2_in_1 = -1;
};

/// The minimum distance of the surfaces S1 and S2 (dim 2, points in R^q, q >= 3: the first three
/// coordinates; degree >= 1 in both directions); when they intersect and `penetration`, also the
/// stationary pairs away from the intersection and the deepest penetration each way (costly: the
/// subdivision follows the intersection curve down to boxes 2^-8 of the model's size).
template <class T>
ContactResult<T> surface_distance(const BSpline<T>& S1, const BSpline<T>& S2, const SolveOptions& options = {},
                                  const Limits& limits = {}, bool penetration = false);

}  // namespace splinex
