// The V-curves between two trimming surfaces of a trimmed cell (vrep/topology/trimmed_curves.cpp).
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// The V-curves between two trimming surfaces of a trimmed cell (issue 18), per pair of leaves
/// (i, j): the parts of the curve {g_i = g_j = 0} in the open parameter domain along which the
/// formula depends on both signs (the two surfaces meet in an edge of the cell's boundary), cut at
/// the V-points where a third trimming surface crosses it. Counted exactly from a certified graph:
/// the domain is subdivided (split fraction 1/2, retried at 7/16 and 13/32 when a crossing falls
/// on a split line) until, in every box where both leaves may vanish and the edge may matter,
///   - one component of grad g_i x grad g_j has one strict sign (Bernstein coefficients): the
///     curve is smooth there and monotone along that direction, so it holds no closed loop and
///     each of its pieces in the box runs from one face of the box to another;
///   - the crossings of the curve with the box's six faces (2x2 systems, the certified solver of
///     solve/solver.hpp: simple roots strictly inside the face) are exactly two: one arc, or none:
///     no curve;
///   - every other leaf has one strict sign, or exactly one leaf k does not and
///     det(grad g_i, grad g_j, grad g_k) has one strict sign: g_k is monotone along the arc, so
///     the arc meets g_k = 0 at most once, exactly when g_k has opposite strict signs at its ends.
/// Crossings on a face two boxes share are matched (every root box overlaps exactly one on the
/// other side); an arc's activity is the formula's dependence on both signs with the other leaves
/// at their signs there. V-points (the formula depends on all three signs) cut the curves.
/// Components with ends (on the domain's faces or at V-points) are arcs, the others loops.
/// The counts are in V's parameter domain: a V-curve that meets a face V identifies with another
/// (a seam) or collapses is counted once per side (`ends_on_identified_faces` says how often).
/// Undecided (the reason said) for a pair when a curve is tangent to a face or a split plane, two
/// crossings cannot be told apart, a trimming surface contains a face or a split plane, more than
/// three surfaces meet, or the box budget is spent. Exact in exact arithmetic; in double the same
/// steps on rounded values, uncertified.
struct CurveOptions {
  std::size_t max_boxes = 6000;       // subdivision boxes per pair and attempt
  int max_level = 36;                 // splits of one box (all directions together)
  std::size_t max_total_boxes = 200000;  // over all pairs and attempts of one cell: the pairs left are undecided
};
template <class T>
struct TrimmedCurves {
  struct Pair {
    std::size_t i = 0, j = 0;  // the leaves (collect order)
    bool decided = false;
    std::size_t arcs = 0, loops = 0;                    // V-curves with two ends; closed ones
    std::size_t ends_on_faces = 0, ends_at_points = 0;  // ends of the arcs: on the domain's faces, at V-points
    std::size_t ends_on_identified_faces = 0;           // of those on faces: on a seam or a collapsed face
    std::size_t boxes = 0, crossings = 0;               // boxes of the deciding attempt; face crossings found
    T split = T(0);                                     // the split fraction that decided it
    std::string undecided_reason;
  };
  std::vector<Pair> pairs;  // every pair of leaves whose zero sets may meet in the domain
  bool decided = true;      // every pair decided
  std::size_t arcs = 0, loops = 0;  // totals over the decided pairs
};
template <class T>
TrimmedCurves<T> trimmed_curves(const BSpline<T>& V, const Region<T>& trim, const CurveOptions& options = {}, const Limits& limits = {});

}  // namespace splinex
