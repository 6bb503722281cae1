// Evaluation and partial derivatives of any order of tensor-product B-splines, polynomial and
// rational. Declarations; definitions in spline/evaluate_impl.hpp, instantiated for the standard
// arithmetics in exact/ and float/.
#pragma once
#include <vector>

#include "spline/bspline.hpp"

namespace splinex {

/// S(x): q coordinates. Throws DomainError when x has the wrong size or leaves the domain.
template <class T>
std::vector<T> evaluate(const BSpline<T>& S, const std::vector<T>& x);

/// S at many points at once: `params` holds N points of dim() parameters each (point-major), the
/// result their N values of q coordinates each. One allocation for the whole batch (the result),
/// none per point; each point is checked as evaluate() checks it ("params[i]" in errors).
template <class T>
std::vector<T> evaluate_points(const BSpline<T>& S, const std::vector<T>& params);

/// S(x) by de Boor's algorithm (NURBS Book A3.1 generalized): the (p_d+1)-point active net is
/// reduced one direction at a time by the de Boor triangle, on homogeneous coordinates. An
/// independent route to evaluate(), which uses the basis functions (A2.2); proofs require that
/// both give the same exact value.
template <class T>
std::vector<T> evaluate_de_boor(const BSpline<T>& S, const std::vector<T>& x);

/// The partial derivative d^{k_0+...}S / dx_0^{k_0} ... at x (orders k_d >= 0, any size; a
/// derivative past the degree is zero). Rational splines use the quotient rule (A4.4 generalized
/// to k directions).
template <class T>
std::vector<T> derivative(const BSpline<T>& S, const std::vector<T>& x, const std::vector<int>& orders);

/// The homogeneous value (w*S, w) for rational splines, S for polynomial ones: the polynomial
/// numerator/denominator used by proofs.
template <class T>
std::vector<T> evaluate_homogeneous(const BSpline<T>& S, const std::vector<T>& x);

}  // namespace splinex
