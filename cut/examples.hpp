// Example solids and cutting data for papers/004's 2D experiments, from exact rational data:
// straight facets are degree-1 segments between integer points, round parts cubic Bezier arcs whose
// control points are chosen so the extreme points are rational (documented per example).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "cut/solid.hpp"
#include "cut/solid3.hpp"

namespace splinex {

struct CutExample {
  std::string name, description;
  Solid2<Rational> solid;
  CutData2<Rational> cut;
};

/// The names: "square", "L" (Figure 10's L-shaped domain), and the domains of Figures 8-9 / Table 1
/// modelled from exact data: "U", "J", "K", "maze", "snake" (descriptions say how).
std::vector<std::string> cut_example_names();
CutExample cut_example(const std::string& name);  // UsageError for an unknown name


/// d = 3 examples: solids made of boxes of a rectilinear grid (every boundary face of a filled
/// box is one bilinear facet, so neighbouring facets share whole sides), with exact coordinates.
/// b is the set of facets on one side of the cutting loop; every loop side lies inside a flat
/// face, and its tangent is that face's inward normal.
struct CutExample3 {
  std::string name, description;
  Solid3<Rational> solid;
  CutData3 cut;
};

/// "tower" (two unit boxes stacked, cut between them), "cube" (2 x 2 x 2 boxes, cut at half height), "slotted" (the bi-slotted cube of Figure 13,
/// modelled: a block with two slots from the top, cut below the first slot), "maiden" (the iron
/// maiden of Figure 11, modelled: the gap between two walls with box spikes reaching past the middle,
/// a wave-shaped loop between them).
std::vector<std::string> cut_example3_names();
CutExample3 cut_example3(const std::string& name);  // UsageError for an unknown name

/// The boundary of the union of the filled boxes [xs[i], xs[i+1]] x [ys[j], ys[j+1]] x
/// [zs[k], zs[k+1]] as bilinear facets oriented outwards. Boxes touching only along an edge or at a
/// corner make a non-manifold boundary, which validate_solid refuses.
Solid3<Rational> box_solid(const std::vector<Rational>& xs, const std::vector<Rational>& ys, const std::vector<Rational>& zs,
                           const std::function<bool(std::size_t, std::size_t, std::size_t)>& filled);

}  // namespace splinex
