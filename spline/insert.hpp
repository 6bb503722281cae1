// Knot insertion in any direction: Boehm's single-knot insertion repeated r times (NURBS Book
// A5.1) and refinement by a whole sorted list at once (A5.4, the Oslo-type refinement). Two
// independent algorithms for the same map; tests check that they agree exactly.
#pragma once
#include <vector>

#include "spline/bspline.hpp"

namespace splinex {

// Inserts x into direction d `times` times (A5.1). x must lie in the open domain or on an
// interior knot; the multiplicity after insertion must stay <= degree+1.
template <class T>
BSpline<T> insert_knot(const BSpline<T>& S, int d, const T& x, int times = 1, const Limits& limits = {});

// Inserts every knot of X (in any order; sorted internally) into direction d (A5.4).
template <class T>
BSpline<T> refine_knots(const BSpline<T>& S, int d, std::vector<T> X, const Limits& limits = {});

// Same function on the domain, with end knots of multiplicity degree+1 in direction d (inserts
// the domain ends and drops the knots and control points outside).
template <class T>
BSpline<T> clamp(const BSpline<T>& S, int d, const Limits& limits = {});
template <class T>
BSpline<T> clamp_all(const BSpline<T>& S, const Limits& limits = {});

}  // namespace splinex
