// Exact polygons in a parameter plane: CGAL's exact polygon area and simplicity test (an
// independent check of the sweep's tiles), and clipping by half-planes (Sutherland-Hodgman, exact).
#pragma once
#include <array>
#include <optional>
#include <vector>

#include "exact/rational.hpp"
#include "compose/trimmed_compose.hpp"
#include "untrim/sweep.hpp"

namespace splinex {

using Polygon = std::vector<Point2<Rational>>;

/// Signed area (positive for counter-clockwise), by CGAL::Polygon_2 over exact rationals.
Rational polygon_area(const Polygon& p);
/// CGAL::Polygon_2::is_simple (no self-intersection, no repeated vertex).
bool polygon_is_simple(const Polygon& p);
/// The part of the polygon p where a*x + b*y + c >= 0, by Sutherland-Hodgman (exact). For a
/// non-convex p whose kept part is disconnected the result joins the parts along the line, which
/// adds no area.
/// Area of the union of simple polygons (any orientation), by CGAL's exact Boolean operations
/// (Polygon_set_2 over exact rationals): with the sum of the areas it gives the exact overlap, with
/// the area of the domain the exact gap of a tiling. Polygons with fewer than 3 vertices or zero
/// area are ignored; a non-simple polygon is a std::invalid_argument (CGAL needs simple ones).
Rational polygon_union_area(const std::vector<Polygon>& polygons);
/// Loops that meet (share a point), each loop simple: none when they are pairwise disjoint, else
/// {l, m} with m the least loop that meets an earlier one and l the least loop it meets. By CGAL's
/// sweep for intersecting segments (Surface_sweep_2, stopping at the first) and a sort of the
/// vertices, bisected over prefixes of the loops: O(n log^2 n) however many edges overlap in x (an
/// interval join over x is quadratic for many equal or nested loops).
std::optional<std::array<std::size_t, 2>> first_meeting_loops(const std::vector<Polygon>& loops);
Polygon clip_halfplane(const Polygon& p, const Rational& a, const Rational& b, const Rational& c);

/// The region of an inner piece for an affine inner map s_c(r, t) = al[c] + be[c] r + ga[c] t: the
/// piece's box clipped by the half-planes of the region's conditions (lo <= s_c, s_c <= hi; the
/// open side of s_c < hi adds no area). Built independently of the sweep, as its check.
Polygon affine_region_polygon(const std::vector<std::pair<Rational, Rational>>& box,
                              const std::vector<CellCondition<Rational>>& region, const Rational al[2], const Rational be[2],
                              const Rational ga[2]);

}  // namespace splinex
