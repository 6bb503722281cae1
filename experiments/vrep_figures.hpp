// Figures of V-models (issue 17): an exploded view of the cells (each cell's six faces, shifted
// away from the model's centre by `explode` times its centroid's offset, one colour per cell: its
// "colour" attribute (three values in [0, 1]) or the palette's),
// optionally with the points where det J = 0 exactly marked in red (sampled on each cell's
// boundary faces, exact evaluation of det J's numerator).
#pragma once
#include <string>

#include "exact/rational.hpp"
#include "vrep/vmodel.hpp"

namespace splinex {

std::string vmodel_svg(const VModel<Rational>& M, double explode, const std::string& title, bool mark_singular, int samples = 12);

}  // namespace splinex
