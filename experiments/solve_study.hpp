// Certified solving (issue 19): figures of curve projections, and the float solvers measured
// against the certified one on a published suite (report section "Certified solving").
#pragma once
#include <string>

#include "exact/rational.hpp"
#include "solve/curve_projection.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// Two panels: the surface's parameter domain with the traced branches (one colour per component)
/// and the special points, and the top view (x, y) of the curve (grey) and its projection on the
/// surface, with the surface's boundary.
std::string curve_projection_svg(const BSpline<Rational>& C, const BSpline<Rational>& S, const CurveProjectionResult& r,
                                 const std::string& title);

/// The curve, the surface's boundary and the projected branches as OBJ polylines (ParaView).
std::string curve_projection_obj(const BSpline<Rational>& C, const BSpline<Rational>& S, const CurveProjectionResult& r);

}  // namespace splinex
