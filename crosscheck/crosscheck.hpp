// Run one operation in exact arithmetic and in a floating arithmetic from the same exact input,
// and measure the difference exactly: every float result is converted to the rational it is
// (no rounding) and subtracted from the exact result.
//
// Reported, for control points (q coordinates, Cartesian), knots, and evaluated points on a
// rational grid over each result's domain:
//   abs   = max |float - exact|                     (exact rational, printed rounded)
//   rel   = abs / max |exact|                       (normwise over the same set)
//   bits lost = max(0, precision + log2(rel)): how many of the format's significand bits the
//               operation (including the rounding of its input) did not deliver.
// Grid points: the float spline is evaluated in float at the rounded grid parameter; the exact
// spline exactly at the exact parameter.
#pragma once
#include <string>

#include "crosscheck/operations.hpp"
#include "io/json_io.hpp"
#include "float/arith_spec.hpp"

namespace splinex {

struct ErrorStat {
  Rational max_abs{0};
  Rational max_ref{0};  // max |exact value| over the compared set
  std::size_t count = 0;

  void add(const Rational& exact, const Rational& approx);
  double abs() const;
  double rel() const;
  double bits_lost(int precision) const;
  Json to_json(int precision) const;
};

struct CrossReport {
  std::string operation;
  std::string arith;
  int precision = 0;
  bool structure_match = true;   // same number of results, degrees and knot counts
  std::string structure_note;
  ErrorStat control_points, knots, grid;
  std::size_t results = 0, control_point_count = 0;
  double seconds_exact = 0, seconds_float = 0;
  Json document() const;
};

/// grid_per_dir = 0 chooses 65 (curves), 17 (surfaces), 7 (trivariates) points per direction.
CrossReport crosscheck(const Operation& op, const BSpline<Rational>& input, const ArithSpec& fl,
                       int grid_per_dir = 0, const Limits& limits = {});

}  // namespace splinex
