/// @file
/// The one affine test of a polynomial Bezier piece's coordinate, used by Algorithm 1 (split an
/// inner piece where an affine coordinate meets a knot of the outer spline) and Algorithm 2
/// (a trimming boundary that is a straight line in the piece's parameters).
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "spline/arith.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// Coordinate c of a Bezier piece as alpha + sum_l beta[l] r_l over its box.
template <class T>
struct AffineForm {
  T alpha;
  std::vector<T> beta;
  /// Depends on parameter l only (every other slope is zero).
  bool only_in(int l) const {
    for (std::size_t m = 0; m < beta.size(); ++m)
      if (static_cast<int>(m) != l && !(beta[m] == T(0))) return false;
    return true;
  }
};

/// Coordinate c of the polynomial Bezier piece P as an affine function of its parameters, if it is
/// one. By linear precision of the Bernstein basis this holds exactly when every forward difference
/// of the coefficients in direction l is the same number d_l (The NURBS Book, Section 1.3;
/// Farin, Curves and Surfaces, Section 5.1). The test compares differences only, so in floating point
/// it asks "are the stored coefficients in exact arithmetic progression"; slopes are
/// beta_l = (last - first coefficient along l) / (box width along l), alpha the value at the box's
/// low corner minus sum_l beta_l lo_l. Rational pieces are never affine here.
template <class T>
std::optional<AffineForm<T>> affine_form(const BSpline<T>& P, int c) {
  if (P.is_rational()) return std::nullopt;
  const int k = P.dim();
  std::vector<std::size_t> stride(k, 1);
  for (int l = 1; l < k; ++l) stride[l] = stride[l - 1] * P.count(l - 1);
  const auto coef = [&](std::size_t i) -> const T& { return P.points[i * P.q + c]; };
  std::vector<T> d(k, T(0));
  for (int l = 0; l < k; ++l)
    if (P.degrees[l] > 0) d[l] = coef(stride[l]) - coef(0);
  for (std::size_t i = 0; i < P.size(); ++i)
    for (int l = 0; l < k; ++l) {
      const std::size_t idx_l = (i / stride[l]) % P.count(l);
      if (static_cast<int>(idx_l) < P.degrees[l] && !(coef(i + stride[l]) - coef(i) == d[l])) return std::nullopt;
    }
  AffineForm<T> F;
  F.alpha = coef(0);
  F.beta.assign(k, T(0));
  for (int l = 0; l < k; ++l) {
    if (P.degrees[l] == 0) continue;
    F.beta[l] = (coef(stride[l] * P.degrees[l]) - coef(0)) / (P.domain_hi(l) - P.domain_lo(l));
  }
  for (int l = 0; l < k; ++l) F.alpha = F.alpha - F.beta[l] * P.domain_lo(l);
  return F;
}

}  // namespace splinex
