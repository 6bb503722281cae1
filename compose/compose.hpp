// Functional composition T(S) of Bezier pieces (papers/000, Sections 1-2): inner S: R^k -> R^n,
// outer T: R^n -> R^q, both single polynomial pieces (clamped, no interior knots), polynomial or
// rational, any k and n (1, 2, 3 tested). The result is a Bezier piece on S's parameter box of
// degree d_l * (e_1 + ... + e_n) in direction l (d: inner degrees, e: outer degrees).
//
// Observation 1 of the paper: a polynomial piece is defined on all of R^n, so S may leave T's
// box; T is then evaluated as the polynomial of its Bernstein form on that box.
//
// Two independent methods that must agree exactly in exact arithmetic:
//  - CompositionMethod::symbolic (Elber): T(S) = sum_I C_I prod_j B^{e_j}_{I_j}(u_j(S)), with
//    u_j the affine local coordinate of S's j-th component, built from products of Bernstein
//    polynomials (h_K = sum_{I+J=K} binom(a,I) binom(b,J) / binom(a+b,K) f_I g_J per direction);
//  - CompositionMethod::interpolation: T(S(r)) evaluated exactly at (D_l+1) equispaced points per
//    direction and interpolated in the Bernstein basis (one exact linear solve per direction).
// Rational S or T: the homogeneous numerator and weight are composed (T's Bernstein sum times
// W^E, E = sum e_j), so the result is rational with weight of degree d * E.
#pragma once
#include "spline/bspline.hpp"

namespace splinex {

enum class CompositionMethod { symbolic, interpolation };

/// The degrees of T(S) per direction of S: d_l * sum_j e_j.
template <class T>
std::vector<int> composed_degrees(const BSpline<T>& outer, const BSpline<T>& inner);

template <class T>
BSpline<T> compose_bezier(const BSpline<T>& outer, const BSpline<T>& inner,
                          CompositionMethod method = CompositionMethod::symbolic, const Limits& limits = {});

/// Composition of B-splines T(S) when every Bezier piece of S lies in one polynomial piece of T
/// (decided exactly on the convex hull of the piece's control points): each piece of S is composed
/// with the piece of T that contains it, and the results are joined into one B-spline on S's
/// domain, with S's breakpoints as knots of multiplicity D_l (C^0 joins), or D_l + 1 where T(S)
/// may jump: S has a knot of multiplicity d_l + 1 there, D_l = 0, or the two sides lie in pieces
/// of T separated by a knot of T of multiplicity e_j + 1. A piece that crosses a knot line of T
/// needs trimmed composition (Algorithm 1): DomainError naming the knot; so does a piece that
/// reaches a knot line where T may jump from below at a parameter it owns. S leaving
/// T's domain: DomainError naming how far, unless `expand` (then the nearest end piece of T is
/// used as a polynomial on all of R^n, Observation 1).
struct CompositionOptions {
  CompositionMethod method = CompositionMethod::symbolic;
  bool expand = false;
};

template <class T>
BSpline<T> compose(const BSpline<T>& outer, const BSpline<T>& inner, const CompositionOptions& options = {},
                   const Limits& limits = {});

/// The least number of control points compose(outer, inner) returns, prod_l (segments_l D_l + 1)
/// (C^0 joins at S's breakpoints; joins where T(S) may jump add one each), computed from the knots
/// and degrees alone, before any work. SizeLimitError when it or a degree is above `limits`.
template <class T>
std::size_t compose_least_size(const BSpline<T>& outer, const BSpline<T>& inner, const Limits& limits = {});

/// The homogeneous composition: a polynomial Bezier piece with q+1 coordinates (w*T(S), w) when S
/// or T is rational (the weight is not required to be positive: trimmed patches evaluated only
/// inside their region may have non-positive weights elsewhere), q coordinates otherwise.
/// The result is `weighted` exactly then.
template <class T>
Homogeneous<T> compose_bezier_homogeneous(const BSpline<T>& outer, const BSpline<T>& inner, CompositionMethod method,
                                          const Limits& limits);

/// T evaluated as the polynomial (or rational) of its Bezier form at any u in R^n, inside its box
/// or not (Observation 1). Homogeneous (w*T, w) for rational T.
template <class T>
std::vector<T> evaluate_bezier_anywhere(const BSpline<T>& bezier, const std::vector<T>& u);

}  // namespace splinex
