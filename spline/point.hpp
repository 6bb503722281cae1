// The one point and segment type of a parameter plane, in the arithmetic T (untrimming's sweep and
// tiles, trimming polylines in double, the hybrid patch's domain).
#pragma once
#include <array>

namespace splinex {

/// A point (x, y) of a parameter plane.
template <class T>
using Point2 = std::array<T, 2>;

/// The closed segment from a to b.
template <class T>
struct Segment2 {
  Point2<T> a, b;
};

}  // namespace splinex
