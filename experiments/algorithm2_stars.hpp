// Algorithm 2 (composition into tensor-product patches by untrimming) on the teapot star pattern
// of papers/000 (Figure 5), compared with Algorithm 1: tiles, orders (the paper: (25, 25)),
// control points, time, and the deviation of each tile from T(S) measured exactly.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace splinex {

struct Algorithm2StarsOptions {
  std::string out_dir;
  int tiles = 7;
  std::vector<double> eps{1e-2, 1e-3, 1e-4};  // polyline tolerances of the untrimming
  bool exact_star = true;  // also run one star exactly (Algorithm 2 in rationals) for the cost ratio
};

/// Writes algorithm2_stars.csv into out_dir and returns a Markdown section; ok is false when a
/// tile of orders other than (25, 25) appears or the tiles fail to cover a star's domain.
std::string run_algorithm2_stars(const Algorithm2StarsOptions& options,
                                 const std::function<void(const std::string&)>& progress, bool& ok);

}  // namespace splinex
