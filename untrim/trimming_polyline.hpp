// Float trimming curves: the level set {s_c(r) = u} of a coordinate of a Bezier surface piece
// (double) on its parameter box, as a polyline within a tolerance eps of the true curve.
// Marching squares on a grid finds the curve's cells; each crossing of a grid edge is bisected
// to eps; each chord is refined at its midpoint against the true curve (bisection along the
// chord's normal) until the midpoint is within eps/2 of it. The tolerance is a named policy.
#pragma once
#include <array>
#include <vector>

#include "base/point.hpp"
#include "spline/bspline.hpp"

namespace splinex {

struct TrimmingTolerance {
  double eps = 1e-6;  // distance to the true curve, in the piece's parameters
  int grid = 16;      // marching-squares cells per direction
  int max_depth = 40; // chord refinement depth
};


std::vector<Segment2<double>> trace_level_set(const BSpline<double>& piece, int coord, double level, const TrimmingTolerance& tol);

/// The side of r relative to the traced curve: true when s_c(r) >= level as the polyline says.
/// Decided by parity: the box corner where |s_c - level| is largest has a known sign, and every
/// crossing of the segment from that corner to r with the polyline flips it. Agrees with the
/// exact sign for points farther than the polyline's deviation from the curve.
bool polyline_side(const BSpline<double>& piece, int coord, double level, const std::vector<Segment2<double>>& polyline,
                   const Point2<double>& r);

/// Where the horizontal line r_1 = t meets the polyline (every crossing, sorted by r_0).
std::vector<double> crossings_at(const std::vector<Segment2<double>>& polyline, double t);

}  // namespace splinex
