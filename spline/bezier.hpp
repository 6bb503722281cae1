// Bezier extraction, splitting, affine reparametrization and reversal, in any direction.
#pragma once
#include <utility>
#include <vector>

#include "spline/bspline.hpp"

namespace splinex {

/// One polynomial piece: its parameter box [lo_d, hi_d] per direction and the Bezier spline
/// (end knots of multiplicity degree+1 on that box).
template <class T>
struct BezierPiece {
  std::vector<std::pair<T, T>> box;
  BSpline<T> spline;
};

/// The Bezier form of a spline in one object, as SISL's s1730 returns it: the spline with every
/// interior breakpoint raised to multiplicity >= degree in every direction (clamped), its
/// breakpoints, and where each piece's net starts. Piece (s_0, s_1, ...) is the (p_0+1) x (p_1+1)
/// x ... block of `spline`'s control net starting at index first[d][s_d] in direction d, on the
/// box [breaks[d][s_d], breaks[d][s_d + 1]]. Consecutive pieces share their end points where
/// the spline is continuous. No per-piece allocation: O(1) vectors whatever the piece count.
template <class T>
struct BezierForm {
  BSpline<T> spline;
  std::vector<std::vector<T>> breaks;              // per direction: the breakpoints
  std::vector<std::vector<std::size_t>> first;     // per direction, per segment: first control index
  /// The number of pieces: the product of the segment counts.
  std::size_t size() const;
  /// Piece k (direction 0 varying fastest) as a spline of its own.
  BezierPiece<T> piece(std::size_t k) const;
};

/// S in Bezier form (A5.4 refinement per direction; the input is never copied whole). Checked
/// against limits as extract_bezier is, before any work.
template <class T>
BezierForm<T> bezier_form(const BSpline<T>& S, const Limits& limits = {});

/// All polynomial pieces, ordered with direction 0 varying fastest. Every interior knot is raised
/// to multiplicity degree (A5.4) and the control net cut into Bezier nets (bezier_form, then
/// piece by piece: one BSpline per piece).
/// Checked against limits.max_control_points before any work: the pieces' control points in
/// all, prod_d segments_d * (p_d + 1), which also bounds every intermediate Bezier form.
template <class T>
std::vector<BezierPiece<T>> extract_bezier(const BSpline<T>& S, const Limits& limits = {});
/// That count (SizeLimitError "pieces" above the limit).
template <class T>
std::size_t bezier_pieces_size(const BSpline<T>& S, const Limits& limits = {});

/// The two halves of S at x in direction d (x strictly inside the domain).
template <class T>
std::pair<BSpline<T>, BSpline<T>> split_at(const BSpline<T>& S, int d, const T& x, const Limits& limits = {});

/// S restricted to the box [lo_d, hi_d] (one pair per direction, inside the domain; a side equal
/// to the domain's end is not split): exact splits, the parametrization kept.
template <class T>
BSpline<T> restrict_to_box(BSpline<T> S, const T* lo, const T* hi, const Limits& limits = {}) {
  for (int d = 0; d < S.dim(); ++d) {
    if (S.domain_lo(d) < lo[d]) S = split_at(S, d, lo[d], limits).second;
    if (hi[d] < S.domain_hi(d)) S = split_at(S, d, hi[d], limits).first;
  }
  return S;
}

/// S reparametrized affinely in direction d so that its domain becomes [lo, hi] (lo < hi):
/// R(phi(x)) = S(x) with phi mapping the old domain onto [lo, hi]. Control points are unchanged.
template <class T>
BSpline<T> reparametrize(const BSpline<T>& S, int d, const T& lo, const T& hi);

/// S with direction d reversed on the same domain [a, b]: R(a + b - x) = S(x).
template <class T>
BSpline<T> reverse(const BSpline<T>& S, int d);

}  // namespace splinex
