// Definition 1 of papers/000 (preservation of the parametrization) made visible, as in the paper's
// Figure 3: a numbered checkerboard texture on the output of Algorithm 1 (trimmed patches, texture
// coordinates = S's parameters) and of Algorithm 2 (tensor-product tiles, texture coordinates = each
// tile's own parameters). Exact: S is affine, so both algorithms run in rationals.
#pragma once
#include <string>

namespace splinex {

/// Writes checkerboard.svg into out_dir; returns a Markdown section with the measured loss of the
/// parametrization: max |R_tile(texture point) - T(S(texture point))| over tiles and a grid, exact
/// (0 for Algorithm 1, proved pointwise here too). ok is false if Algorithm 1's loss is not 0.
std::string run_checkerboard(const std::string& out_dir, bool& ok);

}  // namespace splinex
