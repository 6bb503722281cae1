// The one point and vector algebra of the project, in any arithmetic T: points of a parameter
// plane (untrimming's sweep and tiles, trimming polylines, the hybrid patch's domain, cutting
// loops) and of space (V-rep faces and junctions, cutting surfaces, contact normals).
// Exact in an exact T: every function is a polynomial in the coordinates, no division, no root.
// A rule checked by ctest (scripts/check_size.py, placement): no other file defines a point type
// or writes out a cross product.
#pragma once
#include <array>
#include <cstddef>
#include <type_traits>

namespace splinex {

/// A point (x, y) of a parameter plane.
template <class T>
using Point2 = std::array<T, 2>;

/// A point or vector (x, y, z) of space.
template <class T>
using Point3 = std::array<T, 3>;

/// The first three coordinates of a vector (a derivative, a control point) as a point of space.
template <class Vector>
auto as_point3(const Vector& v) -> Point3<std::decay_t<decltype(v[0])>> {
  return {v[0], v[1], v[2]};
}

/// The closed segment from a to b.
template <class T>
struct Segment2 {
  Point2<T> a, b;
};

/// a - b, coordinate by coordinate.
template <class T, std::size_t N>
std::array<T, N> sub(const std::array<T, N>& a, const std::array<T, N>& b) {
  std::array<T, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = a[i] - b[i];
  return r;
}

/// a + b, coordinate by coordinate.
template <class T, std::size_t N>
std::array<T, N> add(const std::array<T, N>& a, const std::array<T, N>& b) {
  std::array<T, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = a[i] + b[i];
  return r;
}

/// s a.
template <class T, std::size_t N>
std::array<T, N> scale(const T& s, const std::array<T, N>& a) {
  std::array<T, N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = s * a[i];
  return r;
}

/// The inner product a . b (accumulated from the first coordinate on).
template <class T, std::size_t N>
T dot(const std::array<T, N>& a, const std::array<T, N>& b) {
  T r = a[0] * b[0];
  for (std::size_t i = 1; i < N; ++i) r = r + a[i] * b[i];
  return r;
}

/// The cross product a x b of space.
template <class T>
Point3<T> cross(const Point3<T>& a, const Point3<T>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The cross product of the plane, a_x b_y - a_y b_x (twice the signed area of 0, a, b).
template <class T>
T cross(const Point2<T>& a, const Point2<T>& b) {
  return a[0] * b[1] - a[1] * b[0];
}

/// The triple product a . (b x c), the signed volume of the parallelepiped on a, b, c.
template <class T>
T triple(const Point3<T>& a, const Point3<T>& b, const Point3<T>& c) {
  return dot(a, cross(b, c));
}

}  // namespace splinex
