// CGAL's Wachspress coordinates, the independent check of hybrid/hybrid.hpp's own.
#pragma once
#include <array>
#include <vector>

#include "exact/rational.hpp"

namespace splinex {

/// CGAL::Barycentric_coordinates::wachspress_coordinates_2 over an exact kernel (Gmpq), in the
/// vertex order of the patch.
std::vector<Rational> cgal_wachspress(const std::vector<std::array<Rational, 2>>& polygon, const std::array<Rational, 2>& x);

}  // namespace splinex
