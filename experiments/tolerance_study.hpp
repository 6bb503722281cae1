// What a trimming tolerance costs, measured exactly (papers/000, "the price of tolerance"), at
// the scale of an inner curve crossing one knot of T: the float trimming point found to
// tolerance eps moves the piece boundary by up to eps, and the parameters in between are
// evaluated with the neighbouring polynomial piece. With T of degree p and the knot of
// multiplicity m (T is C^(p-m) there) the error grows like eps^(p-m+1).
#pragma once
#include <functional>
#include <string>

namespace splinex {

/// Curve case (trimming points by float bisection) and surface case (trimming polylines within eps,
/// untrim/trimming_polyline.hpp). Writes tolerance*.csv and tolerance*.svg into out_dir; returns a
/// Markdown section. ok is false when a fitted slope misses the predicted order by more than 0.25.
std::string run_tolerance_study(const std::string& out_dir, const std::function<void(const std::string&)>& progress, bool& ok);

}  // namespace splinex
