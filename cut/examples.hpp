// Example solids and cutting data for papers/004's 2D experiments, from exact rational data:
// straight facets are degree-1 segments between integer points, round parts cubic Bezier arcs whose
// control points are chosen so the extreme points are rational (documented per example).
#pragma once
#include <string>
#include <vector>

#include "cut/solid.hpp"

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

}  // namespace splinex
