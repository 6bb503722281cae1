// Point projection onto a surface (solve/projection.hpp), instantiated for Rational and double.
#include "solve/projection.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "float/arith_spec.hpp"
#include "solve/strata.hpp"
#include "spline/errors.hpp"

namespace splinex {

template <class T>
ProjectionResult<T> project_point(const BSpline<T>& S, const std::vector<T>& P, const SolveOptions& options, const Limits& limits) {
  validate(S, limits);
  if (S.dim() != 2 || S.q < 3)
    throw ValidationError("surface", "is not a surface in R^3", "give a spline with two parametric directions and points x,y,z");
  if (P.size() != 3) throw ValidationError("point", "has " + std::to_string(P.size()) + " coordinates", "give x,y,z");
  for (int d = 0; d < 2; ++d) {
    if (S.degrees[d] == 0)
      throw ValidationError("degrees[" + std::to_string(d) + "]", "is 0: the surface has no tangent plane, the projection equations are degenerate",
                            "elevate the surface to degree >= 1");
    // The equations' degrees: 2p - 1 (polynomial) or 3p - 1 (rational) in the derivative's direction.
    limits.check_degree(static_cast<long>(S.is_rational() ? 3 : 2) * S.degrees[d], "degrees[" + std::to_string(d) + "]");
  }
  const auto all = solve_detail::stationary_pairs(solve_detail::surface_strata(S, limits), {solve_detail::point_stratum(P)}, options, false);
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
    return c;
  };
  ProjectionResult<T> out;
  for (const auto& p : all.points) out.critical.push_back(convert(p));
  for (const auto& p : all.undecided) out.undecided.push_back(convert(p));
  out.closest = all.closest;
  out.closest_certified = all.closest_certified;
  out.distance2_lo = all.distance2_lo;
  out.distance2_hi = all.distance2_hi;
  out.boxes = all.boxes;
  out.complete = out.undecided.empty();
  for (const auto& c : out.critical) out.complete = out.complete && (c.unique || c.exact) && !c.merged;
  return out;
}

template ProjectionResult<Rational> project_point(const BSpline<Rational>&, const std::vector<Rational>&, const SolveOptions&, const Limits&);
template ProjectionResult<double> project_point(const BSpline<double>&, const std::vector<double>&, const SolveOptions&, const Limits&);

}  // namespace splinex
