// Non-singular primitives of papers/002 Section 3.2.3 (Figure 9) and the singular single
// trivariates of Figure 8, with rational coefficients.
//
// The disk of radius r is cut into five cells: a square and four ring sectors. The sectors' arcs
// end at the rational points c_k of the circle, c_0 = r (4/5, 3/5) and its rotations by 90
// degrees (a Pythagorean triple instead of the 45-degree points r (1, 1)/sqrt 2, which are
// irrational); each 90-degree arc is the rational quadratic with points c_k, c_k + c_{k+1},
// c_{k+1} and weights (1, 1, 2) or (2, 1, 1) alternately (so that the spoke two sectors share has
// the same weights in both: the gluing compares control nets). The square has corners s c_k (s = 1/2). Each sector is the ruled
// surface from its arc (v = 0) to the square's side (v = 1, a quadratic with unit weights, so the
// side equals the square's side in a common function space).
//  - cylinder: the five disk cells extruded along z by h (extrusions);
//  - cone: ruled volumes between the disk cells of radius r0 at z = 0 and r1 at z = h (a frustum:
//    an apex would be a singular point);
//  - torus: the disk of radius r in the xz-plane centred at (R, 0, 0), R > r, revolved about z
//    (volumes of revolution, exact rational circles); each cell is glued to itself at 0 = 360
//    degrees;
//  - box: one trilinear trivariate.
// The sphere of seven cells (a cube and six ruled cells to sphere patches) is not built: the
// cube-sphere patches need irrational weights (sqrt 2, sqrt 3, sqrt 6) and no exact rational
// replacement that glues is implemented yet (docs/vrep.md).
// Figure 8: singular_cylinder (a rectangle revolved about z: det J = 0 on the axis) and
// singular_sphere (a half disk revolved about z).
#pragma once
#include <vector>

#include "spline/bspline.hpp"

namespace splinex {

/// The five cells of the disk of radius r in the xy-plane (points in R^3, z = 0), each a
/// positively oriented surface (S_u x S_v along +z).
template <class T>
std::vector<BSpline<T>> disk_cells(const T& r);

template <class T>
std::vector<BSpline<T>> cylinder_cells(const T& r, const T& h);

template <class T>
std::vector<BSpline<T>> cone_cells(const T& r0, const T& r1, const T& h);

template <class T>
std::vector<BSpline<T>> torus_cells(const T& R, const T& r);

template <class T>
std::vector<BSpline<T>> box_cells(const std::vector<T>& lo, const std::vector<T>& hi);

template <class T>
BSpline<T> singular_cylinder(const T& r, const T& h);

template <class T>
BSpline<T> singular_sphere(const T& r);

}  // namespace splinex
