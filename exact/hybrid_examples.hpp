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
#include "spline/bspline.hpp"
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

// Example 3.2: a hole between tensor-product B-spline patches, filled by a hybrid patch.
// Construction (the paper prints none): a quadratic host surface z = f(x, y) = (x^2 + y^2)/4 -
// x y / 3 + x / 5; around side i of the domain polygon a neighbour A_i(s, t), the graph of f over
// X_i(s, t) = V_i + s (V_{i+1} - V_i) + t ((1 - s) a_i (V_i - V_{i-1}) + s b_i (V_{i+1} - V_{i+2})),
// t in [0, 1] (outside the hole), exact as a B-spline of degree (p_i, 2) over (U_i, {0,0,0,1,1,1})
// (Bezier (2, 2) by interpolation, elevated and refined by the kernel). The offsets continue the
// neighbouring sides (four patches meet at each hole corner) with a_i = tau_i / sigma_{i-1},
// b_i = tau_i / tau_{i+1}, so that the corner points the hybrid patch shares agree exactly.
// The patch takes C^i_{j,0} = A_i's boundary row and C^i_{j,1} = C^i_{j,0} - (2 / tau_i)
// (A_i row 1 - row 0), so T_i = -dA_i/dt (C1 with h_i = -t). Where two sides demand different
// values for one shared point (the twists C^i_{1,1} = C^{i-1}_{d-1,1}) their mean is used and the
// disagreement reported; points no ribbon determines are f at hybrid_dome's domain points.
struct HybridHole {
  HybridPatch<Rational> patch;
  std::vector<BSpline<Rational>> neighbours;  // A_i, direction 0 along side i, direction 1 outward
  Rational max_conflict{0};                   // largest max-norm disagreement of two demands
  std::size_t conflicts = 0;                  // shared points with disagreeing demands
};
// n = 5: Example 2.1's pentagon, d = 5, p = 2, U = {0,0,0,1/4,1/2,3/4,1,1,1} (Eq. 2.12);
// n = 6: Example 3.1's hexagon, d = 6, p = 5,3,2,4,4,2 uniform (Eq. 2.11).
HybridHole hybrid_hole_example_3_2(int n);

}  // namespace splinex
