// Hybrid patches for the examples of papers/003. The paper prints domains, degrees and knot
// vectors but no control points, so splinex constructs them (documented, deterministic):
//  - the domain point of C^i_{j,k}: near corner V_i (j < l) V_i + (j/d)(V_{i+1} - V_i) +
//    (k/d)(V_{i-1} - V_i); near corner V_{i+1} (j > d - l) the same from V_{i+1}; between,
//    E + (2k/d)(G - E) with E = V_i + (j/d)(V_{i+1} - V_i) and G the vertex centroid. The corner
//    rule makes shared corner points agree exactly (C^i_{a,b} = C^{i-1}_{d-b,a});
//  - the control point is (x, y, z(x, y)) with the dome z = 1 - 2 |(x, y) - G|^2 (exact).
// Knot vectors the paper does not print (Example 3.1) are uniform and clamped.
#pragma once
#include <string>
#include <vector>

#include "exact/rational.hpp"
#include "spline/hybrid.hpp"

namespace splinex {

HybridPatch<Rational> hybrid_dome(const std::vector<std::array<Rational, 2>>& domain, int d, const std::vector<int>& p,
                                  const std::vector<std::vector<Rational>>& knots);
// d + 1 control points of degree p, clamped on [0, 1], uniform interior knots.
std::vector<Rational> uniform_clamped_knots(int d, int p);

// Example 2.1: pentagon, d = 6, p = 2, U = {0,0,0,0.2,0.4,0.6,0.8,1,1,1}.
HybridPatch<Rational> hybrid_example_2_1();
// Example 3.1: hexagon with p = 5,3,2,4,4,2 (uniform knots), d = 6; and the octagon, d = 6, p = 2
// with Example 2.1's knots.
HybridPatch<Rational> hybrid_example_3_1_hexagon();
HybridPatch<Rational> hybrid_example_3_1_octagon();

}  // namespace splinex
