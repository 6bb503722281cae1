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
//  - sphere: the sphere of seven cells of Figure 9, an inner cube [-r/2, r/2]^3 and six ruled
//    cells from its faces to the six patches of the cube sphere (the central projection of a
//    cube's faces). The exact cube-sphere patch has no representation with rational coefficients
//    at all: its corners are r (+-1, +-1, +-1)/sqrt 3, irrational points, and a rational patch's
//    corner is its corner control point. What is built instead keeps everything but the radius
//    exact: patch +z is the homogeneous (r s, r t, r, P(s, t)), s, t in [-1, 1], so every point
//    lies exactly on the ray through (s, t, 1) (the edges lie exactly in the planes x = +-z,
//    y = +-z) and only its distance from the centre, r sqrt(1 + s^2 + t^2) / P, is approximate.
//    P is the tensor spline of degree p with n uniform pieces per direction interpolating
//    sqrt(1 + s^2 + t^2) at the Greville points (values rounded down to 2^-64 by exact integer
//    square roots, the system solved exactly), symmetric in s <-> t and even in each, so the
//    six patches (the +z one under the rotations of the cube) share their edges exactly and the
//    seven cells glue exactly. sphere_deviation bounds | |x - c|^2 / r^2 - 1 | over a patch from
//    exact Bernstein coefficients (docs/vrep/primitives.md has the numbers).
// Figure 8: singular_cylinder (a rectangle revolved about z: det J = 0 on the axis) and
// singular_sphere (a half disk revolved about z).
#pragma once
#include <vector>

#include "exact/rational.hpp"
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

/// The seven cells of the sphere of radius r about the origin: the cube first, then the ruled
/// cells over the faces +z, -z, +x, -x, +y, -y (patch degree `degree`, `pieces` per direction).
template <class T>
std::vector<BSpline<T>> sphere_cells(const T& r, int degree = 3, int pieces = 4);

/// How far a surface is from the sphere |x - centre| = r: `bound` >= | |S(u, v) - centre|^2 / r^2
/// - 1 | everywhere (certified: Bernstein coefficients of the numerator over the least Bernstein
/// coefficient of W^2, exact per piece), `witness` the largest value of that quantity at a grid
/// of `samples` x `samples` parameters (exact values, so bound >= witness), `at` where.
struct SphereDeviation {
  Rational bound, witness;
  std::vector<Rational> at;
};
SphereDeviation sphere_deviation(const BSpline<Rational>& S, const std::vector<Rational>& centre, const Rational& r, int samples = 17);

template <class T>
BSpline<T> singular_cylinder(const T& r, const T& h);

template <class T>
BSpline<T> singular_sphere(const T& r);

}  // namespace splinex
