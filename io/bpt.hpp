// Bezier patch files (.bpt, e.g. Newell's teapot) read exactly, and groups of patches merged
// into one B-spline surface.
#pragma once
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// Reads a .bpt file: the patch count, then per patch "du dv" and (du+1)(dv+1) lines "x y z",
/// row by row (the column index runs fastest and becomes direction 0). Coordinates are parsed
/// exactly from their text. Errors name the line.
std::vector<BSpline<Rational>> read_bpt(const std::string& path);

/// Merges a grid of Bezier patches (rows[j][i]: patch i in direction 0, j in direction 1) into one
/// B-spline surface on [0, #cols] x [0, #rows] with integer interior knots of multiplicity equal to
/// the degree (C^0 joins). Shared edges must coincide exactly, or ValidationError names the pair.
BSpline<Rational> merge_bezier_grid(const std::vector<BSpline<Rational>>& patches,
                                    const std::vector<std::vector<int>>& rows, const std::string& name);

}  // namespace splinex
