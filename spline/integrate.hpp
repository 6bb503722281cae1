// Integrals of tensor-product B-spline functions over their parameter domain.
//
// integrate(f): the integral of each coordinate, in closed form from the B-spline basis integral
//   int N_{i,p} = (U_{i+p+1} - U_i) / (p + 1), so it is exact in exact arithmetic.
// integrate_abs(f): the integral of |f| for a scalar polynomial f (q = 1). Exact where the sign of
//   f is certified constant (all Bernstein coefficients of a cell >= 0 or all <= 0: then
//   int |f| = |int f|); cells with mixed signs are halved (de Casteljau) up to max_depth times,
//   and what remains undecided is enclosed by |int f| <= int |f| <= vol * mean |b_i| (because
//   |f| <= sum |b_i| B_i). The result is an enclosure [lower, upper]; lower == upper means exact.
//   With rel_width > 0 a mixed cell is not halved once its share of the gap is small enough for
//   upper - lower <= rel_width * lower overall (the budget is spread in proportion to cell volume,
//   against the lower bound of an unsplit first pass); max_depth still caps the work.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "spline/bspline.hpp"

namespace splinex {

template <class T>
std::vector<T> integrate(const BSpline<T>& f);

/// A and B on one structure: both clamped, each direction elevated to the larger degree and refined
/// to the union of the knot vectors (largest multiplicity of each value); the same functions,
/// rational ones included. Same dimension and q, and the same domain (DomainError otherwise).
template <class T>
std::pair<BSpline<T>, BSpline<T>> make_compatible(const BSpline<T>& A, const BSpline<T>& B, const Limits& limits = {});

/// A - B as one spline: both polynomial, same dimension, q and domain. Each direction is elevated
/// to the larger degree and refined to the union of the knot vectors (largest multiplicity of each
/// value), so the control points subtract. Exact in exact arithmetic. Clamps both first.
template <class T>
BSpline<T> difference(const BSpline<T>& A, const BSpline<T>& B, const Limits& limits = {});

template <class T>
struct AbsIntegral {
  T lower{}, upper{};
  std::size_t cells = 0;      // Bezier cells visited (after subdivision)
  std::size_t undecided = 0;  // leaf cells left with mixed signs
  bool exact() const { return lower == upper; }
};

template <class T>
AbsIntegral<T> integrate_abs(const BSpline<T>& f, int max_depth = 10, const T& rel_width = T(0));

}  // namespace splinex
