#include "exact/random_spline.hpp"

#include <algorithm>
#include <map>

#include "spline/errors.hpp"
#include "spline/knots.hpp"

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

StructuredCase structured_case(std::mt19937_64& rng, const StructuredOptions& options) {
  StructuredCase c;
  std::vector<std::string>& tags = c.structures;
  auto tag = [&](const std::string& t) {
    if (std::find(tags.begin(), tags.end(), t) == tags.end()) tags.push_back(t);
  };
  auto chance = [&](int one_in) { return uniform(rng, 1, one_in) == 1; };
  BSpline<Rational>& S = c.spline;
  const int dim = static_cast<int>(uniform(rng, 1, options.max_dim));
  const int max_p = dim == 1 ? 7 : dim == 2 ? 4 : 2;
  std::size_t total = 1;
  for (int d = 0; d < dim; ++d) {
    // Degree 0 and the high degrees on purpose, not only by chance.
    const int p = chance(5) ? 0 : static_cast<int>(uniform(rng, 1, max_p));
    if (p == 0) tag("degree 0");
    if (p >= 5) tag("degree >= 5");
    // Domain [a, b]: usually [0, 1], sometimes shifted and scaled.
    Rational a(0), b(1);
    if (chance(3)) {
      a = Rational(uniform(rng, -5000, 5000), 1000);
      b = a + Rational(uniform(rng, 1, 8000), 1000);
      tag("shifted domain");
    }
    // Interior breakpoints with multiplicities 1..p+1.
    const int spans = chance(5) ? 1 : static_cast<int>(uniform(rng, 2, dim == 1 ? 6 : dim == 2 ? 3 : 2));
    if (spans == 1) tag("single span");
    std::vector<Rational> bps;
    for (int i = 1; i < spans; ++i) bps.push_back(Rational(uniform(rng, 1, 999), 1000));
    std::sort(bps.begin(), bps.end());
    bps.erase(std::unique(bps.begin(), bps.end()), bps.end());
    if (!bps.empty() && chance(3)) {  // a knot very close to another one
      const bool below_double = chance(2);
      Rational gap(1);
      for (int e = 0; e < (below_double ? 1100 : 60); ++e) gap /= 2;
      const Rational near = bps.back() + gap;
      if (near < Rational(1)) {
        bps.push_back(near);
        tag(below_double ? "gap 2^-1100" : "gap 2^-60");
      }
    }
    std::vector<Rational> interior;
    for (const auto& x : bps) {
      int m = 1;
      if (options.discontinuous && chance(3)) m = p + 1;
      else if (p > 1 && chance(3)) m = static_cast<int>(uniform(rng, 2, p));
      if (m == p + 1) tag("C^-1 knot");
      for (int r = 0; r < m; ++r) interior.push_back(x);
    }
    const bool clamped = p == 0 || !chance(3);
    if (!clamped) tag("unclamped");
    std::vector<Rational> U;
    if (clamped) {
      U.assign(p + 1, Rational(0));
    } else {
      for (int i = p; i >= 1; --i) U.push_back(Rational(-i, 8) - Rational(uniform(rng, 0, 9), 100));
      U.push_back(Rational(0));
    }
    U.insert(U.end(), interior.begin(), interior.end());
    if (clamped) {
      U.insert(U.end(), p + 1, Rational(1));
    } else {
      U.push_back(Rational(1));
      for (int i = 1; i <= p; ++i) U.push_back(Rational(8 + i, 8) + Rational(uniform(rng, 0, 9), 100));
    }
    for (auto& u : U) u = a + (b - a) * u;
    S.degrees.push_back(p);
    S.knots.push_back(std::move(U));
    total *= S.count(d);
  }
  S.q = static_cast<int>(uniform(rng, 1, 4));
  // Coordinates: small decimals, sometimes scaled by 10^+-30 per coordinate.
  std::vector<Rational> scale(S.q, Rational(1));
  if (options.extreme_values)
    for (int j = 0; j < S.q; ++j)
      if (chance(4)) {
        Rational t(1);
        for (int e = 0; e < 30; ++e) t *= 10;
        const bool huge = chance(2);
        scale[j] = huge ? t : Rational(1) / t;
        tag(huge ? "coordinates ~1e30" : "coordinates ~1e-30");
      }
  for (std::size_t i = 0; i < total; ++i)
    for (int j = 0; j < S.q; ++j) S.points.push_back(Rational(uniform(rng, -2000, 2000), 1000) * scale[j]);
  if (options.rational && chance(3)) {
    tag("rational");
    const bool wide = options.extreme_values && chance(2);
    if (wide) tag("weights 1e-6..1e6");
    for (std::size_t i = 0; i < total; ++i) {
      if (!wide) {
        S.weights.emplace_back(uniform(rng, 500, 2000), 1000);
        continue;
      }
      Rational w(uniform(rng, 1, 9));
      const long e = uniform(rng, -6, 5);
      for (long k = 0; k < (e < 0 ? -e : e); ++k) w = e < 0 ? Rational(w / 10) : Rational(w * 10);
      S.weights.push_back(w);
    }
  }
  validate(S);
  return c;
}

}  // namespace splinex
