// The derivative of a polynomial B-spline in direction d as a B-spline of degree p-1 (NURBS Book
// eq. 3.8/A3.3): Q_i = p (P_{i+1} - P_i) / (U_{i+p+1} - U_{i+1}) on the knots U_1..U_{m-1}.
// An independent route to the first derivative, used to prove the A2.3 derivatives.
#pragma once
#include "spline/bspline.hpp"
#include "spline/errors.hpp"

namespace splinex {

template <class T>
BSpline<T> hodograph(const BSpline<T>& S, int d) {
  if (S.is_rational())
    throw UsageError("spline", "the hodograph of a rational spline is not a B-spline", "use derivative()");
  if (S.degrees[d] == 0) throw UsageError("degrees", "a degree-0 spline has no hodograph here", "elevate first");
  return apply_along(S, d, [&](int p, const std::vector<T>& U, const T* P, std::size_t n, std::size_t m) {
    CurveBlock<T> out;
    out.p = p - 1;
    out.U.assign(U.begin() + 1, U.end() - 1);
    out.P.resize((n - 1) * m);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const T den = U[i + p + 1] - U[i + 1];
      const T f = (den == T(0)) ? T(0) : T(p) / den;  // 0/0: the basis function vanishes
      for (std::size_t c = 0; c < m; ++c) out.P[i * m + c] = f * (P[(i + 1) * m + c] - P[i * m + c]);
    }
    return out;
  });
}

}  // namespace splinex
