#include "cut/solid.hpp"

#include <algorithm>

#include "spline/bernstein.hpp"
#include "spline/bezier.hpp"
#include "spline/errors.hpp"
#include "spline/evaluate.hpp"
#include "spline/knots.hpp"

namespace splinex {

namespace {

std::string facet_field(std::size_t i) { return "facets[" + std::to_string(i) + "]"; }

std::array<Rational, 2> start_of(const BSpline<Rational>& F) { return {F.points[0], F.points[1]}; }
std::array<Rational, 2> end_of(const BSpline<Rational>& F) {
  const std::size_t n = F.size();
  return {F.points[2 * (n - 1)], F.points[2 * (n - 1) + 1]};
}

// The one-sided derivative at s: from the right (side > 0) or the left. The first non-zero
// derivative of order <= degree, so that a vanishing first derivative still gives the direction.
std::array<Rational, 2> direction(const BSpline<Rational>& F, const Rational& s, int side, const std::string& field) {
  // Split at s and read the control polygon: the first control point differing from the end
  // point gives the one-sided direction (exact; equal control points are skipped).
  const Rational lo = F.domain_lo(0), hi = F.domain_hi(0);
  BSpline<Rational> part = F;
  if (side > 0) {
    if (lo < s) part = split_at(F, 0, s).second;
    const auto p0 = start_of(part);
    for (std::size_t i = 1; i < part.size(); ++i) {
      std::array<Rational, 2> d{part.points[2 * i] - p0[0], part.points[2 * i + 1] - p0[1]};
      if (d[0] != 0 || d[1] != 0) return d;
    }
  } else {
    if (s < hi) part = split_at(F, 0, s).first;
    const auto p1 = end_of(part);
    for (std::size_t i = part.size() - 1; i-- > 0;) {
      std::array<Rational, 2> d{p1[0] - part.points[2 * i], p1[1] - part.points[2 * i + 1]};
      if (d[0] != 0 || d[1] != 0) return d;
    }
  }
  throw ValidationError(field, "the facet is a single point near the cut point (no direction)",
                        "give facets that are curves, not points");
}

Rational cross(const std::array<Rational, 2>& a, const std::array<Rational, 2>& b) { return a[0] * b[1] - a[1] * b[0]; }
Rational dot(const std::array<Rational, 2>& a, const std::array<Rational, 2>& b) { return a[0] * b[0] + a[1] * b[1]; }

// t strictly inside the solid's angle at a point with incoming direction ein and outgoing eout
// (counter-clockwise loop: the solid is on the left).
bool points_inside(const std::array<Rational, 2>& ein, const std::array<Rational, 2>& eout, const std::array<Rational, 2>& t) {
  const Rational turn = cross(ein, eout);
  if (turn > 0) return cross(ein, t) > 0 && cross(eout, t) > 0;      // convex corner
  if (turn < 0) return cross(ein, t) > 0 || cross(eout, t) > 0;      // reflex corner
  if (dot(ein, eout) > 0) return cross(eout, t) > 0;                 // smooth
  // A cusp: the solid's angle is 0 (the facets turn back) or 2 pi; refuse either way.
  return false;
}

}  // namespace

void validate_solid(const Solid2<Rational>& S) {
  if (S.facets.size() < 2) throw ValidationError("facets", "has " + std::to_string(S.facets.size()) + " facet(s)", "give at least two facets forming a closed loop");
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const auto& F = S.facets[i];
    const std::string f = facet_field(i);
    validate(F);
    if (F.dim() != 1) throw ValidationError(f, "is not a curve (" + std::to_string(F.dim()) + " parameters)", "give curves with one parameter");
    if (F.q != 2) throw ValidationError(f, "has " + std::to_string(F.q) + " coordinates", "give planar curves (2 coordinates)");
    if (F.is_rational()) throw ValidationError(f, "is rational", "give polynomial facets (rational facets are not supported yet)");
    if (F.degrees[0] < 1) throw ValidationError(f, "has degree 0", "give curves of degree >= 1 (a loop of facets must be continuous)");
    if (!is_clamped(F.knots[0], F.degrees[0], F.count(0)))
      throw ValidationError(f + ".knots", "is not clamped", "clamp the knot vector (end knots of multiplicity degree + 1) so the facet starts and ends at control points");
    // An inner knot of multiplicity degree + 1 (C^-1) may be a jump: the loop must be continuous.
    const auto pieces = extract_bezier(F);
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
      if (end_of(pieces[k].spline) != start_of(pieces[k + 1].spline))
        throw ValidationError(f, "jumps at its inner knot " + to_fraction_string(pieces[k].spline.domain_hi(0)) + " (a C^-1 knot with a gap)",
                              "split the facet there into two facets joined end to start, or close the gap");
  }
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    const std::size_t j = (i + 1) % S.facets.size();
    if (end_of(S.facets[i]) != start_of(S.facets[j]))
      throw ValidationError(facet_field(i), "ends where " + facet_field(j) + " does not start",
                            "order the facets along the boundary so each ends exactly where the next starts (the last where the first starts)");
  }
  const Rational a = signed_area(S);
  if (a == 0) throw ValidationError("facets", "enclose zero signed area", "give a loop around a solid");
  if (a < 0) throw ValidationError("facets", "run clockwise (signed area " + to_fraction_string(a) + ")",
                                   "list the facets counter-clockwise (the solid on the left), or reverse the loop");
}

