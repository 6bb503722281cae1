// Figures of V-models (issue 17): an exploded view of the cells (each cell's six faces, shifted
// away from the model's centre by `explode` times its centroid's offset, one colour per cell: its
// "colour" attribute (three values in [0, 1]) or the palette's),
// optionally with the points where det J = 0 exactly marked in red (sampled on each cell's
// boundary faces, exact evaluation of det J's numerator).
#pragma once
#include <string>

#include "exact/rational.hpp"
#include "vrep/model/vmodel.hpp"

namespace splinex {

std::string vmodel_svg(const VModel<Rational>& M, double explode, const std::string& title, bool mark_singular, int samples = 12);

}  // namespace splinex

#include "vrep/trimmed/trimmed.hpp"

namespace splinex {

/// Trimmed cells for the eye (figures only, doubles): each cell's parameter box sampled on an
/// n x n x n grid of voxels, a voxel kept when the cell's trim holds at its centre (the region
/// evaluated in double at T's double value), its faces towards dropped voxels or the domain's
/// boundary drawn (stair-stepped at the trimming surfaces: the resolution is named in the note).
/// Colours by category (A purple, both cyan, B green, as in Figure 4) or the palette for inputs.
std::string trimmed_svg(const TrimmedModel<Rational>& M, double explode, const std::string& title, int n = 12);
/// The kept voxels as VTK hexahedra (an unstructured grid, .vtu) with cell data "cell" and
/// "category" (0 input, 1 A, 2 both, 3 B) for ParaView.
std::string trimmed_vtu(const TrimmedModel<Rational>& M, int n = 12);

}  // namespace splinex
