// Algorithm 1 of papers/000: the composition T(S) when S crosses knot lines of T, as a set of
// trimmed patches {T_j^e(S_i) restricted to region (i, j)} with an evaluation structure.
//
// Regions are exact: the part of inner piece S_i that T maps through cell j is the semi-algebraic
// set { r in box_i : lo_jc <= s_c(r) < hi_jc for every coordinate c }, a conjunction of sign
// conditions on the polynomials s_c - lo and s_c - hi (rational in r for a rational S). The rule
// is half-open, closed at T's domain end, which is also FindSpan's rule, so the regions of one
// piece are disjoint and cover it (property 2 of the paper); inner pieces are half-open the same
// way. A condition that holds on the whole piece (its control-point hull lies inside [lo, hi))
// is dropped; a piece with no condition left is untrimmed.
//
// Candidate cells come from the exact control-point hull; a candidate whose region is empty is
// dropped when exact subdivision of the piece (hull tests on sub-pieces, up to a depth) proves it
// empty, and kept otherwise (status `unproven_nonempty`, evaluation never lands there if empty).
// Isoparametric crossings (property 1), where s_c is affine in one parameter and meets a knot of
// T at a parameter value inside the piece, split the inner piece there by B-spline subdivision
// instead of trimming.
#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "compose/compose.hpp"
#include "spline/bezier.hpp"

namespace splinex {

template <class T>
struct CellCondition {
  int coord = 0;           // coordinate c of S
  T lo, hi;                // lo <= s_c < hi
  bool check_lo = true;    // false: lo <= s_c holds on the whole piece (hull), not tested
  bool check_hi = true;    // false: s_c < hi (or <= hi) holds on the whole piece
  bool hi_closed = false;  // s_c <= hi (T's domain end)
  bool holds(const T& v) const {
    if (check_lo && v < lo) return false;
    if (check_hi && (hi_closed ? hi < v : !(v < hi))) return false;
    return true;
  }
};

enum class RegionStatus { untrimmed, trimmed, unproven_nonempty };

template <class T>
struct TrimmedPatch {
  std::size_t inner_piece = 0;           // index into TrimmedComposition::inner_pieces
  std::size_t outer_cell = 0;            // index into TrimmedComposition::outer_pieces
  std::vector<CellCondition<T>> region;  // conjunction; empty = the whole piece box
  RegionStatus status = RegionStatus::trimmed;
  Homogeneous<T> patch;                  // T_j^e(S_i) on the inner piece's box (Observation 1)
};

/// The point R of a homogeneous value h = (w*R, w) (the composition's rational form, Observation 1
/// of papers/000): R = (w*R) / w. A vanishing weight is a DomainError.
template <class T>
std::vector<T> divide_by_weight(const std::vector<T>& h) {
  const std::size_t q = h.size() - 1;
  if (h[q] == T(0))
    throw DomainError("composition.weights", "the composed weight vanishes at this point", "check the rational input");
  std::vector<T> out(q);
  for (std::size_t c = 0; c < q; ++c) out[c] = h[c] / h[q];
  return out;
}

/// A trimmed patch's value at r (dividing by the weight for homogeneous patches).
template <class T>
std::vector<T> evaluate_patch(const TrimmedPatch<T>& p, const std::vector<T>& r);

template <class T>
struct TrimmedComposition {
  BSpline<T> outer, inner;
  std::vector<BezierPiece<T>> inner_pieces;  // after isoparametric splits
  std::vector<BezierPiece<T>> outer_pieces;
  std::vector<std::vector<T>> outer_breaks;  // breakpoints of T per direction
  std::vector<TrimmedPatch<T>> patches;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> index;  // (inner piece, cell) -> patch
  std::size_t isoparametric_splits = 0;

  /// The inner piece containing r (half-open boxes, closed at S's domain end).
  std::size_t locate_piece(const std::vector<T>& r) const;
  /// The outer cell containing u = S(r) (half-open, closed at T's domain end).
  std::size_t locate_cell(const std::vector<T>& u) const;
  /// The patch that owns r; DomainError if r is outside S's domain or S(r) outside T's domain.
  std::size_t locate(const std::vector<T>& r) const;
  /// R(r): the owning patch evaluated at r. Definition 1: R(r) = T(S(r)).
  std::vector<T> evaluate(const std::vector<T>& r) const;
  /// Exact membership of r (inside the piece's box) in a patch's region.
  bool in_region(const TrimmedPatch<T>& p, const std::vector<T>& r) const;
};

struct TrimmedOptions {
  CompositionMethod method = CompositionMethod::symbolic;
  int emptiness_depth = 6;  // subdivision depth for proving a candidate region empty
};

template <class T>
TrimmedComposition<T> compose_trimmed(const BSpline<T>& outer, const BSpline<T>& inner, const TrimmedOptions& options = {},
                                      const Limits& limits = {});

}  // namespace splinex
