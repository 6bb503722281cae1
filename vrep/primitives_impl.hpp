// Primitives (vrep/primitives.hpp): the templates, instantiated in vrep/instances.cpp.
#pragma once
#include "spline/elevate.hpp"
#include "spline/errors.hpp"
#include "vrep/primitives.hpp"
#include "vrep/trivariate.hpp"

namespace splinex {

namespace vrep_detail {

template <class T>
void require_positive(const T& x, const std::string& field) {
  if (!(T(0) < x)) throw ValidationError(field, "must be positive", "give a positive size");
}

/// c_k = r (4/5, 3/5) rotated by k x 90 degrees.
template <class T>
std::array<T, 2> circle_point(const T& r, int k) {
  const T a = T(4) / T(5), b = T(3) / T(5);
  const T x[4] = {a, -b, -a, b}, y[4] = {b, a, -b, -a};
  return {r * x[k % 4], r * y[k % 4]};
}

}  // namespace vrep_detail

template <class T>
std::vector<BSpline<T>> disk_cells(const T& r) {
  vrep_detail::require_positive(r, "radius");
  const T s = T(1) / T(2);
  std::array<std::array<T, 2>, 4> c, sq;
  for (int k = 0; k < 4; ++k) {
    c[k] = vrep_detail::circle_point(r, k);
    sq[k] = {s * c[k][0], s * c[k][1]};
  }
  std::vector<BSpline<T>> out;
  // The square: (0,0) = sq2, (1,0) = sq3, (0,1) = sq1, (1,1) = sq0 (positively oriented).
  BSpline<T> Q;
  Q.degrees = {1, 1};
  Q.knots = {{T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
  Q.q = 3;
  for (int k : {2, 3, 1, 0}) Q.points.insert(Q.points.end(), {sq[k][0], sq[k][1], T(0)});
  out.push_back(Q);
  // Sector k: u from c_k to c_{k+1}; v = 0 the arc, v = 1 the square's side (u along it).
  for (int k = 0; k < 4; ++k) {
    const auto& a = c[k];
    const auto& b = c[(k + 1) % 4];
    const auto& sa = sq[k];
    const auto& sb = sq[(k + 1) % 4];
    BSpline<T> S;
    S.degrees = {2, 1};
    S.knots = {{T(0), T(0), T(0), T(1), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
    S.q = 3;
    S.points = {a[0], a[1], T(0), a[0] + b[0], a[1] + b[1], T(0), b[0], b[1], T(0),
                sa[0], sa[1], T(0), (sa[0] + sb[0]) / T(2), (sa[1] + sb[1]) / T(2), T(0), sb[0], sb[1], T(0)};
    // Arc weights (1, 1, 2) and (2, 1, 1) alternately, so that the spoke shared by sectors k and
    // k + 1 has the same weights (2 at the circle, 1 at the square, or 1 and 1) in both.
    if (k % 2 == 0) S.weights = {T(1), T(1), T(2), T(1), T(1), T(1)};
    else S.weights = {T(2), T(1), T(1), T(1), T(1), T(1)};
    out.push_back(S);
  }
  return out;
}

template <class T>
std::vector<BSpline<T>> cylinder_cells(const T& r, const T& h) {
  vrep_detail::require_positive(h, "height");
  std::vector<BSpline<T>> out;
  for (const auto& D : disk_cells(r)) out.push_back(extrude(D, std::vector<T>{T(0), T(0), h}));
  return out;
}

template <class T>
std::vector<BSpline<T>> cone_cells(const T& r0, const T& r1, const T& h) {
  vrep_detail::require_positive(h, "height");
  const auto bottom = disk_cells(r0), top = disk_cells(r1);
  std::vector<BSpline<T>> out;
  for (std::size_t k = 0; k < bottom.size(); ++k) {
    BSpline<T> t = top[k];
    for (std::size_t i = 0; i < t.size(); ++i) t.points[i * 3 + 2] = h;
    out.push_back(ruled(bottom[k], t));
  }
  return out;
}

template <class T>
std::vector<BSpline<T>> torus_cells(const T& R, const T& r) {
  vrep_detail::require_positive(r, "minor radius");
  if (!(r < R)) throw ValidationError("major radius", "must exceed the minor radius", "give R > r (the tube may not touch the axis)");
  std::vector<BSpline<T>> out;
  for (auto D : disk_cells(r)) {
    // (x, y, 0) -> (R + x, 0, y): the disk in the xz-plane around (R, 0, 0).
    for (std::size_t i = 0; i < D.size(); ++i) {
      const T x = D.points[i * 3], y = D.points[i * 3 + 1];
      D.points[i * 3] = R + x;
      D.points[i * 3 + 1] = T(0);
      D.points[i * 3 + 2] = y;
    }
    out.push_back(revolve(D, 2, 4));
  }
  return out;
}

template <class T>
std::vector<BSpline<T>> box_cells(const std::vector<T>& lo, const std::vector<T>& hi) {
  if (lo.size() != 3 || hi.size() != 3) throw ValidationError("box", "needs three coordinates per corner", "give lo and hi in R^3");
  for (int d = 0; d < 3; ++d)
    if (!(lo[d] < hi[d])) throw ValidationError("box", "lo must be below hi in every coordinate", "give lo < hi");
  BSpline<T> B;
  B.degrees = {1, 1, 1};
  B.knots = {{T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
  B.q = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) B.points.insert(B.points.end(), {i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]});
  return {B};
}

template <class T>
BSpline<T> singular_cylinder(const T& r, const T& h) {
  vrep_detail::require_positive(r, "radius");
  vrep_detail::require_positive(h, "height");
  BSpline<T> rect;
  rect.degrees = {1, 1};
  rect.knots = {{T(0), T(0), T(1), T(1)}, {T(0), T(0), T(1), T(1)}};
  rect.q = 3;
  rect.points = {T(0), T(0), T(0), r, T(0), T(0), T(0), T(0), h, r, T(0), h};
  return revolve(rect, 2, 4);
}

template <class T>
BSpline<T> singular_sphere(const T& r) {
  vrep_detail::require_positive(r, "radius");
  const BSpline<T> arc = rational_circle<T>(2);  // (1, 0) -> (0, 1) -> (-1, 0), mapped to (y, 0, -x): south to north pole
  BSpline<T> disk;
  disk.degrees = {2, 1};
  disk.knots = {arc.knots[0], {T(0), T(0), T(1), T(1)}};
  disk.q = 3;
  for (int side = 0; side < 2; ++side)
    for (std::size_t i = 0; i < arc.size(); ++i) {
      const T x = arc.points[2 * i], y = arc.points[2 * i + 1];
      disk.points.insert(disk.points.end(), {side ? r * y : T(0), T(0), -r * x});
      disk.weights.push_back(arc.weights[i]);
    }
  return revolve(disk, 2, 4);
}

}  // namespace splinex
