// Reproducible random exact splines for proofs, tests, crosscheck suites and benchmarks.
// Knots, coordinates and weights are short decimals (k/1000), so they are exact rationals with
// small denominators, like hand-written input; `dyadic` makes them k/1024 instead.
#pragma once
#include <cstdint>
#include <random>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

struct RandomSplineSpec {
  std::vector<int> degrees;
  std::vector<std::size_t> counts;  // control points per direction (>= degree+1)
  int q = 3;
  bool rational = false;
  bool clamped = true;
  bool dyadic = false;
  int max_interior_multiplicity = 0;  // 0: up to the degree
};

BSpline<Rational> random_spline(const RandomSplineSpec& spec, std::mt19937_64& rng);

// A random value strictly inside (lo, hi) on the same grid (k/1000 or k/1024 of the width).
Rational random_inside(const Rational& lo, const Rational& hi, std::mt19937_64& rng, bool dyadic = false);

// A random spline of dimension 1..3 with small random degrees and counts (for proofs/tests).
BSpline<Rational> random_case(std::mt19937_64& rng, int max_degree = 4, int max_dim = 3);

}  // namespace splinex
