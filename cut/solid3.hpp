// Solids bounded by B-spline surface facets and their cutting loops (papers/004 Section 2, d = 3).
//
// A solid is a closed, watertight set of polynomial clamped tensor-product surfaces in R^3, each
// oriented so that F_u x F_v points out of the solid. Neighbouring facets share whole sides: a side
// of one facet (an iso-curve at a domain end) equals a side of exactly one other facet as a curve
// (same degree, same normalized knots, control points in reverse order), so the facets' boundary
// loops, counter-clockwise in their parameter domains, run along a shared side in opposite
// directions. The exact signed volume (1/3 of the integral of F . (F_u x F_v)) is positive.
// Trimmed facets are not supported yet (the bi-slotted cube and the iron maiden are modelled with
// conforming untrimmed patches).
//
// The cutting data for d = 3 name the facets of b (the part of the boundary where the guide is
// positive); the cutting loop L is the set of sides shared by a facet of b and a facet of b-bar.
// It must form one closed cycle of straight sides (segments; curved loops are not built yet). Each
// loop side carries a constant tangent t of the cutting surface, pointing strictly into the solid:
// strictly below both facets' tangent planes along the whole side (t . N < 0 for the outward
// normals N of the two facets, decided exactly by Bernstein signs). At a reflex edge this refuses
// some tangents that do point inside (the wedge is wider than the two half-spaces' intersection).
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/bspline.hpp"

namespace splinex {

template <class T>
struct Solid3 {
  std::vector<BSpline<T>> facets;  // surfaces (two parameters), q = 3, polynomial, clamped, outward
};

/// Sides of a facet on [u0,u1] x [v0,v1], counter-clockwise in the domain: 0: v = v0 (u rising),
/// 1: u = u1 (v rising), 2: v = v1 (u falling), 3: u = u0 (v falling).
BSpline<Rational> facet_side(const BSpline<Rational>& F, int side);

/// A tangent of the cutting surface on one loop side, named by the b facet holding that side.
struct LoopTangent3 {
  std::size_t facet = 0;  // a facet of b
  int side = 0;           // its side on the loop
  std::array<Rational, 3> tangent{Rational(0), Rational(0), Rational(0)};
};

struct CutData3 {
  std::vector<std::size_t> positive;   // the facets of b
  std::vector<LoopTangent3> tangents;  // one per loop side
};

/// A side of the cutting loop, validated: facet a (in b) and its side, facet b (in b-bar) and its
/// side, the segment's end points in the direction of a's side (b on the left seen from outside),
/// the tangent, and n, the guide's target gradient there: (end - start) x t turned towards b and
/// scaled to length 1 within 2^-40 (a rational scale; exact arithmetic has no square roots).
struct LoopSide3 {
  std::size_t facet_a = 0, facet_b = 0;
  int side_a = 0, side_b = 0;
  std::array<Rational, 3> start, end, tangent, normal;
};

/// The solid's adjacency: for facet i and side s, the neighbouring facet and its side.
struct Adjacency3 {
  std::vector<std::array<std::size_t, 4>> facet;
  std::vector<std::array<int, 4>> side;
};

/// Checks the solid (typed errors naming facets[i] and the fix) and returns the adjacency.
Adjacency3 validate_solid(const Solid3<Rational>& S);

/// The exact signed volume enclosed by the facets.
Rational signed_volume(const Solid3<Rational>& S);

/// Checks the cutting data against the solid and returns the loop's sides in cycle order.
std::vector<LoopSide3> validate_cut(const Solid3<Rational>& S, const CutData3& cut);

/// The uniform scaling into the unit cube (papers/004: the bounding box fits into the unit cube).
struct Frame3 {
  std::array<Rational, 3> lo{Rational(0), Rational(0), Rational(0)};
  Rational scale{1};
};
Frame3 unit_frame(const Solid3<Rational>& S);
Solid3<Rational> to_frame(const Solid3<Rational>& S, const Frame3& f);

/// The max-norm distance from x to the segment [a, b] is <= r (exact).
bool within_segment(const std::array<Rational, 3>& x, const std::array<Rational, 3>& a, const std::array<Rational, 3>& b, const Rational& r);

/// x lies in the strip around the loop: within max-norm distance r of some loop side (exact).
bool in_loop_strip(const std::vector<LoopSide3>& loop, const std::array<Rational, 3>& x, const Rational& r);
/// The box [lo, hi] lies in the strip of one loop side: all its corners do (the distance to a
/// segment is convex, so the corners decide).
bool box_in_loop_strip(const std::vector<LoopSide3>& loop, const std::array<Rational, 3>& lo, const std::array<Rational, 3>& hi, const Rational& r);

}  // namespace splinex
