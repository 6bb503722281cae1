// Reproducible random exact splines for proofs, tests, crosscheck suites and benchmarks.
// Knots, coordinates and weights are short decimals (k/1000), so they are exact rationals with
// small denominators, like hand-written input; `dyadic` makes them k/1024 instead.
#pragma once
#include <cstdint>
#include <random>
#include <string>
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

// The structured generator: random legal splines that reach the edges of the input space on
// purpose, each case naming the structures it contains (GUIDE.md, "Inputs at the edges"):
//   degree 0 .. 7 (dimension 1), 0 .. 4 (2), 0 .. 2 (3);      "degree 0", "degree >= 5"
//   interior multiplicities 1 .. p+1 (a C^-1 knot: the spline may jump);  "C^-1 knot"
//   a single span (no interior knot);                           "single span"
//   clamped or unclamped ends;                                  "unclamped"
//   two knots 2^-60 apart, or closer than double can tell apart (2^-1100); "gap 2^-60", "gap 2^-1100"
//   a domain other than [0, 1] (shifted and scaled);            "shifted domain"
//   q = 1 .. 4 coordinates, some far outside [0, 1] (|x| up to 10^30, down to 10^-30); "coordinates ~1e30", "coordinates ~1e-30"
//   rational with weights from 10^-6 to 10^6;                   "rational", "weights 1e-6..1e6"
// Exact throughout: every value is a short decimal or a power of two, read exactly.
struct StructuredCase {
  BSpline<Rational> spline;
  std::vector<std::string> structures;  // the tags above that this case contains
};
struct StructuredOptions {
  int max_dim = 3;
  bool rational = true;        // allow rational cases
  bool discontinuous = true;   // allow multiplicity p+1
  bool extreme_values = true;  // coordinates and weights over many orders of magnitude
};
StructuredCase structured_case(std::mt19937_64& rng, const StructuredOptions& options = {});

}  // namespace splinex
