// Proof by identity (GUIDE.md): two piecewise polynomial (or rational) maps agree on a box if
// they agree at (d_k + 1) distinct rational points per direction in every cell where both are
// polynomial, d_k bounding the degree of the difference in direction k.
//
// For B = A o phi with phi an affine map per direction (identity, reparametrization, reversal):
//  - cells: the product of intervals between the union of A's breakpoints and phi^-1(B's);
//  - polynomial A, B: the difference A - B o phi has degree <= max(p_A, p_B) per direction;
//  - rational: the numerators after cross-multiplying, (w_B o phi) A_h - (B_h o phi) w_A, have
//    degree <= p_A + p_B per direction;
//  - points: lo + (hi - lo) (i+1)/(d+2), i = 0..d, strictly inside each cell (so evaluation picks
//    the cell's polynomial piece on both sides).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

struct IdentityCheck {
  std::string identity;           // what was proved, in words
  std::vector<int> degree_bound;  // per direction
  std::size_t cells = 0;
  std::size_t points = 0;         // evaluations compared
  bool holds = true;
  std::string counterexample;     // exact point and both values, when it fails
  /// Nothing was compared (an empty or inverted box, no cells): no verdict either way.
  bool decided() const { return !holds || points > 0; }
};

/// Affine map of one direction: x -> scale * x + shift (scale != 0).
struct AffineMap1 {
  Rational scale{1}, shift{0};
  Rational operator()(const Rational& x) const { return scale * x + shift; }
  Rational inverse(const Rational& y) const { return (y - shift) / scale; }
};

/// Besides the interior points, compare at the cut values themselves: `lower` each cell's lower
/// end, `upper` the last cut. Not needed for the identity on the open cells, but where a side may
/// jump (C^-1 knots) its value at a breakpoint is a convention (FindSpan: the upper piece, closed
/// at the domain end) that the interior points cannot see.
struct SampleEnds {
  bool lower = false;
  bool upper = false;
};

/// The core: for cells given by sorted cut values per direction and a degree bound per direction,
/// calls `mismatch(x)` at (d+1)^k interior points of every cell (and the `ends`); `mismatch`
/// returns a non-empty description when the two sides differ at x. Stops at the first mismatch.
IdentityCheck prove_by_samples(const std::vector<std::vector<Rational>>& cuts, const std::vector<int>& degree_bound,
                               const std::function<std::string(const std::vector<Rational>&)>& mismatch,
                               const std::string& identity, SampleEnds ends = {});

/// The shape of one side of an identity, read from its inputs: its breakpoints per direction (where
/// it may change polynomial piece) and the degrees of its numerator and denominator (0: polynomial).
struct PiecewiseShape {
  std::vector<std::vector<Rational>> breaks;
  std::vector<int> numerator, denominator;
};
PiecewiseShape shape_of(const BSpline<Rational>& S);
/// Cells and degree bound for A = B: the union of both sides' breakpoints clipped to `box`, and per
/// direction max(num_A + den_B, num_B + den_A) (cross-multiplied numerators). Empty or inverted
/// boxes give no cells.
std::vector<std::vector<Rational>> union_cuts(const PiecewiseShape& A, const PiecewiseShape& B,
                                              const std::vector<std::pair<Rational, Rational>>& box);
std::vector<int> identity_bound(const PiecewiseShape& A, const PiecewiseShape& B);

/// Proves A(x) = B(phi(x)) for x in `box` (one [lo, hi] per direction, inside A's domain, with
/// phi(box) inside B's domain). `phi` empty means identity. Also compares at every breakpoint
/// inside the box and at the box's upper end where that is A's domain end, unless phi reverses
/// a direction or `open_cells_only` (a reversal maps A's upper one-sided values to B's lower ones).
IdentityCheck prove_equal_on_box(const BSpline<Rational>& A, const BSpline<Rational>& B,
                                 const std::vector<std::pair<Rational, Rational>>& box,
                                 const std::vector<AffineMap1>& phi, const std::string& identity,
                                 bool open_cells_only = false);

/// Proves A = B on A's whole domain, after checking that the domains are equal.
IdentityCheck prove_same_function(const BSpline<Rational>& A, const BSpline<Rational>& B, const std::string& identity);

std::vector<std::pair<Rational, Rational>> domain_box(const BSpline<Rational>& S);

}  // namespace splinex
