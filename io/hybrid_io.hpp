// The hybrid patch document (JSON), read exactly.
//   {"type": "hybrid_patch",
//    "domain": [[x, y], ...],                 strictly convex, counter-clockwise, n >= 3
//    "degree": d,                             d >= 3; l = ceil(d / 2) layers
//    "ribbon_factor": "side_interpolant",     optional; or "eq-2.11" (the paper's literal factor)
//    "sides": [{"degree": p_i, "knots": [d + p_i + 2 numbers, clamped on [0, 1]],
//               "layers": [[C_{0,k}, ..., C_{d,k}] for k = 0..l-1]}, ...]}
// Side i runs from domain[i] to domain[i + 1]; layer 0 holds the boundary curve's control points,
// layer 1 the ribbon's second row; corner points are repeated on both sides and must agree
// (C^i_{a,b} = C^{i-1}_{d-b,a}).
#pragma once
#include <array>
#include <vector>

#include "io/json_io.hpp"
#include "hybrid/hybrid.hpp"

namespace splinex {

HybridPatch<Rational> hybrid_from_json(const Json& doc, const Limits& limits = {});
template <class T>
Json hybrid_to_json(const HybridPatch<T>& P);

/// `splinex hybrid eval`: at each parameter x of xs the point, the Wachspress coordinates, the
/// side parameters s and distances h and (away from the corners) the partials du, dv, evaluated
/// in the arithmetic F (Rational, double or Mpfr; the patch is rounded to it).
template <class F>
Json hybrid_points_document(const HybridPatch<Rational>& P, const std::vector<std::array<Rational, 2>>& xs);

}  // namespace splinex