Rational signed_area(const Solid2<Rational>& S) {
  // 1/2 sum over Bezier pieces of the integral of x y' - y x' over [0, 1]: products of Bernstein
  // polynomials integrate to the mean of their coefficients.
  Rational twice(0);
  for (const auto& F : S.facets) {
    for (const auto& piece : extract_bezier(F)) {
      const int p = piece.spline.degrees[0];
      std::vector<Rational> x(p + 1), y(p + 1);
      for (int i = 0; i <= p; ++i) x[i] = piece.spline.points[2 * i], y[i] = piece.spline.points[2 * i + 1];
      // derivative coefficients (degree p - 1) of the piece on [0, 1]
      std::vector<Rational> dx(p), dy(p);
      for (int i = 0; i < p; ++i) dx[i] = p * (x[i + 1] - x[i]), dy[i] = p * (y[i + 1] - y[i]);
      // integral of B_i^p B_j^{p-1} over [0,1] = C(p,i) C(p-1,j) / (C(2p-1, i+j) * 2p)
      for (int i = 0; i <= p; ++i)
        for (int j = 0; j < p; ++j) {
          const Rational w = detail::binomial<Rational>(p, i) * detail::binomial<Rational>(p - 1, j) / (detail::binomial<Rational>(2 * p - 1, i + j) * (2 * p));
          twice += w * (x[i] * dy[j] - y[i] * dx[j]);
        }
    }
  }
  return twice / 2;
}

CutData2<Rational> validate_cut(const Solid2<Rational>& S, const CutData2<Rational>& cut) {
  CutData2<Rational> out = cut;
  const std::size_t n = S.facets.size();
  for (int e = 0; e < 2; ++e) {
    auto& c = out.ends[e];
    const std::string f = "points[" + std::to_string(e) + "]";
    if (c.facet >= n) throw ValidationError(f + ".facet", "is " + std::to_string(c.facet) + ", the solid has " + std::to_string(n) + " facets", "give a facet index from 0 to " + std::to_string(n - 1));
    const auto& F = S.facets[c.facet];
    if (c.param < F.domain_lo(0) || F.domain_hi(0) < c.param)
      throw ValidationError(f + ".parameter", "is outside the facet's domain [" + to_fraction_string(F.domain_lo(0)) + ", " + to_fraction_string(F.domain_hi(0)) + "]", "give a parameter of the facet's domain");
    if (c.tangent[0] == 0 && c.tangent[1] == 0) throw ValidationError(f + ".tangent", "is zero", "give a non-zero tangent pointing into the solid");
    if (c.param == F.domain_hi(0)) {
      c.facet = (c.facet + 1) % n;
      c.param = S.facets[c.facet].domain_lo(0);
    }
    const auto& G = S.facets[c.facet];
    std::array<Rational, 2> ein, eout;
    if (c.param == G.domain_lo(0)) {
      const auto& P = S.facets[(c.facet + n - 1) % n];
      ein = direction(P, P.domain_hi(0), -1, f);
    } else {
      ein = direction(G, c.param, -1, f);
    }
    eout = direction(G, c.param, +1, f);
    if (!points_inside(ein, eout, c.tangent))
      throw ValidationError(f + ".tangent", "does not point strictly into the solid", "give a tangent that points into the solid (the solid lies left of the counter-clockwise facets)");
  }
  if (out.ends[0].facet == out.ends[1].facet && out.ends[0].param == out.ends[1].param)
    throw ValidationError("points", "are the same point of the boundary", "give two distinct points");
  return out;
}

Frame2 unit_frame(const Solid2<Rational>& S) {
  Frame2 f;
  std::array<Rational, 2> hi;
  bool first = true;
  for (const auto& F : S.facets)
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int a = 0; a < 2; ++a) {
        const Rational& x = F.points[2 * i + a];
        if (first || x < f.lo[a]) f.lo[a] = x;
        if (first || hi[a] < x) hi[a] = x;
        if (a == 1) first = false;
      }
  f.scale = hi[0] - f.lo[0];
  if (f.scale < hi[1] - f.lo[1]) f.scale = hi[1] - f.lo[1];
  if (f.scale == 0) throw ValidationError("facets", "lie in one point", "give a solid with an interior");
  return f;
}

Solid2<Rational> to_frame(const Solid2<Rational>& S, const Frame2& f) {
  Solid2<Rational> out = S;
  for (auto& F : out.facets)
    for (std::size_t i = 0; i < F.size(); ++i)
      for (int a = 0; a < 2; ++a) F.points[2 * i + a] = (F.points[2 * i + a] - f.lo[a]) / f.scale;
  return out;
}

bool on_arc(std::size_t facet, const Rational& param, const CutPoint2<Rational>& from, const CutPoint2<Rational>& to) {
  auto less = [](std::size_t f1, const Rational& p1, std::size_t f2, const Rational& p2) { return f1 < f2 || (f1 == f2 && p1 < p2); };
  const bool after_from = less(from.facet, from.param, facet, param);
  const bool before_to = less(facet, param, to.facet, to.param);
  if (less(from.facet, from.param, to.facet, to.param)) return after_from && before_to;
  return after_from || before_to;
}

std::vector<BoundaryPiece> split_at_cut_points(const Solid2<Rational>& S, const CutData2<Rational>& cut) {
  std::vector<BoundaryPiece> parts;
  for (std::size_t i = 0; i < S.facets.size(); ++i) {
    std::vector<Rational> cuts;
    for (const auto& e : cut.ends)
      if (e.facet == i && S.facets[i].domain_lo(0) < e.param && e.param < S.facets[i].domain_hi(0)) cuts.push_back(e.param);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    BSpline<Rational> rest = S.facets[i];
    for (const auto& c : cuts) {
      auto [a, b] = split_at(rest, 0, c);
      parts.push_back({std::move(a), i});
      rest = std::move(b);
    }
    parts.push_back({std::move(rest), i});
  }
  return parts;
}

}  // namespace splinex
