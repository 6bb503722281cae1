// The figure of a guiding curve (papers/004 Figures 6, 8-10): the solid's boundary, the samples of
// b* (green) and b-bar* (red), the strip around the cut points, the tangents, the zero level set of
// f* (blue; marching squares on a grid, in double: a picture, not a measurement) and a violation
// witness or undecided pieces of the separation certificate; the fitted cutting curve (purple).
#pragma once
#include <string>

#include "cut/guide.hpp"
#include "cut/separation.hpp"

namespace splinex {

/// f: the guide exactly (the exact minimizer, or a double guide's values as rationals).
std::string cut_guide_svg(const Solid2<Rational>& solid, const CutData2<Rational>& cut, const BSpline<Rational>& f,
                          const std::vector<std::array<Rational, 2>>& samples, std::size_t samples_positive,
                          const Rational& strip, const SeparationResult* separation, const std::string& title,
                          const BSpline<Rational>* cutting_curve = nullptr);

}  // namespace splinex
