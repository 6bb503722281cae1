// A B-spline's homogeneous value from basis values the caller supplies: for compose/, which
// evaluates Bezier pieces anywhere in the plane from Bernstein polynomials. Defined in
// spline/evaluate_impl.hpp and instantiated with the kernel (SPLINEX_INSTANTIATE_KERNEL).
#pragma once
#include <cstddef>
#include <vector>

#include "spline/bspline.hpp"

namespace splinex {

/// sum_i prod_d B[d][i_d] H_i over the (p_d + 1) tensor of control points ending at span[d] in each
/// direction d, with H_i the homogeneous control point (w_i P_i, w_i), or P_i for a polynomial
/// spline: q (+1) values. B[d] holds p_d + 1 basis values.
template <class T>
std::vector<T> basis_sum(const BSpline<T>& S, const std::vector<std::size_t>& span, const std::vector<const std::vector<T>*>& B);

}  // namespace splinex
