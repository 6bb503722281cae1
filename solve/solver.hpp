// A subdivision solver for square polynomial systems in Bernstein form (issue 19, What to build 1;
// papers/002 Section 5: the paper's IRIT solver, certified here).
//
// f_1 = ... = f_n = 0, each f_i a tensor-product polynomial in Bernstein form on [0, 1]^n, which
// stands for the box [lo, hi] of the caller's coordinates (affinely: the zeros are the same). The
// solver keeps a list of boxes with each f_i restricted to it exactly (de Casteljau, so the
// coefficients are those of the box), and per box:
//   1. discards it when some f_i has coefficients of one strict sign (the convex hull property:
//      f_i has no zero on the closed box);
//   2. runs Krawczyk's test (Krawczyk 1969; Moore, Kearfott and Cloud, Introduction to Interval
//      Analysis, Section 8.2) on the box X = [0, 1]^n: with c the centre, Y an approximate inverse of
//      F'(c) (computed in double, then taken exactly) and J(X) the ranges of the derivatives'
//      Bernstein coefficients, K(X) = c - Y F(c) + (I - Y J(X)) (X - c). Every zero of F in X lies in
//      K(X), so K(X) disjoint from X discards the box; K(X) inside the open box proves exactly one
//      zero in X, and it is simple (J(X) holds no singular matrix);
//   3. otherwise halves the box in every direction, down to `max_depth` halvings; what is still
//      open there is an undecided box.
// Undecided boxes that touch are joined into clusters; a cluster's hull gets the test once more
// in its closed form (K(X) inside X and ||I - Y J(X)||_inf < 1: a contraction of X into itself,
// one zero in the closed X), which finds the zeros that lie on a line where boxes were split.
// A certified box is then shrunk by iterating X <- K(X) (the same theorem on the smaller box) to
// `refine_bits` relative width. Exact rational zeros are recognised: Newton in double from the
// box, the simplest rational number near each coordinate (continued fractions), and every f_i
// evaluated there exactly; a zero residual makes it an exact root.
//
// The answers are three: a certified box with one simple root (and possibly the exact root), an
// exact root whose box is not certified (a multiple root: its multiplicity is not decided), and
// an undecided box. Everything outside the reported boxes is proved free of zeros. In double
// (the float solver beside the exact one) the same steps run with rounding, so nothing is
// certified and the fields say what the test answered in double.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "bernstein/tensor.hpp"
#include "exact/rational.hpp"

namespace splinex {

struct SolveOptions {
  int max_depth = 30;               // halvings per direction of the system's box (width 2^-max_depth)
  std::size_t max_boxes = 20000;    // boxes examined per system (ten times this per projection or contact); what is left is undecided
  int refine_bits = 60;             // certified boxes are shrunk to 2^-refine_bits of the system's box
  bool recognize_rationals = true;  // look for exact rational roots (exact arithmetic only)
  /// Called about every two seconds by the searches over many systems (projection, contact) with a
  /// line of progress; empty: silent.
  std::function<void(const std::string&)> progress;
};

template <class T>
struct RootBox {
  std::vector<T> lo, hi;  // the box, in the caller's coordinates
  bool unique = false;    // Krawczyk: exactly one root in the closed box, a simple one (certified in exact arithmetic)
  bool exact = false;     // `point` is a root: every f_i is exactly 0 there
  std::vector<T> point;   // the exact root; otherwise the box's centre
};

template <class T>
struct SolveResult {
  std::vector<RootBox<T>> roots;      // unique, or exact (then possibly multiple, and its box is also undecided)
  std::vector<RootBox<T>> undecided;  // cluster hulls that may hold roots (multiple, tangential, or beyond the limits)
  std::size_t boxes = 0;              // boxes examined
  std::size_t discarded_by_sign = 0, discarded_by_krawczyk = 0, discarded_by_caller = 0;
  bool budget_exhausted = false;  // max_boxes reached: the rest of the queue is in `undecided`
  /// Every root is in `roots`, each certified unique: no undecided box and no exact root of
  /// unknown multiplicity (in a float arithmetic: the same, uncertified).
  bool complete() const;
};

/// A caller's test that a box cannot matter (branch and bound: a distance known to be larger than
/// one already found). `aux` are polynomials in the same unknowns, split with the system; per box
/// `discard` sees them restricted to it (Bernstein form on that box) with the box, and may update
/// the caller's bound. Boxes it discards are not searched: the result is complete only outside them.
template <class T>
struct Pruning {
  std::vector<Bernstein<T>> aux;
  std::function<bool(const Bernstein<T>* aux, std::size_t count, const std::vector<T>& lo, const std::vector<T>& hi)> discard;
};

/// The roots of f on the box [lo, hi] (f[i] in Bernstein form on [0, 1]^n standing for it).
/// ValidationError when the system is not square (n polynomials in n variables, n >= 1) or a
/// box side is empty.
template <class T>
SolveResult<T> solve_system(const std::vector<Bernstein<T>>& f, const std::vector<T>& lo, const std::vector<T>& hi,
                            const SolveOptions& options = {}, const Pruning<T>* pruning = nullptr);

/// x rounded down (or up) to a multiple of 2^-bits (bits may be negative).
Rational round_to_dyadic(const Rational& x, int bits, bool down);

/// An enclosure [lo, hi] widened outward to 72 significant bits (Rational: shorter numbers, the
/// same certificate; a float arithmetic: unchanged). lo stays >= 0 when it was.
template <class T>
void round_enclosure(T& lo, T& hi);

/// The simplest rational number (smallest denominator, then numerator) in [a, b], a <= b.
Rational simplest_rational_between(const Rational& a, const Rational& b);

}  // namespace splinex
