// The derivative of a polynomial B-spline in direction d as a B-spline of degree p-1 (NURBS Book
// eq. 3.8/A3.3): Q_i = p (P_{i+1} - P_i) / (U_{i+p+1} - U_{i+1}) on the knots U_1..U_{m-1}.
// An independent route to the first derivative, used to prove the A2.3 derivatives.
#pragma once
#include "base/errors.hpp"
#include "spline/bspline.hpp"

namespace splinex {

template <class T>
BSpline<T> hodograph(const BSpline<T>& S, int d) {
  detail::check_direction(S, d);
  if (S.is_rational())
    throw UsageError("spline", "the hodograph of a rational spline is not a B-spline", "use derivative()");
  if (S.degrees[d] == 0) throw UsageError("degrees", "a degree-0 spline has no hodograph here", "elevate first");
  return apply_along(S, d, [&](int p, const std::vector<T>& U, const T* P, std::size_t n, std::size_t m) {
    /// Q_i on knots U_1..U_{m-1}. At a knot of multiplicity p+1 (the spline may jump there)
    /// U_{i+1} = ... = U_{i+p+1}: that degree-(p-1) basis function is zero, so Q_i and one copy of
    /// the knot are dropped; the knot keeps multiplicity p = (p-1)+1, and the derivative may jump.
    CurveBlock<T> out;
    out.p = p - 1;
    out.U.assign(U.begin() + 1, U.end() - 1);
    std::vector<char> drop(n - 1, 0);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const T den = U[i + p + 1] - U[i + 1];
      if (den == T(0)) {
        drop[i] = 1;
        continue;
      }
      const T f = T(p) / den;
      for (std::size_t c = 0; c < m; ++c) out.P.push_back(f * (P[(i + 1) * m + c] - P[i * m + c]));
    }
    for (std::size_t i = n - 1; i-- > 0;)  // from the back, so earlier indices stay valid
      if (drop[i]) out.U.erase(out.U.begin() + static_cast<std::ptrdiff_t>(i));
    return out;
  });
}

}  // namespace splinex
