// Point projection onto a surface (solve/projection.hpp), instantiated for Rational and double.
#include "solve/projection.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "base/errors.hpp"
#include "float/arith_spec.hpp"
#include "float/mpfr.hpp"
#include "solve/strata.hpp"
#include "spline/evaluate.hpp"

namespace splinex {

template <class T>
ProjectionResult<T> project_point(const BSpline<T>& S, const std::vector<T>& P, const SolveOptions& options, const Limits& limits) {
  // The equations' degrees: 2p - 1 (polynomial) or 3p - 1 (rational) in the derivative's direction.
  solve_detail::require_surface(S, "surface", limits, 2);
  if (P.size() != 3) throw ValidationError("point", "has " + std::to_string(P.size()) + " coordinates", "give x,y,z");
  const auto all = solve_detail::stationary_pairs(solve_detail::surface_strata(S, limits), {solve_detail::point_stratum(P)}, options, solve_detail::Search::all);
  for (const auto& u : all.undecided)
    if (u.degenerate && u.where == "interior-point")
      throw ValidationError("point", "every point of " + u.strata.substr(0, u.strata.rfind(" / ")) +
                                         " is a critical point of the distance (the point is a centre of the surface, or the piece is degenerate): the projection is not isolated",
                            "move the point, or give a surface whose distance from it is not constant on a piece");
  // The pairs (stratum, point) as critical points of the stratum: "interior-point" is "interior".
  const auto convert = [](const ContactPoint<T>& p) {
    CriticalPoint<T> c;
    c.where = p.where.substr(0, p.where.rfind('-'));
    c.stratum = p.strata.substr(0, p.strata.rfind(" / "));
    c.lo = p.lo;
    c.hi = p.hi;
    c.exact = p.exact;
    c.unique = p.unique;
    c.merged = p.merged;
    c.d2_lo = p.d2_lo;
    c.d2_hi = p.d2_hi;
    c.point = p.p1;
    c.along = p.along;
    c.collapsed = p.collapsed;
    return c;
  };
  ProjectionResult<T> out;
  for (const auto& p : all.points) out.critical.push_back(convert(p));
  for (const auto& p : all.undecided) out.undecided.push_back(convert(p));
  out.closest = all.closest;
  out.undecided_closest = all.undecided_closest;
  out.closest_certified = all.closest_certified;
  out.reason = all.reason;
  out.distance2_lo = all.distance2_lo;
  out.distance2_hi = all.distance2_hi;
  out.boxes = all.boxes;
  out.complete = out.undecided.empty();
  for (const auto& c : out.critical) out.complete = out.complete && (c.unique || c.exact) && !c.merged && (c.along.empty() || c.collapsed);
  return out;
}

std::vector<std::array<double, 2>> project_point_sampled(const BSpline<double>& S, const std::array<double, 3>& P, int grid) {
  solve_detail::require_surface(S, "surface", Limits{}, 2);
  if (grid < 1 || grid > 4096) throw UsageError("grid", "must be in [1, 4096]", "use e.g. 16");
  const double lo[2] = {S.domain_lo(0), S.domain_lo(1)}, hi[2] = {S.domain_hi(0), S.domain_hi(1)};
  const double size = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  std::vector<std::array<double, 2>> out;
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      double x[2] = {lo[0] + (hi[0] - lo[0]) * (i + 0.5) / grid, lo[1] + (hi[1] - lo[1]) * (j + 0.5) / grid};
      bool ok = false;
      for (int it = 0; it < 50; ++it) {
        const std::vector<double> at{x[0], x[1]};
        const auto p = evaluate(S, at), su = derivative(S, at, {1, 0}), sv = derivative(S, at, {0, 1});
        const auto suu = derivative(S, at, {2, 0}), suv = derivative(S, at, {1, 1}), svv = derivative(S, at, {0, 2});
        double f[2] = {0, 0}, J[2][2] = {{0, 0}, {0, 0}};
        for (int c = 0; c < 3; ++c) {
          const double d = p[c] - P[c];
          f[0] += d * su[c];
          f[1] += d * sv[c];
          J[0][0] += su[c] * su[c] + d * suu[c];
          J[0][1] += su[c] * sv[c] + d * suv[c];
          J[1][1] += sv[c] * sv[c] + d * svv[c];
        }
        J[1][0] = J[0][1];
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        if (!(std::abs(det) > 0) || !std::isfinite(det)) break;
        const double dx = (J[1][1] * f[0] - J[0][1] * f[1]) / det, dy = (J[0][0] * f[1] - J[1][0] * f[0]) / det;
        x[0] -= dx;
        x[1] -= dy;
        if (!(x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1])) break;  // left the domain
        if (std::abs(dx) + std::abs(dy) <= 1e-14 * size) {
          ok = true;
          break;
        }
      }
      if (!ok) continue;
      bool seen = false;
      for (const auto& y : out) seen = seen || std::abs(y[0] - x[0]) + std::abs(y[1] - x[1]) <= 1e-9 * size;
      if (!seen) out.push_back({x[0], x[1]});
    }
  return out;
}

template ProjectionResult<Rational> project_point(const BSpline<Rational>&, const std::vector<Rational>&, const SolveOptions&, const Limits&);
template ProjectionResult<double> project_point(const BSpline<double>&, const std::vector<double>&, const SolveOptions&, const Limits&);
template ProjectionResult<Mpfr> project_point(const BSpline<Mpfr>&, const std::vector<Mpfr>&, const SolveOptions&, const Limits&);

}  // namespace splinex
