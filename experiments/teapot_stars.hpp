// The teapot star pattern of papers/000 (Figure 4): a star-shaped bi-quadratic Bezier surface,
// replicated 7 x 7 over the parameter domain of each teapot surface, composed into it by
// Algorithm 1 (stars cross the surfaces' knot lines transversely), exactly and in double.
#pragma once
#include <functional>
#include <string>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

/// The star: bi-quadratic Bezier on [0,1]^2 -> R^2. Tips at the corners of the unit square, each
/// edge's middle control point pulled a quarter towards the centre, the centre control point at
/// (1/2, 1/2): a four-pointed star with concave sides.
BSpline<Rational> unit_star();

/// The star scaled into tile (i, j) of an n x n tiling of [0, w] x [0, h], with a margin of 1/20
/// of the tile on each side.
BSpline<Rational> star_in_tile(int i, int j, int n, const Rational& w, const Rational& h);

struct StarPatternOptions {
  std::string out_dir;
  int tiles = 7;
  bool write_meshes = true;
};

/// Runs the pattern on the four teapot surfaces; writes figures, meshes and CSV into out_dir and
/// returns a Markdown section. `progress` receives one line per surface.
std::string run_teapot_stars(const StarPatternOptions& options, const std::function<void(const std::string&)>& progress,
                             bool& ok);

}  // namespace splinex
