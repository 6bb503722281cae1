#include "exact/random_spline.hpp"

#include <algorithm>
#include <map>

#include "spline/errors.hpp"

namespace splinex {

namespace {
long uniform(std::mt19937_64& rng, long lo, long hi) { return std::uniform_int_distribution<long>(lo, hi)(rng); }
}  // namespace

Rational random_inside(const Rational& lo, const Rational& hi, std::mt19937_64& rng, bool dyadic) {
  const long den = dyadic ? 1024 : 1000;
  return lo + (hi - lo) * Rational(uniform(rng, 1, den - 1), den);
}

BSpline<Rational> random_spline(const RandomSplineSpec& spec, std::mt19937_64& rng) {
  const long den = spec.dyadic ? 1024 : 1000;
  BSpline<Rational> S;
  S.degrees = spec.degrees;
  S.q = spec.q;
  std::size_t total = 1;
  for (std::size_t d = 0; d < spec.degrees.size(); ++d) {
    const int p = spec.degrees[d];
    const std::size_t n = spec.counts[d];
    if (n < static_cast<std::size_t>(p) + 1) throw UsageError("counts", "too few control points", "use >= degree+1");
    total *= n;
    // Interior knots: n-p-1 values on a grid of (0, 1) fine enough for them (k/1000 or k/1024 for
    // small n; a finer power of 10 or 2 for long knot vectors), occasionally repeated up to the
    // multiplicity limit.
    const std::size_t ni = n - p - 1;
    long kden = den;
    while (static_cast<std::size_t>(kden) < 8 * ni + 8) kden *= spec.dyadic ? 2 : 10;
    const int maxmult = spec.max_interior_multiplicity > 0 ? spec.max_interior_multiplicity : std::max(p, 1);
    std::map<long, int> mult;
    std::size_t placed = 0;
    while (placed < ni) {
      const long k = uniform(rng, 1, kden - 1);
      const long reps = std::min<long>(uniform(rng, 1, 4) == 1 ? uniform(rng, 1, maxmult) : 1, static_cast<long>(ni - placed));
      if (mult[k] + reps > maxmult) continue;
      mult[k] += static_cast<int>(reps);
      placed += reps;
    }
    std::vector<Rational> interior;
    interior.reserve(ni);
    for (const auto& [k, m] : mult)
      for (int r = 0; r < m; ++r) interior.emplace_back(k, kden);
    std::vector<Rational> U;
    if (spec.clamped) {
      U.assign(p + 1, Rational(0));
      U.insert(U.end(), interior.begin(), interior.end());
      U.insert(U.end(), p + 1, Rational(1));
    } else {  // distinct ends outside the domain: -p/8 .. 0 and 1 .. 1 + p/8
      for (int i = p; i >= 1; --i) U.push_back(Rational(-i, 8));
      U.push_back(Rational(0));
      U.insert(U.end(), interior.begin(), interior.end());
      U.push_back(Rational(1));
      for (int i = 1; i <= p; ++i) U.push_back(Rational(8 + i, 8));
    }
    S.knots.push_back(std::move(U));
  }
  for (std::size_t i = 0; i < total * spec.q; ++i) S.points.emplace_back(uniform(rng, -2 * den, 2 * den), den);
  if (spec.rational)
    for (std::size_t i = 0; i < total; ++i) S.weights.emplace_back(uniform(rng, den / 2, 2 * den), den);
  validate(S);
  return S;
}

BSpline<Rational> random_case(std::mt19937_64& rng, int max_degree, int max_dim) {
  RandomSplineSpec spec;
  const int dim = static_cast<int>(uniform(rng, 1, max_dim));
  for (int d = 0; d < dim; ++d) {
    const int p = static_cast<int>(uniform(rng, 1, dim == 3 ? std::min(max_degree, 3) : max_degree));
    spec.degrees.push_back(p);
    spec.counts.push_back(p + 1 + uniform(rng, 0, dim == 1 ? 6 : 3));
  }
  spec.q = static_cast<int>(uniform(rng, 1, 4));
  spec.rational = uniform(rng, 0, 2) == 0;
  spec.clamped = uniform(rng, 0, 3) != 0;
  return random_spline(spec, rng);
}

}  // namespace splinex
