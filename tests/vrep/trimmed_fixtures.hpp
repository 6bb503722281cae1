// Trimmed models the trimmed-cell tests share: placed primitives and bounds of pi.
#pragma once
#include <vector>

#include "exact/rational.hpp"
#include "vrep/model/vmodel.hpp"
#include "vrep/primitives/primitives.hpp"
#include "vrep/trimmed/trimmed.hpp"

namespace splinex::trimmed_fixtures {

// pi lies strictly between these (pi = 3.14159265358979...).
inline const Rational pi_lo = Rational(314159265) / Rational(100000000), pi_hi = Rational(314159266) / Rational(100000000);

/// The box [lo, hi] as a trimmed model with its region.
inline TrimmedModel<Rational> box(std::vector<Rational> lo, std::vector<Rational> hi) {
  return as_trimmed(glue(box_cells<Rational>(lo, hi)), box_region<Rational>(lo, hi));
}

/// The cylinder primitive of radius r and height h along `axis`, moved to `at`.
inline TrimmedModel<Rational> cylinder(const Rational& r, const Rational& h, int axis, std::vector<Rational> at) {
  return placed_primitive(cylinder_cells<Rational>(r, h), cylinder_region<Rational>(r, h), axis, at);
}

}  // namespace splinex::trimmed_fixtures
